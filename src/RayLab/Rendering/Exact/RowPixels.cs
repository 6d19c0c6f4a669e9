using System.Runtime.CompilerServices;

namespace RayLab.Rendering.Exact;

/// <summary>
/// One pixel row's exact linear values as the pieces of one colour are added: R, G, B of pixel 0, then of pixel 1,
/// and so on. A piece adds its exact area to the pixels at its two ends, and to the pixels wholly inside it as one
/// span (a difference array summed once per row, <see cref="SumSpans"/>), so those cost nothing per pixel.
/// </summary>
internal sealed class RowPixels
{
    private readonly int _width;
    private readonly double[] _values;
    private readonly double[] _spans;

    /// <summary>Creates the sums for a row of <paramref name="width"/> pixels in <paramref name="buffers"/>, fitted to the width.</summary>
    /// <param name="width">W.</param>
    /// <param name="buffers">Arrays kept from an earlier render, or new ones.</param>
    public RowPixels(int width, Buffers buffers)
    {
        _width = width;
        if (buffers.Values.Length != 3 * width)
        {
            buffers.Values = new double[3 * width];
            buffers.Spans = new double[3 * (width + 1)];
        }

        _values = buffers.Values;
        _spans = buffers.Spans;
        Arrays = buffers;
    }

    /// <summary>The arrays, for the renderer to keep for its next render.</summary>
    public Buffers Arrays { get; }

    /// <summary>The pixel values, R, G, B per pixel (complete after <see cref="SumSpans"/>).</summary>
    public double[] Values => _values;

    /// <summary>Sets every sum to 0.</summary>
    public void Clear()
    {
        Array.Clear(_values);
        Array.Clear(_spans);
    }

    /// <summary>
    /// Adds the piece of colour <paramref name="c"/> between boundaries at <paramref name="xl"/> and
    /// <paramref name="xr"/> (at mid-height), given ∫X dY of each boundary over the piece's height <paramref name="h"/>.
    /// </summary>
    /// <param name="xl">The left boundary's X at mid-height.</param>
    /// <param name="il">∫X dY of the left boundary.</param>
    /// <param name="xr">The right boundary's X at mid-height.</param>
    /// <param name="ir">∫X dY of the right boundary.</param>
    /// <param name="h">The piece's height.</param>
    /// <param name="c">The piece's colour.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void Piece(double xl, double il, double xr, double ir, double h, Intensity c)
    {
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

    /// <summary>Adds the spans (the pixels wholly inside pieces) to <see cref="Values"/>: once per row, after every piece.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void SumSpans()
    {
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

    private void Add(int x, Intensity c, double area)
    {
        _values[3 * x] += c.R * area;
        _values[(3 * x) + 1] += c.G * area;
        _values[(3 * x) + 2] += c.B * area;
    }

    /// <summary>
    /// A thread's row sums, kept by the <see cref="Renderer"/> from one render to the next (some 92 KB per thread at
    /// 1920 pixels): on 16 threads, new ones each frame meant 16 threads allocating at once as the rows began.
    /// </summary>
    internal sealed class Buffers
    {
        /// <summary>R, G, B per pixel.</summary>
        public double[] Values { get; set; } = [];

        /// <summary>The spans' difference array.</summary>
        public double[] Spans { get; set; } = [];
    }
}
