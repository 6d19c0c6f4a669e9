using RayLab.Tests.Shared;

namespace RayLab.Grading.Tests;

/// <summary>
/// The grader's rules that need no lab: a check's section and a section's result, what one run of the checks comes to,
/// the listed checks, and each student's folder.
/// </summary>
public sealed class GradeJobTests
{
    [Theory]
    [InlineData(0, 60, 2048, "--jobs", "--jobs: expected a count ≥ 1, got 0")]
    [InlineData(1, 0, 2048, "--check-timeout", "--check-timeout: expected a number of seconds ≥ 1, got 0")]
    [InlineData(1, 60, 100, "--memory-limit", "--memory-limit: expected megabytes ≥ 256, got 100")]
    public void ARequestThatCannotBeGradedThrowsTheLibrarysOwnExceptionNamingTheOption(int jobs, int checkSeconds, int memory, string option, string message)
    {
        var request = new GradeRequest("submissions", "checks", null, "report", TimeSpan.FromSeconds(checkSeconds),
            TimeSpan.FromSeconds(60), TimeSpan.FromSeconds(600), UnsafeNoSandbox: true) { Jobs = jobs, MemoryLimitMegabytes = memory };
        GradeRequestException e = Assert.Throws<GradeRequestException>(() => GradeJob.Run(request, TextWriter.Null, TestContext.Current.CancellationToken));
        Assert.Equal(option, e.Option);
        Assert.Equal(message, e.Message);
        Assert.Equal("", new GradeRequestException("no option named here").Option);
    }

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
    [InlineData(false, 0, 0, false, 3, false, "checks did not run", true)]   // no TRX, the reruns spent: the run's first errors say why
    [InlineData(true, 0, 0, true, 3, false, "checks did not run", false)]    // stopped before the first check ended, the reruns spent
    [InlineData(true, 0, 0, false, 3, false, "checks did not run", true)]    // a TRX with no check in it, the reruns spent
    [InlineData(true, 5, 1, true, 1, true, "check time limit", false)]       // a check hung: again without it
    [InlineData(true, 5, 1, false, 3, true, "checks crashed", false)]        // a check crashed the host: again without it
    [InlineData(true, 9, 2, true, GradeJob.MaxCheckRuns, false, null, false)] // the last run: its stopped checks stay
    public void ACheckRunIsOkOnlyWithChecksAndRunsAgainWithoutTheOnesThatStoppedIt(
        bool trx, int checks, int stopped, bool hang, int attempt, bool again, string? problem, bool firstErrors)
    {
        const string errors = "error CS1002: ; expected";
        int read = 0;
        int unrecorded = checks == 0 ? GradeJob.MaxUnrecordedReruns : 0;
        CheckRunVerdict verdict = GradeJob.JudgeCheckRun(new CheckRunOutcome(trx, checks, stopped, hang, LabLimit: false), attempt, unrecorded, () => { read++; return errors; });
        Assert.Equal(again, verdict.RunAgain);
        Assert.False(verdict.Unrecorded);
        Assert.Equal(problem, verdict.Problem);
        Assert.Equal(firstErrors ? 1 : 0, read); // the output is read only for the detail that shows it
        Assert.Equal(firstErrors, verdict.Detail == errors);
        if (problem == "checks did not run" && hang)
        {
            Assert.Contains("--check-timeout", verdict.Detail, StringComparison.Ordinal);
        }
    }

