using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>
/// The one door: every method renders 8-bit rows or linear intensities through <see cref="Renderer"/>, the two agree
/// by the lab's 8-bit rule, and <see cref="Renderer.TracePixel"/> gives a render's own pixel.
/// </summary>
public class OneDoorTests
{
    private const int W = 61, H = 37;

    private static readonly Scene TwoSpheres = new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    private static readonly PerspectiveCamera Perspective = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    private static readonly OrthoCamera Orthographic = new() { Position = new Double3(0, 0, 6), Target = Double3.Zero, Window = new Window(-2.5, -1.6, 2.7, 1.6) };

    public static TheoryData<string, string> Methods => new()
    {
        { "jittered 16 scalar", "perspective" },
        { "jittered 16 packets", "perspective" },
        { "regular 9 packets", "orthographic" },
        { "random 5 packets", "perspective" },
        { "adaptive", "perspective" },
        { "adaptive quincunx", "orthographic" },
        { "adaptive guard", "perspective" },
        { "custom", "perspective" },
        { "exact", "perspective" },
        { "exact", "orthographic" },
    };

    private static (RenderMethod Method, RenderKernel Kernel) Of(string name) => name switch
    {
        "jittered 16 scalar" => (RenderMethod.Sampled(Samplers.Create("jittered", 16, 3)), RenderKernel.Scalar),
        "jittered 16 packets" => (RenderMethod.Sampled(Samplers.Create("jittered", 16, 3)), RenderKernel.Vector256),
        "regular 9 packets" => (RenderMethod.Sampled(Samplers.Create("regular", 9, 0)), RenderKernel.Vector128),
        "random 5 packets" => (RenderMethod.Sampled(Samplers.Create("random", 5, 7)), RenderKernel.Vector512),
        "adaptive" => (RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.05)), RenderKernel.Auto),
        "adaptive quincunx" => (RenderMethod.Adaptive(new AdaptiveSampler(1, 3, 0.05, quincunx: true)), RenderKernel.Auto),
        "adaptive guard" => (RenderMethod.Adaptive(new AdaptiveSampler(0, 2, 0.05, guard: true)), RenderKernel.Auto),
        "custom" => (RenderMethod.Custom(new CornersThenCentre()), RenderKernel.Auto),
        _ => (RenderMethod.Exact, RenderKernel.Auto),
    };

    private static Camera CameraOf(string camera) => camera == "orthographic" ? Orthographic : Perspective;

    [Theory]
    [MemberData(nameof(Methods))]
    public void TheLinearValuesByTheEightBitRuleAreTheEightBitRendersBytes(string name, string camera)
    {
        (RenderMethod method, RenderKernel kernel) = Of(name);
        var renderer = new Renderer { Kernel = kernel, MaxDegreeOfParallelism = 2 };
        var image = new Image(W, H);
        var linear = new Intensity[W * H];
        float[] imageRays = new float[W * H], linearRays = new float[W * H];

        RenderStatistics bytes = renderer.Render(TwoSpheres, CameraOf(camera), method, image, imageRays);
        RenderStatistics values = renderer.Render(TwoSpheres, CameraOf(camera), method, linear, W, H, linearRays);

        Assert.Equal((bytes.PrimaryRays, bytes.Kernel), (values.PrimaryRays, values.Kernel));
        Assert.Equal(imageRays, linearRays);
        int fractional = 0;
        for (int i = 0; i < linear.Length; i++)
        {
            Assert.Equal(image.GetPixel(i % W, i / W), Rgb24.FromIntensity(linear[i]));
            fractional += linear[i].R * 256 % 1 != 0 ? 1 : 0;
        }

        // The values are the renderer's own, finer than the bytes: an edge pixel is not a multiple of 1/256.
        Assert.True(fractional > 0, "some linear value lies between two 8-bit levels");
    }

    [Theory]
    [MemberData(nameof(Methods))]
    public void ATracedPixelIsTheRendersPixelWithThePointsThatMadeIt(string name, string camera)
    {
        (RenderMethod method, _) = Of(name);
        var linear = new Intensity[W * H];
        var rays = new float[W * H];
        new Renderer { Kernel = RenderKernel.Scalar }.Render(TwoSpheres, CameraOf(camera), method, linear, W, H, rays);

        int edges = 0;
        for (int i = 0; i < linear.Length; i += 5)
        {
            (int x, int y) = (i % W, i / W);
            PixelTrace trace = Renderer.TracePixel(TwoSpheres, CameraOf(camera), W, H, method, x, y);

            Assert.Equal((x, y, method), (trace.X, trace.Y, trace.Method));
            Assert.Equal(Rgb24.FromIntensity(linear[i]), Rgb24.FromIntensity(trace.Value));
            Assert.Equal(linear[i].R, trace.Value.R, 1e-12);
            Assert.Equal(linear[i].G, trace.Value.G, 1e-12);
            Assert.Equal(linear[i].B, trace.Value.B, 1e-12);
            if (method == RenderMethod.Exact)
            {
                Assert.Empty(trace.Points);
                continue;
            }

            // The points and their shares make the value (the mean; for adaptive, the lab's combination rule); a
            // method of your own has a rule of its own, and its points an equal share each.
            Assert.Equal(1, trace.Points.Sum(p => p.Weight), 1e-12);
            Intensity made = trace.Points.Aggregate(default(Intensity), (sum, p) => sum + (p.Weight * p.Value));
            Assert.True(name == "custom" || Math.Abs(trace.Value.G - made.G) < 1e-12, $"pixel ({x}, {y}): {trace.Value} is not the points' {made}");
            Assert.All(trace.Points, p => Assert.InRange(p.X, 0, 1));
            if (method.SamplesPerPixel > 0 || name == "custom")
            {
                Assert.Equal(rays[i], trace.Points.Count);
            }

            edges += trace.Points.Select(p => p.Value).Distinct().Count() > 1 ? 1 : 0;
            Assert.Equal(name.StartsWith("adaptive", StringComparison.Ordinal), trace.Squares.Count > 0);
        }

        Assert.True(method == RenderMethod.Exact || edges > 0, "some traced pixel lies on an edge");
    }

    [Fact]
    public void ALinearRenderNamesTheSizeArgumentThatIsWrong()
    {
        var renderer = new Renderer();
        RenderMethod method = RenderMethod.Sampled(new RegularSampler(1));

        Assert.Equal("width", Assert.Throws<ArgumentOutOfRangeException>(() => renderer.Render(TwoSpheres, Perspective, method, new Intensity[6], 0, 6)).ParamName);
        Assert.Equal("height", Assert.Throws<ArgumentOutOfRangeException>(() => renderer.Render(TwoSpheres, Perspective, method, new Intensity[6], 6, -1)).ParamName);
        Assert.Equal("pixels", Assert.Throws<ArgumentException>(() => renderer.Render(TwoSpheres, Perspective, method, new Intensity[6], 3, 3)).ParamName);
        Assert.Equal("pixels", Assert.Throws<ArgumentException>(() => renderer.Render(TwoSpheres, Perspective, method, Span<Intensity>.Empty, 1, 1)).ParamName);
    }

    [Fact]
    public void RendererIsTheOnlyDoorTheExactRendererIsNotPublic()
    {
        Type[] exported = typeof(Renderer).Assembly.GetExportedTypes();

        Assert.Contains(typeof(Renderer), exported);
        Assert.DoesNotContain(exported, t => t.Name == "ExactRenderer");
    }

    /// <summary>The four corners, then the centre where they disagree or the left neighbour differs from the first corner.</summary>
    private sealed class CornersThenCentre : IPixelMethod<int>
    {
        public string Name => "corners-then-centre";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch)
        {
            Intensity a = pixel.Trace(0, 0), b = pixel.Trace(1, 0), c = pixel.Trace(0, 1), d = pixel.Trace(1, 1);
            bool left = pixel.PreviousInRow.Length > 0 && pixel.PreviousInRow[^1] != a;
            if (a == b && b == c && c == d && !left)
            {
                return a;
            }

            return ((a + b + c + d) * 0.125) + (pixel.Trace(0.5, 0.5) * 0.5);
        }
    }
}
