using RayLab.Cameras;

namespace RayLab;

/// <summary>
/// One pixel as an <see cref="IPixelMethod{TScratch}"/> sees it: its coordinates, the trace function for a point
/// (x + sx, row + sy) inside it, and the values already decided to its left in the same row. One tracer serves
/// one thread; it is valid only during <see cref="IPixelMethod{TScratch}.RenderPixel"/>.
/// </summary>
public sealed class PixelTracer
{
    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly Intensity[] _row;

    internal PixelTracer(Scene scene, ImagePlane plane)
    {
        _scene = scene;
        _plane = plane;
        _row = new Intensity[plane.Width];
    }

    /// <summary>The pixel column, 0 on the left.</summary>
    public int X { get; private set; }

    /// <summary>The pixel row, 0 at the top.</summary>
    public int Row { get; private set; }

    /// <summary>The image width W in pixels.</summary>
    public int Width => _plane.Width;

    /// <summary>The image height H in pixels.</summary>
    public int Height => _plane.Height;

    /// <summary>Primary rays traced so far for this pixel.</summary>
    public int RaysTraced { get; private set; }

    /// <summary>
    /// The values already decided for pixels 0 … X − 1 of this row (linear intensity, before the 8-bit rule), the
    /// left neighbour last. Only these neighbours are read: rows are rendered in parallel, so a pixel above may not
    /// be done yet.
    /// </summary>
    public ReadOnlySpan<Intensity> PreviousInRow => _row.AsSpan(0, X);

    /// <summary>
    /// Traces the primary ray through the point (X + <paramref name="sx"/>, Row + <paramref name="sy"/>) of the
    /// image (the camera's projection, <see cref="ImagePlane.GetPixelRay"/>) and returns the colour it sees
    /// (<see cref="Scene.Trace"/>). Each call counts one ray.
    /// </summary>
    /// <param name="sx">Offset inside the pixel, 0 (left edge) to 1 (right edge).</param>
    /// <param name="sy">Offset inside the pixel, 0 (top edge) to 1 (bottom edge).</param>
    /// <returns>The intensity seen at that point.</returns>
    /// <exception cref="ArgumentOutOfRangeException">An offset is outside [0, 1] or NaN: the point is not in this pixel.</exception>
    public Intensity Trace(double sx, double sy)
    {
        CheckOffset(sx, nameof(sx));
        CheckOffset(sy, nameof(sy));
        RaysTraced++;
        Intensity value = _plane.Trace(_scene, _plane.GetPixelRay(X, Row, sx, sy));
        Recorded?.Add((sx, sy, value));
        return value;
    }

    /// <summary>Where <see cref="Trace"/> records the current pixel's points (<see cref="Renderer.TracePixel"/>); null when rendering.</summary>
    internal List<(double X, double Y, Intensity Value)>? Recorded { get; set; }

    /// <summary>Moves to pixel (<paramref name="x"/>, <paramref name="row"/>) with no rays traced yet.</summary>
    internal void Begin(int x, int row)
    {
        X = x;
        Row = row;
        RaysTraced = 0;
    }

    /// <summary>Records the value decided for the current pixel, for <see cref="PreviousInRow"/>.</summary>
    internal void Keep(Intensity value) => _row[X] = value;

    private static void CheckOffset(double offset, string name)
    {
        if (!(offset >= 0 && offset <= 1))
        {
            throw new ArgumentOutOfRangeException(name, offset, "A point inside the pixel has offsets in [0, 1].");
        }
    }
}
