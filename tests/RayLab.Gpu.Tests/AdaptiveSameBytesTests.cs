using System.Security.Cryptography;
using RayLab.Sampling;

namespace RayLab.Gpu.Tests;

/// <summary>
/// The lab's adaptive rule on the device (the kernel's code on ILGPU's CPU accelerator) against the CPU renderer: the
/// same bytes and the same rays-per-pixel map, plain and guarded, at several depths and contrasts, both cameras, two
/// spheres and the sphere field; and the golden set's adaptive renders.
/// </summary>
public class AdaptiveSameBytesTests(CpuAcceleratorFixture fixture) : IClassFixture<CpuAcceleratorFixture>
{
    private const int Width = 64;
    private const int Height = 48;

    private static readonly Dictionary<string, AdaptiveSampler> Rules = new()
    {
        ["default"] = new AdaptiveSampler(),
        ["max1-c0"] = new AdaptiveSampler(0, 1, 0),
        ["min1-max4-c0.05"] = new AdaptiveSampler(1, 4, 0.05),
        ["min2-max2"] = new AdaptiveSampler(2, 2, 0.1),
        ["max3-c0.64"] = new AdaptiveSampler(0, 3, 0.64),
        ["quincunx-max3-c0.7"] = new AdaptiveSampler(0, 3, 0.7, quincunx: true),
        ["guard-max3"] = new AdaptiveSampler(0, 3, 0.1, guard: true),
        ["guard-max3-c0.68"] = new AdaptiveSampler(0, 3, 0.68, guard: true),
        ["guard-min1-max5-c0.02"] = new AdaptiveSampler(1, 5, 0.02, guard: true),
        ["guard-quincunx-max2"] = new AdaptiveSampler(0, 2, 0.1, quincunx: true, guard: true),
    };

    public static TheoryData<string, string, string> Cases()
    {
        var data = new TheoryData<string, string, string>();
        foreach (string rule in Rules.Keys)
        {
            foreach (string camera in new[] { "ortho", "persp", "offaxis" })
            {
                data.Add("two-spheres", camera, rule);
            }

            if (rule is "default" or "min1-max4-c0.05" or "max3-c0.64" or "quincunx-max3-c0.7" or "guard-max3")
            {
                foreach (string camera in TestScenes.FieldCameras.Keys)
                {
                    data.Add("field", camera, rule);
                }
            }
        }

        return data;
    }

    /// <summary>The scene and camera a case names: the 960-sphere field or the two spheres, through the named camera.</summary>
    private static (Scene Scene, Camera Camera) View(string sceneName, string camera) => sceneName == "field"
        ? (TestScenes.SphereField.Value, TestScenes.FieldCameras[camera])
        : (TestScenes.TwoSpheres(), TestScenes.Cameras[camera]);

    [Theory]
    [MemberData(nameof(Cases))]
    public void TheDeviceGivesTheCpuRenderersBytesAndRaysPerPixel(string sceneName, string camera, string rule)
    {
        (Scene scene, Camera view) = View(sceneName, camera);
        AdaptiveSampler sampler = Rules[rule];
        var cpu = new Image(Width, Height);
        var device = new Image(Width, Height);
        float[] cpuRays = new float[Width * Height], deviceRays = new float[Width * Height];
        RenderStatistics cpuStats = new Renderer().Render(scene, view, sampler, cpu, cpuRays);
        RenderStatistics deviceStats = new Renderer { Device = fixture.Device }.Render(scene, view, sampler, device, deviceRays);

        Assert.Null(cpuStats.Device);
        Assert.Equal("ilgpu-cpu", deviceStats.Device);
        Assert.Equal(sceneName == "field", fixture.Device.TracesThroughHierarchy);
        Assert.True(SameBytesTests.Colours(cpu) >= 4, "the view holds the scene");
        Assert.True(sampler.MinDepth == sampler.MaxDepth || cpuRays.Distinct().Count() >= 2, "some pixels are refined");
        SameBytesTests.AssertSameBytes(cpu, device);
        int differing = cpuRays.Zip(deviceRays).Count(p => p.First != p.Second);
        Assert.True(differing == 0, $"{differing} of {cpuRays.Length} pixels' rays differ");
        // The device traces a point once per pixel that asks for it, the CPU once: never fewer on the device.
        Assert.True(deviceStats.PrimaryRays >= cpuStats.PrimaryRays);
    }

