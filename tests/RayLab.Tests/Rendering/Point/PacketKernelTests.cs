using RayLab.Sampling;

namespace RayLab.Tests.Rendering.Point;

/// <summary>
/// The SIMD packet kernels against each other and against the scalar double path. Every width runs on any
/// machine (a width the hardware lacks is emulated), so these tests mean the same everywhere.
/// </summary>
public class PacketKernelTests
{
    private static readonly RenderKernel[] Widths = [RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512];

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    private static readonly PerspectiveCamera Perspective = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    private static readonly OrthoCamera Orthographic = new() { Position = new Double3(0.3, 0.5, 6), Target = new Double3(0.1, 0, 0), ViewHeight = 4.2, NearPlane = 0.1, FarPlane = 100 };

    private static (Image Image, RenderStatistics Stats) Render(RenderKernel kernel, Scene scene, Camera camera, IPixelSampler sampler, int threads = 2, int w = 83, int h = 61)
    {
        var image = new Image(w, h);
        RenderStatistics stats = new Renderer { Kernel = kernel, MaxDegreeOfParallelism = threads }.Render(scene, camera, sampler, image);
        return (image, stats);
    }

    public static TheoryData<string, bool> SamplersAndCameras()
    {
        var data = new TheoryData<string, bool>();
        foreach (string name in Samplers.Names)
        {
            data.Add(name, false);
            data.Add(name, true);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(SamplersAndCameras))]
    public void EveryWidthGivesTheSameBytesWhateverTheThreadCount(string sampler, bool orthographic)
    {
        Camera camera = orthographic ? Orthographic : Perspective;
        IPixelSampler s = Samplers.Create(sampler, 16, 7);
        // 83 px wide: the last packet is partial for every width.
        (Image reference, RenderStatistics stats) = Render(RenderKernel.Vector128, TwoSpheres(), camera, s, threads: 1);
        Assert.Equal(RenderKernel.Vector128, stats.Kernel);
        foreach (RenderKernel width in Widths)
        {
            foreach (int threads in new[] { 1, 2, -1 })
            {
                (Image image, RenderStatistics st) = Render(width, TwoSpheres(), camera, s, threads);
                Assert.Equal(width, st.Kernel);
                Assert.True(reference.PixelBytes.SequenceEqual(image.PixelBytes), $"{width} with {threads} threads differs from Vector128");
            }
        }
    }

    [Theory]
    [MemberData(nameof(SamplersAndCameras))]
    public void PacketsAgreeWithTheScalarPathUpToSamplesWithinFloatResolutionOfASilhouette(string sampler, bool orthographic)
    {
        // Stated tolerance: a sample whose float position lies within float resolution (~1e-4 px here) of an
        // edge may land on the other side than in double. Each such flip moves its pixel by at most
        // 256·(largest colour difference)/spp levels, plus 1 for the float sum's rounding at a level boundary.
        Camera camera = orthographic ? Orthographic : Perspective;
        IPixelSampler s = Samplers.Create(sampler, 16, 7);
        byte[] scalar = Render(RenderKernel.Scalar, TwoSpheres(), camera, s).Image.PixelBytes.ToArray();
        byte[] packet = Render(RenderKernel.Vector256, TwoSpheres(), camera, s).Image.PixelBytes.ToArray();
        int flipLevels = (int)Math.Ceiling(256 * 0.8 / 16) + 1;
        int differing = 0;
        for (int i = 0; i < scalar.Length; i += 3)
        {
            int worst = Math.Max(Math.Abs(scalar[i] - packet[i]), Math.Max(Math.Abs(scalar[i + 1] - packet[i + 1]), Math.Abs(scalar[i + 2] - packet[i + 2])));
            Assert.True(worst <= flipLevels, $"pixel {i / 3}: {worst} levels apart");
            differing += worst > 1 ? 1 : 0;
        }

        Assert.True(differing <= 2, $"{differing} pixels differ by more than a level");
    }

