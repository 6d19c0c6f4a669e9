namespace RayLab.Sampling;

/// <summary>
/// Places a fixed number of sample points in each pixel (the lab's section 4). Implementations are stateless:
/// a point depends only on (pixel, sample index, seed), so any thread may ask for any sample in any order.
/// </summary>
/// <remarks>
/// The SIMD packet kernel traces one pixel per lane. Every built-in sampler gives it a lane form of its own point
/// formula. A sampler of your own has none: the kernel then takes the buffered path, which asks
/// <see cref="GetSamples"/> for each pixel of a packet and loads the points into lanes: the image is the one its points
/// give, but a packet costs a <see cref="GetSamples"/> call per pixel where a built-in sampler computes its points in
/// the lanes themselves.
/// </remarks>
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

    /// <summary>
    /// Every sample of pixel (x, y) at once: <paramref name="points"/>[i] is <see cref="GetSample"/>(x, y, i). The
    /// packet renderer asks a sampler it has no SIMD version of for its points this way, one call per pixel;
    /// this default asks <see cref="GetSample"/> for each, and a sampler may override it with a faster loop that
    /// must give the same points (work shared by a pixel's samples, such as its hash key, done once).
    /// </summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row, 0 at the top.</param>
    /// <param name="points">Where the points go; its length is <see cref="SamplesPerPixel"/>.</param>
    void GetSamples(int x, int y, Span<SamplePoint> points)
    {
        for (int i = 0; i < points.Length; i++)
        {
            points[i] = GetSample(x, y, i);
        }
    }
}
