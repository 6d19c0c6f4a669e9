using System.Numerics;
using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// Kensler's correlated multi-jittered sampling ("Correlated Multi-Jittered Sampling", Pixar Technical Memo
/// 13-01, 2013), the stateless form with hash permutations that works for any number of samples: an m × n grid
/// with m = ⌊√N⌋ columns and n = ⌈N / m⌉ rows. When N = m·n (every square, and 2, 3, 6, 12, 20, …) each of the
/// m × n cells holds exactly one sample and so does each of the N fine columns and N fine rows; otherwise each of
/// the N fine rows and at most one of the m·n fine columns holds a sample.
/// </summary>
/// <remarks>
/// The pattern number is the pixel's <see cref="CounterHash.PixelKey"/>; the rest is Kensler's final
/// listing unchanged: the sample index is permuted, one permutation of the columns and one of the rows are
/// shared by the whole pattern (the correlation), and Kensler's <c>randfloat</c> jitters within the fine cell.
/// </remarks>
public sealed class CorrelatedMultiJitteredSampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates a correlated multi-jittered sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public CorrelatedMultiJitteredSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
        Columns = (int)Math.Sqrt(samplesPerPixel);
        Rows = (samplesPerPixel + Columns - 1) / Columns;
        _x = XCell(Columns, Rows);
        _y = YCell(samplesPerPixel);
    }

    private readonly WholeCell _x, _y;

    /// <inheritdoc />
    public override string Name => "cmj";

    /// <summary>m = ⌊√N⌋: columns of the coarse grid.</summary>
    public int Columns { get; }

    /// <summary>n = ⌈N / m⌉: rows of the coarse grid; <see cref="Columns"/> · n ≥ N.</summary>
    public int Rows { get; }

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index) =>
        Sample(index, SamplesPerPixel, Columns, Rows, CounterHash.PixelKey(x, y, Seed), _x, _y);

    /// <summary>
    /// Kensler's <c>cmj(s, N, p)</c>: sample <paramref name="index"/> of the pattern <paramref name="p"/> with
    /// <paramref name="count"/> samples on an <paramref name="m"/> × <paramref name="n"/> grid.
    /// </summary>
    /// <param name="index">The sample index, 0 ≤ index &lt; count.</param>
    /// <param name="count">N, the number of samples.</param>
    /// <param name="m">Columns, ⌊√N⌋.</param>
    /// <param name="n">Rows, ⌈N / m⌉.</param>
    /// <param name="p">The pattern number.</param>
    internal static SamplePoint Sample(int index, int count, int m, int n, uint p) =>
        Sample(index, count, m, n, p, XCell(m, n), YCell(count));

    private static SamplePoint Sample(int index, int count, int m, int n, uint p, in WholeCell x, in WholeCell y)
    {
        Formula.Point<ScalarLane, ScalarMath>(p, index, count, m, n, x, y, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <summary>The x cell formula (column + (row + jx)/n)/m.</summary>
    internal static WholeCell XCell(int m, int n) => new(Kensler.RandFloatScale, n, m);

    /// <summary>The y cell formula (s + jy)/N.</summary>
    internal static WholeCell YCell(int count) => new(Kensler.RandFloatScale, count, 1);

    /// <summary>Kensler's cmj point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>
        /// Kensler's <c>cmj(s, N, p)</c>: sample <paramref name="index"/> of the pattern <paramref name="p"/> with
        /// <paramref name="count"/> samples on an <paramref name="m"/> × <paramref name="n"/> grid, the cell formulas
        /// <paramref name="x"/> (<see cref="XCell"/>) and <paramref name="y"/> (<see cref="YCell"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(uint p, int index, int count, int m, int n, in WholeCell x, in WholeCell y, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            int s = Permutation.PermutationElement(index, count, p * Kensler.IndexSalt);
            int column = Permutation.PermutationElement(s % m, m, p * Kensler.ColumnSalt);
            int row = Permutation.PermutationElement(s / m, n, p * Kensler.RowSalt);
            TV pattern = TM.BroadcastBits(p);
            JitterKey<TV, TM>(pattern, Kensler.JitterXSalt, out TV jx, out TV jxMultiplier);
            JitterKey<TV, TM>(pattern, Kensler.JitterYSalt, out TV jy, out TV jyMultiplier);
            Place<TV, TM>(TM.BroadcastBits((uint)s), TM.BroadcastBits((uint)column), TM.BroadcastBits((uint)row), jx, jxMultiplier, jy, jyMultiplier, x, y, out sx, out sy);
        }

        /// <summary>
        /// The point of permuted index <paramref name="s"/> in its column and row (each permuted):
        /// ((column + (row + jx)/n)/m, (s + jy)/N), jx and jy Kensler's <c>randfloat</c> of s under the pattern's two
        /// jitter keys (<see cref="JitterKey"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Place<TV, TM>(TV s, TV column, TV row, TV jx, TV jxMultiplier, TV jy, TV jyMultiplier, in WholeCell x, in WholeCell y, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            TM.InWholeCells(column, row, RandomBits<TV, TM>(s, jx, jxMultiplier), x, TM.BroadcastBits(0), s, RandomBits<TV, TM>(s, jy, jyMultiplier), y, out sx, out sy);
        }

        /// <summary>A jitter's key p·salt for <c>randfloat</c>, and its final multiplier 1 | (key ≫ 18).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void JitterKey<TV, TM>(TV pattern, uint salt, out TV key, out TV multiplier)
            where TV : struct
            where TM : IPointMath<TV>
        {
            key = TM.MultiplyBits(pattern, TM.BroadcastBits(salt));
            multiplier = TM.Or(TM.ShiftRightBits(key, 18), TM.BroadcastBits(1));
        }

        /// <summary>Kensler's <c>randfloat(i, p)</c> before its scaling by <see cref="Kensler.RandFloatScale"/>: a hash of (i, p).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static TV RandomBits<TV, TM>(TV i, TV p, TV multiplier)
            where TV : struct
            where TM : IPointMath<TV>
        {
            i = TM.Xor(i, p);
            i = TM.Xor(i, TM.ShiftRightBits(i, 17));
            i = TM.Xor(i, TM.ShiftRightBits(i, 10));
            i = TM.MultiplyBits(i, TM.BroadcastBits(Kensler.RandFloatMultiplier1));
            i = TM.Xor(i, TM.ShiftRightBits(i, 12));
            i = TM.Xor(i, TM.ShiftRightBits(i, 21));
            i = TM.MultiplyBits(i, TM.BroadcastBits(Kensler.RandFloatMultiplier2));
            i = TM.Xor(i, TM.BroadcastBits(Kensler.RandFloatXor));
            i = TM.Xor(i, TM.ShiftRightBits(i, 17));
            return TM.MultiplyBits(i, multiplier);
        }
    }

    /// <inheritdoc />
    /// <remarks>Above <see cref="PatternLimits.MaxSamples"/> samples the lanes would not be exact: the buffered lanes then ask <see cref="GetSample"/>.</remarks>
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        SamplesPerPixel <= PatternLimits.MaxSamples
            ? user.Run(() => new LaneForm<TL>(this))
            : user.Run(() => new BufferedLanes<TL>(this));

    /// <summary>
    /// The points in lanes: Kensler's three permutations walk in SIMD, made a block ahead (<see cref="PointBlock"/>),
    /// and <see cref="Formula.Place"/> runs in lanes, its cell formulas in double (the jitter is a rounded double, so only
    /// double arithmetic gives the scalar sampler's floats).
    /// </summary>
    private struct LaneForm<TL> : ILaneSampler<TL>, IStagedPoints<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private readonly uint _salt;
        private readonly LaneLength<TL> _all, _columns, _rows;
        private readonly TL _inverseColumns, _columnCount;
        private readonly int _columnShift;
        private readonly WholeCell _x, _y;
        private readonly uint[] _scratch = new uint[TL.Count];
        private readonly int _m, _n;
        private readonly bool _tabled, _wideColumns, _wideRows;
        private TL _columnsLow, _columnsHigh, _rowsLow, _rowsHigh;
        private LanePermutation<TL> _index, _column, _row;
        private LanePermutationPair<TL> _indexPair;

        /// <summary>
        /// Where N is a power of two that fits the 16-bit halves (<see cref="LanePermutationPair{TL}.Fits"/>), the
        /// packet's whole index permutation, sample by sample, lane by lane, as bits (made by <see cref="BeginPacket"/>
        /// two samples a round); else null, and <see cref="First"/> walks the permutation itself.
        /// </summary>
        private readonly float[]? _permuted;
        private TL _jx, _jxMultiplier, _jy, _jyMultiplier;

        /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
        public LaneForm(CorrelatedMultiJitteredSampler sampler)
        {
            int count = sampler.SamplesPerPixel;
            _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
            _all = new LaneLength<TL>(count);
            _columns = new LaneLength<TL>(sampler.Columns);
            _rows = new LaneLength<TL>(sampler.Rows);
            _inverseColumns = TL.Broadcast(1f / sampler.Columns);
            _columnCount = TL.BroadcastBits((uint)sampler.Columns);
            _columnShift = BitOperations.Log2((uint)sampler.Columns);
            _x = sampler._x;
            _y = sampler._y;

            // The column and row permutations have only m and n elements per pixel, where a pixel has N ≈ m·n samples:
            // made once per packet, 4 bits an entry, into one 32-bit word per lane (two past 8 entries), and each
            // sample shifts its entry out (AVX2's per-lane shift): three or so instructions where a walk of Kensler's
            // hash is a chain of five multiplies.
            _m = sampler.Columns;
            _n = sampler.Rows;
            _tabled = Math.Max(_m, _n) <= MaxTable;
            _wideColumns = _m > 8;
            _wideRows = _n > 8;
            _permuted = count > 1 && LanePermutationPair<TL>.Fits(count) ? new float[count * TL.Count] : null;
        }

        /// <summary>The largest permutation kept as a packed table: 16 entries of 4 bits (m and n ≤ 16: every count below 273).</summary>
        private const int MaxTable = 16;

        /// <inheritdoc />
        public void BeginPacket(int x0, int row)
        {
            TL p = LaneHash.PixelKeys<TL>(x0, row, _salt);
            TL indexPattern = TL.MultiplyBits(p, TL.BroadcastBits(Kensler.IndexSalt));
            if (_permuted is null)
            {
                _index.Set(indexPattern, _all, _scratch);
            }
            else
            {
                _indexPair.Set(indexPattern, indexPattern, _permuted.Length / TL.Count);
                PermuteIndices(_indexPair, _permuted);
            }

            _column.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.ColumnSalt)), _columns, _scratch);
            _row.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.RowSalt)), _rows, _scratch);
            if (_tabled)
            {
                (_columnsLow, _columnsHigh) = Tabulate(_column, _columns, _m);
                (_rowsLow, _rowsHigh) = Tabulate(_row, _rows, _n);
            }

            Formula.JitterKey<TL, LaneMath<TL>>(p, Kensler.JitterXSalt, out _jx, out _jxMultiplier);
            Formula.JitterKey<TL, LaneMath<TL>>(p, Kensler.JitterYSalt, out _jy, out _jyMultiplier);
        }

        /// <inheritdoc />
        public int Prepare(int start, int end) => PointBlock.Fill<TL, LaneForm<TL>>(ref this, _block, start, end);

        /// <inheritdoc />
        public static bool HasMiddle => true;

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

        /// <summary>
        /// Every element of each lane's index permutation (the same permutation in both halves of <paramref name="pair"/>),
        /// into <paramref name="permuted"/>: elements i and i + 1 in one round, in the low and the high halves.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
        private static void PermuteIndices(in LanePermutationPair<TL> pair, float[] permuted)
        {
            int count = TL.Count, length = permuted.Length / count;
            TL w = LanePermutationPair<TL>.Mask(length);
            Span<float> slots = permuted;
            for (int i = 0; i < length; i += 2)
            {
                TL both = pair.Elements(TL.BroadcastBits((uint)i | ((uint)(i + 1) << 16)), w);
                LanePermutationPair<TL>.Low(both).Store(slots.Slice(i * count, count));
                LanePermutationPair<TL>.High(both).Store(slots.Slice((i + 1) * count, count));
            }
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void First(int index, out TL a, out TL b, out TL c)
        {
            a = _permuted is null ? _index.Element(TL.BroadcastBits((uint)index), _all) : TL.Load(_permuted.AsSpan(index * TL.Count, TL.Count));
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
        public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy) =>
            Formula.Place<TL, LaneMath<TL>>(a, b, c, _jx, _jxMultiplier, _jy, _jyMultiplier, _x, _y, out sx, out sy);

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
    }
}
