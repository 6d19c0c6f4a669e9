using RayLab.Reports.Comparison;
using RayLab.Metrics;
using RayLab.OwnMethod;
using RayLab.Sampling;

namespace RayLab.Reports.Tests.Comparison;

/// <summary>The report's arithmetic on results whose answers are known: slopes, costs to reach an RMSE, the winner.</summary>
public class CompareReportTests
{
    [Fact]
    public void TheSlopeOfAPowerLawIsItsExponent()
    {
        Assert.Equal(-0.75, CompareReport.Slope([(1, 3), (4, 3 * Math.Pow(4, -0.75)), (16, 3 * Math.Pow(16, -0.75)), (64, 3 * Math.Pow(64, -0.75))])!.Value, 12);
        // Points with a zero coordinate cannot be on a log scale and are left out; one x is not enough for a line.
        Assert.Equal(-0.5, CompareReport.Slope([(1, 2), (100, 0.2), (1000, 0)])!.Value, 12);
        Assert.Null(CompareReport.Slope([(4, 1), (4, 2), (8, 0)]));
    }

    [Fact]
    public void TheCostToReachAnRmseIsInterpolatedOnTheLogLogLine()
    {
        CompareResult[] line = [Result("jittered", 16, 0.25, 160), Result("jittered", 1, 4, 10), Result("jittered", 4, 1, 40)];

        // RMSE 2 is halfway (in logs) from 4 to 1: halfway from 10 ms to 40 ms is 20 ms, from 1 ray to 4 is 2.
        Assert.Equal(20, CompareReport.CostToReach(line, 2, r => r.Time.TotalMilliseconds)!.Value, 9);
        Assert.Equal(2, CompareReport.CostToReach(line, 2, r => r.RaysPerPixel)!.Value, 9);
        Assert.Equal(40, CompareReport.CostToReach(line, 1, r => r.Time.TotalMilliseconds)!.Value, 9);
        Assert.Equal(10, CompareReport.CostToReach(line, 5, r => r.Time.TotalMilliseconds)!.Value, 9);
        Assert.Null(CompareReport.CostToReach(line, 0.1, r => r.Time.TotalMilliseconds));
    }

    [Fact]
    public void WithinOneLevelIsTheFastestSettingWithNoPixelMoreThanALevelOff()
    {
        CompareResult[] line = [Result("sobol", 4, 1, 50, max: 3), Result("sobol", 16, 0.5, 90, max: 1), Result("sobol", 64, 0.2, 70, max: 0)];

        Assert.Same(line[2], CompareReport.WithinOneLevel(line));
        Assert.Null(CompareReport.WithinOneLevel(line[..1]));
    }

    [Fact]
    public void TheCsvKeepsARenderTimeToTheTickSoASmallRenderRateIsNotRoundedAway()
    {
        // A 48×36 render takes about 0.03 ms: three decimals would move rays / ms by over 1 %.
        string csv = new CompareReport("h", "c", [Result("jittered", 16, 1, 0.0286)], []).Csv();

        Assert.Equal("0.0286", csv.Split('\n')[1].Split(',')[9]);
    }

    [Fact]
    public void TheMarkdownRanksTheLinesAndLeavesOutSlopesItCannotFit()
    {
        CompareResult[] results =
        [
            Result("regular", 1, 4, 10), Result("regular", 4, 1, 20), Result("regular", 16, 0.25, 40),
            Result("random", 1, 4, 10), Result("random", 4, 2, 40), Result("random", 16, 1, 160),
            Adaptive(0, 1.00, 1.5, 30), Adaptive(3, 1.10, 1.2, 35),
        ];

        string md = new CompareReport("heading", "raylab compare x --out y", results, ["a note"]).Markdown();

        Assert.Contains("| regular | -1.00 | -1.00 | n/a | 3 |", md, StringComparison.Ordinal);
        Assert.Contains("| random | -0.50 | -0.50 | n/a | 3 |", md, StringComparison.Ordinal);
        Assert.Contains("| adaptive c=0.1 | n/a | n/a (rays span less than 2×) | n/a | 2 |", md, StringComparison.Ordinal);
        // Every line reaches 1.2 (the adaptive line's best); regular gets there first, between 10 and 20 ms (in logs).
        Assert.Contains("## Time to RMSE ≤ 1.200 (the lowest RMSE every line reaches)", md, StringComparison.Ordinal);
        double regular = Math.Exp(Math.Log(10) + (Math.Log(1.2 / 4) / Math.Log(1 / 4.0) * Math.Log(2)));
        Assert.Contains(FormattableString.Invariant($"| regular | {regular:F1} | 1.00 |"), md, StringComparison.Ordinal);
        Assert.Contains(FormattableString.Invariant($"| adaptive c=0.1 | 35.0 | {35 / regular:F2} | 1.10 |"), md, StringComparison.Ordinal);
        // Every point sampler reaches 1 (random's best), adaptive does not.
        Assert.Contains("## Time to RMSE ≤ 1.000 (the lowest RMSE every point sampler reaches)", md, StringComparison.Ordinal);
        Assert.Contains("| adaptive c=0.1 | not reached | | |", md, StringComparison.Ordinal);
        Assert.Contains("| random | 160.0 | 8.00 | 16.00 |", md, StringComparison.Ordinal);
        Assert.Contains("- a note", md, StringComparison.Ordinal);
        Assert.EndsWith("```\nraylab compare x --out y\n```\n", md, StringComparison.Ordinal);
    }

