using System.Globalization;
using System.Text.RegularExpressions;
using System.Xml.Linq;
using RayLab.Reports.Comparison;
using RayLab.Metrics;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Cli.Tests;

/// <summary><c>raylab compare</c> end to end on a small scene, its option errors, and its plain progress lines.</summary>
public sealed partial class CompareTests : IDisposable
{
    // 48×32, two spheres on a background: plenty of edge pixels for the samplers to get wrong.
    private const string Scene = """
        {
          "image": { "width": 48, "height": 32 },
          "background": [0.1, 0.1, 0.15],
          "camera": { "type": "perspective", "position": [0, 0.5, 6], "target": [0, 0, 0], "fov": 40 },
          "spheres": [ { "center": [-1.1, 0, 0], "radius": 1, "color": [0.9, 0.2, 0.2] },
                       { "center": [1.2, 0.2, -1], "radius": 1.2, "color": [0.2, 0.8, 0.3] } ],
          "sampler": { "type": "adaptive", "seed": 1 }
        }
        """;

    private static readonly string[] ReportFiles = [.. CompareReport.ChartStems.SelectMany(c => new[] { c + ".png", c + ".svg" }), "index.html", "results.csv", "results.md"];

    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void WritesTheReportWithEverySamplerAndErrorsThatMatchTheImages()
    {
        string scene = WriteScene(Scene);
        string report = _dir.File("report");

        (int code, string stdout, string stderr) = Run("compare", scene, "--out", report, "--budgets", "1,4,16", "--repeats", "2",
            "--max-depths", "0,2", "--contrasts", "0.1,0.5");

        Assert.Equal("", stderr);
        Assert.Equal(0, code);
        Row[] rows = ReadCsv(Path.Combine(report, "results.csv"));
        string[] expectedSeries = [.. Samplers.Names, "adaptive c=0.1", "adaptive c=0.5", "adaptive guard c=0.1"];
        Assert.Equal(expectedSeries, rows.Select(r => r.Series).Distinct());
        Assert.Equal((Samplers.Names.Count * 3) + 6, rows.Length);
        Assert.All(rows.Where(r => r.Sampler != "adaptive"), r => Assert.Equal(r.SamplesPerPixel, r.RaysPerPixel, 9));

        // Every file is there, and the numbers in the table are those of the images on disk.
        Assert.All(ReportFiles, f => Assert.True(File.Exists(Path.Combine(report, f)), f));
        Image exact = Load(Path.Combine(report, "images", "exact.png"));
        Assert.Equal((48, 32), (exact.Width, exact.Height));
        foreach (Row row in rows)
        {
            ImageError error = ImageError.Measure(Load(Path.Combine(report, row.Image)), exact);
            Assert.Equal(error.Rmse, row.Rmse, 6);
            Assert.Equal(error.Max, row.Max);
            Assert.Equal(error.FractionOverOneLevel, row.OverOneLevel, 6);
            Assert.True(Load(Path.Combine(report, row.ErrorImage)).Width > 48, "the error image has a legend");
            Assert.Equal(Flip.Compute(exact, Load(Path.Combine(report, row.Image))).Mean, row.MeanFlip, 1e-8);
            Assert.Equal($"flip/{Path.GetFileName(row.Image)}", row.FlipMap);
            Assert.True(Load(Path.Combine(report, row.FlipMap)).Width > 48, "the FLIP map has a legend");
            Image image = Load(Path.Combine(report, row.Image));
            Assert.Equal(ErrorLocation.LowPassRmse(image, exact, 1), row.LowPass1, 1e-8);
            Assert.Equal(ErrorLocation.LowPassRmse(image, exact, 2), row.LowPass2, 1e-8);
            Assert.Equal(ErrorLocation.Spectrum(image, exact).LowFrequencyShare, row.LowShare, 1e-8);
        }

        foreach (int spp in rows.Where(r => r.SamplesPerPixel > 0).Select(r => r.SamplesPerPixel).Distinct())
        {
            Assert.True(File.Exists(Path.Combine(report, CompareReport.SpectrumStem(spp) + ".svg")), $"spectrum at {spp} spp");
        }

        // The exact image is the exact renderer's, and jittered sampling gets closer to it with every budget.
        var expected = new Image(48, 32);
        PreparedScene prepared = SceneFile.Load(scene).Prepare();
        new Renderer().Render(prepared.Scene, prepared.Camera, RenderMethod.Exact, expected);
        Assert.Equal(expected.PixelBytes.ToArray(), exact.PixelBytes.ToArray());
        double[] jittered = [.. rows.Where(r => r.Series == "jittered").Select(r => r.Rmse)];
        Assert.True(jittered[0] > jittered[1] && jittered[1] > jittered[2], string.Join(", ", jittered));

        // stdout is the table (one row per setting, as in the CSV), a line naming index.html and the run's total time: no progress.
        string[] lines = stdout.TrimEnd('\n').Split('\n');
        Assert.StartsWith("| sampler | setting |", lines[0], StringComparison.Ordinal);
        Assert.Equal(rows.Length + 4, lines.Length);
        Assert.All(lines[2..^2], l => Assert.Equal(15, l.Count(c => c == '|')));
        Assert.All(rows.Select((r, i) => (r, i)), p => Assert.StartsWith($"| {p.r.Series} | {p.r.Setting} |", lines[2 + p.i], StringComparison.Ordinal));
        Assert.Contains("index.html", lines[^2], StringComparison.Ordinal);
        // The last line lists every stage with its time, the longest first (which one that is depends on the machine).
        Match total = Regex.Match(lines[^1], @"^total time \d+\.\d s \((.+)\)$");
        Assert.True(total.Success, lines[^1]);
        (string Name, double Seconds)[] listed = [.. total.Groups[1].Value.Split(", ").Select(p => Regex.Match(p, @"^(.+) (\d+\.\d) s$"))
            .Select(m => (m.Groups[1].Value, double.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture)))];
        Assert.Contains(listed, p => p.Name == "renders");
        Assert.Equal(listed.Select(p => p.Seconds).OrderDescending(), listed.Select(p => p.Seconds));

