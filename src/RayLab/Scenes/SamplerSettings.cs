using RayLab.Sampling;

namespace RayLab.Scenes;

/// <summary>A scene file's <c>sampler</c> object.</summary>
/// <param name="Type">The sampler name (see <see cref="Types"/>).</param>
/// <param name="Samples">Samples per pixel (point samplers).</param>
/// <param name="Seed">The seed (point samplers with randomness).</param>
/// <param name="MinDepth">Adaptive: the minimum subdivision depth.</param>
/// <param name="MaxDepth">Adaptive: the maximum subdivision depth.</param>
/// <param name="Contrast">Adaptive: the spatial contrast threshold.</param>
/// <param name="Quincunx">Adaptive: trace every pixel's centre, even where its corners agree.</param>
/// <param name="Guard">Adaptive: also refine squares a sphere's silhouette may cross (<see cref="AdaptiveSampler.Guard"/>).</param>
public sealed record SamplerSettings(string Type, int Samples, uint Seed, int MinDepth = 0, int MaxDepth = 3, double Contrast = 0.1, bool Quincunx = false, bool Guard = false)
{
    /// <summary>
    /// Every sampler name a scene file or the console accepts: the point samplers, <c>adaptive</c>, and <c>exact</c>
    /// (the exact reference, <see cref="RenderMethod.Exact"/>, which integrates instead of sampling).
    /// </summary>
    public static IReadOnlyList<string> Types { get; } = [.. Samplers.Names, "adaptive", "exact"];

    /// <summary>The fields of a scene file's <c>sampler</c> object.</summary>
    public static IReadOnlyList<string> Fields { get; } = ["type", "samples", "seed", "minDepth", "maxDepth", "contrast", "quincunx", "guard"];

    /// <summary>
    /// The <c>sampler</c> field a sampler constructor's parameter stands for where the names differ
    /// (<see cref="Samplers.Create"/>'s <c>name</c> and <c>samplesPerPixel</c>), or null; the adaptive
    /// sampler's parameters are spelled as the fields are.
    /// </summary>
    /// <param name="parameter">An exception's parameter name.</param>
    public static string? FieldOf(string parameter) => parameter switch
    {
        "name" => "type",
        "samplesPerPixel" => "samples",
        _ => null,
    };

    /// <summary>
    /// Checks every setting the console could use: the adaptive settings whatever the type (<c>--sampler
    /// adaptive</c> keeps them), and the method of this type.
    /// </summary>
    /// <exception cref="ArgumentException">Unknown type, unusable sample count, or a depth or contrast out of range.</exception>
    public void Check()
    {
        _ = CreateAdaptive();
        _ = CreateMethod();
    }

    /// <summary>One ray through each pixel centre: the lab's first picture.</summary>
    public static SamplerSettings Default { get; } = new("regular", 1, 0);

    /// <summary>True for the lab's adaptive sampler.</summary>
    public bool IsAdaptive => Type == "adaptive";

    /// <summary>True for the exact reference (<see cref="RenderMethod.Exact"/>): no samples, no seed.</summary>
    public bool IsExact => Type == "exact";

    /// <summary>Creates the point sampler.</summary>
    /// <exception cref="ArgumentException">Unknown type or unusable sample count.</exception>
    public IPixelSampler CreateSampler() => Samplers.Create(Type, Samples, Seed);

    /// <summary>Creates the adaptive sampler.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A depth or the contrast is out of range.</exception>
    public AdaptiveSampler CreateAdaptive() => new(MinDepth, MaxDepth, Contrast, Quincunx, Guard);

    /// <summary>The render method these settings name: the one mapping from a sampler type to a renderer.</summary>
    /// <exception cref="ArgumentException">Unknown type, unusable sample count, or a depth or contrast out of range.</exception>
    public RenderMethod CreateMethod() => Type switch
    {
        "exact" => RenderMethod.Exact,
        "adaptive" => RenderMethod.Adaptive(CreateAdaptive()),
        _ => RenderMethod.Sampled(CreateSampler()),
    };
}
