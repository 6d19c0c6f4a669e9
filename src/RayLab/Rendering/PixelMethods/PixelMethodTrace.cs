
namespace RayLab.Rendering.PixelMethods;

/// <summary>A point a pixel method traced inside one pixel (<see cref="PixelTracer.Trace"/>), in trace order.</summary>
/// <param name="X">Offset to the right inside the pixel, 0 … 1.</param>
/// <param name="Y">Offset downward inside the pixel, 0 … 1.</param>
/// <param name="Value">What the ray saw.</param>
public readonly record struct TracedPoint(double X, double Y, Intensity Value);

/// <summary>
/// One pixel of an <see cref="IPixelMethod{TScratch}"/>'s render, recorded: every point the method traced in it, in
/// trace order, and the value it gave the pixel. The method runs as the renderer runs it (the row's pixels to the left
/// first, so <see cref="PixelTracer.PreviousInRow"/> holds the same values), so the points are the method's own.
/// </summary>
public sealed class PixelMethodTrace
{
    private PixelMethodTrace(int px, int py, IReadOnlyList<TracedPoint> points, Intensity value)
    {
        PixelX = px;
        PixelY = py;
        Points = points;
        Value = value;
    }

    /// <summary>The pixel's column.</summary>
    public int PixelX { get; }

    /// <summary>The pixel's row.</summary>
    public int PixelY { get; }

    /// <summary>The points the method traced in the pixel, in trace order (one primary ray each).</summary>
    public IReadOnlyList<TracedPoint> Points { get; }

    /// <summary>The pixel's value in linear intensity (before the 8-bit rule), as the method returned it.</summary>
    public Intensity Value { get; }

    /// <summary>Runs <paramref name="method"/> on pixel (<paramref name="px"/>, <paramref name="py"/>) of a W×H render and records its points.</summary>
    /// <typeparam name="TScratch">The method's working space.</typeparam>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">W.</param>
    /// <param name="height">H.</param>
    /// <param name="method">The pixel method.</param>
    /// <param name="px">The pixel's column.</param>
    /// <param name="py">The pixel's row.</param>
    /// <returns>The pixel's points and value.</returns>
    /// <exception cref="ArgumentException">The pixel is outside the image, or the camera's settings are invalid.</exception>
    public static PixelMethodTrace Trace<TScratch>(Scene scene, Camera camera, int width, int height, IPixelMethod<TScratch> method, int px, int py)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(method);
        ArgumentOutOfRangeException.ThrowIfNegative(px);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(px, width);
        ArgumentOutOfRangeException.ThrowIfNegative(py);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(py, height);
        var tracer = new PixelTracer(scene, camera.GetImagePlane(width, height));
        TScratch scratch = method.CreateScratch();
        var points = new List<TracedPoint>();
        Intensity value = default;
        for (int x = 0; x <= px; x++)
        {
            tracer.Begin(x, py);
            tracer.Recorded = x == px ? points : null;
            value = method.RenderPixel(tracer, ref scratch);
            tracer.Keep(value);
        }

        tracer.Recorded = null;
        return new PixelMethodTrace(px, py, points, value);
    }
}
