using RayLab.Sampling;

namespace RayLab.Scenes;

/// <summary>A scene file's <c>sampler</c> object.</summary>
/// <param name="Type">The sampler name (see <see cref="Samplers.Names"/>).</param>
/// <param name="Samples">Samples per pixel.</param>
/// <param name="Seed">The seed.</param>
public sealed record SamplerSettings(string Type, int Samples, uint Seed)
{
    /// <summary>One ray through each pixel centre: the lab's first picture.</summary>
    public static SamplerSettings Default { get; } = new("regular", 1, 0);

    /// <summary>Creates the sampler.</summary>
    /// <exception cref="ArgumentException">Unknown type or unusable sample count.</exception>
    public IPixelSampler CreateSampler() => Samplers.Create(Type, Samples, Seed);
}
