using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Cameras;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The exact reference's work for one pixel row (one per thread, reused row after row): the row's exact
/// linear pixel values, R, G, B for each pixel, in <see cref="Values"/>.
/// </summary>
/// <remarks>
/// <para>1. Cut the row [row, row + 1] at every height where an outline starts or ends, turns left or right,
/// crosses a pixel's left or right edge (X = k), or crosses another outline. Between two cuts — a strip — each
/// outline that is present has a left and a right branch, no branch meets another or a pixel edge, so the branches
/// split the strip into pieces of one colour, found with one ray through the middle of each piece
/// (<see cref="StripCutter"/>).</para>
/// <para>2. A piece between branches L(Y) and R(Y) covers pixel x by ∫ (min(R, x + 1) − max(L, x)) dY over the
/// strip, and inside a strip the min and max pick the same side everywhere: each pixel gets an exact integral
/// of a branch (<see cref="Outline.Integral"/>) or of a pixel edge. Pixels wholly inside a piece are added as one
/// span (<see cref="RowPixels"/>), so they cost nothing per pixel.</para>
/// <para>3. The sweep (<see cref="RowSweep"/>): the strips are not cut afresh. The branches are kept in their left-to-right
/// order down the row, and at a cut only the outlines with something there (their own break, or a crossing of
/// theirs: <see cref="OutlineSet.CrossingsInRow"/> names the pair) are found, taken out and put back; a piece's area
/// is added once for the whole height over which its two branches stay neighbours, and its colour is traced
/// once, or carried when the same two branches are neighbours again just below a cut (not where both their
/// outlines cross or touch at that cut: the two sides of a touching point need not share a colour). So a row costs about
/// O(log n) per event and one ray per piece that really begins, not a ray per piece per strip (on a field of
/// spheres, tens of thousands of rays instead of millions). The pictures are the same bytes as cutting every strip afresh
/// (golden set, <c>SphereHierarchyTests</c>, <c>ExactSweepTests</c>), which the row still does with fewer than
/// eight outlines (where the sweep does not pay) and where the sweep cannot be trusted: a
/// horizontal segment (a circle seen edge-on, which changes the colour without a branch), or branches found
/// out of order by more than rounding (a crossing missed).</para>
/// </remarks>
internal sealed class ExactRow
{
    // The fewest outlines in a row for the sweep (below, strip by strip).
    private const int SweepFrom = 8;

    private readonly OutlineSet _outlines;
    private readonly int _width;
    private readonly PixelRays _rays;
    private readonly RowPixels _pixels;
    private readonly RowBranches _branches;
    private readonly StripCutter _strips;
    private readonly RowSweep _sweep;
    private readonly List<double> _cuts = [];
    private readonly List<(double Y, int Outline, bool Crossing)> _events = [];
    private readonly List<OutlineSet.Crossing> _crossings = [];
    private readonly bool _sweeps;

    public ExactRow(Scene scene, ImagePlane plane, OutlineSet outlines, bool sweep, RowPixels.Buffers buffers)
    {
        _sweeps = sweep;
        _outlines = outlines;
        _width = plane.Width;
        _rays = new PixelRays(scene, plane);
        _pixels = new RowPixels(_width, buffers);
        _branches = new RowBranches(outlines.Outlines);
        _strips = new StripCutter(outlines.Outlines, _width, _branches, _rays, _pixels);
        _sweep = new RowSweep(outlines.Outlines, _width, _branches, _rays, _pixels);
    }

    /// <summary>
    /// The last row's pixel values, R, G, B of pixel 0, then of pixel 1, and so on (linear intensity); not filled
    /// when the row <see cref="IsUniform"/>.
    /// </summary>
    public double[] Values => _pixels.Values;

    /// <summary>The row's arrays, for the renderer to keep for its next render.</summary>
    public RowPixels.Buffers Buffers => _pixels.Arrays;

    /// <summary>True when no outline reaches into the last row: every pixel is <see cref="UniformColor"/>.</summary>
    public bool IsUniform { get; private set; }

    /// <summary>The colour of every pixel of a uniform row.</summary>
    public Intensity UniformColor { get; private set; }

    /// <summary>Computes the exact pixel values of pixel row <paramref name="row"/> (0 at the top) into <see cref="Values"/>.</summary>
    /// <param name="row">The row.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void Integrate(int row)
    {
        double y0 = row, y1 = row + 1;
        bool segment = CutAtBreaks(y0, y1);
        IsUniform = _branches.Present.Count == 0;
        if (IsUniform)
        {
            UniformColor = _rays.Colour(_width / 2.0, row + 0.5);
            return;
        }

        CutAtCrossings(row);
        _cuts.Add(y0);
        _cuts.Add(y1);
        _cuts.Sort();
        _pixels.Clear();
        // A row of a few outlines is cut strip by strip: there the sweep's bookkeeping costs more than it saves.
        bool sweep = _sweeps && !segment && _branches.Present.Count >= SweepFrom;
        if (sweep)
        {
            _events.Sort(static (p, q) => p.Y.CompareTo(q.Y));
        }

        if (!sweep || !_sweep.Run(_cuts, _events))
        {
            // A horizontal segment (a circle seen edge-on) can change the colour without a branch, and a broken
            // order means a crossing was missed: cut every strip afresh, as the sweep's reference does.
            _pixels.Clear();
            _strips.Cut(_cuts);
        }

        _pixels.SumSpans();
    }

    // Lists the outlines that reach into the row [y0, y1] and cuts it at their breaks (each an event of its
    // outline's); true when one of them is a horizontal segment.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private bool CutAtBreaks(double y0, double y1)
    {
        _cuts.Clear();
        _branches.Present.Clear();
        _events.Clear();
        bool segment = false;
        Outline[] outlines = _outlines.Outlines;
        for (int i = 0; i < outlines.Length; i++)
        {
            if (outlines[i].Bottom >= y0 && outlines[i].Top <= y1)
            {
                _branches.Present.Add(i);
                segment |= outlines[i].Hy == 0;
                int before = _cuts.Count;
                outlines[i].AddBreaks(y0, y1, _width, _cuts);
                for (int k = before; k < _cuts.Count; k++)
                {
                    _events.Add((_cuts[k], i, false));
                }
            }
        }

        return segment;
    }

    // Cuts row `row`, (row, row + 1), at every crossing of two outlines inside it (an event of each), in the crossings' order.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void CutAtCrossings(int row)
    {
        _outlines.CrossingsInRow(row, _crossings);
        foreach (OutlineSet.Crossing crossing in CollectionsMarshal.AsSpan(_crossings))
        {
            if (crossing.Y > row)
            {
                _cuts.Add(crossing.Y);
                _events.Add((crossing.Y, crossing.First, true));
                _events.Add((crossing.Y, crossing.Second, true));
            }
        }
    }
}