    [Fact]
    public void NoSlopeIsFittedThroughAPlateau()
    {
        // Falls as rays^-0.5 up to 16 rays, then stays flat: the slope is the falling part's, and says where it stops.
        CompareResult[] results =
        [
            Adaptive(1, 1, 4, 10), Adaptive(2, 4, 2, 20), Adaptive(3, 16, 1, 40), Adaptive(4, 64, 0.99, 80), Adaptive(5, 256, 1.0, 160),
            Result("random", 1, 4, 10), Result("random", 4, 3.9, 20), Result("random", 16, 3.95, 40),
        ];

        Assert.Equal(3, CompareReport.BeforePlateau([.. results[..5]]).Length);
        string md = new CompareReport("heading", "raylab compare x --out y", results, []).Markdown();

        Assert.Contains("| adaptive c=0.1 | -0.50 | -0.50 (fitted below 64 rays/px, where the error stops falling) | n/a | 3 |", md, StringComparison.Ordinal);
        Assert.Contains("| random | n/a | n/a (the error stops falling at 4 rays/px) | n/a | 1 |", md, StringComparison.Ordinal);
    }

    [Fact]
    public void TheMarkdownSaysWhichTimesWereRenderedAgain()
    {
        CompareResult[] results = [Result("random", 1, 4, 1) with { Renders = 40, Retimed = true }, Result("random", 4, 2, 300) with { Renders = 3 }];

        string md = new CompareReport("heading", "raylab compare x --out y", results, []).Markdown();

        Assert.Contains("1 of 2 settings whose quick renders disagreed (the renders beside the median more than 5 % apart) were rendered again until they agreed or added up to 250 ms", md, StringComparison.Ordinal);
        Assert.Contains("up to 40 here", md, StringComparison.Ordinal);
        Assert.DoesNotContain("rendered again", new CompareReport("h", "c", [results[1]], []).Markdown(), StringComparison.Ordinal);
    }

    [Fact]
    public void TheMarkdownSaysWhichTimesAreOneLongRender()
    {
        CompareResult[] results = [Result("random", 1024, 0.1, 4000) with { TimedOnce = true }, Result("random", 4, 2, 300) with { Renders = 3 }];

        string md = new CompareReport("heading", "raylab compare x --out y", results, []).Markdown();

        Assert.Contains("1 of 2 settings took 0.25 s or more in their first render, which is their time", md, StringComparison.Ordinal);
        Assert.DoesNotContain("first render", new CompareReport("h", "c", [results[1]], []).Markdown(), StringComparison.Ordinal);
        Assert.Equal("time = median of 3 renders (1 for a render of 0.25 s or more)", CompareRunner.TimeRule(3));
    }

    [Fact]
    public void KendallsTauCountsThePairsTwoOrdersAgreeOn()
    {
        Assert.Equal(1, CompareReport.KendallTau([(1, 10), (2, 20), (3, 30)])!.Value, 12);
        Assert.Equal(-1, CompareReport.KendallTau([(1, 30), (2, 20), (3, 10)])!.Value, 12);
        // One of three pairs swapped: (2 - 1) / 3.
        Assert.Equal(1 / 3.0, CompareReport.KendallTau([(1, 10), (2, 30), (3, 20)])!.Value, 12);
        // τ-b: a tie in one measure is neither agreement nor disagreement; 2 concordant pairs of 3, one tied in A.
        Assert.Equal(2 / Math.Sqrt(2 * 3), CompareReport.KendallTau([(1, 10), (1, 20), (3, 30)])!.Value, 12);
        Assert.Null(CompareReport.KendallTau([(1, 10)]));
        Assert.Null(CompareReport.KendallTau([(1, 10), (1, 20)]));
    }

