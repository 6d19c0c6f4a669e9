namespace RayLab.Sampling;

/// <summary>
/// Progressive multi-jittered (0, 2) samples with blue-noise spacing, pmj02bn (Christensen, Kensler and Kilpatrick,
/// EGSR 2018): the same stratification as <see cref="Pmj02Sampler"/> (every prefix of 2ᵐ samples a (0, m, 2)-net in
/// base 2), and each new point is the best of several candidates, the one farthest from the points before it, so
/// points keep apart. Any number of samples works; powers of two keep the full guarantee.
/// </summary>
/// <remarks>
/// The sets are generated once by the library (64 of them; docs/samplers.md gives their size). A pixel takes the
/// set its <see cref="CounterHash.PixelKey"/> picks, unscrambled: a digital shift would keep the strata but tear
/// the spacing apart at the shift's binary boundaries. Its points and lanes are pmj02's formula
/// (<see cref="Pmj02Sampler"/>) on these sets with keys 0.
/// </remarks>
public sealed class Pmj02BNSampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates a pmj02bn sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1 (a power of two for the full net property).</param>
    /// <param name="seed">The seed; different seeds give pixels other sets.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public Pmj02BNSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => Sets = Pmj02Tables.Sets(blueNoise: true, samplesPerPixel);

    /// <inheritdoc />
    public override string Name => "pmj02bn";

    /// <summary>The generated sets this sampler reads.</summary>
    internal uint[][] Sets { get; }

    /// <summary>The first <see cref="IPixelSampler.SamplesPerPixel"/> points of each set laid end to end (<see cref="Pmj02Tables.Flat"/>), made at the first render in lanes.</summary>
    internal uint[] FlatSets => LazyInitializer.EnsureInitialized(ref _flatSets, () => Pmj02Tables.Flat(Sets, SamplesPerPixel));

    private uint[]? _flatSets;

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index) =>
        Pmj02Sampler.Point(Sets, Pmj02Tables.Pixel(CounterHash.PixelKey(x, y, Seed), scramble: false), index);

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new Pmj02Sampler.LaneForm<TL>(FlatSets, SamplesPerPixel, Seed, scramble: false));
}
