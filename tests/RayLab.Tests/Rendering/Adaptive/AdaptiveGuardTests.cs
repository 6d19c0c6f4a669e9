using RayLab.Sampling;
using RayLab.Cameras;
using RayLab.Rendering.Adaptive;

namespace RayLab.Tests.Rendering.Adaptive;

public class AdaptiveGuardTests
{
    private static Camera CameraFor(string view) => view switch
    {
        "orthographic" => new OrthoCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Window = new Window(-3, -2.25, 3, 2.25) },
        "off-axis" => new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Window = new Window(-0.05, -0.3, 0.55, 0.15), NearPlane = 0.1, FarPlane = 100 },
        _ => new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 },
    };

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15), Intensity.White);

    /// <summary>
    /// A sphere seen <paramref name="pixels"/> pixels across, centred at image point (<paramref name="x"/>, <paramref name="y"/>)
    /// (in pixels from the top-left corner), <paramref name="distance"/> along the ray through that point.
    /// </summary>
    private static Sphere SphereAt(ImagePlane plane, double x, double y, double pixels, double distance, Intensity colour)
    {
        Ray ray = plane.GetRay(x / plane.Width, 1 - (y / plane.Height));
        Double3 d = ray.Direction * (1 / ray.Direction.Length);
        double pixel = plane.A.Length / plane.Width;
        double radius = plane.IsOrthographic ? 0.5 * pixels * pixel : distance * 0.5 * pixels * pixel / ray.Direction.Length;
        return new Sphere(ray.Origin + (distance * d), radius, colour);
    }

    private static (Image Image, long Rays) Render(Scene scene, Camera camera, AdaptiveSampler sampler, int w, int h, RenderKernel kernel = RenderKernel.Auto)
    {
        var image = new Image(w, h);
        long rays = new Renderer { Kernel = kernel, MaxDegreeOfParallelism = 2 }.Render(scene, camera, sampler, image).PrimaryRays;
        return (image, rays);
    }

    private static Image Exact(Scene scene, Camera camera, int w, int h)
    {
        var image = new Image(w, h);
        new Renderer().Render(scene, camera, RenderMethod.Exact, image);
        return image;
    }

    [Theory]
    [InlineData("orthographic", 0.5, 0.5)]
    [InlineData("orthographic", 0.27, 0.71)]
    [InlineData("orthographic", 0.5, 0.2)]
    [InlineData("perspective", 0.5, 0.5)]
    [InlineData("perspective", 0.77, 0.31)]
    [InlineData("perspective", 0.25, 0.25)]
    [InlineData("off-axis", 0.63, 0.42)]
    [InlineData("off-axis", 0.18, 0.8)]
    public void ASphereAFifthOfAPixelAcrossVanishesUnderTheLabsRuleAndTheGuardFindsIt(string view, double ox, double oy)
    {
        Camera camera = CameraFor(view);
        const int W = 8, H = 6;
        ImagePlane plane = camera.GetImagePlane(W, H);
        var scene = new Scene([SphereAt(plane, 3 + ox, 2 + oy, 0.2, 5, Intensity.White)], Intensity.Black, Intensity.White);
        Image exact = Exact(scene, camera, W, H);
        Assert.True(exact.GetPixel(3, 2).R > 0, "the sphere covers part of pixel (3, 2)");

        (Image lab, _) = Render(scene, camera, new AdaptiveSampler(0, 5, 0.01), W, H);
        Assert.Equal(0, lab.GetPixel(3, 2).R);

        foreach (RenderKernel kernel in new[] { RenderKernel.Auto, RenderKernel.Scalar })
        {
            (Image guarded, _) = Render(scene, camera, new AdaptiveSampler(0, 5, 0.01, guard: true), W, H, kernel);
            Assert.True(guarded.GetPixel(3, 2).R > 0, $"the guard finds the sphere ({kernel})");
            Assert.InRange(ImageError.Measure(guarded, exact).Max, 0, 3);
        }
    }

    public static TheoryData<string, string> HardPlacements => new()
    {
        { "tangent to a pixel edge", "orthographic" },
        { "tangent to a pixel edge", "perspective" },
        { "tangent to a pixel edge", "off-axis" },
        { "two spheres crossing inside one pixel", "orthographic" },
        { "two spheres crossing inside one pixel", "perspective" },
        { "two spheres crossing inside one pixel", "off-axis" },
    };

    [Theory]
    [MemberData(nameof(HardPlacements))]
    public void OnHardPlacementsTheGuardedPictureIsWithinAFewLevelsOfTheExactOne(string placement, string view)
    {
        Camera camera = CameraFor(view);
        const int W = 8, H = 6;
        ImagePlane plane = camera.GetImagePlane(W, H);
        Scene scene = placement switch
        {
            // 0.6 px across, its silhouette touching the line between rows 1 and 2 from below, between traced points.
            "tangent to a pixel edge" => new Scene([SphereAt(plane, 3.37, 2.3, 0.6, 5, new Intensity(0.9, 0.7, 0.2))], Intensity.Black, Intensity.White),
            // Two spheres 0.4 px across, overlapping inside pixel (4, 3), one in front of the other.
            _ => new Scene([SphereAt(plane, 4.35, 3.4, 0.4, 5, new Intensity(1, 0, 0)), SphereAt(plane, 4.62, 3.55, 0.4, 5.3, new Intensity(0, 0, 1))], new Intensity(0.1, 0.1, 0.1), Intensity.White),
        };
        Image exact = Exact(scene, camera, W, H);
        (Image lab, _) = Render(scene, camera, new AdaptiveSampler(0, 5, 0.01), W, H);
        (Image guarded, _) = Render(scene, camera, new AdaptiveSampler(0, 5, 0.01, guard: true), W, H);
        (Image scalar, _) = Render(scene, camera, new AdaptiveSampler(0, 5, 0.01, guard: true), W, H, RenderKernel.Scalar);
        Assert.Equal(scalar.PixelBytes.ToArray(), guarded.PixelBytes.ToArray());
        ImageError error = ImageError.Measure(guarded, exact);
        Assert.InRange(error.Max, 0, 3);
        Assert.True(error.Rmse <= ImageError.Measure(lab, exact).Rmse, "the guard is no worse than the lab's rule");
    }

    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void GuardedAtDepth5TheTwoSphereSceneIsWithinAThirdOfALevelForEightRaysAPixel(string view)
    {
        Camera camera = CameraFor(view);
        const int W = 200, H = 150;
        Image exact = Exact(TwoSpheres(), camera, W, H);
        (Image guarded, long rays) = Render(TwoSpheres(), camera, new AdaptiveSampler(0, 5, 0.01, guard: true), W, H);
        ImageError error = ImageError.Measure(guarded, exact);
        float[] perPixel = ImageError.PerPixel(guarded, exact);
        double over2 = perPixel.Count(e => e > 2) / (double)perPixel.Length;
        Assert.True(error.Rmse <= 0.35, $"RMSE {error.Rmse:F3} levels");
        Assert.True(over2 <= 0.003, $"{over2:P2} of pixels more than 2 levels off");
        Assert.True(rays <= 8L * W * H, $"{(double)rays / (W * H):F2} rays per pixel");
    }

    [Theory]
    [InlineData("orthographic")]
    [InlineData("perspective")]
    [InlineData("off-axis")]
    public void InASphereFieldEverySquareTestingItsTilesSpheresGetsTheAnswerOfEverySphere(string view)
    {
        // Enough spheres for tiles, of every size from a tenth of a pixel to a fifth of the view, one cut by the
        // near plane (a one-sided test), on an image whose width and height are not whole tiles.
        Camera camera = CameraFor(view);
        const int W = 45, H = 29, MaxDepth = 3;
        ImagePlane plane = camera.GetImagePlane(W, H);
        var random = new Random(7);
        var spheres = new List<Sphere>();
        for (int i = 0; i < 3 * SilhouetteGuard.TiledFrom; i++)
        {
            double pixels = Math.Pow(10, (random.NextDouble() * 2.3) - 1);
            spheres.Add(SphereAt(plane, (random.NextDouble() * 1.2 * W) - (0.1 * W), (random.NextDouble() * 1.2 * H) - (0.1 * H), pixels, 1 + (random.NextDouble() * 12), Intensity.White));
        }

        spheres.Add(new Sphere(new Double3(0.04, 0.5, 5.89), 0.03, Intensity.White));
        var scene = new Scene(spheres, Intensity.Black, Intensity.White);
        const long Size = 1L << (MaxDepth + 1);
        var tiled = new SilhouetteGuard(scene, plane, Size);
        var every = new SilhouetteGuard(scene, plane, Size, tiles: false);
        int squares = 0, crossed = 0;
        void Check(long x0, long y0, long size)
        {
            bool expected = every.MayCross(x0, y0, size);
            Assert.True(expected == tiled.MayCross(x0, y0, size), $"square ({x0}, {y0}) of {size} steps: every sphere says {expected}");
            squares++;
            crossed += expected ? 1 : 0;
        }

        for (long y = 0; y < H * Size; y += SilhouetteGuard.TilePixels * Size)
        {
            for (long x = 0; x < W * Size; x += SilhouetteGuard.TilePixels * Size)
            {
                Check(x, y, SilhouetteGuard.TilePixels * Size);
            }
        }

        for (long size = Size; size >= 2; size /= 2)
        {
            for (long y = 0; y < H * Size; y += size)
            {
                for (long x = 0; x < W * Size; x += size)
                {
                    Check(x, y, size);
                }
            }
        }

        // Both answers occur, so the comparison means something.
        Assert.InRange(crossed, squares / 50, squares - (squares / 50));
    }

    [Fact]
    public void FarFromSilhouettesTheGuardCostsNothing()
    {
        // One huge sphere fills the view: no silhouette, so the guarded render traces the corners only, as the lab's does.
        var scene = new Scene([new Sphere(Double3.Zero, 100, Intensity.White)], Intensity.Black, Intensity.White);
        var camera = new PerspectiveCamera { Position = new Double3(0, 0, 150), Target = Double3.Zero, Fov = 20 };
        (_, long rays) = Render(scene, camera, new AdaptiveSampler(0, 5, 0.01, guard: true), 37, 23);
        Assert.Equal(38L * 24, rays);
    }

    [Fact]
    public void TheGuardIsNamedInTheDescription() =>
        Assert.Equal("adaptive (depth 0–5, contrast 0.01, guard)", new AdaptiveSampler(0, 5, 0.01, guard: true).ToString());
}
