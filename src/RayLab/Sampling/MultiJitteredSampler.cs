using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// Multi-jittered sampling (Chiu, Shirley and Wang 1994; Suffern's <c>MultiJittered</c>): n × n jittered
/// sampling that is also an n-rooks pattern on the N = n² fine grid, so each coarse cell, each fine column and each
/// fine row holds exactly one sample.
/// </summary>
/// <remarks>
/// Sample i sits in coarse cell (i mod n, i div n). In the canonical arrangement cell (c, r) uses fine column r
/// of its coarse column and fine row c of its coarse row; the shuffle permutes the fine columns independently in
/// every coarse column and the fine rows independently in every coarse row (unlike Kensler's correlated variant,
/// which shares one permutation). Each permutation is a stateless hash permutation
/// (<see cref="Permutation.PermutationElement"/>) keyed on the pixel, so no table is stored.
/// </remarks>
public sealed class MultiJitteredSampler : GridSampler, ILaneSampled
{
    private readonly CellDivisor _divisor;

    /// <summary>Xored into the pixel key for the shuffles of the fine columns.</summary>
    internal const uint ColumnSalt = 0x2f5a1c37u;

    /// <summary>Xored into the pixel key for the shuffles of the fine rows.</summary>
    internal const uint RowSalt = 0xc13fa9a9u;

    /// <summary>Creates an n×n multi-jittered sampler.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentException">Not a positive perfect square.</exception>
    public MultiJitteredSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => _divisor = new CellDivisor(GridSize, GridSize);

    /// <inheritdoc />
    public override string Name => "multijittered";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        Formula.Point<ScalarLane, ScalarMath>(CounterHash.PixelKey(x, y, Seed), index, GridSize, _divisor, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <summary>The multi-jittered point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>
        /// Sample <paramref name="index"/> of the n × n pattern of the pixel whose key is <paramref name="key"/>: its
        /// coarse cell (i mod n, i div n), its fine column and fine row from the hash permutations of that coarse column
        /// and coarse row, then <see cref="InSubCells"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(uint key, int index, int n, in CellDivisor divisor, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            int column = index % n, row = index / n;

            // Fine column of this sample inside its coarse column: a permutation (over rows) of that column.
            int subColumn = Permutation.PermutationElement(row, n, CounterHash.SampleHash(key ^ ColumnSalt, column));

            // Fine row of this sample inside its coarse row: a permutation (over columns) of that row.
            int subRow = Permutation.PermutationElement(column, n, CounterHash.SampleHash(key ^ RowSalt, row));

            InSubCells<TV, TM>(TM.BroadcastBits(key), index, column, row, TM.BroadcastBits((uint)subColumn), TM.BroadcastBits((uint)subRow), divisor, out sx, out sy);
        }