        // The charts (ScottPlot, PNG and SVG) name every series; index.html links every file it names, and they all exist.
        foreach (string chart in CompareReport.ChartStems)
        {
            string text = string.Concat(XDocument.Load(Path.Combine(report, chart + ".svg")).Descendants(XName.Get("text", "http://www.w3.org/2000/svg")).Select(t => t.Value));
            Assert.All(expectedSeries, name => Assert.Contains(name, text, StringComparison.Ordinal));
            Assert.Equal((LogLogChart.Width, LogLogChart.Height), (SkiaDecode.Load(Path.Combine(report, chart + ".png")) is var png ? (png.Width, png.Height) : default));
        }

        string[] links = [.. Href().Matches(File.ReadAllText(Path.Combine(report, "index.html"))).Select(m => m.Groups[1].Value).Distinct()];
        // Per row its picture, error image and FLIP map; the results, the exact image, four charts and a spectrum chart per budget.
        Assert.Equal((3 * rows.Length) + 7 + 3, links.Length);
        Assert.All(links, l => Assert.True(File.Exists(Path.Combine(report, l)), l));
        Assert.DoesNotContain(_dir.Entries(), e => e.EndsWith(".tmp", StringComparison.Ordinal));

        string md = File.ReadAllText(Path.Combine(report, "results.md"));
        Assert.Contains("## Convergence slopes", md, StringComparison.Ordinal);
        Assert.Contains("## Time to mean FLIP ≤", md, StringComparison.Ordinal);
        Assert.Contains("## RMSE and FLIP: the same ranking?", md, StringComparison.Ordinal);
        Assert.Contains("## Where the error sits", md, StringComparison.Ordinal);
        Assert.Contains($"raylab compare {scene} --out {report} --budgets 1,4,16 --repeats 2", md, StringComparison.Ordinal);
    }

    [Fact]
    public void AGridSamplerRunsABudgetAtTheSquareBelowAndTheReportSaysSo()
    {
        string report = _dir.File(Path.Combine("new", "deeper", "report")); // created with its parents

        (int code, _, string stderr) = Run("compare", WriteScene(Scene), "--out", report, "--budgets", "2,5,8", "--repeats", "1",
            "--samplers", "jittered,random");

        Assert.Equal("", stderr);
        Assert.Equal(0, code);
        Row[] rows = ReadCsv(Path.Combine(report, "results.csv"));
        Assert.Equal([("jittered", 1), ("jittered", 4), ("random", 2), ("random", 5), ("random", 8)], rows.Select(r => (r.Series, r.SamplesPerPixel)));
        string md = File.ReadAllText(Path.Combine(report, "results.md"));
        Assert.Contains("jittered: budget 5 runs as 4 samples", md, StringComparison.Ordinal);
        Assert.Contains("jittered: budget 8 would be 4 samples (an n×n grid), as budget 5 is; left out.", md, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("raylab: error: --budgets: '0' is not a whole number from 1 to 65536", "--budgets", "1,0")]
    [InlineData("raylab: error: --budgets: '99999999' is not a whole number from 1 to 65536", "--budgets", "1,99999999")]
    [InlineData("raylab: error: --budgets: '4' appears twice", "--budgets", "4,16,4")]
    [InlineData("raylab: error: --budgets: an empty item in '1,,4'", "--budgets", "1,,4")]
    [InlineData("raylab: error: --budgets: 'x' is not a whole number from 1 to 65536", "--budgets", "x")]
    [InlineData("raylab: error: --max-depths: '11' is not a whole number from 0 to 10", "--max-depths", "2,11")]
    [InlineData("raylab: error: --contrasts: '-0.1' is not a number ≥ 0", "--contrasts", "-0.1")]
    [InlineData("raylab: error: --samplers: 'jitter' is not one of regular, random", "--samplers", "jitter")]
    [InlineData("raylab: error: --repeats: must be at least 1, got 0", "--repeats", "0")]
    [InlineData("raylab: error: --threads: must be at least 1, got 0", "--threads", "0")]
    [InlineData("raylab: error: --width: ", "--width", "0")]
    [InlineData("raylab: error: --height: ", "--height", "-3")]
    [InlineData("raylab: error: ", "--repeats", "three")]
    public void ABadOptionIsOneLineAndWritesNothing(string expectedStart, string option, string value)
    {
        string scene = WriteScene(Scene);
        AssertFailsCleanly(expectedStart, "compare", scene, "--out", _dir.File("report"), option, value);
    }

    [Fact]
    public void StatsSaysWhereTheTimeWentAndThePageShowsIt()
    {
        string scene = WriteScene(Scene);
        string report = _dir.File("report");
        string stats = _dir.File("stats.json");

        (int code, _, string stderr) = Run("compare", scene, "--out", report, "--budgets", "1,4", "--repeats", "1",
            "--samplers", "jittered,adaptive", "--max-depths", "0,1", "--contrasts", "0.1", "--stats", stats);

        Assert.Equal("", stderr);
        Assert.Equal(0, code);
        using var json = System.Text.Json.JsonDocument.Parse(File.ReadAllText(stats));
        System.Text.Json.JsonElement root = json.RootElement;
        // One setting per row of results.csv: jittered 1, 4; adaptive and guarded at depths 0, 1 at the one contrast.
        int settings = File.ReadAllLines(Path.Combine(report, "results.csv")).Length - 1;
        Assert.Equal(6, settings);
        Assert.Equal(settings, root.GetProperty("settings").GetInt32());
        Dictionary<string, (double Seconds, int Calls)> stages = root.GetProperty("stages").EnumerateArray()
            .ToDictionary(s => s.GetProperty("name").GetString()!, s => (s.GetProperty("seconds").GetDouble(), s.GetProperty("calls").GetInt32()));
        string[] expected = ["exact image", "renders", "8-bit error", "FLIP", "low-pass error", "error spectrum", "error images", "image files", "tables", "charts", "report into place"];
        Assert.Equal(expected.Order(StringComparer.Ordinal), stages.Keys.Order(StringComparer.Ordinal));
        Assert.Equal(settings, stages["FLIP"].Calls);
        Assert.Equal(settings, stages["error spectrum"].Calls);
        Assert.True(stages["renders"].Calls >= settings, "at least one render a setting");
        Assert.True(stages.Values.Sum(s => s.Seconds) <= root.GetProperty("totalS").GetDouble() + 0.01, "the stages run one after another, inside the total");
        string page = File.ReadAllText(Path.Combine(report, "index.html"));
        Assert.Contains("<h2>Where the time went</h2>", page, StringComparison.Ordinal);
        Assert.Contains("<td>error spectrum</td>", page, StringComparison.Ordinal);
        AssertFailsCleanly($"raylab: error: --stats: the folder '{_dir.File("no")}' does not exist", "compare", scene, "--out", _dir.File("other"),
            "--stats", Path.Combine(_dir.File("no"), "stats.json"));
    }

    [Fact]
    public void ABadSceneOrOutputFolderIsOneLineAndWritesNothing()
    {
        string scene = WriteScene(Scene);
        AssertFailsCleanly($"raylab: error: {_dir.File("missing.json")}", "compare", _dir.File("missing.json"), "--out", _dir.File("report"));
        string wide = WriteScene(Scene.Replace("\"fov\": 40", "\"fov\": 190", StringComparison.Ordinal));
        AssertFailsCleanly($"raylab: error: {wide}: camera.fov", "compare", wide, "--out", _dir.File("report"));
        string behind = WriteScene(Scene.Replace("\"center\": [-1.1, 0, 0]", "\"center\": [0, 0.5, 5.5]", StringComparison.Ordinal));
        AssertFailsCleanly($"raylab: error: {behind}: spheres[0]: ", "compare", behind, "--out", _dir.File("report")); // the exact reference cannot draw it
        AssertFailsCleanly($"raylab: error: --out: '{scene}' is a file, not a folder", "compare", scene, "--out", scene);
        AssertFailsCleanly($"raylab: error: --out: '{scene}' is a file, not a folder", "compare", scene, "--out", Path.Combine(scene, "report"));
        if (OperatingSystem.IsLinux())
        {
            // A folder nobody can create folders in, even root: named by its option, before any render.
            AssertFailsCleanly("raylab: error: --out: cannot write in the folder '/proc/raylab-report': ", "compare", scene, "--out", "/proc/raylab-report");
        }

        AssertFailsCleanly("raylab: error: --budgets:", "compare", scene, "--out", _dir.File(Path.Combine("no", "report")), "--budgets", "0");
        AssertFailsCleanly("raylab: error: ", "compare", scene); // --out is required: a command-line error
    }

    [Fact]
    public void AFileInTheWayOfTheReportFailsBeforeAnythingIsMoved()
    {
        string report = _dir.File("report");
        Directory.CreateDirectory(report);
        File.WriteAllText(Path.Combine(report, "images"), "in the way");
        string scene = WriteScene(Scene);

        AssertFailsCleanly($"raylab: error: --out: '{Path.Combine(report, "images")}'", "compare", scene, "--out", report,
            "--budgets", "1", "--repeats", "1", "--samplers", "regular");
        Assert.Equal("in the way", File.ReadAllText(Path.Combine(report, "images")));
    }

    [Fact]
    public void PlainProgressIsOneLinePerRender()
    {
        var writer = new StringWriter();
        CompareProgress progress = CompareProgress.Lines(writer, 2);
        RenderStatistics first = progress.Render("exact image", () => new RenderStatistics(10, TimeSpan.FromMilliseconds(12.34)));
        progress.Render("jittered, 4 spp (1/1)", () => new RenderStatistics(40, TimeSpan.FromMilliseconds(3)));

        Assert.Equal(10, first.PrimaryRays);
        Assert.Equal("[1/2] exact image: 12.3 ms\n[2/2] jittered, 4 spp (1/1): 3.0 ms\n", writer.ToString().ReplaceLineEndings("\n"));
    }

    // ---- helpers --------------------------------------------------------------------------------------

    private sealed record Row(string Series, string Sampler, string Setting, int SamplesPerPixel, double RaysPerPixel, double Rmse, int Max, double OverOneLevel, double MeanFlip, string Image, string ErrorImage, string FlipMap)
    {
        public double LowPass1 { get; init; }

        public double LowPass2 { get; init; }

        public double LowShare { get; init; }
    }

    private static Row[] ReadCsv(string path)
    {
        string[] lines = File.ReadAllLines(path);
        string[] header = lines[0].Split(',');
        Assert.Equal(22, header.Length);
        int Col(string name) => Array.IndexOf(header, name) is >= 0 and int i ? i : throw new InvalidOperationException($"no column {name}");
        return [.. lines[1..].Select(line =>
        {
            string[] f = line.Split(',');
            Assert.Equal(header.Length, f.Length);
            double D(string name) => double.Parse(f[Col(name)], CultureInfo.InvariantCulture);
            Assert.True(D("median_ms") >= 0);
            Assert.True(long.Parse(f[Col("rays")], CultureInfo.InvariantCulture) > 0);
            return new Row(f[Col("series")], f[Col("sampler")], f[Col("setting")],
                f[Col("samples_per_pixel")] is { Length: > 0 } spp ? int.Parse(spp, CultureInfo.InvariantCulture) : 0,
                D("rays_per_pixel"), D("rmse"), int.Parse(f[Col("max")], CultureInfo.InvariantCulture), D("over_one_level"), D("mean_flip"),
                f[Col("image")], f[Col("error_image")], f[Col("flip_map")])
            {
                LowPass1 = D("lowpass_1"),
                LowPass2 = D("lowpass_2"),
                LowShare = D("low_frequency_share"),
            };
        })];
    }

    private static Image Load(string path)
    {
        SkiaDecode.Result png = SkiaDecode.Decode(File.ReadAllBytes(path));
        var image = new Image(png.Width, png.Height);
        png.Rgb.CopyTo(image.PixelBytes);
        return image;
    }

    private void AssertFailsCleanly(string expectedStart, params string[] args)
    {
        string[] before = _dir.Entries();
        (int code, string stdout, string stderr) = Run(args);

        Assert.True(code is 1 or 2, $"exit code {code}");
        Assert.Equal("", stdout);
        string line = Assert.Single(stderr.TrimEnd('\n').Split('\n'));
        Assert.StartsWith(expectedStart, line, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", stderr, StringComparison.Ordinal);
        Assert.Equal(before, _dir.Entries());
    }

    private string WriteScene(string json)
    {
        string path = _dir.File($"scene-{Guid.NewGuid():N}.json");
        File.WriteAllText(path, json);
        return path;
    }

    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString().ReplaceLineEndings("\n"), stderr.ToString().ReplaceLineEndings("\n"));
    }

    [GeneratedRegex("href=\"([^\"#]+)\"")]
    private static partial Regex Href();
}