    [Theory]
    [InlineData("two-spheres", "persp", "guard-min1-max5-c0.02")]
    [InlineData("two-spheres", "ortho", "guard-max3")]
    [InlineData("field", "persp", "guard-max3")]
    public void PixelsWhoseGuardTheDeviceLeavesUndecidedAreTheHostsAndGiveTheSameBytes(string sceneName, string camera, string rule)
    {
        // Every guard test the device does not find crossing is left to the host here: those pixels are the CPU
        // rule's on the CPU's lattice formulas and guard, and the frame's bytes and rays are still the CPU renderer's.
        (Scene scene, Camera view) = View(sceneName, camera);
        AdaptiveSampler sampler = Rules[rule];
        var cpu = new Image(Width, Height);
        var device = new Image(Width, Height);
        float[] cpuRays = new float[Width * Height], deviceRays = new float[Width * Height];
        new Renderer().Render(scene, view, sampler, cpu, cpuRays);
        fixture.Device.ForceUncertainGuard = true;
        try
        {
            new Renderer { Device = fixture.Device }.Render(scene, view, sampler, device, deviceRays);
        }
        finally
        {
            fixture.Device.ForceUncertainGuard = false;
        }

        Assert.True(fixture.Device.LastHostPixels > Width, $"{fixture.Device.LastHostPixels} pixels left to the host");
        SameBytesTests.AssertSameBytes(cpu, device);
        Assert.Equal(cpuRays, deviceRays);
    }

    [Fact]
    public void ABandOfRowsGivesTheWholeRendersRowsAndRays()
    {
        Scene scene = TestScenes.TwoSpheres();
        Camera camera = TestScenes.Cameras["persp"];
        RenderMethod method = RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.1, guard: true));
        var whole = new Image(Width, Height);
        float[] wholeRays = new float[Width * Height];
        new Renderer().Render(scene, camera, method, whole, wholeRays);
        var band = new Image(Width, Height);
        float[] bandRays = new float[Width * Height];
        new Renderer { Device = fixture.Device }.RenderRows(scene, camera, method, band, 10, 7, bandRays);

        for (int y = 0; y < Height; y++)
        {
            bool inBand = y is >= 10 and < 17;
            Assert.Equal(inBand, band.GetRowSpan(y).SequenceEqual(whole.GetRowSpan(y)));
            Assert.Equal(inBand, bandRays.AsSpan(y * Width, Width).SequenceEqual(wholeRays.AsSpan(y * Width, Width)));
        }
    }

    [Fact]
    public void TheDeviceKeepsTheGoldenSetsAdaptiveBytes()
    {
        // The golden set (tests/RayLab.Tests/Golden) pins 37×23 adaptive renders of four rules on the four cameras.
        Dictionary<string, string> golden = File.ReadAllLines(Path.Combine(AppContext.BaseDirectory, "Golden", "golden.txt"))
            .Select(line => line.Split('\t'))
            .ToDictionary(parts => parts[0], parts => parts[1]);
        Scene scene = TestScenes.TwoSpheres();
        int checkedCount = 0;
        foreach ((string cameraName, Camera camera) in TestScenes.Cameras)
        {
            foreach ((string label, AdaptiveSampler adaptive) in new[]
            {
                ("default", new AdaptiveSampler()),
                ("min1-max4-c0.05", new AdaptiveSampler(1, 4, 0.05)),
                ("quincunx", new AdaptiveSampler(0, 3, 0.1, quincunx: true)),
                ("max0", new AdaptiveSampler(0, 0, 0.1)),
            })
            {
                var image = new Image(37, 23);
                RenderStatistics stats = new Renderer { Device = fixture.Device }.Render(scene, camera, adaptive, image);
                Assert.Equal("ilgpu-cpu", stats.Device);
                Assert.Equal(golden[$"{cameraName} adaptive {label}"], Convert.ToHexStringLower(SHA256.HashData(image.PixelBytes)));
                checkedCount++;
            }
        }

        Assert.Equal(16, checkedCount);
    }
}