        /// <summary>
        /// Sample <paramref name="index"/> in fine cell (subColumn, subRow) of its coarse cell (column, row):
        /// ((column + (subColumn + u)/n)/n, (row + (subRow + v)/n)/n), u and v two hashes of the sample.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void InSubCells<TV, TM>(TV keys, int index, int column, int row, TV subColumn, TV subRow, in CellDivisor divisor, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            TV h1 = PointHash.SampleHash<TV, TM>(keys, index);
            TV h2 = TM.Hash(h1);
            sx = TM.InSubCell(column, subColumn, h1, divisor);
            sy = TM.InSubCell(row, subRow, h2, divisor);
        }
    }

    /// <inheritdoc />
    /// <remarks>Above <see cref="PatternLimits.MaxSamples"/> samples the lanes would not be exact: the buffered lanes then ask <see cref="GetSample"/>.</remarks>
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        SamplesPerPixel <= PatternLimits.MaxSamples
            ? user.Run(() => new LaneForm<TL>(this))
            : user.Run(() => new BufferedLanes<TL>(this));

    /// <summary>
    /// The points in lanes: the n column and n row permutations of each pixel get their pattern numbers once per
    /// packet and their elements walk in SIMD: for a power-of-two n (up to 32) all of them at the packet's start, a
    /// column's and a row's permutation side by side in each lane's halves, else one sample at a time; the points are
    /// made a block ahead (<see cref="PointBlock"/>), each the float of the scalar one.
    /// </summary>
    private struct LaneForm<TL> : ILaneSampler<TL>, IStagedPoints<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private readonly uint _salt;
        private readonly int _n;
        private readonly LaneLength<TL> _length;
        private readonly CellDivisor _divisor;
        private readonly uint[] _scratch = new uint[TL.Count];
        private readonly LanePermutation<TL>[] _columns, _rows;
        private readonly (int Column, int Row)[] _cells;
        private readonly float[]? _subColumns, _subRows;
        private readonly TL _halfMask;
        private TL _keys;

        /// <summary>The most samples whose fine columns and rows are made per packet into tables (two floats a sample and lane).</summary>
        private const int MaxTabled = 1024;

        public LaneForm(MultiJitteredSampler sampler)
        {
            _salt = PointHash.Salt(sampler.Seed);
            _n = sampler.GridSize;
            _length = new LaneLength<TL>(_n);
            _divisor = sampler._divisor;
            _columns = new LanePermutation<TL>[_n];
            _rows = new LanePermutation<TL>[_n];
            if (LanePermutationPair<TL>.Fits(_n) && _n * _n <= MaxTabled)
            {
                _subColumns = new float[_n * _n * TL.Count];
                _subRows = new float[_n * _n * TL.Count];
                _halfMask = LanePermutationPair<TL>.Mask(_n);
            }

            // Sample i's coarse cell (i mod n, i div n), looked up rather than divided for in the hot loop.
            _cells = new (int, int)[_n * _n];
            for (int i = 0; i < _cells.Length; i++)
            {
                _cells[i] = (i % _n, i / _n);
            }
        }

        public void BeginPacket(int x0, int row)
        {
            _keys = PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, _salt);
            TL columnKeys = TL.Xor(_keys, TL.BroadcastBits(ColumnSalt)), rowKeys = TL.Xor(_keys, TL.BroadcastBits(RowSalt));
            if (_subColumns is not null)
            {
                Tabulate(columnKeys, rowKeys);
                return;
            }

            for (int k = 0; k < _n; k++)
            {
                _columns[k].Set(PointHash.SampleHash<TL, LaneMath<TL>>(columnKeys, k), _length, _scratch);
                _rows[k].Set(PointHash.SampleHash<TL, LaneMath<TL>>(rowKeys, k), _length, _scratch);
            }
        }

        /// <summary>
        /// Every sample's fine column and fine row, for a power-of-two n: column permutation k and row permutation k
        /// side by side in the lanes' halves (<see cref="LanePermutationPair{TL}"/>), each of their n elements once.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        private readonly void Tabulate(TL columnKeys, TL rowKeys)
        {
            int n = _n, count = TL.Count;
            Span<float> subColumns = _subColumns, subRows = _subRows;
            var pair = default(LanePermutationPair<TL>);
            for (int k = 0; k < n; k++)
            {
                pair.Set(PointHash.SampleHash<TL, LaneMath<TL>>(columnKeys, k), PointHash.SampleHash<TL, LaneMath<TL>>(rowKeys, k), n);
                for (int i = 0; i < n; i++)
                {
                    // Low: the fine column of the sample in column k, row i; high: the fine row of the sample in row k, column i.
                    TL both = pair.Elements(LanePermutationPair<TL>.Both((uint)i), _halfMask);
                    LanePermutationPair<TL>.Low(both).Store(subColumns.Slice(((i * n) + k) * count, count));
                    LanePermutationPair<TL>.High(both).Store(subRows.Slice(((k * n) + i) * count, count));
                }
            }
        }

        public int Prepare(int start, int end)
        {
            if (_subColumns is null)
            {
                return PointBlock.Fill<TL, LaneForm<TL>>(ref this, _block, start, end);
            }

            int stop = Math.Min(end, start + PointBlock.Size);
            FromTables(start, stop);
            return stop;
        }

        /// <summary>
        /// Samples <paramref name="start"/> … <paramref name="stop"/> − 1 into the block (<see cref="PointBlock.Read"/>'s
        /// layout) straight from the tables <see cref="Tabulate"/> made: the last stage alone, reading its fine columns
        /// and rows where they lie instead of copying them through the first stage.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
        private readonly void FromTables(int start, int stop)
        {
            int count = TL.Count;
            ReadOnlySpan<float> subColumns = _subColumns.AsSpan(start * count, (stop - start) * count);
            ReadOnlySpan<float> subRows = _subRows.AsSpan(start * count, (stop - start) * count);
            Span<float> slots = _block.AsSpan(0, 3 * count * (stop - start));
            for (int index = start; index < stop; index++)
            {
                Last(index, TL.Load(subColumns), TL.Load(subRows), default, out TL sx, out TL sy);
                sx.Store(slots);
                sy.Store(slots[count..]);
                subColumns = subColumns[count..];
                subRows = subRows[count..];
                slots = slots[(3 * count)..];
            }
        }

        public static bool HasMiddle => false;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void First(int index, out TL a, out TL b, out TL c)
        {
            // Only without the tables (Prepare reads those itself).
            (int column, int row) = _cells[index];
            (a, b) = LanePermutation<TL>.Pair(
                _columns[column], TL.BroadcastBits((uint)row), _length, _rows[row], TL.BroadcastBits((uint)column), _length);
            c = default;
        }

        public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
        {
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
        {
            (int column, int row) = _cells[index];
            Formula.InSubCells<TL, LaneMath<TL>>(_keys, index, column, row, a, b, _divisor, out sx, out sy);
        }
    }
}
