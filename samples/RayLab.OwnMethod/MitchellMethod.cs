using RayLab.Sampling;

namespace RayLab.OwnMethod;

/// <summary>
/// An adaptive method of your own: Mitchell's contrast test (Mitchell 1987, "Generating antialiased images at low
/// sampling densities"). Each pixel first gets 4 samples; where they differ in contrast
/// C = (I_max − I_min)/(I_max + I_min) by more than 0.4 in red, 0.3 in green or 0.6 in blue (his thresholds, after
/// the eye's sensitivity to each channel), it gets 12 more, and the pixel is the mean of all of them.
/// </summary>
/// <remarks>
/// The 16 points are the 4×4 rotated grid (<see cref="RotatedGridSampler"/>); the first 4 are the cells that form
/// a 2×2 rotated grid of their own, so the first pass already sees an edge at any angle.
/// </remarks>
public sealed class MitchellMethod : IPixelMethod<Intensity[]>
{
    private static readonly Intensity Threshold = new(0.4, 0.3, 0.6);

    // Cells (i, j) of the 4×4 grid: the first four one per row and column, then the rest.
    private static readonly SamplePoint[] Points = Order().ToArray();

    /// <inheritdoc />
    public string Name => "mitchell";

    /// <summary>A buffer for one pixel's 16 samples.</summary>
    /// <returns>The buffer.</returns>
    public Intensity[] CreateScratch() => new Intensity[Points.Length];

    /// <summary>4 samples, and 12 more where their contrast exceeds a channel's threshold.</summary>
    /// <param name="pixel">The pixel.</param>
    /// <param name="samples">This thread's sample buffer.</param>
    /// <returns>The mean of the samples traced.</returns>
    public Intensity RenderPixel(PixelTracer pixel, ref Intensity[] samples)
    {
        int count = Trace(pixel, samples, 0, 4);
        if (ExceedsContrast(samples.AsSpan(0, count)))
        {
            count = Trace(pixel, samples, count, Points.Length);
        }

        Intensity sum = default;
        foreach (Intensity sample in samples.AsSpan(0, count))
        {
            sum += sample;
        }

        return sum / count;
    }

    private static int Trace(PixelTracer pixel, Intensity[] samples, int from, int to)
    {
        for (int i = from; i < to; i++)
        {
            samples[i] = pixel.Trace(Points[i].X, Points[i].Y);
        }

        return to;
    }

    /// <summary>True when some channel's contrast (max − min)/(max + min) exceeds its threshold.</summary>
    private static bool ExceedsContrast(ReadOnlySpan<Intensity> samples) =>
        Contrast(samples, s => s.R) > Threshold.R || Contrast(samples, s => s.G) > Threshold.G || Contrast(samples, s => s.B) > Threshold.B;

    private static double Contrast(ReadOnlySpan<Intensity> samples, Func<Intensity, double> channel)
    {
        double min = double.MaxValue, max = double.MinValue;
        foreach (Intensity sample in samples)
        {
            min = Math.Min(min, channel(sample));
            max = Math.Max(max, channel(sample));
        }

        return max + min > 0 ? (max - min) / (max + min) : 0;
    }

    private static IEnumerable<SamplePoint> Order()
    {
        (int I, int J)[] first = [(0, 1), (1, 3), (2, 0), (3, 2)];
        foreach ((int i, int j) in first)
        {
            yield return RotatedGridSampler.At(4, i, j);
        }

        for (int j = 0; j < 4; j++)
        {
            for (int i = 0; i < 4; i++)
            {
                if (!first.Contains((i, j)))
                {
                    yield return RotatedGridSampler.At(4, i, j);
                }
            }
        }
    }
}
