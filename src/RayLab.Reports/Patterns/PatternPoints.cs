using RayLab.Sampling;

namespace RayLab.Reports.Patterns;

/// <summary>
/// The points an <see cref="IPixelSampler"/> puts in one pixel (the lab's section 4, Rys. 12 and 13), as a point set
/// in the unit square: what every measure in this folder takes. A pixel is one realisation of the sampler; pixels
/// (x, y) of a block are independent realisations for the random samplers and the same points for <c>regular</c>.
/// </summary>
public static class PatternPoints
{
    /// <summary>The sampler's points in pixel (<paramref name="x"/>, <paramref name="y"/>), in sample order.</summary>
    /// <param name="sampler">Any sampler, the built-in ones or a student's own.</param>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row.</param>
    /// <returns><see cref="IPixelSampler.SamplesPerPixel"/> points in [0, 1)².</returns>
    /// <exception cref="ArgumentException">The sampler returned a point outside [0, 1]² or not a number.</exception>
    public static SamplePoint[] Of(IPixelSampler sampler, int x, int y)
    {
        ArgumentNullException.ThrowIfNull(sampler);
        var points = new SamplePoint[sampler.SamplesPerPixel];
        Fill(sampler, x, y, points);
        return points;
    }

    /// <summary>Writes the sampler's points in pixel (<paramref name="x"/>, <paramref name="y"/>) into <paramref name="points"/>.</summary>
    /// <param name="sampler">The sampler.</param>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row.</param>
    /// <param name="points">Exactly <see cref="IPixelSampler.SamplesPerPixel"/> entries.</param>
    /// <exception cref="ArgumentException">The span's length differs from the sample count, or a point is outside [0, 1]².</exception>
    public static void Fill(IPixelSampler sampler, int x, int y, Span<SamplePoint> points)
    {
        ArgumentNullException.ThrowIfNull(sampler);
        if (points.Length != sampler.SamplesPerPixel)
        {
            throw new ArgumentException($"Expected {sampler.SamplesPerPixel} points, got a span of {points.Length}.", nameof(points));
        }

        for (int i = 0; i < points.Length; i++)
        {
            SamplePoint p = sampler.GetSample(x, y, i);
            if (!(p.X >= 0 && p.X <= 1 && p.Y >= 0 && p.Y <= 1))
            {
                throw new ArgumentException(
                    $"Sampler '{sampler.Name}' put sample {i} of pixel ({x}, {y}) at ({p.X}, {p.Y}), outside the pixel [0, 1]².",
                    nameof(sampler));
            }

            points[i] = p;
        }
    }
}
