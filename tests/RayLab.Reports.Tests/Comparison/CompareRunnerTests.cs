using RayLab.Reports.Comparison;
using RayLab.Reports.Imaging;
using RayLab.OwnMethod;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Reports.Tests.Comparison;

/// <summary>The library's compare API on its own, as a project outside the repository calls it.</summary>
public sealed class CompareRunnerTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-compare-runner-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static PreparedScene Lab(int width, int height)
    {
        SceneDescription d = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json"));
        return (d with { Width = width, Height = height }).Prepare();
    }

    [Fact]
    public void RunWritesTheReportWithYourMethodsBesideTheBuiltInOnes()
    {
        PreparedScene lab = Lab(32, 24);
        string folder = Path.Combine(_dir, "nested", "report");
        CompareCase[] cases =
        [
            CompareCase.Sampled(new JitteredSampler(4, seed: 1), 4),
            CompareCase.Sampled(new RotatedGridSampler(16), 16),
            CompareCase.Custom("mitchell", "4 → 16", RenderMethod.Custom(new MitchellMethod())),
        ];

        CompareReport report = CompareRunner.Run(lab.Scene, lab.Camera, 32, 24, cases, folder, new CompareSettings(Repeats: 1),
            TestContext.Current.CancellationToken);

        Assert.Equal(["jittered", "rotated-grid", "mitchell"], report.Series.Select(s => s.Key));
        foreach (string file in new[] { "index.html", "results.md", "error-vs-time.svg", "error-vs-rays.svg", "error-vs-time.png", "error-vs-rays.png", "images/exact.png", "errors/mitchell-4---16.png" })
        {
            Assert.True(File.Exists(Path.Combine(folder, file)), $"{file} was not written");
        }

        // Each picture's mean FLIP is the library's against the exact image, and its map is beside its error image.
        Image exact = Image.Load(Path.Combine(folder, "images", "exact.png"));
        foreach (CompareResult r in report.Series.SelectMany(s => s))
        {
            string stem = r.Case.FileStem;
            Assert.Equal(RayLab.Metrics.Flip.Compute(exact, Image.Load(Path.Combine(folder, "images", stem + ".png"))).Mean, r.MeanFlip);
            Assert.True(Image.Load(Path.Combine(folder, "flip", stem + ".png")).Width > 32, $"flip/{stem}.png has a colour bar");
        }

        Assert.All(CompareReport.ChartStems, c => Assert.True(File.Exists(Path.Combine(folder, c + ".svg")), c));
        string[] rows = [.. File.ReadAllLines(Path.Combine(folder, "results.csv")).Skip(1)];
        Assert.Equal(["jittered", "rotated-grid", "mitchell"], rows.Select(r => r.Split(',')[0]));
        Assert.Contains("32×24", File.ReadAllText(Path.Combine(folder, "results.md")), StringComparison.Ordinal);
        Assert.DoesNotContain("Made by", File.ReadAllText(Path.Combine(folder, "index.html")), StringComparison.Ordinal);
    }

    [Fact]
    public void ARenderOfASecondOrMoreIsTimedOnceAndAQuickOneIsRepeated()
    {
        PreparedScene lab = Lab(2, 1);
        var slow = new CountingMethod();
        CompareCase[] cases = [CompareCase.Custom("slow", "reported as a second", RenderMethod.Custom(slow)), CompareCase.Sampled(new JitteredSampler(1, seed: 1), 1)];
        // No render takes a second: the runner times each counted render by the statistics the progress hands back,
        // and this progress reports the slow setting's renders as LongRender long and every other as 1 ms.
        var progress = new CountingProgress(label => label.StartsWith("slow,", StringComparison.Ordinal) ? CompareRunner.LongRender : TimeSpan.FromMilliseconds(1));

        CompareMeasurement measured = CompareRunner.Measure(lab.Scene, lab.Camera, 2, 1, cases, _dir, new CompareSettings(Repeats: 3, Progress: progress),
            TestContext.Current.CancellationToken);

        Assert.Equal(1, slow.Renders);
        Assert.True(measured.Results[0].TimedOnce);
        Assert.Equal(1, measured.Results[0].Renders);
        Assert.Equal(CompareRunner.LongRender, measured.Results[0].Time);
        Assert.False(measured.Results[1].TimedOnce);
        Assert.True(measured.Results[1].Renders >= 3, $"the quick setting was rendered {measured.Results[1].Renders} times");
        Assert.Equal(1 + (2 * 3), progress.Counted);
    }

    [Theory]
    [InlineData(new double[] { 10, 10.2, 10.1 }, true)]
    [InlineData(new double[] { 10, 10.6, 10.1 }, false)]
    [InlineData(new double[] { 10, 10.2 }, false)]
    [InlineData(new double[] { 10, 10.2, 30 }, false)]
    [InlineData(new double[] { 10, 10.2, 30, 10.1 }, false)]
    [InlineData(new double[] { 10, 10.2, 30, 10.1, 10.3 }, true)]
    [InlineData(new double[] { 4, 10.2, 30, 10.1, 10.3 }, true)]
    [InlineData(new double[] { 4, 10.2, 30, 9, 10.3 }, false)]
    public void AQuickSettingsMedianStandsWhenTheRendersBesideItAgreeWithinFivePerCent(double[] milliseconds, bool agree)
    {
        Assert.Equal(agree, CompareRunner.Agree([.. milliseconds.Select(TimeSpan.FromMilliseconds)]));
    }

    /// <summary>A method that counts its renders (on their first pixel).</summary>
    private sealed class CountingMethod : IPixelMethod<int>
    {
        public int Renders { get; private set; }

        public string Name => "slow";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch)
        {
            if (pixel.X == 0 && pixel.Row == 0)
            {
                Renders++;
            }

            return pixel.Trace(0.5, 0.5);
        }
    }

    /// <summary>
    /// Counts renders as a progress bar would (each render and each planned repeat left out), and stands in for the
    /// clock: each render's statistics come back with the time <paramref name="renderTime"/> gives for its label.
    /// </summary>
    private sealed class CountingProgress(Func<string, TimeSpan> renderTime) : ICompareProgress
    {
        public int Counted { get; private set; }

        public RenderStatistics Render(string label, Func<RenderStatistics> render)
        {
            Counted++;
            return render() with { RenderTime = renderTime(label) };
        }

        public void Skipped(int renders) => Counted += renders;
    }

    [Fact]
    public void SettingsSharingAnImageAreRejectedBeforeAnythingIsWritten()
    {
        PreparedScene lab = Lab(8, 6);
        string folder = Directory.CreateDirectory(Path.Combine(_dir, "twice")).FullName;
        CompareCase[] cases = [CompareCase.Sampled(new RotatedGridSampler(16), 16), CompareCase.Sampled(new RotatedGridSampler(16), 16)];

        var e = Assert.Throws<ArgumentException>(() => CompareRunner.Measure(lab.Scene, lab.Camera, 8, 6, cases, folder, new CompareSettings(), TestContext.Current.CancellationToken));

        Assert.Equal("cases", e.ParamName);
        Assert.Contains("rotated-grid-16.png", e.Message, StringComparison.Ordinal);
        Assert.Empty(Directory.EnumerateFileSystemEntries(folder));
    }

    [Fact]
    public void BadArgumentsNameTheirParameter()
    {
        PreparedScene lab = Lab(8, 6);
        CompareCase[] one = [CompareCase.Sampled(new JitteredSampler(4, seed: 1), 4)];

        Assert.Equal("cases", Assert.Throws<ArgumentException>(() => CompareRunner.Measure(lab.Scene, lab.Camera, 8, 6, [], _dir, new CompareSettings(), TestContext.Current.CancellationToken)).ParamName);
        Assert.Equal("settings", Assert.Throws<ArgumentException>(() => CompareRunner.Measure(lab.Scene, lab.Camera, 8, 6, one, _dir, new CompareSettings(Repeats: 0), TestContext.Current.CancellationToken)).ParamName);
        Assert.Equal("width", Assert.Throws<ArgumentOutOfRangeException>(() => CompareRunner.Measure(lab.Scene, lab.Camera, 0, 6, one, _dir, new CompareSettings(), TestContext.Current.CancellationToken)).ParamName);
        Assert.Equal("folder", Assert.Throws<ArgumentException>(() => CompareRunner.Run(lab.Scene, lab.Camera, 8, 6, one, " ", cancellation: TestContext.Current.CancellationToken)).ParamName);
    }

    [Fact]
    public void TheBuiltInPlanSquaresGridBudgetsAndAddsTheGuardedLine()
    {
        var notes = new List<string>();

        IReadOnlyList<CompareCase> cases = ComparePlan.BuiltIn(["regular", "adaptive"], [4, 8, 9], [1, 2], [0.1, 0.01], 1, notes);

        Assert.Equal(["regular-4", "regular-9", "adaptive-c0.1-d1", "adaptive-c0.1-d2", "adaptive-c0.01-d1", "adaptive-c0.01-d2", "adaptive-guard-c0.01-d1", "adaptive-guard-c0.01-d2"],
            cases.Select(c => c.FileStem));
        Assert.Single(notes, n => n.Contains("budget 8 would be 4 samples", StringComparison.Ordinal));
        Assert.Equal("samplers", Assert.Throws<ArgumentException>(() => ComparePlan.BuiltIn(["nope"], [1], [1], [0.1], 1, notes)).ParamName);
    }

    [Fact]
    public void TheOwnMethodGuidesSnippetIsWhatTheSampleRuns()
    {
        string repo = RepoPaths.Root();

        string readme = File.ReadAllText(Path.Combine(repo, "docs", "own-method.md"));
        string sample = File.ReadAllText(Path.Combine(repo, "samples", "RayLab.OwnMethod", "SpeedAgainstError.cs"));
        int start = readme.IndexOf("```csharp\nusing RayLab.Reports.Comparison;\n", StringComparison.Ordinal);
        Assert.True(start >= 0, "docs/own-method.md has no compare snippet");
        string[] lines = [.. readme[start..readme.IndexOf("\n```\n", start + 3, StringComparison.Ordinal)].Split('\n')
            .Skip(1).Select(l => l.Trim()).Where(l => l.StartsWith("CompareCase.", StringComparison.Ordinal) || l.StartsWith("using", StringComparison.Ordinal))];
        Assert.Equal(4, lines.Length);
        Assert.All(lines, l => Assert.Contains(l, sample, StringComparison.Ordinal));
        Assert.Contains("CompareRunner.Run(prepared.Scene, prepared.Camera, width, height, cases, folder, new CompareSettings(Repeats: 1));", sample, StringComparison.Ordinal);
    }
}
