using RayLab.Sampling;

namespace MyLab;

/// <summary>
/// Your own antialiasing method (the lab's alternative to its adaptive one), as a point sampler: a fixed set of
/// points in each pixel, like the lab's regular, random and jittered sampling (4.1); the renderer traces a ray through
/// each and the pixel is their mean. It starts as the smallest sampler that works: one point at the pixel's centre
/// (no antialiasing).
/// </summary>
/// <remarks>
/// A sampler must be stateless: any thread may ask for any sample, so take randomness from a hash of
/// (x, y, index, <see cref="Seed"/>), never from a shared <see cref="Random"/>.
/// </remarks>
public sealed class MyMethod : IPixelSampler
{
    /// <summary>The points, as offsets inside the pixel: (0, 0) its top-left corner, (0.5, 0.5) its centre.</summary>
    private static readonly SamplePoint[] Points = [new(0.5, 0.5)];

    /// <inheritdoc />
    public string Name => "my-method";

    /// <summary>Rays per pixel.</summary>
    public int SamplesPerPixel => Points.Length;

    /// <summary>The seed of a random sampler; this one has no randomness.</summary>
    public uint Seed => 0;

    /// <summary>Sample <paramref name="index"/> of pixel (<paramref name="x"/>, <paramref name="y"/>).</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row, 0 at the top.</param>
    /// <param name="index">The sample, 0 ≤ index &lt; <see cref="SamplesPerPixel"/>.</param>
    /// <returns>The point's offset (sx, sy) in [0, 1)² inside the pixel.</returns>
    public SamplePoint GetSample(int x, int y, int index)
    {
        // ---- Write your method here: more points, and where in the pixel they go (a grid, a rotated grid, jitter).
        // The tests (MyMethodTests) hold your error and your rays per pixel.
        return Points[index];
    }
}
