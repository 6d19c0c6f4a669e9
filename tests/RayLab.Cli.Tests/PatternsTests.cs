using System.Text.RegularExpressions;
using RayLab.Reports.Patterns;
using RayLab.Sampling;

namespace RayLab.Cli.Tests;

/// <summary><c>raylab patterns</c>: a small run (two samplers, few realisations), determinism, and bad input.</summary>
public sealed partial class PatternsTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    private static PatternsRequest Small(string folder, uint seed = 1) => new(
        folder,
        [PatternSampler.BuiltIn("jittered"), PatternSampler.BuiltIn("nrooks")],
        Samples: 16,
        Seed: seed,
        SpectrumSamples: 16,
        SpectrumRealisations: 32,
        Measures: new PatternMeasureOptions(DiscrepancyRealisations: 1, StarMaxSamples: 16, IntegrationRealisations: 4));

    private static (int Code, string Out, string Err) Run(PatternsRequest request)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = PatternsJob.Run(request, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void The_same_seed_writes_the_same_files_and_every_figure_the_page_shows_is_there()
    {
        string a = _dir.File("a"), b = _dir.File("b");
        (int code, string output, string error) = Run(Small(a));
        Assert.True(code == 0, error);
        Assert.Equal(0, Run(Small(b)).Code);

        string[] files = [.. Directory.GetFiles(a).Select(Path.GetFileName).Order(StringComparer.Ordinal)!];
        Assert.Equal(files, Directory.GetFiles(b).Select(Path.GetFileName).Order(StringComparer.Ordinal));
        foreach (string file in files)
        {
            Assert.True(File.ReadAllBytes(Path.Combine(a, file)).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(b, file))), $"{file} differs");
        }

        string html = File.ReadAllText(Path.Combine(a, "index.html"));
        string[] images = [.. ImageSource().Matches(html).Select(m => m.Groups[1].Value)];
        Assert.Contains("pixel-jittered-strata.png", images);
        Assert.Contains("adaptive.png", images);
        Assert.Contains("rmse-disc.png", images);
        foreach (string image in images)
        {
            byte[] png = File.ReadAllBytes(Path.Combine(a, image));
            Assert.Equal([0x89, (byte)'P', (byte)'N', (byte)'G'], png[..4]);
            Assert.True(File.Exists(Path.Combine(a, Path.ChangeExtension(image, ".svg"))), $"{image} has no SVG");
        }

        Assert.DoesNotContain(Directory.EnumerateFileSystemEntries(a), e => Path.GetFileName(e).StartsWith('.'));
        Assert.Matches(@"jittered +slopes: disc -?\d\.\d\d", output);
        string[] csv = File.ReadAllLines(Path.Combine(a, "patterns.csv"));
        Assert.Equal("sampler,samples,l2_star,star,rmse_disc,rmse_gaussian,rmse_bilinear-step", csv[0]);
        Assert.Equal(PatternMeasures.Counts(squaresOnly: true).Count + PatternMeasures.Counts().Count, csv.Length - 1);
    }

    [Fact]
    public void Another_seed_draws_other_points()
    {
        string a = _dir.File("a"), b = _dir.File("b");
        Assert.Equal(0, Run(Small(a, seed: 1)).Code);
        Assert.Equal(0, Run(Small(b, seed: 2)).Code);
        Assert.False(File.ReadAllBytes(Path.Combine(a, "pixel-jittered.svg")).AsSpan().SequenceEqual(File.ReadAllBytes(Path.Combine(b, "pixel-jittered.svg"))));
    }

    [Fact]
    public void A_sampler_of_your_own_is_drawn_and_measured_beside_the_built_in_ones()
    {
        string a = _dir.File("own");
        var request = Small(a) with { Samplers = [PatternSampler.BuiltIn("random"), new PatternSampler("diagonal", (n, _) => new Diagonal(n))] };
        (int code, _, string error) = Run(request);
        Assert.True(code == 0, error);
        Assert.True(File.Exists(Path.Combine(a, "pixel-diagonal.png")));
        Assert.Contains(File.ReadAllLines(Path.Combine(a, "patterns.csv")), l => l.StartsWith("diagonal,1024,", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData("--sampler", "jitterd", "--sampler: unknown sampler 'jitterd'", "did you mean 'jittered'?")]
    [InlineData("--samples", "10", "--samples: regular needs a perfect square", "got 10")]
    [InlineData("--samples", "2000", "--samples: expected 1 to 1024", "got 2000")]
    [InlineData("--sampler", "random", "--sampler: 'random' appears twice", "twice", "--sampler", "Random")]
    public void Bad_options_are_one_line_and_write_nothing(string option, string value, string start, string end, params string[] more)
    {
        string folder = _dir.File("out");
        (int code, string _, string error) = ConsoleRunner.Run(["patterns", "--out", folder, option, value, .. more]);
        Assert.Equal(1, code);
        Assert.StartsWith($"raylab: error: {start}", error);
        Assert.Contains(end, error);
        Assert.Single(error.TrimEnd().Split('\n'));
        Assert.False(Directory.Exists(folder));
    }

    [Fact]
    public void An_output_that_is_a_file_is_an_error()
    {
        string file = _dir.File("taken");
        File.WriteAllText(file, "x");
        (int code, string _, string error) = ConsoleRunner.Run("patterns", "--out", file, "--sampler", "random");
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --out: '{file}' is a file, not a folder", error.TrimEnd());
    }

    [Fact]
    public void A_folder_where_a_file_goes_stops_the_run_before_anything_is_moved()
    {
        string folder = _dir.File("blocked");
        string blocker = Path.Combine(folder, "patterns.csv");
        Directory.CreateDirectory(blocker);
        (int code, _, string error) = Run(Small(folder));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --out: '{blocker}' is a folder where the report writes a file", error.TrimEnd());
        Assert.Equal([blocker], Directory.EnumerateFileSystemEntries(folder));
    }

    [GeneratedRegex("<img src=\"([^\"]+)\"")]
    private static partial Regex ImageSource();

    private sealed class Diagonal(int n) : IPixelSampler
    {
        public string Name => "diagonal";

        public int SamplesPerPixel => n;

        public uint Seed => 0;

        public SamplePoint GetSample(int x, int y, int index) => new((index + 0.5) / n, (index + 0.5) / n);
    }
}
