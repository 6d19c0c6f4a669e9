using RayLab.Scenes;

namespace RayLab.OwnMethod;

/// <summary>
/// Your own antialiasing method: a rotated-grid point sampler and Mitchell's adaptive contrast test, each rendered
/// on the lab's two-sphere scene and measured against the exact reference beside plain jittered sampling; then the speed-against-error report with both.
/// </summary>
internal static class Program
{
    private static void Main()
    {
        SceneDescription scene = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json"));
        Directory.CreateDirectory("out");
        foreach (MethodResult result in Comparison.Run(scene))
        {
            Console.WriteLine(result);
            result.Image.Save(Path.Combine("out", result.Name.Replace(' ', '-') + ".png"));
        }

        SpeedAgainstError.Write(scene, Path.Combine("out", "report"), 200, 150);
        Console.WriteLine($"wrote {Path.Combine("out", "report", "index.html")}");
    }
}
