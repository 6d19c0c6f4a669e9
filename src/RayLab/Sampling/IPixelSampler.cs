namespace RayLab.Sampling;

/// <summary>
/// Places a fixed number of sample points in each pixel (the lab's section 4). Implementations are stateless:
/// a point depends only on (pixel, sample index, seed), so any thread may ask for any sample in any order.
/// </summary>
public interface IPixelSampler
{
    /// <summary>The sampler's name as the console and scene files spell it, e.g. <c>jittered</c>.</summary>
    string Name { get; }

    /// <summary>Samples (primary rays) per pixel.</summary>
    int SamplesPerPixel { get; }

    /// <summary>The seed; samplers without randomness ignore it.</summary>
    uint Seed { get; }

    /// <summary>Sample <paramref name="index"/> (0 ≤ index &lt; <see cref="SamplesPerPixel"/>) of pixel (x, y).</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row, 0 at the top.</param>
    /// <param name="index">The sample index.</param>
    SamplePoint GetSample(int x, int y, int index);
}
