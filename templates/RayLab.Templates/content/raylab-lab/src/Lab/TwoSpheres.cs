using RayLab;
using RayLab.Scenes;

namespace MyLab;

/// <summary>The lab's task (section 5): two spheres, seen by an orthographic and a perspective camera.</summary>
public static class TwoSpheres
{
    /// <summary>
    /// The scene file scenes/two-spheres.json: the image size (800×600), the two spheres and their colours, the
    /// background and the ambient intensity I_a. Edit it to change the scene.
    /// </summary>
    /// <returns>The scene file's contents.</returns>
    public static SceneDescription Load() =>
        SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json"));

    /// <summary>
    /// The perspective camera (3.2): the eye e at <see cref="Camera.Position"/>, the gaze g = Target − Position,
    /// the up vector, a vertical field of view of 40°, and the near and far planes.
    /// </summary>
    public static PerspectiveCamera Perspective { get; } = new()
    {
        Name = "perspective",
        Position = new Double3(0, 0.5, 6),
        Target = new Double3(0, 0, 0),
        Up = new Double3(0, 1, 0),
        Fov = 40,
        NearPlane = 0.1,
        FarPlane = 100,
    };

    /// <summary>
    /// The orthographic camera (3.2): the same eye, gaze and up; every ray parallel to the gaze, through a window
    /// 4.2 units high (the width follows from the image's aspect ratio).
    /// </summary>
    public static OrthoCamera Orthographic { get; } = new()
    {
        Name = "orthographic",
        Position = new Double3(0, 0.5, 6),
        Target = new Double3(0, 0, 0),
        Up = new Double3(0, 1, 0),
        ViewHeight = 4.2,
        NearPlane = 0.1,
        FarPlane = 100,
    };
}
