using System.Diagnostics;
using System.Globalization;
using RayLab;
using RayLab.Sampling;
using RayLab.Scenes;

namespace MyLab;

/// <summary>
/// Lab II, section 5: renders the two spheres with both cameras, once with the lab's adaptive antialiasing and once
/// with your own method (MyMethod.cs); prints each render's rays, time and error against the exact image; writes the
/// pictures into out/, and the lab's obrazkoncowy.jpg. A small warm-up render comes first, timed apart and not counted:
/// the first render of a run pays for the JIT. A render that outlasts the time limit (60 s, or LAB_TIME_LIMIT_S
/// seconds) stops the run with the rows it had finished, instead of leaving it silent.
/// </summary>
internal static class Program
{
    private static void Main()
    {
        SceneDescription file = TwoSpheres.Load();
        Scene scene = file.Scene;                  // the spheres, the background and the ambient intensity I_a
        int width = file.Width, height = file.Height;
        Console.WriteLine($"two spheres, {width}×{height}, ambient I_a = {scene.Ambient}");

        // The lab's adaptive antialiasing (4.1.4): the pixel's corners and centre, split where two values differ by
        // more than the contrast, at most 3 levels deep.
        RenderMethod adaptive = RenderMethod.Adaptive(new AdaptiveSampler(minDepth: 0, maxDepth: 3, contrast: 0.05));
        // Your own method (MyMethod.cs).
#if (Sampler)
        RenderMethod mine = RenderMethod.Sampled(new MyMethod());
#else
        RenderMethod mine = RenderMethod.Custom(new MyMethod());
#endif

        Directory.CreateDirectory("out");
        var progress = new RenderProgress(); // the rows each render has finished, for the time limit below
        var renderer = new Renderer { Progress = progress };

        // The first render of a run pays for the JIT: a small one with each camera and method first, timed apart and named.
        var warmUp = Stopwatch.StartNew();
        foreach (Camera camera in new Camera[] { TwoSpheres.Orthographic, TwoSpheres.Perspective })
        {
            renderer.Render(scene, camera, adaptive, new Image(80, 60));
            Watched($"the warm-up's {camera.Name} mymethod", progress, () => renderer.Render(scene, camera, mine, new Image(80, 60)));
        }

        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"warm-up (80×60, both cameras, both methods, not counted) {warmUp.Elapsed.TotalMilliseconds:F1} ms"));

        foreach (Camera camera in new Camera[] { TwoSpheres.Orthographic, TwoSpheres.Perspective })
        {
            // The exact reference: each pixel's exact area-weighted colour, what every antialiasing method aims at.
            var exact = new Image(width, height);
            renderer.Render(scene, camera, RenderMethod.Exact, exact);
            exact.Save($"out/two-spheres-{camera.Name}-exact.png");

            foreach ((string name, RenderMethod method) in new[] { ("adaptive", adaptive), ("mymethod", mine) })
            {
                var image = new Image(width, height);
                RenderStatistics stats = Watched($"{camera.Name} {name}", progress, () => renderer.Render(scene, camera, method, image));
                ImageError error = ImageError.Measure(image, exact);
                string path = $"out/two-spheres-{camera.Name}-{name}.png";
                image.Save(path);
                Console.WriteLine(
                    $"{camera.Name,-12} {name,-8} {stats.PrimaryRays,10:N0} rays ({(double)stats.PrimaryRays / (width * height),5:F2} per pixel) "
                    + $"{stats.RenderTime.TotalMilliseconds,8:F1} ms   error against exact: RMSE {error.Rmse:F3}, max {error.Max} levels   {path}");
                if (camera == TwoSpheres.Perspective && name == "adaptive")
                {
                    image.Save("out/obrazkoncowy.jpg"); // the lab's own file name (2.2)
                }
            }
        }

        Console.WriteLine("wrote out/obrazkoncowy.jpg");
    }

    /// <summary>
    /// Runs <paramref name="render"/> with the time limit: past it, the run stops (exit code 1) and says how many
    /// rows <paramref name="progress"/> had counted, so a method that never returns is named, not silent.
    /// </summary>
    private static RenderStatistics Watched(string what, RenderProgress progress, Func<RenderStatistics> render)
    {
        TimeSpan limit = double.TryParse(Environment.GetEnvironmentVariable("LAB_TIME_LIMIT_S"), NumberStyles.Float, CultureInfo.InvariantCulture, out double seconds) && seconds > 0
            ? TimeSpan.FromSeconds(seconds)
            : TimeSpan.FromSeconds(60);
        using var watchdog = new Timer(_ =>
        {
            Console.Error.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"Time limit of {limit.TotalSeconds:0.#} s passed: {what} did not finish (an endless loop in MyMethod?). {progress.RowsCompleted} of {progress.TotalRows} rows were done; dotnet test names the pixel."));
            Environment.Exit(1);
        }, null, limit, Timeout.InfiniteTimeSpan);
        return render();
    }
}
