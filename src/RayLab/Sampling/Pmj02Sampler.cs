namespace RayLab.Sampling;

/// <summary>
/// Progressive multi-jittered (0, 2) samples (Christensen, Kensler and Kilpatrick, EGSR 2018): every prefix of 2ᵐ
/// samples of a pixel is a (0, m, 2)-net in base 2, so it has exactly one point in each elementary interval
/// [a/2ʲ, (a+1)/2ʲ) × [b/2ᵏ, (b+1)/2ᵏ) with j + k = m, and the first N of a 4N-sample pixel are themselves such a
/// set. Any number of samples works; at a count between two powers of two the samples are the first of the next
/// power's set, so the largest power-of-two prefix keeps the guarantee.
/// </summary>
/// <remarks>
/// The sets are generated once by the library (64 of them, each as long as the sample count rounded up to a power of
/// two; see docs/samplers.md for their size). A pixel takes the set its <see cref="CounterHash.PixelKey"/> picks,
/// and XORs each coordinate with a key hashed from it (a random digital shift, which keeps every net a net).
/// </remarks>
public sealed class Pmj02Sampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates a pmj02 sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1 (a power of two for the full net property).</param>
    /// <param name="seed">The seed; different seeds give pixels other sets and shifts.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public Pmj02Sampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => Sets = Pmj02Tables.Sets(blueNoise: false, samplesPerPixel);

    /// <inheritdoc />
    public override string Name => "pmj02";

    /// <summary>The generated sets this sampler reads.</summary>
    internal uint[][] Sets { get; }

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index) =>
        Pmj02Tables.Point(Sets, Pmj02Tables.Pixel(CounterHash.PixelKey(x, y, Seed), scramble: true), index);

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new Pmj02Lanes<TL>(this));
}
