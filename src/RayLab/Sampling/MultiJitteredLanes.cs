using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// <see cref="MultiJitteredSampler"/> in lanes: the n column and n row permutations of each pixel get their
/// pattern numbers once per packet and their elements walk in SIMD. Each point is the scalar sampler's float: with
/// n a power of two the formula's double value is exact and one float rounding gives it; otherwise it runs in double.
/// </summary>
internal struct MultiJitteredLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();

    private readonly uint _salt;
    private readonly int _n;
    private readonly LaneLength<TL> _length;
    private readonly CellFormula _cell;
    private readonly bool _exactInFloat;
    private readonly TL _inverseCount;
    private readonly uint[] _scratch = new uint[TL.Count];
    private readonly LanePermutation<TL>[] _columns, _rows;
    private readonly (int Column, int Row)[] _cells;
    private TL _keys;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public MultiJitteredLanes(MultiJitteredSampler sampler)
    {
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _n = sampler.GridSize;
        _length = new LaneLength<TL>(_n);
        _cell = new CellFormula(CellFormula.UnitScale, _n, _n);
        _exactInFloat = int.IsPow2(_n);
        _inverseCount = TL.Broadcast(1f / (_n * _n));
        _columns = new LanePermutation<TL>[_n];
        _rows = new LanePermutation<TL>[_n];

        // Sample i's coarse cell (i mod n, i div n), looked up rather than divided for in the hot loop.
        _cells = new (int, int)[_n * _n];
        for (int i = 0; i < _cells.Length; i++)
        {
            _cells[i] = (i % _n, i / _n);
        }
    }

    /// <inheritdoc />
    public void BeginPacket(int x0, int row)
    {
        _keys = LaneHash.PixelKeys<TL>(x0, row, _salt);
        TL columnKeys = TL.Xor(_keys, TL.BroadcastBits(MultiJitteredSampler.ColumnSalt)), rowKeys = TL.Xor(_keys, TL.BroadcastBits(MultiJitteredSampler.RowSalt));
        for (int k = 0; k < _n; k++)
        {
            _columns[k].Set(LaneHash.SampleHash(columnKeys, k), _length, _scratch);
            _rows[k].Set(LaneHash.SampleHash(rowKeys, k), _length, _scratch);
        }
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, MultiJitteredLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => false;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        (int column, int row) = _cells[index];
        (a, b) = LanePermutation<TL>.Pair(
            _columns[column], TL.BroadcastBits((uint)row), _length, _rows[row], TL.BroadcastBits((uint)column), _length);
        c = default;
    }

    /// <inheritdoc />
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        (int column, int row) = _cells[index];
        TL subColumn = TL.BitsToFloat(a), subRow = TL.BitsToFloat(b);
        TL h1 = LaneHash.SampleHash(_keys, index);
        TL h2 = TL.Hash(h1);
        if (_exactInFloat)
        {
            // (column + (sub + u)/n)/n = (column·n + sub + u)/n² with n = 2ᵏ: one rounding of the sum, an exact scaling.
            TL unit = TL.Broadcast(1f / 16777216f);
            sx = TL.MultiplyAdd(TL.Top24(h1), unit, TL.Broadcast(column * _n) + subColumn) * _inverseCount;
            sy = TL.MultiplyAdd(TL.Top24(h2), unit, TL.Broadcast(row * _n) + subRow) * _inverseCount;
        }
        else
        {
            sx = TL.InDouble(_cell, subColumn, TL.Top24(h1), TL.Broadcast(column), default);
            sy = TL.InDouble(_cell, subRow, TL.Top24(h2), TL.Broadcast(row), default);
        }
    }
}