    [Fact]
    public void PixelCentresMatchTheScalarPathExactly()
    {
        // One sample per pixel at its centre, on both cameras: no centre here is within float resolution of an
        // edge, and a single sample has no sum to round, so the bytes are the same.
        foreach (Camera camera in new Camera[] { Perspective, Orthographic })
        {
            byte[] scalar = Render(RenderKernel.Scalar, TwoSpheres(), camera, new RegularSampler(1), w: 320, h: 240).Image.PixelBytes.ToArray();
            byte[] packet = Render(RenderKernel.Vector512, TwoSpheres(), camera, new RegularSampler(1), w: 320, h: 240).Image.PixelBytes.ToArray();
            Assert.Equal(scalar, packet);
        }
    }

    [Theory]
    [InlineData(1e-4, 0.2, true)]
    [InlineData(1e-5, 2, false)]
    public void ATinyFarSphereIsDecidedInDoubleWhereFloatIsUnsure(double ratio, double fov, bool visible)
    {
        // r/D = 1e-4 (4 pixels wide) or 1e-5 (a twentieth of a pixel): float's discriminant cannot decide near
        // the sphere, so those lanes are traced again in double, and the picture is the scalar path's to the byte.
        double distance = 1 / ratio;
        var direction = Double3.Normalize(new Double3(0.31, -0.27, -0.91));
        var eye = new Double3(0.7, 0.2, -0.4);
        var scene = new Scene([new Sphere(eye + (distance * direction), 1, Intensity.White)], Intensity.Black, Intensity.White);
        var camera = new PerspectiveCamera { Position = eye, Target = eye + direction, Up = new Double3(0.1, 1, 0.2), Fov = fov, NearPlane = 0.5, FarPlane = 2 * distance };
        (Image scalar, _) = Render(RenderKernel.Scalar, scene, camera, new RegularSampler(1), w: 64, h: 64);
        (Image packet, RenderStatistics stats) = Render(RenderKernel.Vector256, scene, camera, new RegularSampler(1), w: 64, h: 64);
        Assert.Equal(RenderKernel.Vector256, stats.Kernel);
        Assert.True(stats.RetracedSamples > 0);
        Assert.True(scalar.PixelBytes.SequenceEqual(packet.PixelBytes));
        Assert.Equal(visible, packet.PixelBytes.ToArray().Any(b => b == 255));
    }

    [Fact]
    public void OverlappingSpheresCheckTheDepthOrderAndMatchTheScalarPath()
    {
        // Two spheres cutting each other: along the intersection curve their hits are equally near, where float
        // could order them wrongly; those lanes go to double.
        var scene = new Scene(
            [new Sphere(new Double3(-0.5, 0, 0), 1, new Intensity(1, 0, 0)), new Sphere(new Double3(0.5, 0.1, 0.2), 1, new Intensity(0, 0, 1))],
            Intensity.Black,
            Intensity.White);
        (Image scalar, _) = Render(RenderKernel.Scalar, scene, Perspective, new RegularSampler(1), w: 200, h: 150);
        (Image packet, RenderStatistics stats) = Render(RenderKernel.Vector512, scene, Perspective, new RegularSampler(1), w: 200, h: 150);
        Assert.True(stats.RetracedSamples > 0);
        Assert.True(scalar.PixelBytes.SequenceEqual(packet.PixelBytes));
    }

