using RayLab.PrecisionReport;

namespace RayLab.Cli.Tests.Precision;

/// <summary>
/// The report behind docs/precision.md, on small images: it runs, and RayLab's renderer gets every pixel of
/// every hard case right (the regression guard for any faster render path).
/// </summary>
public class PrecisionReportTests
{
    private const int Size = 20;

    private static readonly Lazy<IReadOnlyList<CaseResult>> Results = new(() => PrecisionReport.PrecisionReport.Run(Size));

    private readonly ITestOutputHelper _output;

    public PrecisionReportTests(ITestOutputHelper output) => _output = output;

    [Fact]
    public void TheRenderersImageMatchesTheExactDecisionOnEveryPixelOfEveryCase()
    {
        IReadOnlyList<CaseResult> results = Results.Value;
        Assert.Equal(HardCase.All.Count, results.Count);
        foreach (CaseResult r in results)
        {
            _output.WriteLine($"{r.Case.Name}: exact hits {r.ExactHits}/{r.Pixels}, wrong: float textbook {r.NaiveFloatWrong}, float RTG {r.RtgFloatWrong}, double RTG {r.DoubleWrong}, "
                + string.Join(", ", r.RayLab.Select(k => $"RayLab {k.Asked} (ran {k.Ran}, {k.Retraced} retraced) {k.Wrong}")));
            int side = r.Case.Size ?? Size;
            Assert.Equal(side * side, r.Pixels);
            Assert.True(r.ExactHits > 0 && r.ExactHits < r.Pixels, $"{r.Case.Name}: the window must show both sphere and background, got {r.ExactHits} hits");
            Assert.Equal(KernelRun.Kernels, r.RayLab.Select(k => k.Asked));
            foreach (KernelRun k in r.RayLab)
            {
                Assert.True(k.Wrong == 0, $"{r.Case.Name}: RayLab's renderer with Kernel = {k.Asked} (ran {k.Ran}) got {k.Wrong} pixels wrong");
            }
        }
    }

    [Fact]
    public void TheGrazingCasesRunOnEveryPacketWidthAndNeedItsDoubleRetrace()
    {
        // Without these the guard above would never reach the packet kernel: it sends every other case to the
        // scalar path. Here float alone gets pixels wrong, so only the packets' error bound and retrace save them.
        CaseResult[] grazing = [.. Results.Value.Where(r => r.Case.Size == HardCase.GrazingSize)];
        Assert.Equal(4, grazing.Length);
        foreach (CaseResult r in grazing)
        {
            Assert.True(r.RtgFloatWrong > 0, $"{r.Case.Name}: float gets these right, so they test nothing");
            foreach (KernelRun k in r.RayLab.Where(k => k.Asked is not (RenderKernel.Auto or RenderKernel.Scalar)))
            {
                Assert.Equal(k.Asked, k.Ran);
                Assert.True(k.Retraced >= 24, $"{r.Case.Name}, {k.Asked}: only {k.Retraced} samples retraced in double");
            }
        }
    }

    [Fact]
    public void TheCasesAreHardEnoughToCatchAFloatPath()
    {
        // If the renderer behaved like a float32 tracer, the guard above would see it: float gets these wrong.
        Dictionary<string, CaseResult> byName = Results.Value.ToDictionary(r => r.Case.Name);
        Assert.True(byName[HardCase.TinyFarSphere("perspective", 1e-4, edge: false).Name].NaiveFloatWrong > Size * Size / 4);
        Assert.True(byName[HardCase.Horizon(0.01).Name].RtgFloatWrong > Size * Size / 4);
        Assert.All(Results.Value.Where(r => r.Case.Name.Contains("silhouette", StringComparison.Ordinal)), r => Assert.True(r.RtgFloatWrong > 0, r.Case.Name));
    }

    [Fact]
    public void AccurateHitPointsAreWithinAnUlpOfTheSurfaceAndPlainDoubleOnesAreNot()
    {
        foreach (CaseResult r in Results.Value)
        {
            Assert.True(r.AccurateErrorUlps <= 1, $"{r.Case.Name}: {r.AccurateErrorUlps:G3} ulp(|p|)");
        }

        Assert.True(Results.Value.Single(r => r.Case.Name == HardCase.Horizon(0.01).Name).DoubleErrorUlps > 1000);
    }

    [Fact]
    public void TheMarkdownHasTheCommandAndOneRowPerCaseInBothTables()
    {
        string markdown = PrecisionReport.PrecisionReport.ToMarkdown(Results.Value, Size);

        Assert.Contains(PrecisionReport.PrecisionReport.Command, markdown, StringComparison.Ordinal);
        foreach (HardCase c in HardCase.All)
        {
            Assert.Equal(2, markdown.Split('\n').Count(line => line.StartsWith($"| {c.Name} |", StringComparison.Ordinal)));
        }

        Assert.Contains($"got 0 of {Results.Value.Sum(r => r.Pixels)} pixels wrong", markdown, StringComparison.Ordinal);
    }

    [Fact]
    public void TheToolWritesTheFileAtomicallyAndRejectsABadCommandLine()
    {
        using var dir = new TempDirectory();
        string path = dir.File("precision.md");

        // The tool's messages go to writers the test reads, not to dotnet test's output.
        using var stdout = new StringWriter();
        using var stderr = new StringWriter();
        Assert.Equal(0, RayLab.PrecisionReport.Program.Run(["--size", "4", "--out", path], stdout, stderr));
        Assert.StartsWith("# Precision", File.ReadAllText(path), StringComparison.Ordinal);
        Assert.Equal(["precision.md"], dir.Entries());
        Assert.Contains("wrote", stderr.ToString(), StringComparison.Ordinal);

        foreach (string[] bad in new[] { new[] { "--size", "0" }, ["--bogus"] })
        {
            using var error = new StringWriter();
            Assert.Equal(2, RayLab.PrecisionReport.Program.Run(bad, TextWriter.Null, error));
            Assert.Contains($"unexpected '{bad[0]}'", error.ToString(), StringComparison.Ordinal);
        }

        using var missing = new StringWriter();
        Assert.Equal(1, RayLab.PrecisionReport.Program.Run(["--size", "4", "--out", dir.File("missing/precision.md")], TextWriter.Null, missing));
        Assert.Contains("does not exist", missing.ToString(), StringComparison.Ordinal);
        Assert.Equal(["precision.md"], dir.Entries());
    }
}
