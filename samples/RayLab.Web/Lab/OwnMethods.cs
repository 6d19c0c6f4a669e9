using RayLab.OwnMethod;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Web.Lab;

/// <summary>
/// The sample project's own methods (samples/RayLab.OwnMethod, the own-method guide's code, compiled into the page as
/// they are): the rotated grid, a point sampler, and Mitchell's adaptive contrast test, a pixel method.
/// </summary>
internal static class OwnMethods
{
    /// <summary>Their names, as the method list shows them.</summary>
    public static IReadOnlyList<string> Names { get; } = ["rotated-grid", "mitchell"];

    /// <summary>Whether <paramref name="type"/> names one of them.</summary>
    public static bool IsOwn(string type) => Names.Contains(type);

    /// <summary>The rotated grid's sampler for these settings, or null for a method that is not a point sampler.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A sample count the rotated grid cannot use.</exception>
    public static IPixelSampler? Sampler(SamplerSettings settings) =>
        settings.Type == "rotated-grid" ? new RotatedGridSampler(settings.Samples) : null;

    /// <summary>The method for these settings.</summary>
    /// <exception cref="ArgumentOutOfRangeException">A sample count the rotated grid cannot use.</exception>
    public static RenderMethod Create(SamplerSettings settings) =>
        Sampler(settings) is IPixelSampler sampler ? RenderMethod.Sampled(sampler) : RenderMethod.Custom(new MitchellMethod());
}
