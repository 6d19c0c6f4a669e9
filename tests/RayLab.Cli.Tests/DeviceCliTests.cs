using System.Text.Json;
using RayLab.Gpu;

namespace RayLab.Cli.Tests;

/// <summary>The console's --device option (the JIT build, which carries the GPU device) and the stats it writes.</summary>
public sealed class DeviceCliTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-device-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    [Fact]
    public void WithoutAGpuTheGpuDeviceIsAOneLineErrorAndNoFile()
    {
        Assert.SkipWhen(GpuDevice.IsCudaAvailable(), "a CUDA GPU is present");
        string image = Path.Combine(_dir, "d.png");
        var r = ConsoleRunner.Run("render", Scene, "-o", image, "--device", "gpu");
        Assert.Equal(1, r.Code);
        Assert.StartsWith("raylab: error: --device gpu: No CUDA GPU: ", r.Err, StringComparison.Ordinal);
        Assert.Single(r.Err.TrimEnd().Split('\n'));
        Assert.Empty(Directory.GetFiles(_dir));
    }

    [Theory]
    [InlineData("cpu")]
    [InlineData("auto")]
    public void TheDeviceThatRenderedIsInTheStats(string device)
    {
        bool gpu = device == "auto" && GpuDevice.IsCudaAvailable();
        string image = Path.Combine(_dir, "d.png"), stats = Path.Combine(_dir, "d.json");
        var r = ConsoleRunner.Run("render", Scene, "-o", image, "--width", "48", "--height", "32", "--sampler", "jittered", "--samples", "4", "--device", device, "--stats", stats);
        Assert.True(r.Code == 0, r.Err);
        string? written = JsonDocument.Parse(File.ReadAllText(stats)).RootElement.GetProperty("device").GetString();
        Assert.Equal(gpu, written != "cpu");
    }

    [Fact]
    public void AnUnknownDeviceIsAOneLineErrorListingTheChoices()
    {
        var r = ConsoleRunner.Run("render", Scene, "-o", Path.Combine(_dir, "d.png"), "--device", "quantum");
        Assert.Equal(1, r.Code);
        Assert.Equal("raylab: error: --device: unknown device 'quantum'; expected one of: cpu, gpu, auto", r.Err.TrimEnd());
    }
}
