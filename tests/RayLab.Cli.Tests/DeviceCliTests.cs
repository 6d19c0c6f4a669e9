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

    [Fact]
    public void CompareOnTheDeviceGivesTheCpusPicturesAndSaysWhichDeviceRanAndItsFirstLaunch()
    {
        // The device kernels' own code on ILGPU's CPU accelerator, at a tiny size: every picture's bytes are the CPU
        // run's, the report's heading and --stats name the device, and the first launch is a stage of its own.
        string[] common = ["--samplers", "jittered,sobol,adaptive", "--budgets", "1,4", "--max-depths", "1,2", "--contrasts", "0.1", "--repeats", "1", "--width", "24", "--height", "16"];
        string cpuReport = Path.Combine(_dir, "cpu"), deviceReport = Path.Combine(_dir, "device"), stats = Path.Combine(_dir, "compare.json");
        var cpu = ConsoleRunner.Run(["compare", Scene, "--out", cpuReport, .. common]);
        var device = ConsoleRunner.Run(["compare", Scene, "--out", deviceReport, .. common, "--device", "ilgpu-cpu", "--stats", stats]);

        Assert.True(cpu.Code == 0, cpu.Err);
        Assert.True(device.Code == 0, device.Err);
        string[] pictures = [.. Directory.GetFiles(Path.Combine(cpuReport, "images")).Select(Path.GetFileName).Order(StringComparer.Ordinal)!];
        Assert.Equal(9, pictures.Length); // exact, 2 samplers × 2 budgets, adaptive and guarded adaptive at 2 depths each
        foreach (string picture in pictures)
        {
            Assert.True(File.ReadAllBytes(Path.Combine(cpuReport, "images", picture)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(deviceReport, "images", picture))), picture);
        }

        Assert.Contains("renders on ilgpu-cpu", File.ReadAllText(Path.Combine(deviceReport, "index.html")), StringComparison.Ordinal);
        Assert.Contains("renders on cpu", File.ReadAllText(Path.Combine(cpuReport, "index.html")), StringComparison.Ordinal);
        Assert.Contains("--device ilgpu-cpu", File.ReadAllText(Path.Combine(deviceReport, "index.html")), StringComparison.Ordinal);
        JsonElement root = JsonDocument.Parse(File.ReadAllText(stats)).RootElement;
        Assert.Equal("ilgpu-cpu", root.GetProperty("device").GetString());
        Assert.True(root.GetProperty("firstLaunchMs").GetDouble() > 0);
        Assert.Contains(root.GetProperty("stages").EnumerateArray(), stage => stage.GetProperty("name").GetString() == "device first launch");
    }

    [Fact]
    public void CompareWithAnUnknownDeviceIsAOneLineErrorAndNoReport()
    {
        string report = Path.Combine(_dir, "report");
        var r = ConsoleRunner.Run("compare", Scene, "--out", report, "--device", "quantum");
        Assert.Equal(1, r.Code);
        Assert.Equal("raylab: error: --device: unknown device 'quantum'; expected one of: cpu, gpu, auto", r.Err.TrimEnd());
        Assert.False(Directory.Exists(report));
    }

    [Fact]
    public void CompareWithoutAGpuOnTheGpuDeviceIsAOneLineErrorAndNoReport()
    {
        Assert.SkipWhen(GpuDevice.IsCudaAvailable(), "a CUDA GPU is present");
        string report = Path.Combine(_dir, "report");
        var r = ConsoleRunner.Run("compare", Scene, "--out", report, "--samplers", "jittered", "--budgets", "1", "--device", "gpu", "--width", "8", "--height", "6");
        Assert.Equal(1, r.Code);
        Assert.StartsWith("raylab: error: --device gpu: No CUDA GPU: ", r.Err, StringComparison.Ordinal);
        Assert.Single(r.Err.TrimEnd().Split('\n'));
        Assert.False(Directory.Exists(report));
    }
}
