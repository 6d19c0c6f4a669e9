using System.Text.Json;

namespace RayLab.Tests.Cli;

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
}
