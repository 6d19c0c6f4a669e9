using System.Text.Json;

namespace RayLab.Cli.Tests;

/// <summary>The console's --kernel and --quincunx options and the statistics they show.</summary>
public sealed class KernelCliTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-kernel-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    private static (int Code, string Out, string Err) Run(params string[] args) => ConsoleRunner.Run(args);

    private JsonElement Stats(params string[] options)
    {
        string image = Path.Combine(_dir, "k.png"), stats = Path.Combine(_dir, "k.json");
        var r = Run(["render", Scene, "-o", image, "--width", "48", "--height", "32", "--stats", stats, "--warmup", .. options]);
        Assert.True(r.Code == 0, r.Err);
        return JsonDocument.Parse(File.ReadAllText(stats)).RootElement;
    }

    [Theory]
    [InlineData("scalar")]
    [InlineData("vector128")]
    [InlineData("vector256")]
    [InlineData("vector512")]
    public void TheKernelAskedForIsTheOneThatRendersAndTheStatsSaySo(string kernel)
    {
        JsonElement stats = Stats("--sampler", "jittered", "--samples", "4", "--kernel", kernel);
        Assert.Equal(kernel, stats.GetProperty("kernel").GetString());
        Assert.True(stats.GetProperty("warmupMs").GetDouble() > 0);
        Assert.True(stats.GetProperty("retracedSamples").GetInt64() >= 0);
    }

    /// <summary>
    /// The built app started on its own (raylab.dll with its own runtimeconfig.json, as <c>dotnet run</c> and the JIT tool
    /// start it) is the JIT build, and its printed time says it includes JIT compilation: Native AOT's feature switches
    /// (IsDynamicCodeSupported false) must not reach its runtimeconfig.json, where the native build's project settings
    /// could put them. <c>--stats</c> alone does not warm up: it reports the render as done.
    /// </summary>
    [Fact]
    public async Task TheBuiltAppStartedOnItsOwnIsTheJitBuildAndStatsAloneDoNotWarmUp()
    {
        string stats = Path.Combine(_dir, "child.json");
        var r = await ConsoleRunner.RunChildAsync(_dir, "render", Scene, "-o", "child.png", "--width", "48", "--height", "32", "--stats", stats);
        Assert.True(r.Code == 0, r.Err);
        Assert.Contains("JIT build: includes compiling", r.Out, StringComparison.Ordinal);
        JsonElement root = JsonDocument.Parse(File.ReadAllText(stats)).RootElement;
        Assert.False(root.TryGetProperty("warmupMs", out _), "--stats alone made a warm-up render");
        Assert.False(root.TryGetProperty("commitMs", out _), "--stats alone committed the image's pages");
    }

    [Fact]
    public void Warmup_renders_first_and_the_printed_time_says_so()
    {
        string image = Path.Combine(_dir, "w.png"), stats = Path.Combine(_dir, "w.json");
        var r = Run(["render", Scene, "-o", image, "--width", "48", "--height", "32", "--warmup", "--stats", stats]);
        Assert.True(r.Code == 0, r.Err);
        JsonElement root = JsonDocument.Parse(File.ReadAllText(stats)).RootElement;
        Assert.True(root.GetProperty("warmupMs").GetDouble() > 0);
        Assert.True(root.GetProperty("commitMs").GetDouble() >= 0);
        Assert.Matches(@"Mrays/s; after a \d+\.\d ms warm-up render\)", r.Out);
    }

    [Theory]
    [InlineData(1920, 1080, 16, 480, 270)]   // the benchmark: 1/16 of its samples
    [InlineData(3840, 2160, 1024, 60, 33)]
    [InlineData(48, 32, 4, 48, 32)]          // small renders warm up on the whole picture
    [InlineData(1000000, 4, 16, 166666, 1)]  // never below one pixel on a side
    public void TheWarmUpIsTheSamePictureScaledDownToAFewMillionSamples(int width, int height, int spp, int warmWidth, int warmHeight)
    {
        Image warm = RenderJob.WarmupImage(width, height, spp);
        Assert.Equal((warmWidth, warmHeight), (warm.Width, warm.Height));
        Assert.True((double)warm.Width * warm.Height * spp <= Math.Max(RenderJob.WarmupSamples, (double)width * height * spp));
    }

    [Fact]
    public void AnUnknownKernelIsAOneLineErrorListingTheChoices()
    {
        string image = Path.Combine(_dir, "k.png");
        var r = Run("render", Scene, "-o", image, "--kernel", "avx");
        Assert.Equal(1, r.Code);
        Assert.Equal("raylab: error: --kernel: unknown kernel 'avx'; expected one of: auto, scalar, vector128, vector256, vector512", r.Err.TrimEnd());
        Assert.Empty(Directory.GetFiles(_dir));
    }

    [Fact]
    public void TheQuincunxTracesEveryCentre()
    {
        long without = Stats("--sampler", "adaptive").GetProperty("rays").GetInt64();
        JsonElement with = Stats("--sampler", "adaptive", "--quincunx");
        Assert.True(with.GetProperty("quincunx").GetBoolean());
        Assert.True(with.GetProperty("rays").GetInt64() >= without + (48 * 32 * 9 / 10), $"{with.GetProperty("rays")} vs {without}");
    }
}
