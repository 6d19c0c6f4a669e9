using RayLab.Cameras;

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
    /// Builds and checks the camera and sampler. The camera's image plane is built once, here: its checks and the
    /// exact reference's (which make no outlines) use it, and so does <see cref="PreparedScene.Render"/>. A problem is reported as a
    /// <see cref="SceneFileException"/> naming the scene-file field, even when it came from a combination of
    /// fields (position equal to target, near ≥ far) or from an override.
    /// </summary>
    /// <exception cref="SceneFileException">A setting is out of range or the combination is invalid.</exception>
    public PreparedScene Prepare()
    {
        // Each step's ArgumentException names a parameter of the section being built, which resolves it to a field.
        SceneSection section = SceneSection.Image;
        try
        {
            CheckRange(Width, SceneFile.MaxImageSide, "width");
            CheckRange(Height, SceneFile.MaxImageSide, "height");
            Image.CheckSize(Width, Height);
            section = SceneSection.Camera;
            Camera camera = Camera.CreateCamera();
            ImagePlane plane = camera.GetImagePlane(Width, Height); // the camera's checks, and the plane every render of it uses
            section = SceneSection.Sampler;
            if (!Sampler.IsExact && !Sampler.IsAdaptive)
            {
                CheckRange(Sampler.Samples, SceneFile.MaxSamples, "samples");
            }

            RenderMethod method = Sampler.CreateMethod();
            method.Check(Scene, plane); // what a render would refuse (the exact outlines' checks), without rendering
            return new PreparedScene(this, camera, method) { Prepared = (camera, plane) };
        }
        catch (UnsupportedSceneException e)
        {
            throw new SceneFileException(Source, SceneSection.Sphere(e.SphereIndex).Path, e.Reason, e);
        }
        catch (ArgumentException e)
        {
            throw section.Error(Source, e);
        }
    }

    // The scene file's own limits, for values an override set (the console's --width, --height, --samples), with
    // the reader's message at both ends (not ArgumentOutOfRangeException's "width ('0') must be greater than …").
    private static void CheckRange(int value, int max, string name)
    {
        if (value < 1 || value > max)
        {
            throw new ArgumentOutOfRangeException(name, value, $"must be an integer from 1 to {max}, got {value}");
        }
    }
}

/// <summary>A scene description with its camera and render method built and checked, ready to render.</summary>
/// <param name="Description">The settings it was built from.</param>
/// <param name="Camera">The camera.</param>
/// <param name="Method">How each pixel's value is found: point sampling, adaptive or exact (<see cref="SamplerSettings.CreateMethod"/>).</param>
public sealed record PreparedScene(SceneDescription Description, Camera Camera, RenderMethod Method)
{
    /// <summary>True for the exact reference (<see cref="RenderMethod.Exact"/>).</summary>
    public bool IsExact => Method == RenderMethod.Exact;

    /// <summary>The sampler's name (<c>jittered</c>, <c>adaptive</c>, <c>exact</c>, …).</summary>
    public string SamplerName => Method.Name;

    /// <summary>Samples per pixel of a point sampler; 0 for the adaptive one, whose count varies per pixel, and for the exact reference.</summary>
    public int SamplesPerPixel => Method.SamplesPerPixel;

    /// <summary>Describes the sampler, e.g. <c>jittered 16 spp</c> or <c>adaptive (depth 0–3, contrast 0.1)</c>.</summary>
    public string SamplerDescription => Method.ToString() ?? Method.Name;

    /// <summary>Renders into <paramref name="image"/> by this scene's method.</summary>
    /// <param name="renderer">The renderer (threads, kernel, progress, cancellation).</param>
    /// <param name="image">An image of the described size.</param>
    /// <param name="raysPerPixel">Optional W·H array that receives the rays charged to each pixel.</param>
    /// <returns>Rays traced and render time.</returns>
    public RenderStatistics Render(Renderer renderer, Image image, float[]? raysPerPixel = null)
    {
        ArgumentNullException.ThrowIfNull(renderer);
        ArgumentNullException.ThrowIfNull(image);
        // The plane Prepare built, while the camera is still the one it was built from (not replaced by `with`).
        return Prepared is ({ } camera, { } plane) && ReferenceEquals(camera, Camera) && plane.Width == image.Width && plane.Height == image.Height
            ? renderer.Render(Scene, plane, Method, image, raysPerPixel)
            : renderer.Render(Scene, Camera, Method, image, raysPerPixel);
    }

    /// <summary>The camera <see cref="SceneDescription.Prepare"/> built, and its image plane.</summary>
    internal (Camera Camera, ImagePlane Plane)? Prepared { get; init; }

    /// <summary>The scene.</summary>
    public Scene Scene => Description.Scene;

    /// <summary>A new black image of the described size.</summary>
    public Image CreateImage() => new(Description.Width, Description.Height);
}
