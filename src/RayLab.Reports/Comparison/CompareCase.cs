using RayLab.Sampling;

namespace RayLab.Reports.Comparison;

/// <summary>
/// One setting a comparison renders, as a <see cref="RenderMethod"/>: a point sampler at one budget
/// (<see cref="Sampled"/>, a sampler of your own too), one adaptive setting (<see cref="Adaptive"/>, the lab's rule or the guarded one), or a method of
/// your own (<see cref="Custom"/>).
/// </summary>
/// <param name="Series">Its line on the chart: the sampler's name, <c>adaptive c=0.1</c> for each contrast, or <c>adaptive guard c=0.01</c> for the guarded sampler.</param>
/// <param name="Setting">What varies along the line: <c>16 spp</c>, or <c>depth 0–3</c>.</param>
/// <param name="Budget">The budget asked for (point samplers); a grid sampler uses the nearest square below it.</param>
/// <param name="Method">How the setting renders.</param>
/// <param name="FileStem">The name of its image files: <c>jittered-16</c>, <c>adaptive-c0.1-d3</c>, <c>adaptive-guard-c0.01-d3</c>.</param>
/// <param name="MaxDepth">The adaptive sampler's maximum depth, or null.</param>
/// <param name="Contrast">The adaptive sampler's contrast, or null.</param>
public sealed record CompareCase(string Series, string Setting, int? Budget, RenderMethod Method, string FileStem, int? MaxDepth = null, double? Contrast = null)
{
    /// <summary>A point sampler at the budget asked for.</summary>
    /// <param name="sampler">The sampler, with the samples per pixel it runs at.</param>
    /// <param name="budget">The budget asked for.</param>
    public static CompareCase Sampled(IPixelSampler sampler, int budget)
    {
        ArgumentNullException.ThrowIfNull(sampler);
        return new(sampler.Name, $"{sampler.SamplesPerPixel} spp", budget, RenderMethod.Sampled(sampler), $"{sampler.Name}-{sampler.SamplesPerPixel}");
    }

    /// <summary>One adaptive setting: a line per contrast (and one for the guarded sampler), a point per maximum depth.</summary>
    /// <param name="sampler">The adaptive settings.</param>
    public static CompareCase Adaptive(AdaptiveSampler sampler)
    {
        ArgumentNullException.ThrowIfNull(sampler);
        string guard = sampler.Guard ? " guard" : "";
        return new(FormattableString.Invariant($"adaptive{guard} c={sampler.Contrast:G6}"), $"depth {sampler.MinDepth}–{sampler.MaxDepth}", null,
            RenderMethod.Adaptive(sampler), FormattableString.Invariant($"adaptive{guard.Replace(' ', '-')}-c{sampler.Contrast:G6}-d{sampler.MaxDepth}"), sampler.MaxDepth, sampler.Contrast);
    }

    /// <summary>
    /// A method of your own (a <see cref="RenderMethod.Custom{TScratch}"/> pixel method, or any other method) as one
    /// point of its own line on the chart. A point sampler of your own goes in with <see cref="Sampled"/>.
    /// </summary>
    /// <param name="series">Its line on the chart, e.g. <c>mitchell</c>; settings with the same series join one line.</param>
    /// <param name="setting">What distinguishes this point on the line, e.g. <c>4 → 16</c>.</param>
    /// <param name="method">How the setting renders.</param>
    /// <exception cref="ArgumentException"><paramref name="series"/> or <paramref name="setting"/> is empty.</exception>
    public static CompareCase Custom(string series, string setting, RenderMethod method)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(series);
        ArgumentException.ThrowIfNullOrWhiteSpace(setting);
        ArgumentNullException.ThrowIfNull(method);
        string stem = string.Concat($"{series}-{setting}".Select(ch => char.IsAsciiLetterOrDigit(ch) || ch is '.' or '-' ? ch : '-'));
        return new(series, setting, null, method, stem);
    }

    /// <summary>The sampler's name (<c>jittered</c>, <c>adaptive</c>, …).</summary>
    public string Sampler => Method.Name;

    /// <summary>Samples per pixel of a point sampler; null for the adaptive one.</summary>
    public int? SamplesPerPixel => Method.SamplesPerPixel > 0 ? Method.SamplesPerPixel : null;

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