    [Theory]
    [InlineData(false, 0, false, false, 0, true)]   // no TRX, no limit of the lab's: the machine's doing, run again
    [InlineData(true, 0, false, false, 0, true)]    // a TRX with no check in it: again
    [InlineData(true, 0, true, false, 1, true)]     // stopped for inactivity before its first check, none unfinished: again
    [InlineData(false, 0, false, false, 1, true)]   // the second such run: again, the last time
    [InlineData(false, 0, false, false, 2, false)]  // the reruns spent: checks did not run
    [InlineData(false, 0, false, true, 0, false)]   // a limit of the lab's own (memory, processes, disk, CPU): no rerun
    [InlineData(true, 0, true, true, 0, false)]
    [InlineData(false, 7, false, false, 0, true)]   // no TRX after earlier runs recorded checks: again
    public void ARunThatRecordedNothingAndHitNoLimitOfTheLabsRunsAgainAFewTimes(bool trx, int checks, bool hang, bool labLimit, int unrecorded, bool again)
    {
        int read = 0;
        CheckRunVerdict verdict = GradeJob.JudgeCheckRun(new CheckRunOutcome(trx, checks, 0, hang, labLimit), 1 + unrecorded, unrecorded, () => { read++; return "error"; });
        Assert.Equal(again, verdict.RunAgain);
        Assert.Equal(again, verdict.Unrecorded);
        Assert.Equal(again ? null : "checks did not run", verdict.Problem);
        Assert.Equal(again ? 0 : hang ? 0 : 1, read);
        Assert.False(GradeJob.JudgeCheckRun(new CheckRunOutcome(trx, checks, 0, hang, labLimit), GradeJob.MaxCheckRuns, unrecorded, () => "").RunAgain); // the last run never runs again
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

    [Fact]
    public void NamesThatMakeTheSameFolderGetFoldersOfTheirOwn()
    {
        // Polish letters, spaces and case all fold: each student still gets a folder (work copy, pictures, log) of their own.
        string[] names = ["Jan Kowalski", "Jan_Kowalski", "jan_kowalski", "Łucja", "Żucja", "_ucja-2", "anna"];
        string[] folders = GradeJob.StudentFolders(names);
        Assert.Equal(["Jan_Kowalski", "Jan_Kowalski-2", "jan_kowalski-3", "_ucja", "_ucja-2", "_ucja-2-2", "anna"], folders);
        Assert.Equal(names.Length, folders.Distinct(StringComparer.OrdinalIgnoreCase).Count());
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

    [Theory]
    [InlineData("exercise/tests/Lab.Tests", "checks.runsettings")]
    [InlineData("tests/Lab.Tests", "tests.runsettings")]
    public void TheChecksRunOnTheirAssemblyWithTheSettingsAndLoggerTheirProjectGivesDotnetTest(string template, string settings)
    {
        using var dir = new TempDirectory();
        string tests = Path.Combine(dir.Path, "tests", "Lab.Tests");
        Directory.CreateDirectory(tests);
        string from = Path.Combine(RepositoryRoot(), "templates", "RayLab.Templates", "content", "raylab-lab", template);
        File.Copy(Path.Combine(from, "Lab.Tests.csproj"), Path.Combine(tests, "Lab.Tests.csproj"));
        Assert.Equal(["--logger", "console;verbosity=detailed"], GradeChecks.ProjectTestSettings(dir.Path));
        File.Copy(Path.Combine(from, settings), Path.Combine(tests, settings));
        Assert.Equal(["--settings", Path.Combine(tests, settings), "--logger", "console;verbosity=detailed"], GradeChecks.ProjectTestSettings(dir.Path));
        Assert.Null(GradeChecks.BuiltTests(dir.Path));
        Directory.CreateDirectory(Path.GetDirectoryName(Path.Combine(dir.Path, GradeChecks.TestsOutput))!);
        File.WriteAllText(Path.Combine(dir.Path, GradeChecks.TestsOutput), "");
        Assert.Equal(Path.Combine(dir.Path, GradeChecks.TestsOutput), GradeChecks.BuiltTests(dir.Path));
    }

    /// <summary>The repository's folder: the first one above the test assembly that holds RayLab.sln.</summary>
    private static string RepositoryRoot()
    {
        for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            if (File.Exists(Path.Combine(folder.FullName, "RayLab.sln")))
            {
                return folder.FullName;
            }
        }

        throw new InvalidOperationException("no RayLab.sln above " + AppContext.BaseDirectory);
    }
}
