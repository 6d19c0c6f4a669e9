using System.Text.Json;
using RayLab.Scenes;

namespace RayLab.Cli.Tests;

public sealed class AdaptiveCliTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-adaptive-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    private static (int Code, string Out, string Err) Run(params string[] args) => ConsoleRunner.Run(args);

    [Fact]
    public void AdaptiveRenderWritesImageHeatMapAndStatsWithTheRaysTraced()
    {
        string image = Path.Combine(_dir, "a.png"), heat = Path.Combine(_dir, "heat.png"), stats = Path.Combine(_dir, "s.json");
        var r = Run("render", Scene, "-o", image, "--sampler", "adaptive", "--min-depth", "0", "--max-depth", "2",
            "--contrast", "0.1", "--width", "80", "--height", "60", "--heatmap", heat, "--stats", stats);
        Assert.True(r.Code == 0, r.Err);
        Assert.True(File.Exists(image));
        byte[] png = File.ReadAllBytes(heat);
        Assert.Equal(0x89, png[0]);
        Assert.True(BitConverter.ToInt32([png[19], png[18], png[17], png[16]]) > 80, "the heat map is wider than the image: it has a legend");

        using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
        JsonElement root = json.RootElement;
        Assert.Equal("adaptive", root.GetProperty("sampler").GetString());
        Assert.Equal(2, root.GetProperty("maxDepth").GetInt32());
        long rays = root.GetProperty("rays").GetInt64();
        // At least the corners; with edges in the picture (centres and subdivisions there), more.
        Assert.True(rays > 81L * 61, $"rays = {rays}");
        Assert.Contains($"{rays:N0} rays", r.Out);
    }

    [Theory]
    [InlineData("--max-depth", "11", "--max-depth")]
    [InlineData("--min-depth", "5", "--min-depth")]
    [InlineData("--contrast", "-1", "--contrast")]
    public void OutOfRangeAdaptiveOptionsAreOneLineErrorsNamingTheOption(string option, string value, string named)
    {
        string image = Path.Combine(_dir, "a.png");
        var r = Run("render", Scene, "-o", image, "--sampler", "adaptive", option, value);
        Assert.NotEqual(0, r.Code);
        Assert.StartsWith($"raylab: error: {named}", r.Err);
        Assert.Single(r.Err.TrimEnd().Split('\n'));
        Assert.Empty(Directory.GetFiles(_dir));
    }

    [Theory]
    [InlineData("adaptive", "--samples", "16", "--samples does not apply to the adaptive sampler (ignored)")]
    [InlineData("exact", "--samples", "16", "--samples does not apply to the exact sampler (ignored)")]
    [InlineData("jittered", "--contrast", "0.2", "--contrast applies to the adaptive sampler only, not jittered (ignored)")]
    [InlineData("jittered", "--max-depth", "2", "--max-depth applies to the adaptive sampler only, not jittered (ignored)")]
    public void AnOptionTheSamplerDoesNotUseIsNamedInAOneLineNotice(string sampler, string option, string value, string notice)
    {
        string image = Path.Combine(_dir, "n.png");
        var r = Run("render", Scene, "-o", image, "--sampler", sampler, option, value, "--width", "40", "--height", "30");
        Assert.True(r.Code == 0, r.Err);
        Assert.Equal($"raylab: note: {notice}", r.Err.TrimEnd());
        Assert.True(File.Exists(image));
    }

    [Fact]
    public void OptionsThatApplyGiveNoNotice()
    {
        string image = Path.Combine(_dir, "n.png");
        var r = Run("render", Scene, "-o", image, "--sampler", "adaptive", "--max-depth", "2", "--contrast", "0.2", "--width", "40", "--height", "30");
        Assert.True(r.Code == 0, r.Err);
        Assert.Equal("", r.Err);
        r = Run("render", Scene, "-o", image, "--sampler", "jittered", "--samples", "4", "--width", "40", "--height", "30");
        Assert.Equal("", r.Err);
    }

    [Theory]
    [InlineData(800, 600, 3, 50, 37)]      // min = max depth 3: ~256 rays a pixel, so a few thousand pixels
    [InlineData(800, 600, 0, 400, 300)]
    [InlineData(1920, 1080, 0, 480, 270)]
    [InlineData(1920, 1080, 1, 240, 135)]
    public void AnAdaptiveWarmUpIsSmallAndBoundedNeverTheWholePicture(int width, int height, int minDepth, int warmWidth, int warmHeight)
    {
        var sampler = new SamplerSettings("adaptive", 0, 0, MinDepth: minDepth, MaxDepth: 3);
        Image warm = RenderJob.WarmupImage(width, height, RenderJob.WarmupCostPerPixel(sampler));
        Assert.Equal((warmWidth, warmHeight), (warm.Width, warm.Height));
        Assert.True((long)warm.Width * warm.Height * 4 <= (long)width * height);
    }

    [Fact]
    public void TheGuardOptionReachesTheSamplerAndTheStats()
    {
        string image = Path.Combine(_dir, "g.png"), stats = Path.Combine(_dir, "g.json");
        var r = Run("render", Scene, "-o", image, "--sampler", "adaptive", "--guard", "--max-depth", "4", "--width", "80", "--height", "60", "--stats", stats);
        Assert.True(r.Code == 0, r.Err);
        Assert.Contains("guard", r.Out);
        using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
        Assert.True(json.RootElement.GetProperty("guard").GetBoolean());
    }
}
