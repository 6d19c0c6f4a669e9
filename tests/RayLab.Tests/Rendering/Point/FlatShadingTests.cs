using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Sampling;
using RayLab.Tests.Rendering.Exact;

namespace RayLab.Tests.Rendering.Point;

/// <summary>
/// The flat-shading contract: <see cref="Scene.ColourOf"/> is the scene's whole shading, and the scalar trace,
/// the packet kernel, the adaptive renderer and the exact renderer all take their colours from it. Shading
/// changed in one of them alone makes these tests fail.
/// </summary>
public class FlatShadingTests
{
    private const int W = 64, H = 48;

    // Sphere 1 has radius 0 (the packet kernel leaves it out, so its colour indices shift); ambient is not white.
    // No colour × 256 lies near a whole number, so float and double agree on every level.
    private static Scene MakeScene() => new(
        [
            new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)),
            new Sphere(Double3.Zero, 0, new Intensity(0.5, 0.5, 0.5)),
            new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3)),
            new Sphere(new Double3(0.1, -0.9, 0.8), 0.5, new Intensity(0.3, 0.35, 0.9)),
        ],
        new Intensity(0.1, 0.1, 0.15),
        new Intensity(0.9, 1, 0.8));

    public static TheoryData<string> Cameras() => ["perspective", "orthographic"];

    private static Camera MakeCamera(string name) => name == "perspective"
        ? new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 }
        : new OrthoCamera { Position = new Double3(0.3, 0.5, 6), Target = new Double3(0.1, 0, 0), ViewHeight = 4.2, NearPlane = 0.1, FarPlane = 100 };

    [Fact]
    public void ColourOfIsTheBackgroundOrTheSpheresColourTimesAmbient()
    {
        Scene scene = MakeScene();
        Assert.Equal(scene.Background, scene.ColourOf(-1));
        for (int k = 0; k < scene.Spheres.Count; k++)
        {
            Assert.Equal(scene.Spheres[k].Color * scene.Ambient, scene.ColourOf(k));
        }

        Assert.Equal("sphere", Assert.Throws<ArgumentOutOfRangeException>(() => scene.ColourOf(-2)).ParamName);
        Assert.Equal("sphere", Assert.Throws<ArgumentOutOfRangeException>(() => scene.ColourOf(scene.Spheres.Count)).ParamName);
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void TraceIsTheColourOfTheNearestHit(string camera)
    {
        Scene scene = MakeScene();
        ImagePlane plane = MakeCamera(camera).GetImagePlane(W, H);
        var hit = new HashSet<int>();
        for (int row = 0; row < H; row++)
        {
            for (int x = 0; x < W; x++)
            {
                foreach ((double sx, double sy) in new[] { (0.5, 0.5), (0.1, 0.7), (0.9, 0.2) })
                {
                    Ray ray = plane.GetPixelRay(x, row, sx, sy);
                    int nearest = plane.Nearest(scene, ray);
                    hit.Add(nearest);
                    Assert.Equal(scene.ColourOf(nearest), plane.Trace(scene, ray));
                }
            }
        }

        Assert.Equal([-1, 0, 2, 3], hit.Order());
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void ThePacketFramesColoursAreThePalette(string camera)
    {
        Scene scene = MakeScene();
        Assert.True(PacketFrame.TryCreate(scene, MakeCamera(camera).GetImagePlane(W, H), out PacketFrame? frame, out string? reason), reason);
        Assert.Equal((Float3)ToDouble3(scene.ColourOf(-1)), frame!.Background);
        // Sphere 1 (radius 0) is left out: the frame's spheres are 0, 2 and 3.
        Assert.Equal([.. KeptSpheres.Select(k => (Float3)ToDouble3(scene.ColourOf(k)))], frame.Spheres.Select(sphere => sphere.Colour));
    }

    private static readonly int[] KeptSpheres = [0, 2, 3];

    [Theory]
    [MemberData(nameof(Cameras))]
    public void EveryPointKernelWritesThePaletteColourOfWhatThePixelCentreHits(string camera)
    {
        Scene scene = MakeScene();
        Camera cam = MakeCamera(camera);
        ImagePlane plane = cam.GetImagePlane(W, H);
        foreach (RenderKernel kernel in new[] { RenderKernel.Scalar, RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512 })
        {
            var image = new Image(W, H);
            RenderStatistics stats = new Renderer { Kernel = kernel }.Render(scene, cam, new RegularSampler(1), image);
            Assert.Equal(kernel, stats.Kernel);
            for (int row = 0; row < H; row++)
            {
                for (int x = 0; x < W; x++)
                {
                    int nearest = plane.Nearest(scene, plane.GetPixelRay(x, row, 0.5, 0.5));
                    Assert.True(Rgb24.FromIntensity(scene.ColourOf(nearest)) == image.GetPixel(x, row), $"{kernel}, pixel ({x}, {row}): {image.GetPixel(x, row)}, the palette's colour of {nearest} is {scene.ColourOf(nearest)}");
                }
            }
        }
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void AdaptiveAndExactPixelsInsideOneRegionHaveThatRegionsPaletteColour(string camera)
    {
        Scene scene = MakeScene();
        Camera cam = MakeCamera(camera);
        ImagePlane plane = cam.GetImagePlane(W, H);
        var adaptive = new Image(W, H);
        new Renderer().Render(scene, cam, new AdaptiveSampler(), adaptive);
        Intensity[] exact = ExactLinear.Of(scene, cam, W, H);
        int[,] corner = new int[W + 1, H + 1];
        for (int j = 0; j <= H; j++)
        {
            for (int i = 0; i <= W; i++)
            {
                corner[i, j] = plane.Nearest(scene, plane.GetRayAt(i, j));
            }
        }

        var checkedPixels = new Dictionary<int, int>();
        for (int row = 1; row < H - 1; row++)
        {
            for (int x = 1; x < W - 1; x++)
            {
                // Well inside one region: all 16 corners of the 3×3 pixels around it hit the same thing.
                int id = corner[x, row];
                bool flat = true;
                for (int j = row - 1; j <= row + 2 && flat; j++)
                {
                    for (int i = x - 1; i <= x + 2 && flat; i++)
                    {
                        flat = corner[i, j] == id;
                    }
                }

                if (!flat)
                {
                    continue;
                }

                Intensity colour = scene.ColourOf(id);
                Assert.True(Rgb24.FromIntensity(colour) == adaptive.GetPixel(x, row), $"adaptive pixel ({x}, {row}): {adaptive.GetPixel(x, row)}, the palette's colour of {id} is {colour}");
                Intensity value = exact[(row * W) + x];
                Assert.True(Math.Abs(value.R - colour.R) + Math.Abs(value.G - colour.G) + Math.Abs(value.B - colour.B) <= 1e-9, $"exact pixel ({x}, {row}): {value}, the palette's colour of {id} is {colour}");
                checkedPixels[id] = checkedPixels.GetValueOrDefault(id) + 1;
            }
        }

        Assert.Equal([-1, 0, 2, 3], checkedPixels.Keys.Order());
    }

    private static Double3 ToDouble3(Intensity i) => new(i.R, i.G, i.B);
}
