using System.Runtime.CompilerServices;
using RayLab.Cameras;
using RayLab.Geometry;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The exact reference's work for one pixel row (one per thread, reused row after row): the row's exact
/// linear pixel values, R, G, B for each pixel, in <see cref="Values"/>.
/// </summary>
/// <remarks>
/// <para>1. Cut the row [row, row + 1] at every height where an outline starts or ends, turns left or right,
/// crosses a pixel's left or right edge (X = k), or crosses another outline. Between two cuts — a strip — each
/// outline that is present has a left and a right branch, no branch meets another or a pixel edge, so the branches
/// split the strip into pieces of one colour, found with one ray through the middle of each piece.</para>
/// <para>2. A piece between branches L(Y) and R(Y) covers pixel x by ∫ (min(R, x + 1) − max(L, x)) dY over the
/// strip, and inside a strip the min and max pick the same side everywhere: each pixel gets an exact integral
/// of a branch (<see cref="Outline.Integral"/>) or of a pixel edge. Pixels wholly inside a piece are added as one
/// span (a difference array summed once per row), so they cost nothing per pixel.</para>
/// </remarks>
internal sealed class ExactRow
{
    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly OutlineSet _outlines;
    private readonly int _width;
    private readonly double[] _values;
    private readonly double[] _spans;
    private readonly List<double> _cuts = [];
    private readonly List<int> _present = [];
    private Branch[] _branches = new Branch[8];

    public ExactRow(Scene scene, ImagePlane plane, OutlineSet outlines)
    {
        _scene = scene;
        _plane = plane;
        _outlines = outlines;
        _width = plane.Width;
        _values = new double[3 * _width];
        _spans = new double[3 * (_width + 1)];
    }

    /// <summary>
    /// The last row's pixel values, R, G, B of pixel 0, then of pixel 1, and so on (linear intensity); not filled
    /// when the row <see cref="IsUniform"/>.
    /// </summary>
    public double[] Values => _values;

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
        _cuts.Clear();
        _present.Clear();
        Outline[] outlines = _outlines.Outlines;
        for (int i = 0; i < outlines.Length; i++)
        {
            if (outlines[i].Bottom >= y0 && outlines[i].Top <= y1)
            {
                _present.Add(i);
                outlines[i].AddBreaks(y0, y1, _width, _cuts);
            }
        }

        IsUniform = _present.Count == 0;
        if (IsUniform)
        {
            UniformColor = Probe(_width / 2.0, row + 0.5);
            return;
        }

        double[] crossings = _outlines.CrossingHeights;
        int at = Array.BinarySearch(crossings, y0);
        for (at = at < 0 ? ~at : at; at < crossings.Length && crossings[at] < y1; at++)
        {
            if (crossings[at] > y0)
            {
                _cuts.Add(crossings[at]);
            }
        }

        _cuts.Add(y0);
        _cuts.Add(y1);
        _cuts.Sort();
        Array.Clear(_values);
        Array.Clear(_spans);
        for (int k = 0; k + 1 < _cuts.Count; k++)
        {
            if (_cuts[k + 1] > _cuts[k])
            {
                Strip(_cuts[k], _cuts[k + 1]);
            }
        }

        double r = 0, g = 0, b = 0;
        for (int x = 0; x < _width; x++)
        {
            r += _spans[3 * x];
            g += _spans[(3 * x) + 1];
            b += _spans[(3 * x) + 2];
            _values[3 * x] += r;
            _values[(3 * x) + 1] += g;
            _values[(3 * x) + 2] += b;
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Strip(double ya, double yb)
    {
        double ym = 0.5 * (ya + yb), h = yb - ya;
        Outline[] outlines = _outlines.Outlines;
        int n = 0;
        foreach (int i in _present)
        {
            Outline o = outlines[i];
            if (o.Hy > 0 && Math.Abs(ym - o.Yc) < o.Hy)
            {
                if (n + 2 > _branches.Length)
                {
                    Array.Resize(ref _branches, 2 * _branches.Length);
                }

                (double left, double right) = o.At(ym);
                _branches[n++] = new Branch(left, i, -1);
                _branches[n++] = new Branch(right, i, +1);
            }
        }

        // Sorted by X; equal X in the order they were added (outline index, then left before right), as
        // insertion one by one would leave them: O(n log n) where a row of a field of spheres meets hundreds.
        Span<Branch> branches = _branches.AsSpan(0, n);
        branches.Sort(static (p, q) => p.X != q.X ? p.X.CompareTo(q.X) : (p.Outline != q.Outline ? p.Outline.CompareTo(q.Outline) : p.Sign.CompareTo(q.Sign)));

        // Walk the pieces left to right; a branch outside the image stands for the image's edge.
        double leftX = 0, leftIntegral = 0;
        for (int k = 0; k <= n; k++)
        {
            double rightX = _width, rightIntegral = _width * h;
            if (k < n)
            {
                Branch branch = branches[k];
                if (branch.X <= 0)
                {
                    continue;
                }

                if (branch.X < _width)
                {
                    rightX = branch.X;
                    rightIntegral = outlines[branch.Outline].Integral(branch.Sign, ya, yb);
                }
            }

            if (rightX > leftX)
            {
                Piece(leftX, leftIntegral, rightX, rightIntegral, ym, h);
                leftX = rightX;
                leftIntegral = rightIntegral;
            }

            if (rightX >= _width)
            {
                break;
            }
        }
    }

    // The piece between boundaries at xl and xr (at mid-strip), with ∫X dY of each over the strip.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Piece(double xl, double il, double xr, double ir, double ym, double h)
    {
        Intensity c = Probe(0.5 * (xl + xr), ym);
        int a = Math.Min((int)xl, _width - 1), b = Math.Min((int)xr, _width - 1);
        if (a == b)
        {
            Add(a, c, ir - il);
            return;
        }

        Add(a, c, ((a + 1) * h) - il);
        Add(b, c, ir - (b * h));
        if (b > a + 1)
        {
            _spans[3 * (a + 1)] += c.R * h;
            _spans[(3 * (a + 1)) + 1] += c.G * h;
            _spans[(3 * (a + 1)) + 2] += c.B * h;
            _spans[3 * b] -= c.R * h;
            _spans[(3 * b) + 1] -= c.G * h;
            _spans[(3 * b) + 2] -= c.B * h;
        }
    }

    private void Add(int x, Intensity c, double area)
    {
        _values[3 * x] += c.R * area;
        _values[(3 * x) + 1] += c.G * area;
        _values[(3 * x) + 2] += c.B * area;
    }

    // The colour at pixel coordinates (X, Y): the ColourOf what the ray there hits (flat shading).
    private Intensity Probe(double x, double y)
    {
        Ray ray = _plane.GetRayAt(x, y);
        return _scene.ColourOf(_scene.Nearest(ray, _plane.TMin, _plane.TMax));
    }

    private readonly record struct Branch(double X, int Outline, int Sign);
}
