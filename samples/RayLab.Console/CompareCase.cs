using RayLab.Cameras;
using RayLab.Imaging;
using RayLab.Rendering;
using RayLab.Sampling;
using RayLab.Rendering.Adaptive;

namespace RayLab.Cli;

/// <summary>One setting <c>raylab compare</c> renders: a point sampler at one budget, or one adaptive setting.</summary>
/// <param name="Series">Its line on the chart: the sampler's name, <c>adaptive c=0.1</c> for each contrast, or <c>adaptive guard c=0.01</c> for the guarded sampler at the smallest contrast.</param>
/// <param name="Setting">What varies along the line: <c>16 spp</c>, or <c>depth 0–3</c>.</param>
/// <param name="Budget">The budget asked for (point samplers); a grid sampler uses the nearest square below it.</param>
/// <param name="Point">The point sampler, or null.</param>
/// <param name="Adaptive">The adaptive sampler, or null.</param>
public sealed record CompareCase(string Series, string Setting, int? Budget, IPixelSampler? Point, AdaptiveSampler? Adaptive)
{
    /// <summary>The sampler's name (<c>jittered</c>, <c>adaptive</c>, …).</summary>
    public string Sampler => Point?.Name ?? "adaptive";

    /// <summary>The name of its image files: <c>jittered-16</c>, <c>adaptive-c0.1-d3</c>, <c>adaptive-guard-c0.1-d3</c>.</summary>
    public string FileStem => Point is { } p
        ? $"{p.Name}-{p.SamplesPerPixel}"
        : FormattableString.Invariant($"adaptive{(Adaptive!.Guard ? "-guard" : "")}-c{Adaptive.Contrast:G6}-d{Adaptive.MaxDepth}");

    /// <summary>The render method of this case.</summary>
    public RenderMethod Method { get; } = Point is not null ? RenderMethod.Sampled(Point) : RenderMethod.Adaptive(Adaptive!);

    /// <summary>Renders the setting into <paramref name="image"/>.</summary>
    /// <param name="renderer">The renderer.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="image">The image to fill.</param>
    /// <returns>Rays traced and render time.</returns>
    public RenderStatistics Render(Renderer renderer, Scene scene, Camera camera, Image image)
    {
        ArgumentNullException.ThrowIfNull(renderer);
        return renderer.Render(scene, camera, Method, image);
    }
}
