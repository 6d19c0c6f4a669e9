using System.Security.Cryptography;
using RayLab.Sampling;

namespace RayLab.Gpu.Tests;

/// <summary>
/// The device path's bytes (the kernel's code on ILGPU's CPU accelerator) against the CPU renderer's: every built-in
/// point sampler (the later-ported ones at two seeds), both cameras, the packet kernels' bytes and the scalar loop's, and the golden set.
/// </summary>
public class SameBytesTests(CpuAcceleratorFixture fixture) : IClassFixture<CpuAcceleratorFixture>
{
    private const int Width = 64;
    private const int Height = 48;

    public static TheoryData<string, string, int, uint, RenderKernel> Cases()
    {
        var data = new TheoryData<string, string, int, uint, RenderKernel>();
        var samplers = new (string Name, int[] Counts, uint[] Seeds)[]
        {
            ("regular", [1, 9], [7]), ("jittered", [4, 16], [7]), ("random", [1, 6], [7]), ("hammersley", [6], [7]),
            ("nrooks", [5, 16], [7, 1234567]), ("multijittered", [4, 9], [7, 1234567]), ("cmj", [6, 16], [7, 1234567]),
            ("sobol", [6, 16], [7, 1234567]), ("pmj02", [6, 16], [7, 1234567]), ("pmj02bn", [5, 16], [7, 1234567]),
            ("zsobol", [6, 16], [7, 1234567]),
        };
        foreach (string camera in TestScenes.Cameras.Keys)
        {
            foreach ((string sampler, int[] counts, uint[] seeds) in samplers)
            {
                foreach (int n in counts)
                {
                    foreach (uint seed in seeds)
                    {
                        data.Add(camera, sampler, n, seed, RenderKernel.Auto);
                        data.Add(camera, sampler, n, seed, RenderKernel.Scalar);
                    }
                }
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void TheDeviceGivesTheCpuRenderersBytes(string camera, string sampler, int samples, uint seed, RenderKernel kernel)
    {
        Scene scene = TestScenes.TwoSpheres();
        IPixelSampler points = Samplers.Create(sampler, samples, seed);
        var cpu = new Image(Width, Height);
        var device = new Image(Width, Height);
        RenderStatistics cpuStats = new Renderer { Kernel = kernel }.Render(scene, TestScenes.Cameras[camera], RenderMethod.Sampled(points), cpu);
        RenderStatistics deviceStats = new Renderer { Kernel = kernel, Device = fixture.Device }.Render(scene, TestScenes.Cameras[camera], RenderMethod.Sampled(points), device);

        Assert.Null(cpuStats.Device);
        Assert.Equal("ilgpu-cpu", deviceStats.Device);
        Assert.Equal(kernel == RenderKernel.Scalar, deviceStats.Kernel == RenderKernel.Scalar);
        Assert.Equal(cpuStats.PrimaryRays, deviceStats.PrimaryRays);
        AssertSameBytes(cpu, device);
    }

    [Theory]
    [InlineData("regular")]
    [InlineData("jittered")]
    [InlineData("random")]
    [InlineData("hammersley")]
    [InlineData("nrooks")]
    [InlineData("multijittered")]
    [InlineData("cmj")]
    [InlineData("sobol")]
    [InlineData("pmj02")]
    [InlineData("pmj02bn")]
    [InlineData("zsobol")]
    public void TheDeviceKeepsTheGoldenSetsBytes(string sampler)
    {
        // The golden set (tests/RayLab.Tests/Golden) pins 37×23 renders of each sampler, camera and kernel: the device's
        // render with the automatic kernel must be its packet kernels' picture, with the scalar kernel its scalar one.
        Dictionary<string, string> golden = File.ReadAllLines(Path.Combine(AppContext.BaseDirectory, "Golden", "golden.txt"))
            .Select(line => line.Split('\t'))
            .ToDictionary(parts => parts[0], parts => parts[1]);
        Scene scene = TestScenes.TwoSpheres();
        int checkedCount = 0;
        foreach ((string cameraName, Camera camera) in TestScenes.Cameras)
        {
            foreach (int n in sampler is "regular" or "jittered" or "multijittered" ? new[] { 1, 9, 16 } : [1, 6, 16])
            {
                foreach ((RenderKernel kernel, string pinned) in new[] { (RenderKernel.Auto, "Vector512"), (RenderKernel.Scalar, "Scalar") })
                {
                    var image = new Image(37, 23);
                    new Renderer { Kernel = kernel, Device = fixture.Device }.Render(scene, camera, RenderMethod.Sampled(Samplers.Create(sampler, n, 7)), image);
                    Assert.Equal(golden[$"{cameraName} {sampler} {n} {pinned}"], Convert.ToHexStringLower(SHA256.HashData(image.PixelBytes)));
                    checkedCount++;
                }
            }
        }

        Assert.Equal(24, checkedCount);
    }

    [Fact]
    public void ABandOfRowsGivesTheWholeRendersRows()
    {
        Scene scene = TestScenes.TwoSpheres();
        Camera camera = TestScenes.Cameras["persp"];
        RenderMethod method = RenderMethod.Sampled(new JitteredSampler(4, 3));
        var whole = new Image(Width, Height);
        new Renderer().Render(scene, camera, method, whole);
        var band = new Image(Width, Height);
        RenderStatistics stats = new Renderer { Device = fixture.Device }.RenderRows(scene, camera, method, band, 10, 7);

        Assert.Equal((long)Width * 7 * 4, stats.PrimaryRays);
        for (int y = 0; y < Height; y++)
        {
            bool inBand = y is >= 10 and < 17;
            Assert.Equal(inBand, band.GetRowSpan(y).SequenceEqual(whole.GetRowSpan(y)));
        }
    }

    [Fact]
    public void ASamplerOfYourOwnRendersOnTheCpu()
    {
        Scene scene = TestScenes.TwoSpheres();
        Camera camera = TestScenes.Cameras["ortho"];
        var own = new DiagonalSampler(4);
        var cpu = new Image(Width, Height);
        var device = new Image(Width, Height);
        new Renderer().Render(scene, camera, RenderMethod.Sampled(own), cpu);
        RenderStatistics stats = new Renderer { Device = fixture.Device }.Render(scene, camera, RenderMethod.Sampled(own), device);

        Assert.Null(stats.Device);
        AssertSameBytes(cpu, device);
    }

    public static TheoryData<string, string, int, uint, RenderKernel> FieldCases()
    {
        var data = new TheoryData<string, string, int, uint, RenderKernel>();
        foreach (string camera in TestScenes.FieldCameras.Keys)
        {
            foreach ((string sampler, int n, uint seed) in new[] { ("jittered", 4, 1u), ("cmj", 6, 7u), ("sobol", 16, 1234567u), ("pmj02bn", 5, 7u) })
            {
                data.Add(camera, sampler, n, seed, RenderKernel.Auto);
                data.Add(camera, sampler, n, seed, RenderKernel.Scalar);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(FieldCases))]
    public void TheSphereFieldThroughItsHierarchyGivesTheCpuRenderersBytes(string camera, string sampler, int samples, uint seed, RenderKernel kernel)
    {
        // 960 spheres at 64×48: the CPU and the device both trace them through the scene's hierarchy (the device its
        // nodes and order uploaded once, with a fixed-size stack); the nearest hit, and so the bytes, are the same.
        Scene scene = TestScenes.SphereField.Value;
        Assert.True(scene.Spheres.Count > 900);
        RenderMethod method = RenderMethod.Sampled(Samplers.Create(sampler, samples, seed));
        var cpu = new Image(Width, Height);
        var device = new Image(Width, Height);
        new Renderer { Kernel = kernel }.Render(scene, TestScenes.FieldCameras[camera], method, cpu);
        RenderStatistics stats = new Renderer { Kernel = kernel, Device = fixture.Device }.Render(scene, TestScenes.FieldCameras[camera], method, device);

        Assert.Equal("ilgpu-cpu", stats.Device);
        Assert.True(fixture.Device.TracesThroughHierarchy);
        Assert.True(Colours(cpu) >= 8, "the view holds the field");
        AssertSameBytes(cpu, device);
    }

    /// <summary>How many different pixel colours <paramref name="image"/> holds.</summary>
    internal static int Colours(Image image) => image.PixelBytes.ToArray().Chunk(3).Select(rgb => (rgb[0] << 16) | (rgb[1] << 8) | rgb[2]).Distinct().Count();

    internal static void AssertSameBytes(Image expected, Image actual)
    {
        byte[] a = expected.PixelBytes.ToArray(), b = actual.PixelBytes.ToArray();
        int differing = a.Zip(b).Count(p => p.First != p.Second);
        Assert.True(differing == 0, $"{differing} of {a.Length} bytes differ");
    }

    /// <summary>A sampler outside RayLab: points on the pixel's diagonal.</summary>
    private sealed class DiagonalSampler(int samplesPerPixel) : IPixelSampler
    {
        public string Name => "diagonal";

        public int SamplesPerPixel => samplesPerPixel;

        public uint Seed => 0;

        public SamplePoint GetSample(int x, int y, int index) => new((index + 0.5) / samplesPerPixel, (index + 0.5) / samplesPerPixel);
    }
}
