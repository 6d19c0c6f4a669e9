using RayLab.Cameras;
using RayLab.Imaging;
using RayLab.Sampling;

namespace RayLab.Scenes;

/// <summary>
/// Everything a scene file says: the image size, the scene, and the camera and sampler settings. Change a
/// setting with a <c>with</c> expression (as the console's options do), then call <see cref="Prepare"/>.
/// </summary>
/// <param name="Source">The file it came from (for messages).</param>
/// <param name="Width">Image width.</param>
/// <param name="Height">Image height.</param>
/// <param name="Scene">The spheres, background and ambient.</param>
/// <param name="Camera">The camera settings.</param>
/// <param name="Sampler">The sampler settings.</param>
public sealed record SceneDescription(
    string Source, int Width, int Height, Scene Scene, CameraSettings Camera, SamplerSettings Sampler)
{
    /// <summary>
    /// Builds and checks the camera, sampler and image plane. A problem is reported as a
    /// <see cref="SceneFileException"/> naming the scene-file field, even when it came from a combination of
    /// fields (position equal to target, near ≥ far) or from an override.
    /// </summary>
    /// <exception cref="SceneFileException">A setting is out of range or the combination is invalid.</exception>
    public PreparedScene Prepare()
    {
        string field = "image";
        try
        {
            Image.CheckSize(Width, Height);
            field = "camera";
            Camera camera = Camera.CreateCamera();
            camera.GetImagePlane(Width, Height);
            field = "sampler";
            IPixelSampler sampler = Sampler.CreateSampler();
            return new PreparedScene(this, camera, sampler);
        }
        catch (ArgumentException e)
        {
            throw new SceneFileException(Source, FieldOf(field, e.ParamName), FirstLine(e.Message), e);
        }
    }

    private static string FieldOf(string section, string? param) => (section, param) switch
    {
        ("image", "height") => "image.height",
        ("image", _) => "image.width",
        ("camera", "Target") => "camera.target",
        ("camera", "Up") => "camera.up",
        ("camera", "NearPlane") => "camera.near",
        ("camera", "FarPlane") => "camera.far",
        ("camera", "Fov") => "camera.fov",
        ("camera", "ViewHeight") => "camera.height",
        ("camera", "Distance") => "camera.distance",
        ("camera", "Window" or "window") => "camera.window",
        ("camera", "Type") => "camera.type",
        ("sampler", "name") => "sampler.type",
        ("sampler", _) => "sampler.samples",
        _ => section,
    };

    // ArgumentException appends " (Parameter 'x')": the field name already says that.
    private static string FirstLine(string message)
    {
        int at = message.IndexOf(" (Parameter '", StringComparison.Ordinal);
        return at >= 0 ? message[..at] : message;
    }
}

/// <summary>A scene description with its camera and sampler built and checked, ready to render.</summary>
/// <param name="Description">The settings it was built from.</param>
/// <param name="Camera">The camera.</param>
/// <param name="Sampler">The sampler.</param>
public sealed record PreparedScene(SceneDescription Description, Camera Camera, IPixelSampler Sampler)
{
    /// <summary>The scene.</summary>
    public Scene Scene => Description.Scene;

    /// <summary>A new black image of the described size.</summary>
    public Image CreateImage() => new(Description.Width, Description.Height);
}
