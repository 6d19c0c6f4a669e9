using RayLab.Cameras;
using RayLab.Sampling;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>
/// The exact reference against brute force: <see cref="Renderer"/> with a regular 64×64 grid per pixel
/// (<see cref="RegularSampler"/>(4096)), on small scenes that exercise every kind of border. Each pixel must agree
/// within the grid's own error bound, <c>D · m / 64²</c> per channel (<see cref="GridErrorBound"/>): D the largest
/// difference between two of the scene's colours, m the number of the pixel's 4096 cells a border touches.
/// </summary>
public class ExactBruteForceTests
{
    private readonly ITestOutputHelper _output;

    public ExactBruteForceTests(ITestOutputHelper output) => _output = output;

    private static readonly Intensity Background = new(0.1, 0.1, 0.15);
    private static readonly Intensity Red = new(0.9, 0.2, 0.2);
    private static readonly Intensity Green = new(0.2, 0.8, 0.3);
    private static readonly Intensity Blue = new(0.25, 0.35, 0.95);

    public static TheoryData<string> Scenes => new(SceneNames);

    private static readonly string[] SceneNames =
    [
        "lab, perspective", "lab, orthographic", "meeting spheres, off-axis window", "same depth, orthographic",
        "near plane reveals an inner sphere", "far plane cuts", "three spheres, tilted camera",
    ];

    [Theory]
    [MemberData(nameof(Scenes))]
    public void EveryPixelIsWithinTheGridsErrorBound(string name)
    {
        (Scene scene, Camera camera, int w, int h) = Build(name);
        const int n = 64;
        ImagePlane plane = camera.GetImagePlane(w, h);

        Intensity[] exact = ExactLinear.Of(scene, camera, w, h);
        int[] touched = GridErrorBound.TouchedCells(scene, plane, n);
        Intensity spread = GridErrorBound.LargestColourDifference(scene);

        var grids = new Intensity[w * h];
        new Renderer { Kernel = RenderKernel.Scalar }.Render(scene, camera, RenderMethod.Sampled(new RegularSampler(n * n)), grids, w, h);
        double worst = 0, worstShare = 0;
        int edges = 0;
        for (int row = 0; row < h; row++)
        {
            for (int x = 0; x < w; x++)
            {
                Intensity grid = grids[(row * w) + x];
                Intensity e = exact[(row * w) + x];
                double cells = touched[(row * w) + x] / (double)(n * n);
                edges += cells > 0 ? 1 : 0;
                foreach ((double g, double v, double d) in new[] { (grid.R, e.R, spread.R), (grid.G, e.G, spread.G), (grid.B, e.B, spread.B) })
                {
                    double bound = (d * cells) + 1e-12;
                    Assert.True(Math.Abs(g - v) <= bound, $"{name}: pixel ({x}, {row}): grid {grid}, exact {e}, bound {bound:G3}");
                    worst = Math.Max(worst, Math.Abs(g - v));
                    worstShare = Math.Max(worstShare, Math.Abs(g - v) / bound);
                }
            }
        }

        _output.WriteLine($"{name}: {edges} pixels touched by a border; largest |grid − exact| {worst:E2}, at most {worstShare:P0} of its bound");
        Assert.True(edges > 0, "the scene has borders in view");
    }

    private static (Scene Scene, Camera Camera, int Width, int Height) Build(string name)
    {
        var lab = new Scene([new Sphere(new Double3(-1.1, 0, 0), 1, Red), new Sphere(new Double3(1.2, 0.2, -1), 1.2, Green)], Background, Intensity.White);
        switch (name)
        {
            case "lab, perspective":
                return (lab, new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 }, 32, 24);
            case "lab, orthographic":
                return (lab, new OrthoCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, ViewHeight = 4.2, NearPlane = 0.1, FarPlane = 100 }, 32, 24);
            case "meeting spheres, off-axis window":
                // Two spheres that cut into each other: the border between them is their circle of intersection.
                return (new Scene([new Sphere(new Double3(-0.4, 0, 0), 1, Red), new Sphere(new Double3(0.5, 0.3, -0.4), 0.9, Green)], Background, new Intensity(0.9, 1, 0.8)),
                    new PerspectiveCamera { Position = new Double3(0.5, 1, 5), Target = Double3.Zero, NearPlane = 0.1, FarPlane = 100, Window = new Window(-0.35, -0.3, 0.45, 0.25) }, 28, 20);
            case "same depth, orthographic":
                // Equal spheres side by side at one depth: their circle of intersection is seen edge-on, a segment.
                return (new Scene([new Sphere(new Double3(-0.5, 0, 0), 1, Red), new Sphere(new Double3(0.5, 0, 0), 1, Blue)], Background, Intensity.White),
                    new OrthoCamera { Position = new Double3(0, 0, 5), Target = Double3.Zero, ViewHeight = 2.6, NearPlane = 0, FarPlane = 100 }, 30, 20);
            case "near plane reveals an inner sphere":
                // The near plane cuts the big sphere open; through the cut the small sphere inside it shows.
                return (new Scene([new Sphere(new Double3(0, 0, 0), 1.5, Red), new Sphere(new Double3(0.2, 0.1, -0.3), 0.6, Blue)], Background, Intensity.White),
                    new PerspectiveCamera { Position = new Double3(0, 0, 4), Target = Double3.Zero, Fov = 50, NearPlane = 3.2, FarPlane = 100 }, 24, 24);
            case "far plane cuts":
                // The far plane slices the back sphere: beyond it, the background shows.
                return (lab, new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 6.6 }, 32, 24);
            case "three spheres, tilted camera":
                return (new Scene(
                        [new Sphere(new Double3(-1.1, 0, 0), 1, Red), new Sphere(new Double3(0.2, 0.3, -0.5), 0.8, Green), new Sphere(new Double3(0.9, -0.4, 0.6), 0.5, Blue)],
                        Background, Intensity.White),
                    new PerspectiveCamera { Position = new Double3(1.5, 2, 5), Target = new Double3(0, 0, -0.3), Up = new Double3(0.3, 1, 0), Fov = 45, NearPlane = 0.1 }, 30, 22);
            default:
                throw new ArgumentException(name, nameof(name));
        }
    }
}
