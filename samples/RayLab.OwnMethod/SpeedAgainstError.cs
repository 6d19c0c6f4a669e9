using RayLab.Reports.Comparison;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.OwnMethod;

/// <summary>
/// The speed-against-error report (the one <c>raylab compare</c> writes) with your two methods beside jittered:
/// <c>results.md</c>, <c>results.csv</c>, two log-log charts, every image and error image, and <c>index.html</c>.
/// </summary>
public static class SpeedAgainstError
{
    /// <summary>Compares jittered, the rotated grid and Mitchell's method on the scene and writes the report.</summary>
    /// <param name="description">The scene file (its camera; its sampler is ignored).</param>
    /// <param name="folder">The report's folder (created if missing).</param>
    /// <param name="width">Image width for the report.</param>
    /// <param name="height">Image height for the report.</param>
    /// <returns>The report that was written.</returns>
    public static CompareReport Write(SceneDescription description, string folder, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(description);
        PreparedScene prepared = (description with { Width = width, Height = height }).Prepare();
        CompareCase[] cases =
        [
            CompareCase.Sampled(new JitteredSampler(4, seed: 1), 4),
            CompareCase.Sampled(new JitteredSampler(16, seed: 1), 16),
            CompareCase.Sampled(new RotatedGridSampler(16), 16),
            CompareCase.Custom("mitchell", "4 → 16", RenderMethod.Custom(new MitchellMethod())),
        ];
        return CompareRunner.Run(prepared.Scene, prepared.Camera, width, height, cases, folder, new CompareSettings(Repeats: 1));
    }
}
