using RayLab;
using RayLab.Sampling;
using RayLab.Scenes;

namespace MyLab.Tests;

/// <summary>Pixels of the lab's picture whose colour is known without rendering: a sphere's colour is its own colour times I_a.</summary>
public class TwoSpheresTests
{
    private static readonly SceneDescription File = TwoSpheres.Load();

    [Fact]
    public void TheRedSpheresCentreHasTheSpheresColourTimesTheAmbient()
    {
        // Where the red sphere's centre (−1.1, 0, 0) lands in the perspective picture.
        (double x, double y) = TwoSpheres.Perspective.GetImagePlane(File.Width, File.Height).ToPixel(new Double3(-1.1, 0, 0));
        int px = (int)x, py = (int)y;

        Image image = Render(TwoSpheres.Perspective);

        // (0.9, 0.2, 0.2) × I_a (1, 1, 1), then int(256·I): 230.4 → 230, 51.2 → 51.
        Assert.Equal(new Rgb24(230, 51, 51), image.GetPixel(px, py));
    }

    [Fact]
    public void TheCornerSeesTheBackground()
    {
        Image image = Render(TwoSpheres.Orthographic);

        // (0.1, 0.1, 0.15): 25.6 → 25, 38.4 → 38.
        Assert.Equal(new Rgb24(25, 25, 38), image.GetPixel(0, 0));
        Assert.Equal(new Rgb24(25, 25, 38), image.GetPixel(File.Width - 1, File.Height - 1));
    }

    /// <summary>The picture as your method renders it, within the time limit (<see cref="TimeLimit"/>).</summary>
    private static Image Render(Camera camera)
    {
        var image = new Image(File.Width, File.Height);
        var limit = new TimeLimit();
        limit.Run(() => new Renderer().Render(File.Scene, camera, limit.Method(), image));
        return image;
    }
}
