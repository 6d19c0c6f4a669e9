using System.Globalization;
using RayLab.Grading;

namespace RayLab.Cli.Tests;

/// <summary>
/// <c>raylab grade</c>'s input checks (one line naming the option and what is wrong, exit 1, no report) and its
/// reading of sections from check names. Grading real labs in bubblewrap is ClassKitTests' (tests/RayLab.Templates.Tests).
/// </summary>
public sealed class GradeCliTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Theory]
    [InlineData("3.2 Kamera perspektywiczna: promień przez środek piksela", "3.2")]
    [InlineData("4.1.4 Adaptacyjne: podział, gdy kontrast > 0,05", "4.1.4")]
    [InlineData("5 Zadanie: dwie kule", "5")]
    [InlineData("own Moja metoda: RMSE ≤ 2,5", "own")]
    [InlineData("MyLab.Tests.CameraTests.ACameraLookingDownMinusZHasTheWorldAxesAsItsFrame", "CameraTests")]
    [InlineData("Lab_1.Tests.MyMethodTests.MyMethodIsCloseToTheExactImageAtAStatedCost(cameraName: \"perspective\")", "MyMethodTests")]
    [InlineData("ownership is not a section", "ownership is not a section")]
    public void ASectionIsTheDisplayNamesSectionNumberOrElseTheChecksClass(string display, string section) =>
        Assert.Equal(section, GradeJob.SectionOf(display));

    [Theory]
    [InlineData("Passed,Passed", false, "pass")]
    [InlineData("Passed,Skipped", false, "not written")]          // a check of a section still to write is skipped
    [InlineData("Skipped,Skipped", false, "not written")]
    [InlineData("Passed,Skipped,Failed", false, "fail")]          // wrong beats not written
    [InlineData("Passed,Passed", true, "fail")]                   // a use the lab does not allow
    [InlineData("Skipped,Timeout", false, "timeout")]
    [InlineData("", false, "")]
    public void ASectionWithASkippedCheckIsNotWrittenAndEarnsNothing(string outcomes, bool refused, string result)
    {
        Assert.Equal(result, GradeJob.SectionResult(outcomes.Length == 0 ? [] : outcomes.Split(','), refused));
        Assert.Equal(0, RayLab.Grading.GradingScheme.Default.Grade(new Dictionary<string, string> { ["2.1"] = "not written" }, []));
    }

    [Theory]
    [InlineData(true, 12, 0, false, 1, false, null, false)]                  // every check ended: ok
    [InlineData(false, 0, 0, false, 1, false, "checks did not run", true)]   // no TRX: the run's first errors say why
    [InlineData(true, 0, 0, true, 1, false, "checks did not run", false)]    // stopped before the first check ended
    [InlineData(true, 0, 0, false, 1, false, "checks did not run", true)]    // a TRX with no check in it
    [InlineData(true, 5, 1, true, 1, true, "check time limit", false)]       // a check hung: again without it
    [InlineData(true, 5, 1, false, 3, true, "checks crashed", false)]        // a check crashed the host: again without it
    [InlineData(true, 9, 2, true, GradeJob.MaxCheckRuns, false, null, false)] // the last run: its stopped checks stay
    public void ACheckRunIsOkOnlyWithChecksAndRunsAgainWithoutTheOnesThatStoppedIt(
        bool trx, int checks, int stopped, bool hang, int attempt, bool again, string? problem, bool firstErrors)
    {
        const string errors = "error CS1002: ; expected";
        int read = 0;
        CheckRunVerdict verdict = GradeJob.JudgeCheckRun(trx, checks, stopped, hang, attempt, () => { read++; return errors; });
        Assert.Equal(again, verdict.RunAgain);
        Assert.Equal(problem, verdict.Problem);
        Assert.Equal(firstErrors ? 1 : 0, read); // the output is read only for the detail that shows it
        Assert.Equal(firstErrors, verdict.Detail == errors);
        if (problem == "checks did not run" && hang)
        {
            Assert.Contains("--check-timeout", verdict.Detail, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void TheChecksLeftWithoutAResultAreSelectedByTheirDisplayNamesEscapedForTheTestPlatformsFilter()
    {
        // A check that ended its run leaves the checks not yet started without a result: the next run selects them by
        // name, and the filter's own characters in a name ((), =, |, !, ~, &, \) are escaped.
        string filter = GradeJob.DisplayNameFilter(["3 Kamera: baza w = −g/|g|", "4.1.1 Próbkowanie regularne(n: 4)", "a!~&\\b"]);
        Assert.Equal("DisplayName=3 Kamera: baza w \\= −g/\\|g\\||DisplayName=4.1.1 Próbkowanie regularne\\(n: 4\\)|DisplayName=a\\!\\~\\&\\\\b", filter);
        Assert.Equal("", GradeJob.DisplayNameFilter([]));
    }

    [Fact]
    public void TheListedChecksAreTheIndentedLinesAfterTheHeadingWithoutTheAdaptersOwn()
    {
        // dotnet test --list-tests of a lab, as it prints (the adapter's lines fall among the names).
        const string output = """
            Test run for /lab/tests/Lab.Tests/bin/Debug/net10.0/Lab.Tests.dll (.NETCoreApp,Version=v10.0)
                A line before the heading
            The following Tests are available:
            [xUnit.net 00:00:00.01] xUnit.net VSTest Adapter v4.0.1+0f7d528729 (64-bit .NET 10.0.12)
            [xUnit.net 00:00:00.74]   Discovering: Lab.Tests
                4.1.4 Próbkowanie adaptacyjne: te same promienie(cameraName: "perspective")
            [xUnit.net 00:00:01.87]   Discovered:  Lab.Tests
                4.1.4 Próbkowanie adaptacyjne: te same promienie(cameraName: "orthographic")
                5 Zadanie: dwie kule (RMSE, FLIP)(cameraName: "orthographic")

            """;
        string[] listed = ["4.1.4 Próbkowanie adaptacyjne: te same promienie(cameraName: \"perspective\")", "4.1.4 Próbkowanie adaptacyjne: te same promienie(cameraName: \"orthographic\")",
            "5 Zadanie: dwie kule (RMSE, FLIP)(cameraName: \"orthographic\")"];
        Assert.Equal(listed, GradeJob.ListedTests(output));
        Assert.Equal(listed, GradeJob.ListedTests(output.ReplaceLineEndings("\r\n")));
        Assert.Empty(GradeJob.ListedTests("No test matches the given testcase filter"));
    }

    [Theory]
    [InlineData("exercise/tests/Lab.Tests", "checks.runsettings")]
    [InlineData("tests/Lab.Tests", "tests.runsettings")]
    public void TheChecksRunOnTheirAssemblyWithTheSettingsAndLoggerTheirProjectGivesDotnetTest(string template, string settings)
    {
        string tests = Path.Combine(_dir.Path, "tests", "Lab.Tests");
        Directory.CreateDirectory(tests);
        string from = Path.Combine(RepoPaths.Root(), "templates", "RayLab.Templates", "content", "raylab-lab", template);
        File.Copy(Path.Combine(from, "Lab.Tests.csproj"), Path.Combine(tests, "Lab.Tests.csproj"));
        Assert.Equal(["--logger", "console;verbosity=detailed"], GradeChecks.ProjectTestSettings(_dir.Path));
        File.Copy(Path.Combine(from, settings), Path.Combine(tests, settings));
        Assert.Equal(["--settings", Path.Combine(tests, settings), "--logger", "console;verbosity=detailed"], GradeChecks.ProjectTestSettings(_dir.Path));
        Assert.Null(GradeChecks.BuiltTests(_dir.Path));
        Directory.CreateDirectory(Path.GetDirectoryName(Path.Combine(_dir.Path, GradeChecks.TestsOutput))!);
        File.WriteAllText(Path.Combine(_dir.Path, GradeChecks.TestsOutput), "");
        Assert.Equal(Path.Combine(_dir.Path, GradeChecks.TestsOutput), GradeChecks.BuiltTests(_dir.Path));
    }

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

    [Fact]
    public void NamesThatMakeTheSameFolderGetFoldersOfTheirOwn()
    {
        // Polish letters, spaces and case all fold: each student still gets a folder (work copy, pictures, log) of their own.
        string[] names = ["Jan Kowalski", "Jan_Kowalski", "jan_kowalski", "Łucja", "Żucja", "_ucja-2", "anna"];
        string[] folders = GradeJob.StudentFolders(names);
        Assert.Equal(["Jan_Kowalski", "Jan_Kowalski-2", "jan_kowalski-3", "_ucja", "_ucja-2", "_ucja-2-2", "anna"], folders);
        Assert.Equal(names.Length, folders.Distinct(StringComparer.OrdinalIgnoreCase).Count());
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
