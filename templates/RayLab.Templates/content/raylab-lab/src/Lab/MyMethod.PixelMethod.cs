using RayLab;
using RayLab.Sampling;

namespace MyLab;

/// <summary>
/// Your own antialiasing method (the lab's alternative to its adaptive one), as a pixel method: the renderer calls
/// <see cref="RenderPixel"/> once for each pixel, and you decide where inside the pixel to look and how to combine
/// what you see. It starts as the smallest method that works: one ray through the pixel's centre (no antialiasing).
/// </summary>
public sealed class MyMethod : IPixelMethod<Intensity[]>
{
    /// <summary>The points to trace, as offsets inside the pixel: (0, 0) its top-left corner, (0.5, 0.5) its centre.</summary>
    private static readonly SamplePoint[] Points = [new(0.5, 0.5)];

    /// <inheritdoc />
    public string Name => "my-method";

    /// <summary>This thread's working space: room for one pixel's samples.</summary>
    /// <returns>A buffer for the samples.</returns>
    public Intensity[] CreateScratch() => new Intensity[Points.Length];

    /// <summary>The pixel's value: here, the mean of the samples at <see cref="Points"/>.</summary>
    /// <param name="pixel">The pixel: <c>pixel.Trace(sx, sy)</c> traces one primary ray through (x + sx, row + sy) and
    /// returns the <see cref="Intensity"/> it sees; <c>pixel.X</c> and <c>pixel.Row</c> say which pixel it is.</param>
    /// <param name="samples">This thread's buffer (from <see cref="CreateScratch"/>).</param>
    /// <returns>The pixel's linear intensity; the renderer applies the 8-bit rule int(256·I).</returns>
    public Intensity RenderPixel(PixelTracer pixel, ref Intensity[] samples)
    {
        // ---- Write your method here: trace more points where the pixel needs them (an edge), fewer where it is flat.
        // Every pixel.Trace counts one ray; the tests (MyMethodTests) hold your error and your rays per pixel.
        Intensity sum = Intensity.Black;
        for (int i = 0; i < Points.Length; i++)
        {
            samples[i] = pixel.Trace(Points[i].X, Points[i].Y);
            sum += samples[i];
        }

        return sum / Points.Length;
    }
}
