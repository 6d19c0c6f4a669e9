using RayLab.Sampling;
using RayLab.Rendering.Adaptive;

namespace RayLab.Tests.Rendering.Adaptive;

public class AdaptiveTests
{
    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15), Intensity.White);

    /// <summary>A lattice whose values are given point by point; asking for any other point fails the test.</summary>
    private struct TableSource(Dictionary<(long, long), Intensity> table) : ILatticeSource
    {
        public readonly List<(long, long)> Asked = [];

        public readonly Intensity At(long lx, long ly, out double weight)
        {
            weight = 1;
            Asked.Add((lx, ly));
            Assert.True(table.TryGetValue((lx, ly), out Intensity value), $"traced ({lx}, {ly}), which the lab's figure does not have");
            return value;
        }

        public readonly Intensity Centre(long lx, long ly) => At(lx, ly, out _);

        public readonly bool MayCross(long x0, long y0, long size) => false;
    }

    [Fact]
    public void TheCombinationIsTheLabsWorkedExample()
    {
        // Pixel corners A (top left), B (top right), C (bottom right), D (bottom left), centre E; MaxDepth 2, so the
        // lattice has 8 steps per pixel. Quadrant B is refined (centre G, new corners F, H), and inside it the
        // quarter toward E (centre K, new corners J, L); quadrant C is refined (centre M, new corner N) and inside it
        // the quarter toward C (centre Q, new corners P, R). Red and green are random; blue sets which values agree
        // (within the contrast 0.5) so that the sampler must split exactly as the lab's figure does.
        var random = new Random(2024);
        var blue = new Dictionary<char, double>
        {
            ['A'] = 1.2, ['B'] = 1.9, ['C'] = 2.5, ['D'] = 0.9, ['E'] = 1.0, ['F'] = 2.2, ['G'] = 2.0, ['H'] = 1.6,
            ['J'] = 1.7, ['K'] = 1.5, ['L'] = 1.2, ['M'] = 1.3, ['N'] = 1.4, ['P'] = 2.0, ['Q'] = 2.1, ['R'] = 1.9,
        };
        var at = new Dictionary<char, (long, long)>
        {
            ['A'] = (0, 0), ['B'] = (8, 0), ['C'] = (8, 8), ['D'] = (0, 8), ['E'] = (4, 4),
            ['F'] = (4, 0), ['G'] = (6, 2), ['H'] = (8, 4), ['J'] = (4, 2), ['K'] = (5, 3), ['L'] = (6, 4),
            ['M'] = (6, 6), ['N'] = (4, 8), ['P'] = (8, 6), ['Q'] = (7, 7), ['R'] = (6, 8),
        };
        var v = blue.ToDictionary(p => p.Key, p => new Intensity(random.NextDouble() * 0.3, random.NextDouble() * 0.3, p.Value + ((random.NextDouble() - 0.5) * 0.04)));
        var source = new TableSource(at.ToDictionary(p => p.Value, p => v[p.Key]));

        Intensity pixel = AdaptivePixel.Evaluate(new AdaptiveSampler(minDepth: 0, maxDepth: 2, contrast: 0.5), ref source, 0, 0, out _);

        Intensity A = v['A'], B = v['B'], C = v['C'], D = v['D'], E = v['E'], F = v['F'], G = v['G'], H = v['H'];
        Intensity J = v['J'], K = v['K'], L = v['L'], M = v['M'], N = v['N'], P = v['P'], Q = v['Q'], R = v['R'];
        Intensity expected = 0.25 * (((A + E) / 2) + ((D + E) / 2)
            + (0.25 * (((F + G) / 2) + ((B + G) / 2) + ((H + G) / 2) + (0.25 * (((J + K) / 2) + ((G + K) / 2) + ((L + K) / 2) + ((E + K) / 2)))))
            + (0.25 * (((E + M) / 2) + ((H + M) / 2) + ((N + M) / 2) + (0.25 * (((M + Q) / 2) + ((P + Q) / 2) + ((C + Q) / 2) + ((R + Q) / 2))))));
        Assert.Equal(expected.R, pixel.R, 1e-12);
        Assert.Equal(expected.G, pixel.G, 1e-12);
        Assert.Equal(expected.B, pixel.B, 1e-12);
        // Every point of the figure is traced, and none twice.
        Assert.Equal(16, source.Asked.Count);
        Assert.Equal(16, source.Asked.Distinct().Count());
    }

    [Theory]
    [InlineData(0, 0, true)]
    [InlineData(0, 3, true)]
    [InlineData(0, 0, false)]
    [InlineData(0, 3, false)]
    public void AnImageWithNoEdgesCostsItsCornersAndWithTheQuincunxItsCentres(int minDepth, int maxDepth, bool quincunx)
    {
        // One huge sphere fills the view: every value agrees, so no pixel is split.
        var scene = new Scene([new Sphere(Double3.Zero, 100, Intensity.White)], Intensity.Black, Intensity.White);
        var camera = new PerspectiveCamera { Position = new Double3(0, 0, 150), Target = Double3.Zero, Fov = 20 };
        const int W = 37, H = 23;
        var image = new Image(W, H);
        RenderStatistics stats = new Renderer().Render(scene, camera, new AdaptiveSampler(minDepth, maxDepth, 0.1, quincunx), image);
        Assert.Equal(((W + 1L) * (H + 1)) + (quincunx ? (long)W * H : 0), stats.PrimaryRays);
        Assert.All(image.PixelBytes.ToArray(), b => Assert.Equal(255, b));
    }

    [Theory]
    [InlineData(800, 600, 1.2)]
    [InlineData(1920, 1080, 1.1)]
    public void AtItsDefaultSettingsTheTwoSphereSceneCostsLittleMoreThanARayPerPixel(int w, int h, double most)
    {
        // Corners (shared: one per pixel) everywhere, centres and subdivisions only at the silhouettes.
        RenderStatistics stats = new Renderer().Render(TwoSpheres(), Camera, new AdaptiveSampler(), new Image(w, h));
        Assert.InRange((double)stats.PrimaryRays / (w * h), 1, most);
    }

    [Fact]
    public void AFlatPixelHasTheSameValueWithOrWithoutTheQuincunx()
    {
        // Same picture either way, the quincunx costs a ray per pixel more.
        var with = new Image(96, 72);
        var without = new Image(96, 72);
        long raysWith = new Renderer().Render(TwoSpheres(), Camera, new AdaptiveSampler(0, 3, 0.05, quincunx: true), with).PrimaryRays;
        long raysWithout = new Renderer().Render(TwoSpheres(), Camera, new AdaptiveSampler(0, 3, 0.05), without).PrimaryRays;
        Assert.True(raysWith > raysWithout + (96 * 72 * 9 / 10));
        byte[] a = with.PixelBytes.ToArray(), b = without.PixelBytes.ToArray();
        Assert.True(a.Zip(b).Count(p => p.First != p.Second) < a.Length / 100, "more than 1% of the bytes differ");
    }

    [Fact]
    public void PointsOnPixelEdgesAreSharedAndTracedOnce()
    {
        // MinDepth 1 = MaxDepth 1 splits every pixel once: per pixel 4 quadrant centres; per pixel edge one midpoint,
        // shared by the two pixels beside it.
        var scene = new Scene([], Intensity.Black, Intensity.White);
        const int W = 13, H = 9;
        RenderStatistics stats = new Renderer().Render(scene, Camera, new AdaptiveSampler(1, 1, 0.1), new Image(W, H));
        long corners = (W + 1L) * (H + 1), centres = (long)W * H, quadrantCentres = 4L * W * H;
        long edgeMidpoints = ((long)W * (H + 1)) + ((W + 1L) * H);
        Assert.Equal(corners + centres + quadrantCentres + edgeMidpoints, stats.PrimaryRays);
    }

    public static TheoryData<string, int, int, double, bool> KernelCases => new()
    {
        { "perspective", 0, 3, 0.1, false },
        { "perspective", 0, 2, 0.01, true },
        { "perspective", 1, 3, 0.05, false },
        { "orthographic", 0, 3, 0.1, false },
        { "orthographic", 0, 4, 0.001, true },
        { "off-axis", 0, 3, 0.1, false },
        { "off-axis", 2, 2, 0.1, false },
        { "on the lattice", 0, 3, 0.1, false },
        { "on the lattice", 1, 2, 0.1, true },
    };

    [Theory]
    [MemberData(nameof(KernelCases))]
    public void EveryPacketWidthGivesTheScalarLoopsBytesRaysAndHeatMap(string view, int minDepth, int maxDepth, double contrast, bool quincunx)
    {
        // The corner grid traced in SIMD float must agree with the double loop to the byte, including where a
        // silhouette passes exactly through lattice points ("on the lattice": a sphere of radius 2 pixels centred
        // on a pixel corner, seen straight on, touches corners of the grid).
        (Scene scene, Camera camera) = view switch
        {
            "orthographic" => (TwoSpheres(), (Camera)new OrthoCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Window = new Window(-3, -2, 3, 2) }),
            "off-axis" => (TwoSpheres(), new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Window = new Window(-0.1, -0.25, 0.5, 0.15) }),
            "on the lattice" => (new Scene([new Sphere(new Double3(1, 1, 0), 0.5, Intensity.White), new Sphere(new Double3(-1.25, 0.5, -1), 0.75, new Intensity(0.3, 0.6, 0.9))], Intensity.Black, Intensity.White),
                new OrthoCamera { Position = new Double3(0, 0, 10), Target = Double3.Zero, Window = new Window(-3, -2, 3, 2) }),
            _ => (TwoSpheres(), Camera),
        };
        const int W = 24, H = 16;
        var sampler = new AdaptiveSampler(minDepth, maxDepth, contrast, quincunx);
        var reference = new Image(W, H);
        var referenceHeat = new float[W * H];
        RenderStatistics expected = new Renderer { Kernel = RenderKernel.Scalar }.Render(scene, camera, sampler, reference, referenceHeat);
        Assert.Equal(RenderKernel.Scalar, expected.Kernel);
        foreach (RenderKernel kernel in new[] { RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512, RenderKernel.Auto })
        {
            var image = new Image(W, H);
            var heat = new float[W * H];
            RenderStatistics stats = new Renderer { Kernel = kernel, MaxDegreeOfParallelism = 2 }.Render(scene, camera, sampler, image, heat);
            Assert.Equal(reference.PixelBytes.ToArray(), image.PixelBytes.ToArray());
            Assert.Equal(expected.PrimaryRays, stats.PrimaryRays);
            Assert.Equal(referenceHeat, heat);
        }
    }

    [Fact]
    public void RaysGoToEdgesAndTheBytesDoNotDependOnThreads()
    {
        const int W = 96, H = 72;
        var sampler = new AdaptiveSampler(0, 3, 0.05);
        var one = new Image(W, H);
        var two = new Image(W, H);
        var heat = new float[W * H];
        RenderStatistics s1 = new Renderer { MaxDegreeOfParallelism = 1 }.Render(TwoSpheres(), Camera, sampler, one, heat);
        RenderStatistics s2 = new Renderer { MaxDegreeOfParallelism = 2 }.Render(TwoSpheres(), Camera, sampler, two);
        Assert.Equal(one.PixelBytes.ToArray(), two.PixelBytes.ToArray());
        Assert.Equal(s1.PrimaryRays, s2.PrimaryRays);
        // Flat pixels cost a quarter of each corner: 1. Edge pixels cost more.
        Assert.Equal(1f, heat[0]);
        Assert.Contains(heat, h => h > 10);
        double perPixel = (double)s1.PrimaryRays / (W * H);
        Assert.InRange(perPixel, 1, 6);
        // Shared points are charged in halves and quarters, so the heat map sums to at most the rays traced.
        Assert.InRange(heat.Sum(), s1.PrimaryRays * 0.9, s1.PrimaryRays + 1e-3);
    }

    [Fact]
    public void AdaptiveIsFarCloserToAConvergedReferenceThanOneSampleAPixel()
    {
        const int W = 64, H = 48;
        byte[] Render(Action<Image> draw)
        {
            var image = new Image(W, H);
            draw(image);
            return image.PixelBytes.ToArray();
        }

        byte[] reference = Render(i => new Renderer().Render(TwoSpheres(), Camera, new JitteredSampler(1024, 5), i));
        byte[] adaptive = Render(i => new Renderer().Render(TwoSpheres(), Camera, new AdaptiveSampler(0, 4, 0.02), i));
        byte[] single = Render(i => new Renderer().Render(TwoSpheres(), Camera, new RegularSampler(1), i));
        static double Rmse(byte[] a, byte[] b) => Math.Sqrt(a.Zip(b, (x, y) => (double)(x - y) * (x - y)).Average());

        double adaptiveError = Rmse(adaptive, reference), singleError = Rmse(single, reference);
        Assert.True(adaptiveError < singleError / 4, $"adaptive RMSE {adaptiveError:F3} vs one sample {singleError:F3}");
    }

    [Fact]
    public void ASphereSmallerThanAPixelCanVanish()
    {
        // The scheme is biased: a sphere that falls between the corners and the centre is never seen, however deep
        // MaxDepth is, because no value ever disagrees. Measured here: a sphere of 0.2 px diameter placed in the gap.
        var camera = new OrthoCamera { Position = new Double3(0, 0, 10), Target = Double3.Zero, Window = new Window(0, 0, 4, 4) };
        // Pixel (1, 1) spans u ∈ [1, 2], v ∈ [2, 3]; its centre is (1.5, 2.5). Put the sphere at (1.25, 2.75): a quarter
        // of the way in from the top-left corner, 0.25 px from the nearest traced point, with radius 0.1 px.
        var tiny = new Sphere(new Double3(1.25, 2.75, 0), 0.1, Intensity.White);
        var scene = new Scene([tiny], Intensity.Black, Intensity.White);
        var image = new Image(4, 4);
        RenderStatistics stats = new Renderer().Render(scene, camera, new AdaptiveSampler(0, 8, 0.001), image);
        Assert.Equal(0, image.GetPixel(1, 1).R); // the truth is π·0.1² ≈ 0.0314 of the pixel: level 8
        Assert.Equal(5L * 5, stats.PrimaryRays); // the corners only: they all agree, so no centre is traced
        stats = new Renderer().Render(scene, camera, new AdaptiveSampler(0, 8, 0.001, quincunx: true), image);
        Assert.Equal(0, image.GetPixel(1, 1).R);
        Assert.Equal((5L * 5) + 16, stats.PrimaryRays);

        // With MinDepth 1 the quadrant centres are traced; (1.25, 2.75) is the top-left quadrant's centre, so it is found.
        new Renderer().Render(scene, camera, new AdaptiveSampler(1, 8, 0.001), image);
        Assert.True(image.GetPixel(1, 1).R > 0);
    }

    [Theory]
    [InlineData(-1, 3, 0.1, "minDepth")]
    [InlineData(4, 3, 0.1, "minDepth")]
    [InlineData(0, 11, 0.1, "maxDepth")]
    [InlineData(0, -1, 0.1, "maxDepth")]
    [InlineData(0, 3, -0.1, "contrast")]
    [InlineData(0, 3, double.NaN, "contrast")]
    public void SettingsOutOfRangeAreRejectedNamingTheParameter(int min, int max, double contrast, string param)
    {
        Assert.Equal(param, Assert.Throws<ArgumentOutOfRangeException>(() => new AdaptiveSampler(min, max, contrast)).ParamName);
    }
}
