using RayLab.Rendering;
using RayLab.Rendering.Exact;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>The exact method's linear values for the tests, through the one door (<see cref="Renderer"/>), or with the row sweep off.</summary>
internal static class ExactLinear
{
    /// <summary>W·H exact linear values, row 0 first, rendered by <see cref="Renderer"/> with <see cref="RenderMethod.Exact"/>.</summary>
    public static Intensity[] Of(Scene scene, Camera camera, int width, int height, int threads = -1)
    {
        var values = new Intensity[(long)width * height];
        new Renderer { MaxDegreeOfParallelism = threads }.Render(scene, camera, RenderMethod.Exact, values, width, height);
        return values;
    }

    /// <summary>The same values with the row sweep on or off (every strip of every row cut afresh).</summary>
    public static Intensity[] Of(Scene scene, Camera camera, int width, int height, int threads, bool sweep) =>
        ExactRenderer.RenderLinear(scene, camera.GetImagePlane(width, height), new RenderOptions(threads, RenderKernel.Scalar, null, default), sweep);
}
