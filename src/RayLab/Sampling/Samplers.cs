namespace RayLab.Sampling;

/// <summary>Creates samplers by the names the console and scene files use.</summary>
public static class Samplers
{
    /// <summary>The sampler names, as scene files and the console spell them.</summary>
    public static IReadOnlyList<string> Names { get; } = ["regular", "random", "jittered", "cmj", "multijittered", "nrooks", "hammersley", "sobol", "pmj02", "pmj02bn", "zsobol"];

    /// <summary>Creates the sampler called <paramref name="name"/>.</summary>
    /// <param name="name">One of <see cref="Names"/> (case-insensitive).</param>
    /// <param name="samplesPerPixel">Samples per pixel: a perfect square for <c>regular</c>, <c>jittered</c> and <c>multijittered</c>.</param>
    /// <param name="seed">The seed.</param>
    /// <exception cref="ArgumentException">Unknown name, or a sample count the sampler cannot use.</exception>
    public static IPixelSampler Create(string name, int samplesPerPixel, uint seed)
    {
        ArgumentNullException.ThrowIfNull(name);
        return name.ToLowerInvariant() switch
        {
            "regular" => new RegularSampler(samplesPerPixel),
            "random" => new RandomSampler(samplesPerPixel, seed),
            "jittered" => new JitteredSampler(samplesPerPixel, seed),
            "cmj" => new CorrelatedMultiJitteredSampler(samplesPerPixel, seed),
            "multijittered" => new MultiJitteredSampler(samplesPerPixel, seed),
            "nrooks" => new NRooksSampler(samplesPerPixel, seed),
            "hammersley" => new HammersleySampler(samplesPerPixel, seed),
            "sobol" => new SobolSampler(samplesPerPixel, seed),
            "pmj02" => new Pmj02Sampler(samplesPerPixel, seed),
            "pmj02bn" => new Pmj02BNSampler(samplesPerPixel, seed),
            "zsobol" => new ZSobolSampler(samplesPerPixel, seed),
            _ => throw new ArgumentException(
                $"Unknown sampler '{name}'; expected one of: {string.Join(", ", Names)}.", nameof(name)),
        };
    }
}
