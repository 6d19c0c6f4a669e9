using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// Suffern's n-rooks (Latin hypercube) sampling: the pixel is an N × N grid and the N samples sit like N rooks
/// that cannot take each other, exactly one in each row and each column, jittered inside their cells. Good
/// projections on both axes, though the 2-D distribution can still clump. Any number of samples.
/// </summary>
/// <remarks>
/// Suffern starts from the diagonal and shuffles the x and the y coordinates; here sample i takes row
/// π_y(i) and column π_x(i) of two independent hash permutations (<see cref="Permutation.PermutationElement"/>)
/// keyed on the pixel, which gives the same distribution with no stored table.
/// </remarks>
public sealed class NRooksSampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates an n-rooks sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public NRooksSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => _divisor = new CellDivisor(samplesPerPixel, 1);

    private readonly CellDivisor _divisor;

    /// <summary>The pixel key's multiplier for the permutation of the columns.</summary>
    internal const uint ColumnSalt = 0xa511e9b3u;

    /// <summary>The pixel key's multiplier for the permutation of the rows.</summary>
    internal const uint RowSalt = 0x63d83595u;

    /// <inheritdoc />
    public override string Name => "nrooks";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        Formula.Point<ScalarLane, ScalarMath>(CounterHash.PixelKey(x, y, Seed), index, SamplesPerPixel, _divisor, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <summary>The n-rooks point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>
        /// Sample <paramref name="index"/> of the pixel whose key is <paramref name="key"/>: column π_x(index) and row
        /// π_y(index) of two hash permutations of 0 … N − 1, then <see cref="InCells"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(uint key, int index, int count, in CellDivisor divisor, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            int column = Permutation.PermutationElement(index, count, key * ColumnSalt);
            int row = Permutation.PermutationElement(index, count, key * RowSalt);
            InCells<TV, TM>(TM.BroadcastBits(key), index, TM.BroadcastBits((uint)column), TM.BroadcastBits((uint)row), divisor, out sx, out sy);
        }

        /// <summary>
        /// Sample <paramref name="index"/> in its cell (column, row) of the N × N grid: ((column + u)/N, (row + v)/N), u
        /// and v two hashes of the sample.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void InCells<TV, TM>(TV keys, int index, TV column, TV row, in CellDivisor divisor, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            TV h1 = PointHash.SampleHash<TV, TM>(keys, index);
            TV h2 = TM.Hash(h1);
            sx = TM.InCellExactly(column, h1, divisor);
            sy = TM.InCellExactly(row, h2, divisor);
        }
    }

    /// <inheritdoc />
    /// <remarks>Above <see cref="PatternLimits.MaxSamples"/> samples the lanes would not be exact: the buffered lanes then ask <see cref="GetSample"/>.</remarks>
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        SamplesPerPixel <= PatternLimits.MaxSamples
            ? user.Run(() => new LaneForm<TL>(this))
            : user.Run(() => new BufferedLanes<TL>(this));

    /// <summary>
    /// The points in lanes: both of a pixel's permutations (column and row) walk in SIMD, side by side in each lane's
    /// 16-bit halves when N is a power of two ≤ 2¹⁵ (<see cref="LanePermutationPair{TL}"/>), made a block ahead
    /// (<see cref="PointBlock"/>), and each point is the float of the scalar one.
    /// </summary>
    private struct LaneForm<TL> : ILaneSampler<TL>, IStagedPoints<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private readonly uint _salt;
        private readonly LaneLength<TL> _length;
        private readonly CellDivisor _divisor;
        private readonly uint[] _scratch = new uint[TL.Count];
        private readonly bool _halves;
        private readonly int _count;
        private readonly TL _halfMask;
        private LanePermutation<TL> _columns, _rows;
        private LanePermutationPair<TL> _pair;
        private TL _keys;

        public LaneForm(NRooksSampler sampler)
        {
            _salt = PointHash.Salt(sampler.Seed);
            _length = new LaneLength<TL>(sampler.SamplesPerPixel);
            _divisor = sampler._divisor;
            _count = sampler.SamplesPerPixel;
            _halves = LanePermutationPair<TL>.Fits(_count);
            _halfMask = LanePermutationPair<TL>.Mask(sampler.SamplesPerPixel);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row)
        {
            _keys = PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, _salt);
            TL columnPatterns = TL.MultiplyBits(_keys, TL.BroadcastBits(ColumnSalt)), rowPatterns = TL.MultiplyBits(_keys, TL.BroadcastBits(RowSalt));
            if (_halves)
            {
                _pair.Set(columnPatterns, rowPatterns, _count);
            }
            else
            {
                _columns.Set(columnPatterns, _length, _scratch);
                _rows.Set(rowPatterns, _length, _scratch);
            }
        }

        public int Prepare(int start, int end) => PointBlock.Fill<TL, LaneForm<TL>>(ref this, _block, start, end);

        public static bool HasMiddle => false;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void First(int index, out TL a, out TL b, out TL c)
        {
            if (_halves)
            {
                // Both permutations at once, the column's in the low halves and the row's in the high ones.
                TL both = _pair.Elements(LanePermutationPair<TL>.Both((uint)index), _halfMask);
                a = LanePermutationPair<TL>.Low(both);
                b = LanePermutationPair<TL>.High(both);
            }
            else
            {
                TL i = TL.BroadcastBits((uint)index);
                (a, b) = LanePermutation<TL>.Pair(_columns, i, _length, _rows, i, _length);
            }

            c = default;
        }

        public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
        {
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy) =>
            Formula.InCells<TL, LaneMath<TL>>(_keys, index, a, b, _divisor, out sx, out sy);
    }
}
