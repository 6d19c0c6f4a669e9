namespace RayLab.Cli;

/// <summary>The parsed <c>raylab render</c> command line; null means "as the scene file says".</summary>
/// <param name="ScenePath">The scene file.</param>
/// <param name="OutputPath">The image to write.</param>
/// <param name="Camera">Camera type override.</param>
/// <param name="Sampler">Sampler override.</param>
/// <param name="Samples">Samples-per-pixel override.</param>
/// <param name="Seed">Seed override.</param>
/// <param name="Threads">Thread count.</param>
/// <param name="Width">Width override.</param>
/// <param name="Height">Height override.</param>
/// <param name="StatsPath">Where to write statistics JSON.</param>
/// <param name="MinDepth">Adaptive minimum depth override.</param>
/// <param name="MaxDepth">Adaptive maximum depth override.</param>
/// <param name="Contrast">Adaptive contrast override.</param>
/// <param name="HeatmapPath">Where to write the rays-per-pixel heat map.</param>
/// <param name="Kernel">Point samplers: the render loop (see <c>RenderKernel</c>), null for auto.</param>
/// <param name="Quincunx">Adaptive: trace every pixel's centre.</param>
/// <param name="Guard">Adaptive: also refine squares a sphere's silhouette may cross.</param>
/// <param name="Quality">JPEG/WebP quality (0–100), null for <c>ImageFormats.DefaultQuality</c>.</param>
/// <param name="Warmup">The timing harness: a scaled-down warm-up render and the image's pages committed before the timed render.</param>
/// <param name="Device">Point samplers: where the render runs, <c>cpu</c>, <c>gpu</c> or <c>auto</c>; null for the CPU.</param>
public sealed record RenderRequest(
    string ScenePath, string OutputPath, string? Camera = null, string? Sampler = null, int? Samples = null,
    uint? Seed = null, int? Threads = null, int? Width = null, int? Height = null, string? StatsPath = null,
    int? MinDepth = null, int? MaxDepth = null, double? Contrast = null, string? HeatmapPath = null,
    string? Kernel = null, bool Quincunx = false, bool Guard = false, int? Quality = null, bool Warmup = false, string? Device = null)
{
    /// <summary>The options that override scene-file fields.</summary>
    internal SceneOverrides Overrides => new(Width, Height, Camera, Sampler, Samples, Seed, MinDepth, MaxDepth, Contrast, Quincunx, Guard);
}
