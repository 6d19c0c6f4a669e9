
namespace RayLab.Scenes;

/// <summary>
/// A scene file's <c>camera</c> object. It keeps the settings of both projections (<c>fov</c> for perspective,
/// <c>height</c> for orthographic), so one file can be rendered with either camera.
/// </summary>
/// <param name="Type"><c>perspective</c> or <c>orthographic</c>.</param>
/// <param name="Position">The eye.</param>
/// <param name="Target">The point looked at.</param>
/// <param name="Up">The up vector.</param>
/// <param name="Fov">Vertical field of view in degrees (perspective).</param>
/// <param name="Height">View height in world units (orthographic).</param>
/// <param name="Near">Near plane.</param>
/// <param name="Far">Far plane.</param>
/// <param name="Distance">Plane distance s (perspective).</param>
/// <param name="Window">Explicit window u0, v0, u1, v1, or null for the one from fov/height.</param>
public sealed record CameraSettings(
    string Type, Double3 Position, Double3 Target, Double3 Up, double Fov, double Height,
    double Near, double Far, double Distance, Window? Window)
{
    /// <summary>The camera type names.</summary>
    public static IReadOnlyList<string> Types { get; } = ["perspective", "orthographic"];

    /// <summary>The fields of a scene file's <c>camera</c> object.</summary>
    public static IReadOnlyList<string> Fields { get; } = ["type", "position", "target", "up", "fov", "height", "near", "far", "distance", "window"];

    /// <summary>
    /// The <c>camera</c> field that sets a camera property (<c>NearPlane</c> → <c>near</c>), or null for a name
    /// that is no camera property: the one map from the camera's names to the file's, so that an error a camera
    /// reports about a property names the field to change.
    /// </summary>
    /// <param name="property">A property of <see cref="Camera"/>, <see cref="PerspectiveCamera"/> or <see cref="OrthoCamera"/> (an exception's parameter name).</param>
    public static string? FieldOf(string property) => property switch
    {
        nameof(Camera.Name) or nameof(Type) => "type",
        nameof(Camera.Position) => "position",
        nameof(Camera.Target) => "target",
        nameof(Camera.Up) => "up",
        nameof(Camera.Fov) => "fov",
        nameof(OrthoCamera.ViewHeight) => "height",
        nameof(Camera.NearPlane) => "near",
        nameof(Camera.FarPlane) => "far",
        nameof(PerspectiveCamera.Distance) => "distance",
        nameof(Camera.Window) => "window",
        _ => null,
    };

    /// <summary>
    /// Checks every setting by building the camera of each type: a file keeps the settings of both projections
    /// and may be rendered with either (the console's <c>--camera</c>).
    /// </summary>
    /// <exception cref="ArgumentException">A setting is out of range (the parameter names the camera property).</exception>
    public void Check()
    {
        foreach (string type in Types)
        {
            _ = (this with { Type = type }).CreateCamera();
        }
    }

    /// <summary>Creates the camera these settings describe.</summary>
    /// <exception cref="ArgumentException">A setting is out of range (the parameter names the camera property).</exception>
    public Camera CreateCamera() => Type switch
    {
        "perspective" => new PerspectiveCamera
        {
            Name = Type, Position = Position, Target = Target, Up = Up, Fov = Fov,
            NearPlane = Near, FarPlane = Far, Distance = Distance, Window = Window,
        },
        "orthographic" => new OrthoCamera
        {
            Name = Type, Position = Position, Target = Target, Up = Up,
            NearPlane = Near, FarPlane = Far, ViewHeight = Height, Window = Window,
        },
        _ => throw new ArgumentException($"Unknown camera '{Type}'; expected one of: {string.Join(", ", Types)}.", nameof(Type)),
    };
}