    [Fact]
    public void TheCostToReachAMeanFlipUsesTheFlipOfEachSetting()
    {
        CompareResult[] line = [Result("jittered", 1, 4, 10, flip: 0.04), Result("jittered", 4, 1, 40, flip: 0.01), Result("jittered", 16, 0.25, 160)];

        // FLIP 0.02 is halfway (in logs) from 0.04 to 0.01; the setting without a FLIP is passed over.
        Assert.Equal(20, CompareReport.CostToReach(line, 0.02, r => r.Time.TotalMilliseconds, r => r.MeanFlip)!.Value, 9);
        Assert.Null(CompareReport.CostToReach(line, 0.001, r => r.Time.TotalMilliseconds, r => r.MeanFlip));
    }

    [Fact]
    public void TheMarkdownShowsFlipBesideRmseAndWhereTheyRankDifferently()
    {
        CompareResult[] results =
        [
            // At 1 spp regular has the lower RMSE but the higher FLIP (its error is structured); at 4 spp they agree.
            Result("regular", 1, 4, 10, flip: 0.05), Result("regular", 4, 1, 20, flip: 0.02),
            Result("jittered", 1, 5, 10, flip: 0.04), Result("jittered", 4, 2, 40, flip: 0.03),
        ];

        CompareReport report = new("heading", "raylab compare x --out y", results, []);
        string md = report.Markdown();

        Assert.Contains("| sampler | setting | rays/px | time (ms) | kernel | rays/ms | RMSE | mean FLIP |", md, StringComparison.Ordinal);
        Assert.Contains("| regular | 1 spp | 1.00 | 10.0 | scalar | 10 | 4.000 | 0.0500 |", md, StringComparison.Ordinal);
        Assert.Contains("| regular | -1.00 | -1.00 | -0.66 | 2 |", md, StringComparison.Ordinal);
        // Every line reaches FLIP 0.03 (jittered's best): regular between 1 and 4 spp, jittered at 4.
        Assert.Contains("## Time to mean FLIP ≤ 0.0300 (the lowest mean FLIP every line reaches)", md, StringComparison.Ordinal);
        double regular = Math.Exp(Math.Log(10) + (Math.Log(0.03 / 0.05) / Math.Log(0.02 / 0.05) * Math.Log(2)));
        Assert.Contains(FormattableString.Invariant($"| regular | {regular:F1} | 1.00 |"), md, StringComparison.Ordinal);
        Assert.Contains("## RMSE and FLIP: the same ranking?", md, StringComparison.Ordinal);
        Assert.Contains("| 1 | regular < jittered | jittered < regular | -1.00 | regular < jittered by RMSE, > by FLIP |", md, StringComparison.Ordinal);
        Assert.Contains("| 4 | regular < jittered | regular < jittered | 1.00 | none |", md, StringComparison.Ordinal);
        Assert.Contains("mean_flip", report.Csv().Split('\n')[0], StringComparison.Ordinal);
        Assert.EndsWith(",0.05,Scalar,images/regular-1.png,errors/regular-1.png,flip/regular-1.png,,,", report.Csv().Split('\n')[1], StringComparison.Ordinal);
    }

