using RayLab;
using RayLab.Rendering.Exact;
using RayLab.Sampling;
using RayLab.Scenes;
using Xunit.Sdk;

namespace MyLab.Tests;

/// <summary>
/// Your method (MyMethod.cs) against the exact image: its error in 8-bit levels (<see cref="ImageError"/>) and its
/// cost in rays per pixel, on the lab's two spheres with both cameras. The method you start with (one ray through the
/// pixel's centre) has an RMSE of about 2 levels at 1 ray per pixel, the lab's adaptive method about 0.28 at 1.1 (see
/// <c>dotnet run</c>). Tighten <see cref="MaxRmse"/> as your method gets better, so that the test keeps it there.
/// </summary>
public class MyMethodTests
{
    /// <summary>The largest root-mean-square error, in 8-bit levels, over every pixel and channel.</summary>
    private const double MaxRmse = 2.5;

    /// <summary>The most rays per pixel your method may trace on average: the cost of 16 jittered samples.</summary>
    private const double MaxRaysPerPixel = 16;

    private static readonly SceneDescription File = TwoSpheres.Load();

    public static TheoryData<string> Cameras => ["orthographic", "perspective"];

    [Theory]
    [MemberData(nameof(Cameras))]
    public void MyMethodIsCloseToTheExactImageAtAStatedCost(string cameraName)
    {
        Camera camera = cameraName == "orthographic" ? TwoSpheres.Orthographic : TwoSpheres.Perspective;
        var exact = new Image(File.Width, File.Height);
        new ExactRenderer().Render(File.Scene, camera, exact);

        var image = new Image(File.Width, File.Height);
#if (Sampler)
        RenderStatistics stats = new Renderer().Render(File.Scene, camera, RenderMethod.Sampled(new MyMethod()), image);
#else
        RenderStatistics stats = new Renderer().Render(File.Scene, camera, RenderMethod.Custom(new MyMethod()), image);
#endif

        ImageError error = ImageError.Measure(image, exact);
        double raysPerPixel = (double)stats.PrimaryRays / (File.Width * File.Height);
        TestContext.Current.SendDiagnosticMessage(
            $"{cameraName}: RMSE {error.Rmse:F3}, mean {error.MeanAbsolute:F4}, max {error.Max} levels, {raysPerPixel:F2} rays per pixel");

        Assert.True(error.Rmse <= MaxRmse, $"RMSE {error.Rmse:F3} levels > {MaxRmse}");
        Assert.True(raysPerPixel <= MaxRaysPerPixel, $"{raysPerPixel:F2} rays per pixel > {MaxRaysPerPixel}");
    }
}
