using System.Globalization;
using RayLab.Grading;

namespace RayLab.Cli.Tests;

/// <summary>
/// <c>raylab grade</c>'s input checks (one line naming the option and what is wrong, exit 1, no report), through the
/// console's front. The grading's own rules are RayLab.Grading.Tests'. Grading real labs in bubblewrap is ClassKitTests' (tests/RayLab.Templates.Tests).
/// </summary>
public sealed class GradeCliTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void MissingSubmissionsNameTheArgument()
    {
        string checks = Checks();
        (int code, string stdout, string stderr) = ConsoleRunner.Run("grade", _dir.File("nowhere"), "--checks", checks, "--out", _dir.File("report"));
        Assert.Equal(1, code);
        Assert.Equal("", stdout);
        Assert.Equal($"raylab: error: submissions: no such folder '{_dir.File("nowhere")}'", stderr.TrimEnd());
        Assert.False(Directory.Exists(_dir.File("report")));
    }

    [Fact]
    public void ChecksWithoutTheirTestsNameWhatIsMissing()
    {
        string checks = Checks();
        Directory.Delete(Path.Combine(checks, "tests"), recursive: true);
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        Directory.CreateDirectory(_dir.File("subs/anna"));
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("report"));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --checks: {checks} has no tests/Lab.Tests; give a kit's checks/exercise or checks/method", stderr.TrimEnd());
        Assert.False(Directory.Exists(_dir.File("report")));
    }

    [Fact]
    public void ChecksWhoseListOfUsesIsNotAListNameTheFileAndTheFieldBeforeAnyLabIsGraded()
    {
        string checks = Checks();
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        Directory.CreateDirectory(_dir.File("subs/anna"));
        string uses = Path.Combine(checks, "tests", "Lab.Tests", "uses.json");
        File.WriteAllText(uses, """{ "allowed": ["RayLab.*.Camera"] }""");
        (int code, string stdout, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("report"));
        Assert.Equal(1, code);
        Assert.Equal("", stdout);
        Assert.Equal($"raylab: error: --checks: {uses}: allowed: 'RayLab.*.Camera' is not a rule: expected Namespace.*, Namespace.Type or Namespace.Type::Member", stderr.TrimEnd());
        Assert.False(Directory.Exists(_dir.File("report")));
    }

    [Fact]
    public void AKitWithoutAFeedSaysWhereItLooked()
    {
        string checks = Checks();
        Directory.CreateDirectory(_dir.File("subs/anna"));
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("report"));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --feed: no packages in {_dir.File("kit/feed")} (the kit's feed/ beside checks/); give the feed with --feed", stderr.TrimEnd());
    }

    [Theory]
    [InlineData("nofeed", "no such folder: {0}")]
    [InlineData("afile", "{0} is a file, not the feed's folder")]
    [InlineData("empty", "no packages (*.nupkg) in {0}")]
    public void AGivenFeedThatIsNoFeedSaysWhatItIs(string name, string problem)
    {
        string checks = Checks();
        Directory.CreateDirectory(_dir.File("subs/anna"));
        Directory.CreateDirectory(_dir.File("empty"));
        File.WriteAllText(_dir.File("afile"), "");
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("report"), "--feed", _dir.File(name));
        Assert.Equal(1, code);
        Assert.Equal("raylab: error: --feed: " + string.Format(CultureInfo.InvariantCulture, problem, _dir.File(name)), stderr.TrimEnd());
        Assert.False(Directory.Exists(_dir.File("report")));
    }

    [Fact]
    public void AReportInsideTheSubmissionsIsRefused()
    {
        string checks = Checks();
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        Directory.CreateDirectory(_dir.File("subs/anna"));
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("subs/report"));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --out: '{_dir.File("subs/report")}' is inside the submissions folder; write the report elsewhere", stderr.TrimEnd());
    }

    [Fact]
    public void AReportFolderNothingCanBeCreatedInIsRefusedBeforeAnyLabIsGraded()
    {
        Assert.SkipUnless(OperatingSystem.IsLinux(), "/proc is Linux's: nobody can create files or folders in it, not even root");
        string checks = Checks();
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        Directory.CreateDirectory(_dir.File("subs/anna"));
        (int code, string stdout, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", "/proc/raylab-grades");
        Assert.Equal(1, code);
        Assert.Equal("raylab: error: --out: cannot write in the folder '/proc/raylab-grades': nothing can be created there", stderr.TrimEnd());
        Assert.DoesNotContain("restoring", stdout, StringComparison.Ordinal); // refused before the checks' packages are restored
    }

    [Theory]
    [InlineData("--check-timeout", "0", "expected a number of seconds ≥ 1, got 0")]
    [InlineData("--jobs", "0", "expected a count ≥ 1, got 0")]
    [InlineData("--memory-limit", "100", "expected megabytes ≥ 256, got 100")]
    [InlineData("--process-limit", "10", "expected a count ≥ 64, got 10")]
    [InlineData("--disk-limit", "10", "expected megabytes ≥ 64, got 10")]
    [InlineData("--cpu-limit", "1", "expected seconds ≥ 10, got 1")]
    [InlineData("--unsafe-no-limit", "network", "expected memory, processes, disk, cpu, got 'network'")]
    public void ALimitOutOfRangeIsRefusedWithOneLine(string option, string value, string problem)
    {
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.Path, "--checks", _dir.Path, "--out", _dir.File("r"), option, value);
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: {option}: {problem}", stderr.TrimEnd());
        Assert.False(Directory.Exists(_dir.File("r")));
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void ASubmissionsProcessPastTheMemoryLimitRunsOutOfMemoryAndOneWithinItRuns(bool sandboxed)
    {
        // raylab itself as the submission's program: a 16000×16000 picture needs 768 MB for its pixels alone (about
        // 6 s and 800 MB unlimited), and fails at once under 256 MB; an 80×60 one runs under the same limit.
        string lab = Directory.CreateDirectory(_dir.File("lab")).FullName;
        string packages = Directory.CreateDirectory(_dir.File("packages")).FullName;
        GradeSandbox sandbox;
        try
        {
            sandbox = GradeSandbox.Create(unsafeNoSandbox: !sandboxed, [], packages, new GradeLimits { MemoryMegabytes = 256 });
        }
        catch (SandboxUnavailableException e) when (sandboxed)
        {
            Assert.Skip($"no sandbox here: {e.Message}");
            return;
        }

        using GradeSandbox owned = sandbox;
        // raylab's assemblies and scenes in a folder of the test's own: the checkout may lie in a folder the sandbox's uid cannot pass.
        string bin = Directory.CreateDirectory(_dir.File("raylab")).FullName;
        foreach (string file in Directory.EnumerateFiles(AppContext.BaseDirectory).Where(f => f.EndsWith(".dll", StringComparison.Ordinal) || Path.GetFileName(f).StartsWith("raylab.", StringComparison.Ordinal)))
        {
            File.Copy(file, Path.Combine(bin, Path.GetFileName(file)));
        }

        Directory.CreateDirectory(Path.Combine(bin, "scenes"));
        foreach (string file in Directory.EnumerateFiles(Path.Combine(AppContext.BaseDirectory, "scenes")))
        {
            File.Copy(file, Path.Combine(bin, "scenes", Path.GetFileName(file)));
        }

        string raylab = Path.Combine(bin, "raylab.dll");
        ChildRun big = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "dotnet", [raylab, "render", "two-spheres", "--width", "16000", "--height", "16000", "-o", "big.png"],
            TestContext.Current.CancellationToken, [bin]);
        Assert.False(big.TimedOut);
        Assert.True(big.ExitCode == 1, $"exit {big.ExitCode}: {big.Output}");
        Assert.Contains("raylab: error: not enough memory to render two-spheres at the requested size", big.Output, StringComparison.Ordinal);
        Assert.False(File.Exists(Path.Combine(lab, "big.png")));

        ChildRun small = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "dotnet", [raylab, "render", "two-spheres", "--width", "80", "--height", "60", "-o", "small.png"],
            TestContext.Current.CancellationToken, [bin]);
        Assert.True(small.ExitCode == 0, $"exit {small.ExitCode}: {small.Output}");
        Assert.True(File.Exists(Path.Combine(lab, "small.png")));
    }

    [Fact]
    public void ABadPointsValueInGradingJsonNamesTheFileAndTheField()
    {
        string checks = Checks();
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        Directory.CreateDirectory(_dir.File("subs/anna"));
        File.WriteAllText(Path.Combine(checks, "grading.json"), "{ \"kind\": \"method\", \"points\": { \"3.1\": -1 } }");
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("report"));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --checks: {Path.Combine(checks, "grading.json")}: points.3.1: expected points ≥ 0, got -1", stderr.TrimEnd());
    }

    [Fact]
    public void AWorksheetThatIsNotMoodlesSaysWhichColumnIsMissing()
    {
        string checks = Checks();
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        Directory.CreateDirectory(_dir.File("subs/anna"));
        File.WriteAllText(_dir.File("sheet.csv"), "Identifier,Full name,Feedback comments\nParticipant 1,Anna,\n");
        (int code, _, string stderr) = ConsoleRunner.Run("grade", _dir.File("subs"), "--checks", checks, "--out", _dir.File("report"), "--moodle-worksheet", _dir.File("sheet.csv"));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: --moodle-worksheet: {_dir.File("sheet.csv")}: no column 'Grade' in the header (Identifier, Full name, Feedback comments); give the assignment's grading worksheet as Moodle writes it", stderr.TrimEnd());
        Assert.False(Directory.Exists(_dir.File("report")));
    }

    [Fact]
    public void AMoodleDownloadZipThatClimbsOutIsRefusedWhole()
    {
        string checks = Checks();
        File.WriteAllText(_dir.File("kit/feed/x.1.0.0.nupkg"), "");
        string zip = _dir.File("download.zip");
        using (var archive = System.IO.Compression.ZipFile.Open(zip, System.IO.Compression.ZipArchiveMode.Create))
        {
            archive.CreateEntry("Anna Nowak_1_assignsubmission_file_/lab.zip");
            archive.CreateEntry("../evil.txt");
        }

        (int code, _, string stderr) = ConsoleRunner.Run("grade", zip, "--checks", checks, "--out", _dir.File("report"));
        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: submissions: {zip}: zip refused: entry ../evil.txt climbs out of the folder", stderr.TrimEnd());
        Assert.False(File.Exists(_dir.File("evil.txt")));
    }

    /// <summary>A kit's checks folder with what the grader looks for first (the lab's folders and scene), and an empty feed beside it.</summary>
    private string Checks()
    {
        string checks = _dir.File("kit/checks/method");
        Directory.CreateDirectory(Path.Combine(checks, "tests", "Lab.Tests"));
        Directory.CreateDirectory(Path.Combine(checks, "src", "Lab"));
        Directory.CreateDirectory(Path.Combine(checks, "scenes"));
        Directory.CreateDirectory(_dir.File("kit/feed"));
        File.WriteAllText(Path.Combine(checks, "Directory.Build.props"), "<Project />");
        File.Copy(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json"), Path.Combine(checks, "scenes", "two-spheres.json"));
        return checks;
    }
}
