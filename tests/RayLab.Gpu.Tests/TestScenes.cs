namespace RayLab.Gpu.Tests;

/// <summary>The golden set's scene and cameras (tests/RayLab.Tests/Golden), so the device's bytes can be checked against it.</summary>
internal static class TestScenes
{
    public static Scene TwoSpheres() => new(
        [
            new Sphere(new Double3(-0.9, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)),
            new Sphere(new Double3(1.1, 0.3, -1), 1.2, new Intensity(0.2, 0.8, 0.3)),
            new Sphere(new Double3(0.2, -0.6, 1.5), 0.05, new Intensity(0.3, 0.3, 0.95)),
        ],
        new Intensity(0.1, 0.1, 0.15),
        new Intensity(0.9, 0.95, 1));

    public static readonly IReadOnlyDictionary<string, Camera> Cameras = new Dictionary<string, Camera>
    {
        ["ortho"] = new OrthoCamera { Position = new Double3(0, 0.2, 6), Target = Double3.Zero, ViewHeight = 4.5, NearPlane = 0.1, FarPlane = 100 },
        ["persp"] = new PerspectiveCamera { Position = new Double3(0.3, 0.5, 6), Target = Double3.Zero, Fov = 45, NearPlane = 0.1, FarPlane = 100 },
        ["offaxis"] = new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = new Double3(0, 0.1, 0), Up = new Double3(0.1, 1, 0), Distance = 2, Window = new Window(-1.5, -0.4, 0.9, 1.1), NearPlane = 0.1, FarPlane = 100 },
        ["ortho-offaxis"] = new OrthoCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero, Window = new Window(-2.5, -1.2, 1.5, 2.1), NearPlane = 0.1, FarPlane = 100 },
    };

    /// <summary>samples/scenes/sphere-field.json: 960 spheres, traced through the scene's hierarchy.</summary>
    public static readonly Lazy<Scene> SphereField = new(() =>
        Scenes.SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "sphere-field.json")).Prepare().Description.Scene);

    /// <summary>The field's own camera and an orthographic one from above and behind.</summary>
    public static readonly IReadOnlyDictionary<string, Camera> FieldCameras = new Dictionary<string, Camera>
    {
        ["persp"] = new PerspectiveCamera { Position = new Double3(0, 1.2, 4), Target = new Double3(0, 0, -60), Fov = 30, NearPlane = 0.1, FarPlane = 1000 },
        ["ortho"] = new OrthoCamera { Position = new Double3(3, 12, 12), Target = new Double3(0, 0, -12), ViewHeight = 24, NearPlane = 0.1, FarPlane = 1000 },
    };
}
