using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// <see cref="NRooksSampler"/> in lanes: both of a pixel's permutations (column and row) walk in SIMD and the
/// jitter is the counter hash in SIMD. Each point is the scalar sampler's float: with a power-of-two count the cell
/// formula's double value is exact and one float rounding gives it; otherwise it runs in double.
/// </summary>
internal struct NRooksLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly uint _salt;
    private readonly LaneLength<TL> _length;
    private readonly CellFormula _cell;
    private readonly bool _exactInFloat;
    private readonly TL _inverseCount;
    private readonly uint[] _scratch = new uint[TL.Count];
    private LanePermutation<TL> _columns, _rows;
    private TL _keys;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public NRooksLanes(NRooksSampler sampler)
    {
        int count = sampler.SamplesPerPixel;
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _length = new LaneLength<TL>(count);
        _cell = new CellFormula(CellFormula.UnitScale, count, 1);
        _exactInFloat = int.IsPow2(count);
        _inverseCount = TL.Broadcast(1f / count);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row)
    {
        _keys = LaneHash.PixelKeys<TL>(x0, row, _salt);
        _columns.Set(TL.MultiplyBits(_keys, TL.BroadcastBits(NRooksSampler.ColumnSalt)), _length, _scratch);
        _rows.Set(TL.MultiplyBits(_keys, TL.BroadcastBits(NRooksSampler.RowSalt)), _length, _scratch);
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, NRooksLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => false;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        TL i = TL.BroadcastBits((uint)index);
        (a, b) = LanePermutation<TL>.Pair(_columns, i, _length, _rows, i, _length);
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
        TL column = TL.BitsToFloat(a), row = TL.BitsToFloat(b);
        TL h1 = LaneHash.SampleHash(_keys, index);
        TL h2 = TL.Hash(h1);
        if (_exactInFloat)
        {
            // (column + u)/N with N = 2ᵏ: column + u rounded once (u·2²⁴ is exact), then an exact scaling.
            TL unit = TL.Broadcast(1f / 16777216f);
            sx = TL.MultiplyAdd(TL.Top24(h1), unit, column) * _inverseCount;
            sy = TL.MultiplyAdd(TL.Top24(h2), unit, row) * _inverseCount;
        }
        else
        {
            sx = TL.InDouble(_cell, column, TL.Top24(h1), default, default);
            sy = TL.InDouble(_cell, row, TL.Top24(h2), default, default);
        }
    }
}
