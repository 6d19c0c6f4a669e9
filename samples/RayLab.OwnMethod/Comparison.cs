using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.OwnMethod;

/// <summary>
/// Renders a scene with the two methods of your own and with plain jittered sampling at equal (or more) rays, and
/// measures each against the exact reference.
/// </summary>
public static class Comparison
{
    /// <summary>Renders and measures: the exact image first, then each method.</summary>
    /// <param name="description">The scene file (its camera; its sampler is ignored).</param>
    /// <returns>Rotated grid 16, jittered 16, Mitchell, and jittered with at least Mitchell's rays per pixel.</returns>
    public static IReadOnlyList<MethodResult> Run(SceneDescription description)
    {
        ArgumentNullException.ThrowIfNull(description);
        PreparedScene prepared = description.Prepare();
        Image exact = prepared.CreateImage();
        new Renderer().Render(prepared.Scene, prepared.Camera, RenderMethod.Exact, exact);

        MethodResult Measure(string name, RenderMethod method)
        {
            Image image = prepared.CreateImage();
            RenderStatistics stats = new Renderer().Render(prepared.Scene, prepared.Camera, method, image);
            return new MethodResult(name, (double)stats.PrimaryRays / (image.Width * image.Height), ImageError.Measure(image, exact), image);
        }

        MethodResult rotated = Measure("rotated-grid 16", RenderMethod.Sampled(new RotatedGridSampler(16)));
        MethodResult jittered = Measure("jittered 16", RenderMethod.Sampled(new JitteredSampler(16, seed: 1)));
        MethodResult mitchell = Measure("mitchell", RenderMethod.Custom(new MitchellMethod()));
        // Jittered needs n² samples: the smallest square with at least Mitchell's rays per pixel.
        int n = (int)Math.Ceiling(Math.Sqrt(mitchell.RaysPerPixel));
        MethodResult jitteredLikeMitchell = Measure($"jittered {n * n}", RenderMethod.Sampled(new JitteredSampler(n * n, seed: 1)));
        return [rotated, jittered, mitchell, jitteredLikeMitchell];
    }
}
