using System.Globalization;
using RayLab;
using RayLab.Grading;
using RayLab.Scenes;

namespace MyLab.Tests;

/// <summary>
/// Your method (MyMethod.cs) against the exact image: its error in 8-bit levels (<see cref="ImageError"/>) and its
/// cost in rays per pixel, on the lab's two spheres with both cameras. The method you start with (one ray through the
/// pixel's centre) has an RMSE of about 2 levels at 1 ray per pixel, the lab's adaptive method about 0.28 at 1.1 (see
/// <c>dotnet run</c>). Tighten <see cref="MaxRmse"/> as your method gets better, so that the test keeps it there.
/// Each test writes its figures (RMSE, mean and max error, rays per pixel, time) where <c>dotnet test</c> shows them,
/// passed or failed, and into its failure message; a render that outlasts <see cref="TimeLimit.Limit"/> fails with
/// the pixel MyMethod was on.
/// </summary>
public class MyMethodTests(ITestOutputHelper output)
{
    /// <summary>The largest root-mean-square error, in 8-bit levels, over every pixel and channel.</summary>
    private const double MaxRmse = 2.5;

    /// <summary>The most rays per pixel your method may trace on average: the cost of 16 jittered samples.</summary>
    private const double MaxRaysPerPixel = 16;

    private static readonly SceneDescription File = TwoSpheres.Load();

    public static TheoryData<string> Cameras => ["orthographic", "perspective"];

    /// <summary>
    /// MyMethod uses only what the lab allows (uses.json, the list the grader reads too): RayLab's classes, but not the
    /// exact renderer, and no reflection, native code or processes. Read from the built lab with RayLab.Grading.
    /// </summary>
    [Fact]
    public void MyMethodUsesOnlyWhatTheLabAllows()
    {
        string[] refused = [.. UseList.Load(Path.Combine(AppContext.BaseDirectory, "uses.json"))
            .Check(AssemblyUses.Read(typeof(MyMethod).Assembly.Location)).Select(f => f.Message(polish: false))];
        Assert.True(refused.Length == 0, string.Join("\n", refused));
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void MyMethodIsCloseToTheExactImageAtAStatedCost(string cameraName)
    {
        Camera camera = cameraName == "orthographic" ? TwoSpheres.Orthographic : TwoSpheres.Perspective;
        var exact = new Image(File.Width, File.Height);
        new Renderer().Render(File.Scene, camera, RenderMethod.Exact, exact);

        var image = new Image(File.Width, File.Height);
        var limit = new TimeLimit();
        RenderStatistics stats = limit.Run(() => new Renderer().Render(File.Scene, camera, limit.Method(), image));

        ImageError error = ImageError.Measure(image, exact);
        double raysPerPixel = (double)stats.PrimaryRays / (File.Width * File.Height);
        string figures = string.Create(CultureInfo.InvariantCulture,
            $"{cameraName}: RMSE {error.Rmse:F3}, mean {error.MeanAbsolute:F4}, max {error.Max} levels, {raysPerPixel:F2} rays per pixel, {stats.RenderTime.TotalMilliseconds:F1} ms");
        output.WriteLine(figures);

        Assert.True(error.Rmse <= MaxRmse, string.Create(CultureInfo.InvariantCulture, $"RMSE {error.Rmse:F3} levels > {MaxRmse} ({figures})"));
        Assert.True(raysPerPixel <= MaxRaysPerPixel, string.Create(CultureInfo.InvariantCulture, $"{raysPerPixel:F2} rays per pixel > {MaxRaysPerPixel} ({figures})"));
    }
}
