using RayLab.Scenes;

namespace RayLab.Benchmarks;

/// <summary>
/// The benchmark scene: the lab's two spheres (samples/scenes/two-spheres.json) at 1920×1080, the same scene
/// as the native anchors' benchmarks/anchors/bench-1080.json.
/// </summary>
public static class BenchScene
{
    public const int Width = 1920;
    public const int Height = 1080;

    private static readonly Lazy<SceneDescription> Description = new(() =>
        SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json")) with { Width = Width, Height = Height });

    public static Scene Scene => Description.Value.Scene;

    public static Camera Camera => Description.Value.Camera.CreateCamera();

    /// <summary>The scene with <paramref name="count"/> spheres of radius 0.3 on a jittered grid in front of the camera (deterministic).</summary>
    public static Scene WithSpheres(int count)
    {
        var spheres = new List<Sphere>();
        int side = (int)Math.Ceiling(Math.Sqrt(count));
        for (int i = 0; i < count; i++)
        {
            uint h = Sampling.CounterHash.Hash((uint)i + 12345);
            double jx = Sampling.CounterHash.ToUnit(h) - 0.5, jy = Sampling.CounterHash.ToUnit(Sampling.CounterHash.Hash(h)) - 0.5;
            double x = -2.4 + (4.8 * ((i % side) + 0.5 + (0.3 * jx)) / side);
            double y = -1.6 + (3.2 * ((i / side) + 0.5 + (0.3 * jy)) / side);
            double z = -(i % 3);
            spheres.Add(new Sphere(new Double3(x, y, z), 0.35 * 4 / side, new Intensity(0.2 + (0.6 * (i % 2)), 0.8 - (0.6 * (i % 2)), 0.3)));
        }

        return new Scene(spheres, Scene.Background, Scene.Ambient);
    }
}

/// <summary>
/// The pair every error measure's benchmark compares: the bench scene rendered jittered 16 spp (the reference) against
/// regular 1 spp (the test), at 1920×1080. The measures' work does not depend on the pictures' content.
/// </summary>
public static class BenchPair
{
    /// <summary>The bench scene, jittered 16 spp.</summary>
    public static Image Reference() => PngSizes.Picture();

    /// <summary>The bench scene, regular 1 spp.</summary>
    public static Image Test()
    {
        var image = new Image(BenchScene.Width, BenchScene.Height);
        new Renderer().Render(BenchScene.Scene, BenchScene.Camera, new Sampling.RegularSampler(1), image);
        return image;
    }
}