    [Theory]
    [InlineData(1)]
    [InlineData(3)]
    [InlineData(15)]
    [InlineData(16)]
    [InlineData(17)]
    [InlineData(33)]
    public void NarrowAndOddWidthsWriteEveryPixelAndNoMore(int width)
    {
        // Pixels are written as 4-byte words, all but each packet's last: a packet narrower than the lanes, or a
        // row ending mid-packet, must still get every pixel right and leave the next row alone.
        var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = new Double3(-1.1, 0, 0), Fov = 40, NearPlane = 0.1, FarPlane = 100 };
        byte[] scalar = Render(RenderKernel.Scalar, TwoSpheres(), camera, new RegularSampler(1), w: width, h: 9).Image.PixelBytes.ToArray();
        Assert.True(scalar.Chunk(3).Select(p => (p[0], p[1], p[2])).Distinct().Count() >= 2, "the picture has sphere and background");
        foreach (RenderKernel kernel in Widths)
        {
            byte[] packet = Render(kernel, TwoSpheres(), camera, new RegularSampler(1), w: width, h: 9).Image.PixelBytes.ToArray();
            Assert.Equal(scalar, packet);
        }
    }

    [Fact]
    public void ScenesFloatCannotRenderTakeTheScalarPathAndSayWhy()
    {
        var sphere = new Scene([new Sphere(Double3.Zero, 1, Intensity.White)], Intensity.Black, Intensity.White);
        var nearCuts = new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero, NearPlane = 5.5 };
        var farCuts = new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero, FarPlane = 6.5 };
        var narrow = new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = new Double3(0.3, 0.2, 0), Fov = 0.0001 };
        var farAway = new OrthoCamera { Position = new Double3(1e5, 0, 6), Target = new Double3(1e5, 0, 0), ViewHeight = 0.01 };
        var ground = new Scene([new Sphere(new Double3(0, -1e6, 0), 1e6, Intensity.White)], Intensity.Black, Intensity.White);
        var horizon = new PerspectiveCamera { Position = new Double3(0, 0.01, 0), Target = new Double3(1, 0.01, 0), NearPlane = 0.001, FarPlane = 1e7 };
        foreach ((Scene scene, Camera camera, string why) in new[]
        {
            (sphere, (Camera)nearCuts, "near or far plane"),
            (sphere, farCuts, "near or far plane"),
            (sphere, narrow, "ray directions"),
            (sphere, farAway, "ray origins"),
            (ground, horizon, "near or far plane"),
        })
        {
            RenderStatistics stats = Render(RenderKernel.Auto, scene, camera, new JitteredSampler(4, 1), w: 32, h: 24).Stats;
            Assert.Equal(RenderKernel.Scalar, stats.Kernel);
            Assert.Contains(why, stats.ScalarReason);
        }

        RenderStatistics fine = Render(RenderKernel.Auto, sphere, new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero }, new JitteredSampler(4, 1), w: 32, h: 24).Stats;
        Assert.Null(fine.ScalarReason);
        Assert.Equal(System.Runtime.Intrinsics.Vector128.IsHardwareAccelerated, fine.Kernel != RenderKernel.Scalar);
    }

    [Fact]
    public void AdaptiveRendersReportTheCornerGridsLoopAndExactRendersTheScalarOne()
    {
        var image = new Image(32, 24);
        RenderStatistics stats = new Renderer { Kernel = RenderKernel.Vector512 }.Render(TwoSpheres(), Perspective, new AdaptiveSampler(), image);
        Assert.Equal(RenderKernel.Vector512, stats.Kernel);
        stats = new Renderer { Kernel = RenderKernel.Scalar }.Render(TwoSpheres(), Perspective, new AdaptiveSampler(), image);
        Assert.Equal(RenderKernel.Scalar, stats.Kernel);
        Assert.Equal(RenderKernel.Scalar, new Renderer().Render(TwoSpheres(), Perspective, RenderMethod.Exact, image).Kernel);
    }

    [Fact]
    public void AskingForScalarAlwaysGetsScalar()
    {
        RenderStatistics stats = Render(RenderKernel.Scalar, TwoSpheres(), Perspective, new JitteredSampler(4, 1)).Stats;
        Assert.Equal((RenderKernel.Scalar, 0L, null), (stats.Kernel, stats.RetracedSamples, stats.ScalarReason));
    }
}
