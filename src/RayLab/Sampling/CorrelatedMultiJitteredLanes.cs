using System.Numerics;
using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// <see cref="CorrelatedMultiJitteredSampler"/> in lanes: Kensler's three permutations walk in SIMD, his
/// <c>randfloat</c> hash runs in SIMD, and the cell formulas run in double (the jitter is a rounded double, so
/// only double arithmetic gives the scalar sampler's floats).
/// </summary>
internal struct CorrelatedMultiJitteredLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly uint _salt;
    private readonly LaneLength<TL> _all, _columns, _rows;
    private readonly TL _inverseColumns, _columnCount;
    private readonly int _columnShift;
    private readonly WholeHashCellFormula _x, _y;
    private readonly PowerOfTwoCellFormula _xPowerOfTwo, _yPowerOfTwo;
    private readonly bool _powersOfTwo;
    private readonly uint[] _scratch = new uint[TL.Count];
    private readonly int _m, _n;
    private readonly bool _tabled, _wideColumns, _wideRows;
    private TL _columnsLow, _columnsHigh, _rowsLow, _rowsHigh;
    private LanePermutation<TL> _index, _column, _row;
    private TL _jx, _jxMultiplier, _jy, _jyMultiplier;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public CorrelatedMultiJitteredLanes(CorrelatedMultiJitteredSampler sampler)
    {
        int count = sampler.SamplesPerPixel;
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _all = new LaneLength<TL>(count);
        _columns = new LaneLength<TL>(sampler.Columns);
        _rows = new LaneLength<TL>(sampler.Rows);
        _inverseColumns = TL.Broadcast(1f / sampler.Columns);
        _columnCount = TL.BroadcastBits((uint)sampler.Columns);
        _columnShift = BitOperations.Log2((uint)sampler.Columns);
        _x = new WholeHashCellFormula(new CellFormula(Kensler.RandFloatScale, sampler.Rows, sampler.Columns));
        _y = new WholeHashCellFormula(new CellFormula(Kensler.RandFloatScale, count, 1));

        // 4, 16, 64, 256, 1024 … spp: N, m and n all powers of two, the cell formulas without a branch.
        _powersOfTwo = int.IsPow2(count) && int.IsPow2(sampler.Columns) && int.IsPow2(sampler.Rows);
        if (_powersOfTwo)
        {
            _xPowerOfTwo = new PowerOfTwoCellFormula(Kensler.RandFloatScale, sampler.Rows, sampler.Columns);
            _yPowerOfTwo = new PowerOfTwoCellFormula(Kensler.RandFloatScale, count, 1);
        }

        // The column and row permutations have only m and n elements per pixel, where a pixel has N ≈ m·n samples:
        // made once per packet, 4 bits an entry, into one 32-bit word per lane (two past 8 entries), and each
        // sample shifts its entry out (AVX2's per-lane shift): three or so instructions where a walk of Kensler's
        // hash is a chain of five multiplies.
        _m = sampler.Columns;
        _n = sampler.Rows;
        _tabled = Math.Max(_m, _n) <= MaxTable;
        _wideColumns = _m > 8;
        _wideRows = _n > 8;
    }

    /// <summary>The largest permutation kept as a packed table: 16 entries of 4 bits (m and n ≤ 16: every count below 273).</summary>
    private const int MaxTable = 16;

    /// <inheritdoc />
    public void BeginPacket(int x0, int row)
    {
        TL p = LaneHash.PixelKeys<TL>(x0, row, _salt);
        _index.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.IndexSalt)), _all, _scratch);
        _column.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.ColumnSalt)), _columns, _scratch);
        _row.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.RowSalt)), _rows, _scratch);
        if (_tabled)
        {
            (_columnsLow, _columnsHigh) = Tabulate(_column, _columns, _m);
            (_rowsLow, _rowsHigh) = Tabulate(_row, _rows, _n);
        }

        _jx = TL.MultiplyBits(p, TL.BroadcastBits(Kensler.JitterXSalt));
        _jxMultiplier = TL.ShiftRightBits(_jx, 18) | TL.BroadcastBits(1);
        _jy = TL.MultiplyBits(p, TL.BroadcastBits(Kensler.JitterYSalt));
        _jyMultiplier = TL.ShiftRightBits(_jy, 18) | TL.BroadcastBits(1);
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, CorrelatedMultiJitteredLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => true;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        a = _index.Element(TL.BroadcastBits((uint)index), _all);
        b = default;
        c = default;
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
        TL s = a;
        TL quotient, remainder;
        if (_columns.IsPowerOfTwo)
        {
            quotient = TL.ShiftRightBits(s, _columnShift);
            remainder = s & _columns.Last;
        }
        else
        {
            (quotient, remainder) = DivideByColumns(s);
        }

        if (_tabled)
        {
            b = Pick(_columnsLow, _columnsHigh, _wideColumns, remainder);
            c = Pick(_rowsLow, _rowsHigh, _wideRows, quotient);
        }
        else
        {
            (b, c) = LanePermutation<TL>.Pair(_column, remainder, _columns, _row, quotient, _rows);
        }
    }

    /// <summary>
    /// Entries 0 … <paramref name="length"/> − 1 (≤ 16) of each lane's permutation, 4 bits each: entry k in bits
    /// 4(k mod 8) of the low word (k &lt; 8) or the high one.
    /// </summary>
    private static (TL Low, TL High) Tabulate(in LanePermutation<TL> permutation, in LaneLength<TL> lanes, int length)
    {
        TL low = default, high = default;
        for (int k = 0; k < length; k++)
        {
            TL entry = TL.ShiftLeftBits(permutation.Element(TL.BroadcastBits((uint)k), lanes), 4 * (k & 7));
            if (k < 8)
            {
                low |= entry;
            }
            else
            {
                high |= entry;
            }
        }

        return (low, high);
    }

    /// <summary>Each lane's entry <paramref name="index"/> (0 … 15) of its packed table (<see cref="Tabulate"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL Pick(TL low, TL high, bool wide, TL index)
    {
        TL seven = TL.BroadcastBits(7);
        TL word = wide ? TL.Select(TL.LessThanBits(seven, index), high, low) : low;
        return TL.ShiftRightBitsVariable(word, TL.ShiftLeftBits(index & seven, 2)) & TL.BroadcastBits(15);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        TL s = a;
        TL jx = RandomBits(s, _jx, _jxMultiplier);
        TL jy = RandomBits(s, _jy, _jyMultiplier);
        if (_powersOfTwo)
        {
            sx = TL.InDoubleFromBits(_xPowerOfTwo, c, jx, b);
            sy = TL.InDoubleFromBits(_yPowerOfTwo, s, jy, default);
        }
        else
        {
            (sx, sy) = InGeneral(s, jx, jy, b, c);
        }
    }

    /// <summary>The cell formulas with a divisor that is not a power of two, in a call of its own (the JIT's inlining budget).</summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private readonly (TL X, TL Y) InGeneral(TL s, TL jx, TL jy, TL column, TL row) =>
        (TL.InDoubleFromBits(_x, row, jx, column), TL.InDoubleFromBits(_y, s, jy, default));

    /// <summary>s div m and s mod m: a float quotient (s &lt; 2²⁴ is exact) truncated, then corrected by one either way.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private readonly (TL Quotient, TL Remainder) DivideByColumns(TL s)
    {
        TL quotient = TL.TruncateToBits(TL.BitsToFloat(s) * _inverseColumns);
        TL remainder = TL.SubtractBits(s, TL.MultiplyBits(quotient, _columnCount));
        TL low = TL.LessThanBits(remainder, default);
        quotient = TL.Select(low, TL.SubtractBits(quotient, TL.BroadcastBits(1)), quotient);
        remainder = TL.Select(low, TL.AddBits(remainder, _columnCount), remainder);
        TL high = TL.LessThanBits(TL.SubtractBits(_columnCount, TL.BroadcastBits(1)), remainder);
        quotient = TL.Select(high, TL.AddBits(quotient, TL.BroadcastBits(1)), quotient);
        remainder = TL.Select(high, TL.SubtractBits(remainder, _columnCount), remainder);
        return (quotient, remainder);
    }

    /// <summary>Kensler's <c>randfloat</c> hash before its scaling (<see cref="CorrelatedMultiJitteredSampler.RandFloat"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL RandomBits(TL i, TL p, TL multiplier)
    {
        i = TL.Xor(i, p);
        i = TL.Xor(i, TL.ShiftRightBits(i, 17));
        i = TL.Xor(i, TL.ShiftRightBits(i, 10));
        i = TL.MultiplyBits(i, TL.BroadcastBits(Kensler.RandFloatMultiplier1));
        i = TL.Xor(i, TL.ShiftRightBits(i, 12));
        i = TL.Xor(i, TL.ShiftRightBits(i, 21));
        i = TL.MultiplyBits(i, TL.BroadcastBits(Kensler.RandFloatMultiplier2));
        i = TL.Xor(i, TL.BroadcastBits(Kensler.RandFloatXor));
        i = TL.Xor(i, TL.ShiftRightBits(i, 17));
        return TL.MultiplyBits(i, multiplier);
    }
}
