using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The lab's jittered (stratified) sampling: an n×n grid with one uniformly random point in each cell.
/// </summary>
public sealed class JitteredSampler : GridSampler, ILaneSampled
{
    private readonly uint _salt;
    private readonly float _scale;
    private readonly Cell[] _cells;

    /// <summary>Creates an n×n jittered sampler.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentException">Not a positive perfect square.</exception>
    public JitteredSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
        _salt = PointHash.Salt(seed);
        _scale = 1f / GridSize / 16777216f;
        _cells = Cells(GridSize);
    }

    /// <inheritdoc />
    public override string Name => "jittered";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        ScalarLane keys = PointHash.PixelKeys<ScalarLane, ScalarMath>(x, y, _salt);
        Formula.Point<ScalarLane, ScalarMath>(keys, index, _cells[index], GridSize, _scale, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) => user.Run(() => new LaneForm<TL>(this));

    /// <summary>The salted seed the pixel keys are made with (the device form's input).</summary>
    internal uint Salt => _salt;

    /// <summary>The jitter's scale, 1/n/2²⁴ in float (the device form's input).</summary>
    internal float Scale => _scale;

    /// <summary>The jittered sampler's point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>
        /// Sample <paramref name="index"/>: in cell (i mod n, i div n), ((i mod n) + u)/n across and ((i div n) + v)/n
        /// down, u and v two hashes of the sample (<see cref="IPointMath{TV}.InCell"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(TV keys, int index, Cell cell, int n, float scale, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            TV h1 = PointHash.SampleHash<TV, TM>(keys, index);
            TV h2 = TM.Hash(h1);
            sx = TM.InCell(h1, cell.Column, n, cell.ColumnCorner, scale);
            sy = TM.InCell(h2, cell.Row, n, cell.RowCorner, scale);
        }

        /// <summary>Cell <paramref name="index"/> of an n×n grid, row by row, with its corners in float.</summary>
        /// <param name="index">The sample's index.</param>
        /// <param name="n">The grid's side.</param>
        /// <returns>The cell.</returns>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Cell CellOf(int index, int n) => new(index % n, index / n, (float)(index % n) / n, (float)(index / n) / n);
    }

    /// <summary>Sample i's cell (i mod n, i div n) and its corner in float, looked up rather than divided for in the hot loop.</summary>
    private static Cell[] Cells(int n)
    {
        var cells = new Cell[n * n];
        for (int i = 0; i < cells.Length; i++)
        {
            cells[i] = Formula.CellOf(i, n);
        }

        return cells;
    }

    /// <summary>A sample's cell: its column and row, and their corners (column/n, row/n) in float.</summary>
    internal readonly record struct Cell(int Column, int Row, float ColumnCorner, float RowCorner);

    /// <summary>The points in lanes, one pixel per lane.</summary>
    private struct LaneForm<TL>(JitteredSampler sampler) : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly uint _salt = sampler._salt;
        private readonly int _n = sampler.GridSize;
        private readonly float _scale = sampler._scale;
        private readonly Cell[] _cells = sampler._cells;
        private TL _keys;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row) => _keys = PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, _salt);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly int Prepare(int start, int end) => end;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => Formula.Point<TL, LaneMath<TL>>(_keys, index, _cells[index], _n, _scale, out sx, out sy);
    }
}