    [Fact]
    public void TheReportSaysWhichSamplerEachMeasurePutsFirstAndChartsTheSpectra()
    {
        // regular: the lower RMSE, all of it in one smooth patch; jittered: more error, but as fine grain.
        var random = new Random(3);
        double[] grain = [.. Enumerable.Range(0, 64 * 48).Select(_ => random.NextDouble() < 0.5 ? -2.0 : 2.0)];
        double[] patch = [.. Enumerable.Range(0, 64 * 48).Select(i => 1.5 * Math.Sin(Math.PI * (i % 64) / 64))];
        static ErrorPlacement Of(double[] plane) => new(
            ErrorLocation.LowPassRmse(plane, 64, 48, 1), ErrorLocation.LowPassRmse(plane, 64, 48, 2), ErrorLocation.Spectrum(plane, 64, 48));
        CompareResult[] results =
        [
            Result("regular", 4, 1.06, 10, flip: 0.02) with { Placement = Of(patch) },
            Result("jittered", 4, 2, 10, flip: 0.03) with { Placement = Of(grain) },
        ];

        CompareReport report = new("heading", "", results, []);
        string md = report.Markdown();

        Assert.Contains("| RMSE | mean FLIP | low-pass σ=1 | low-pass σ=2 | low share |", md, StringComparison.Ordinal);
        Assert.Contains("## Where the error sits", md, StringComparison.Ordinal);
        Assert.Contains("| 4 | regular | regular | jittered | jittered | jittered |", md, StringComparison.Ordinal);
        Assert.Contains(FormattableString.Invariant($",{Of(grain).Spectrum.LowFrequencyShare:G9}"), report.Csv().Split('\n')[2], StringComparison.Ordinal);
        string folder = Directory.CreateTempSubdirectory("raylab-spectrum").FullName;
        try
        {
            report.WriteTo(folder);
            Assert.True(File.Exists(Path.Combine(folder, CompareReport.SpectrumStem(4) + ".png")));
            Assert.Contains("error-spectrum-4spp.png", File.ReadAllText(Path.Combine(folder, "index.html")), StringComparison.Ordinal);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void EveryRowNamesItsKernelAndItsRaysPerMillisecond()
    {
        // The case that misleads: a pixel method of one's own (scalar kernel) at 5 rays/px and 27.2 ms beside jittered
        // (a packet kernel) at 16 rays/px and 1.9 ms, on a 640×480 image.
        CompareResult own = new(
            CompareCase.Custom("mitchell", "4 → 16", RenderMethod.Custom(new MitchellMethod())),
            5L * 640 * 480, 5, TimeSpan.FromMilliseconds(27.2), new ImageError(1, 1, 9, 0.01), RenderKernel.Scalar);
        CompareResult jittered = Result("jittered", 16, 0.5, 1.9) with { Rays = 16L * 640 * 480, Kernel = RenderKernel.Vector256 };
        CompareResult instant = Result("random", 1, 4, 0);

        CompareReport report = new("heading", "", [own, jittered, instant], []);
        string md = report.Markdown();

        Assert.Contains("| sampler | setting | rays/px | time (ms) | kernel | rays/ms | RMSE |", md, StringComparison.Ordinal);
        // 1 536 000 rays in 27.2 ms and 4 915 200 in 1.9 ms.
        Assert.Contains("| mitchell | 4 → 16 | 5.00 | 27.2 | scalar | 56471 | 1.000 |", md, StringComparison.Ordinal);
        Assert.Contains("| jittered | 16 spp | 16.00 | 1.9 | vector256 | 2586947 | 0.500 |", md, StringComparison.Ordinal);
        Assert.Contains("| random | 1 spp | 1.00 | 0.0 | scalar | n/a | 4.000 |", md, StringComparison.Ordinal);
        Assert.Contains("compare rays/ms within one kernel", md, StringComparison.Ordinal);
        string folder = Directory.CreateTempSubdirectory("raylab-kernel").FullName;
        try
        {
            report.WriteTo(folder);
            string html = File.ReadAllText(Path.Combine(folder, "index.html"));
            Assert.Contains("<th>time (ms)</th><th>kernel</th><th>rays/ms</th>", html, StringComparison.Ordinal);
            Assert.Contains("<td>27.2</td><td>scalar</td><td>56471</td>", html, StringComparison.Ordinal);
            Assert.Contains("<td>1.9</td><td>vector256</td><td>2586947</td>", html, StringComparison.Ordinal);
            Assert.Contains("compare rays/ms within one kernel", html, StringComparison.Ordinal);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void ASlowRateKeepsThreeSignificantDigits()
    {
        CompareResult slow = Result("random", 1, 4, 30) with { Rays = 370 };

        Assert.Contains("| random | 1 spp | 1.00 | 30.0 | scalar | 12.3 | 4.000 |", new CompareReport("h", "", [slow], []).Table(), StringComparison.Ordinal);
    }

    private static CompareResult Result(string sampler, int spp, double rmse, double ms, int max = 9, double? flip = null) => new(
        CompareCase.Sampled(Samplers.Create(sampler, spp, 1), spp),
        spp * 100L, spp, TimeSpan.FromMilliseconds(ms), new ImageError(rmse, rmse, max, 0.01), RenderKernel.Scalar)
    {
        MeanFlip = flip,
    };

    private static CompareResult Adaptive(int depth, double raysPerPixel, double rmse, double ms) => new(
        CompareCase.Adaptive(new AdaptiveSampler(0, depth, 0.1)),
        (long)(raysPerPixel * 100), raysPerPixel, TimeSpan.FromMilliseconds(ms), new ImageError(rmse, rmse, 40, 0.01), RenderKernel.Scalar);
}
