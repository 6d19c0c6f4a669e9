using System.Globalization;
using System.Runtime.Intrinsics;
using RayLab.Reports.Comparison;
using RayLab.OwnMethod;

namespace RayLab.Cli.Tests.OwnMethod;

/// <summary>The compare API the console uses, given a student's own sampler and pixel method beside the built-in ones.</summary>
public sealed class CompareOwnMethodTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-compare-own-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    [Fact]
    public void TheReportHasTheStudentsMethodsBesideJittered()
    {
        string report = Path.Combine(_dir, "report");
        var request = new CompareRequest(Scene, report, Budgets: "4,16", Repeats: 1, Samplers: "jittered", Width: 48, Height: 36,
            Methods: [CompareCase.Sampled(new RotatedGridSampler(16), 16), CompareCase.Custom("mitchell", "4 → 16", RenderMethod.Custom(new MitchellMethod()))]);
        var stdout = new StringWriter();
        var stderr = new StringWriter();

        int code = CompareJob.Run(request, stdout, stderr, TestContext.Current.CancellationToken);

        Assert.Equal("", stderr.ToString());
        Assert.Equal(0, code);
        string[] series = [.. File.ReadAllLines(Path.Combine(report, "results.csv")).Skip(1).Select(line => line.Split(',')[0]).Distinct()];
        Assert.Equal(["jittered", "rotated-grid", "mitchell"], series);
        Assert.True(File.Exists(Path.Combine(report, "images", "rotated-grid-16.png")));
        Assert.True(File.Exists(Path.Combine(report, "images", "mitchell-4---16.png")));
        Assert.Contains("mitchell", File.ReadAllText(Path.Combine(report, "index.html")), StringComparison.Ordinal);

        // The printed table names each row's kernel and its rays per millisecond, so the student's method (a pixel
        // method: the scalar kernel) is not read as slow beside jittered (a packet kernel wherever the CPU has SIMD).
        string[][] csv = [.. File.ReadAllLines(Path.Combine(report, "results.csv")).Skip(1).Select(line => line.Split(','))];
        string[][] table = [.. stdout.ToString().Split('\n').Where(l => l.StartsWith("| ", StringComparison.Ordinal)).Skip(1)
            .Select(l => l.Split('|').Select(cell => cell.Trim()).ToArray())];
        Assert.Equal(csv.Length, table.Length);
        for (int i = 0; i < csv.Length; i++)
        {
            (string name, long rays, double ms, string kernel) = (csv[i][0], long.Parse(csv[i][7], CultureInfo.InvariantCulture),
                double.Parse(csv[i][9], CultureInfo.InvariantCulture), csv[i][15]);
            Assert.Equal(name, table[i][1]);
            Assert.Equal(kernel.ToLowerInvariant(), table[i][5]);
            Assert.Equal(rays / ms, double.Parse(table[i][6], CultureInfo.InvariantCulture), rays / ms / 100);
        }

        Assert.All(table.Where(row => row[1] == "mitchell"), row => Assert.Equal("scalar", row[5]));
        if (Vector128.IsHardwareAccelerated)
        {
            Assert.All(table.Where(row => row[1] == "jittered"), row => Assert.StartsWith("vector", row[5], StringComparison.Ordinal));
        }
    }

    [Fact]
    public void TwoMethodsWritingTheSameImageAreRejectedBeforeRendering()
    {
        string report = Path.Combine(_dir, "twice");
        var request = new CompareRequest(Scene, report, Budgets: "16", Repeats: 1, Samplers: "jittered", Width: 8, Height: 6,
            Methods: [CompareCase.Sampled(new RotatedGridSampler(16), 16), CompareCase.Sampled(new RotatedGridSampler(16), 16)]);
        var stderr = new StringWriter();

        Assert.Equal(1, CompareJob.Run(request, new StringWriter(), stderr, TestContext.Current.CancellationToken));
        Assert.Contains("rotated-grid-16.png", stderr.ToString(), StringComparison.Ordinal);
        Assert.False(Directory.Exists(report));
    }
}
