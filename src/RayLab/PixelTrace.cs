using RayLab.Rendering.Inspection;

namespace RayLab;

/// <summary>A point traced inside one pixel (<see cref="PixelTrace"/>), in trace order.</summary>
/// <param name="X">Offset to the right inside the pixel, 0 … 1.</param>
/// <param name="Y">Offset downward inside the pixel, 0 … 1.</param>
/// <param name="Value">What the ray saw.</param>
/// <param name="Weight">
/// The point's share of the pixel's value: 1/n for a point sampler's n samples, the lab's combination rule for the
/// adaptive method (the shares add up to 1); for a pixel method of your own, whose rule is its own, 1/n.
/// </param>
public readonly record struct TracedPoint(double X, double Y, Intensity Value, double Weight);

/// <summary>
/// One pixel of a render, traced by <see cref="Renderer.TracePixel"/>: the value the method gives the pixel (linear,
/// before the 8-bit rule) and the points it traced there, each with its share of the value — what the pixel
/// inspector, the adaptive diagram and the playground show.
/// </summary>
public sealed class PixelTrace
{
    internal PixelTrace(int x, int y, RenderMethod method, Intensity value, IReadOnlyList<TracedPoint> points, IReadOnlyList<AdaptiveSquare> squares)
    {
        X = x;
        Y = y;
        Method = method;
        Value = value;
        Points = points;
        Squares = squares;
    }

    /// <summary>The pixel's column, 0 on the left.</summary>
    public int X { get; }

    /// <summary>The pixel's row, 0 at the top.</summary>
    public int Y { get; }

    /// <summary>The method that traced it.</summary>
    public RenderMethod Method { get; }

    /// <summary>
    /// The pixel's value in linear intensity, as the method computes it: the same value a render into linear
    /// intensities gives this pixel (for point sampling, the scalar kernel's, <see cref="RenderKernel.Scalar"/>).
    /// </summary>
    public Intensity Value { get; }

    /// <summary>The points traced in the pixel, in trace order (one primary ray each); none for the exact method, which integrates.</summary>
    public IReadOnlyList<TracedPoint> Points { get; }

    /// <summary>For the adaptive method, every square its recursion looked at (the pixel, and the quadrants of each refined square); otherwise none.</summary>
    public IReadOnlyList<AdaptiveSquare> Squares { get; }
}
