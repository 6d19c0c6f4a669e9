using System.Diagnostics;
using System.Globalization;
using System.Text;
using System.Text.RegularExpressions;
using RayLab.Reports.Imaging;
using RayLab.Metrics;
using RayLab.Reports.Output;
using RayLab.Scenes;

namespace RayLab.Grading;

/// <summary>
/// <c>raylab grade</c>: for each submitted lab, a copy whose <c>tests/</c>, root build files and <c>nuget.config</c> are
/// the instructor's (the pinned checks, and the kit's feed as the only package source); built, tested (one TRX per
/// run, each check stopped after its limit by the test platform's hang detection and the rest run again without it)
/// and run (the built program, the pictures) in the sandbox (<see cref="GradeSandbox"/>); its two
/// pictures read back as untrusted and scored against the exact image (RMSE in 8-bit levels, mean FLIP), the
/// program timed by the grader's own clock, and the rays per pixel its lines claim shown as its own report beside the
/// rays the lab's adaptive rule takes. One row per student in grades.csv,
/// grades.json and index.html.
/// </summary>
public static partial class GradeJob
{
    private static readonly string[] SkippedFolders = ["bin", "obj", "out", "TestResults", ".git", ".vs", ".idea", ".home", ".grade"];

    /// <summary>Runs the grading.</summary>
    /// <param name="request">What to grade.</param>
    /// <param name="stdout">One line per submission, then the report's path.</param>
    /// <param name="cancellation">Stops the submission in progress; no report is written.</param>
    /// <returns>0 when the report is written (whatever the grades).</returns>
    /// <exception cref="GradeRequestException">The request cannot be graded (a limit out of range, checks without their
    /// files, no submissions, a report folder in the way, …); the message names the option.</exception>
    /// <exception cref="SandboxUnavailableException">The machine has no sandbox, or cannot hold a limit asked for.</exception>
    /// <exception cref="SceneFileException">The checks' scene file is not valid.</exception>
    /// <exception cref="OperationCanceledException">The run was cancelled; no report is written.</exception>
    /// <exception cref="IOException">A file could not be read or written; the message says which (a bad request too).</exception>
    public static int Run(GradeRequest request, TextWriter stdout, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(stdout);
        return RunChecked(request, stdout, cancellation);
    }

    // Long: the grading's one sequence (set-up, sandbox, builds side by side, programs one at a time, report), read top to bottom.
    private static int RunChecked(GradeRequest request, TextWriter stdout, CancellationToken cancellation)
    {
        string work = Directory.CreateTempSubdirectory("raylab-grade-").FullName;
        try
        {
            GradeSetup setup = GradeSetup.Check(request, work);
            string packages = Path.Combine(work, "packages");
            Directory.CreateDirectory(packages);
            stdout.WriteLine($"restoring the checks' packages from {setup.Feed} (once, outside the sandbox)");
            RestoreChecks(setup, work, packages, cancellation);
            using GradeSandbox sandbox = GradeSandbox.Create(request.UnsafeNoSandbox, [setup.Submissions, setup.Output, work], packages, request.Limits);
            if (!sandbox.IsSandboxed)
            {
                stdout.WriteLine("warning: --unsafe-no-sandbox: the submissions' code runs as you, with your files and network");
            }

            foreach (string line in sandbox.Mechanisms)
            {
                stdout.WriteLine(line);
            }

            GradeReference reference = GradeReference.Create(setup);
            string staging = Path.Combine(work, "report");
            Directory.CreateDirectory(staging);
            reference.Save(staging);
            var grading = Stopwatch.StartNew();
            string[] names = [.. setup.Submitted.Select(s => s.Name)];
            string[] folders = StudentFolders(names);
            var labs = new GradedLab[setup.Students.Length];
            stdout.WriteLine($"building and checking {labs.Length} submissions, {setup.Jobs} at a time");
            int done = 0;
            SideBySide.Run(labs.Length, setup.Jobs, (i, stop) =>
            {
                // What the student uploaded, unpacked safely; a refused zip is the row's status, and nothing of it is graded.
                var row = new StudentRow(names[i], folders[i]) { ParticipantId = setup.Submitted[i].ParticipantId };
                UploadedLab upload = UploadedLab.Unpack(setup.Students[i], Path.Combine(work, "uploads", folders[i]), ZipLimits.Upload);
                GradedLab lab = upload.Folder is null
                    ? GradeMarks.Refused(upload, row, staging)
                    : BuildAndCheck(setup, sandbox, upload.Folder, row, work, staging, stop);
                labs[i] = lab;
                int k = Interlocked.Increment(ref done);
                lock (stdout)
                {
                    stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                        $"  [{k}/{labs.Length}] {lab.Row.Name}: {(lab.Built ? lab.Row.CheckCounts : lab.Row.Status)} ({lab.Clock.Elapsed.TotalSeconds:0} s)"));
                }
            }, cancellation);

            // The programs one at a time, in name order: their times are in the report, side by side.
            stdout.WriteLine("running the programs one at a time, so that their times compare");
            var rows = new List<StudentRow>();
            foreach (GradedLab lab in labs)
            {
                cancellation.ThrowIfCancellationRequested();
                RunProgram(setup, sandbox, reference, lab, grading, cancellation);
                cancellation.ThrowIfCancellationRequested();
                StudentRow row = lab.Row;
                rows.Add(row);
                stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                    $"{row.Name}: {row.Status}; {row.CheckCounts} ({row.Seconds:0} s)"));
            }

            foreach (string warning in GradeMarks.UnknownSections(setup, rows))
            {
                stdout.WriteLine(warning);
            }

            GradeReport.Write(staging, setup, reference, rows, sandbox.IsSandboxed);
            string? worksheet = GradeMarks.WriteWorksheet(staging, setup, rows, stdout);
            Directory.CreateDirectory(setup.Output);
            try
            {
                ReportFolder.Publish(staging, setup.Output);
            }
            catch (UsageException e)
            {
                throw new GradeRequestException(e.Message, e);
            }

            stdout.WriteLine($"wrote {Path.Combine(setup.Output, "index.html")}, grades.csv and grades.json: {rows.Count} submissions");
            if (worksheet is not null)
            {
                stdout.WriteLine($"wrote the Moodle grading worksheet {Path.Combine(setup.Output, worksheet)}: upload it with \"Upload grading worksheet\"");
            }
            return 0;
        }
        finally
        {
            try
            {
                Directory.Delete(work, recursive: true);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // a child stopped on its limit may still hold a file; the temporary folder is not worth failing for
            }
        }
    }

    /// <summary>The pinned lab restored once, outside the sandbox (trusted: the instructor's own), into the package folder the sandboxes read.</summary>
    private static void RestoreChecks(GradeSetup setup, string work, string packages, CancellationToken cancellation)
    {
        string lab = Path.Combine(work, "checks");
        CopyLab(setup.Checks, lab);
        WriteNuGetConfig(lab, setup.Feed);
        GradeSandbox plain = GradeSandbox.Create(unsafeNoSandbox: true, [], packages);
        ChildRun restore = plain.Run(lab, null, TimeSpan.FromMinutes(10), "dotnet", ["restore", Path.Combine("tests", "Lab.Tests")], cancellation);
        cancellation.ThrowIfCancellationRequested();
        if (restore.ExitCode != 0)
        {
            throw new GradeRequestException($"--checks: the checks do not restore from the feed {setup.Feed}: {FirstErrors(restore.Output, lab)}");
        }
    }

    /// <summary>
    /// Each student's folder in the report and in the grader's work: the submission's name with every character but
    /// ASCII letters, digits, '-', '_' and '.' made '_', and "-2", "-3", … after a name an earlier one already took
    /// (compared ignoring case, for reports copied to Windows or macOS): "Łucja" and "Żucja" are "_ucja" and "_ucja-2".
    /// </summary>
    /// <param name="names">The submissions' names, in the report's order.</param>
    /// <returns>One distinct folder name per submission.</returns>
    internal static string[] StudentFolders(IReadOnlyList<string> names)
    {
        ArgumentNullException.ThrowIfNull(names);
        var taken = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
        var folders = new string[names.Count];
        for (int i = 0; i < names.Count; i++)
        {
            string safe = SafeName(names[i]);
            string folder = safe;
            for (int n = 2; !taken.Add(folder); n++)
            {
                folder = string.Create(CultureInfo.InvariantCulture, $"{safe}-{n}");
            }

            folders[i] = folder;
        }

        return folders;
    }

    /// <summary>A submission's copy built and checked, the first part of its grading; its program runs later.</summary>
    // Long: a submission's build, scan and checks as numbered steps, each ending the row where it fails.
    private static GradedLab BuildAndCheck(GradeSetup setup, GradeSandbox sandbox, string submission, StudentRow row, string work, string staging, CancellationToken cancellation)
    {
        string folder = Path.Combine(staging, "students", row.Folder);
        Directory.CreateDirectory(folder);
        var lab = new GradedLab(row, Path.Combine(work, "labs", row.Folder), Path.Combine(folder, "log.txt"), folder);
        lab.Clock.Start();
        try
        {
            string? root = FindLab(submission);
            if (root is null)
            {
                row.Problems.Add("no lab");
                row.Detail = "no src/Lab/*.csproj in the folder or in one folder below it";
                return lab;
            }

            CopyLab(root, lab.Path);
            string? space = PinBuildFiles(setup, lab.Path);

            // 1. The lab's own project, alone (the restore comes from the prepared, read-only package folder; no network),
            // compiled with optimisations as a release build is (Optimize=true; same bytes, the output still in
            // bin/Debug): the checks and the program then run the lab's code JIT-optimised, not at the debug build's pace.
            ChildRun build = sandbox.Run(lab.Path, lab.Log, Min(lab.Left(setup), TimeSpan.FromMinutes(10)), "dotnet",
                ["build", Path.Combine("src", "Lab"), "-nodeReuse:false", "-p:UseSharedCompilation=false", "-p:Optimize=true"], cancellation);
            row.Steps["build"] = build.Elapsed.TotalSeconds;
            cancellation.ThrowIfCancellationRequested();
            string? assembly = GradeChecks.BuiltAssembly(lab.Path);
            if (build.TimedOut || build.ExitCode != 0 || assembly is null)
            {
                row.Problems.Add(build.TimedOut ? "build time limit" : build.Limit != SandboxLimit.None ? $"build {GradeSandbox.LimitName(build.Limit)}" : "does not build");
                row.Detail = build.TimedOut ? "the build ran past the submission's limit"
                    : build.ExitCode != 0 ? FirstErrors(build.Output, lab.Path)
                    : "the build left no assembly at src/Lab/bin/Debug/net10.0/ (the project file's name, .dll)";
                return lab;
            }

            // 2. What the lab's code uses from other assemblies, read from the built assembly (never loaded here).
            ScanUses(setup, assembly, row);

            // 3. The checks, in a folder of their own the lab never sees, compiled against the lab's assembly.
            string checksFolder = Path.Combine(work, "checks-of", row.Folder);
            GradeChecks.Prepare(setup.Checks, NuGetConfig(setup.Feed), assembly, space, checksFolder);
            ChildRun checksBuild = sandbox.Run(checksFolder, lab.Log, Min(lab.Left(setup), TimeSpan.FromMinutes(10)), "dotnet",
                ["build", Path.Combine("tests", "Lab.Tests"), "-nodeReuse:false", "-p:UseSharedCompilation=false"], cancellation);
            row.Steps["build"] += checksBuild.Elapsed.TotalSeconds;
            cancellation.ThrowIfCancellationRequested();
            string? tests = GradeChecks.BuiltTests(checksFolder);
            if (checksBuild.TimedOut || checksBuild.ExitCode != 0 || tests is null)
            {
                row.Problems.Add(checksBuild.TimedOut ? "build time limit" : checksBuild.Limit != SandboxLimit.None ? $"build {GradeSandbox.LimitName(checksBuild.Limit)}" : "checks do not build");
                row.Detail = checksBuild.TimedOut ? "the build ran past the submission's limit"
                    : checksBuild.ExitCode != 0 ? FirstErrors(checksBuild.Output, checksFolder)
                    : $"the checks' build left no {GradeChecks.TestsOutput}";
                return lab;
            }

            // 4. The checks run, from their folder shown read-only, with only the results' folder writable: runs of
            // dotnet test; a run the hang detection stops names the checks that were running, which count as timed out,
            // and the next run leaves them out.
            string results = Path.Combine(work, "results-of", row.Folder);
            Directory.CreateDirectory(results);
            var checks = Stopwatch.StartNew();
            RunChecks(setup, sandbox, new CheckFolders(checksFolder, results, tests), lab.Log, row, () => lab.Left(setup), cancellation);
            row.Steps["checks"] = checks.Elapsed.TotalSeconds;
            lab.Built = true;
            return lab;
        }
        finally
        {
            lab.Clock.Stop();
        }
    }

    /// <summary>
    /// 3. The program of a lab that built (<see cref="ProgramCommand"/>): its pictures, timed by the grader's own clock,
    /// and the rays per pixel its lines claim; then the pictures scored.
    /// </summary>
    private static void RunProgram(GradeSetup setup, GradeSandbox sandbox, GradeReference reference, GradedLab lab, Stopwatch grading, CancellationToken cancellation)
    {
        StudentRow row = lab.Row;
        lab.Clock.Start();
        if (lab.Built)
        {
            if (lab.Left(setup) <= TimeSpan.Zero)
            {
                row.Problems.Add("submission time limit");
            }
            else
            {
                TimeSpan limit = Min(lab.Left(setup), setup.Request.RunTimeout);
                row.ProgramStart = grading.Elapsed.TotalSeconds;
                ProgramLaunch launch = ProgramCommand(lab.Path);
                ChildRun run = sandbox.Run(lab.Path, lab.Log, limit, launch.Command, launch.Args, cancellation);
                row.Steps["program"] = run.Elapsed.TotalSeconds;
                row.ProgramTimedBy = launch.TimedBy;
                cancellation.ThrowIfCancellationRequested();
                if (run.TimedOut)
                {
                    row.Problems.Add(limit < setup.Request.RunTimeout ? "submission time limit" : "program time limit");
                }
                else if (run.Limit is not SandboxLimit.None and not SandboxLimit.Memory)
                {
                    row.Problems.Add($"program {GradeSandbox.LimitName(run.Limit)}");
                    row.Detail ??= FirstErrors(run.Output, lab.Path);
                }
                else if (run.ExitCode != 0 && (OutOfMemory(run.Output) || run.Limit == SandboxLimit.Memory))
                {
                    row.Problems.Add("program memory limit");
                    row.Detail ??= OutOfMemoryDetail(setup, "the program");
                }
                else if (run.ExitCode != 0)
                {
                    row.Problems.Add($"program failed (exit {run.ExitCode})");
                    row.Detail ??= FirstErrors(run.Output, lab.Path);
                }

                ReadTimings(setup, run.Output, row);
            }

            ScorePictures(setup, reference, lab.Path, lab.ReportFolder, row);
        }

        lab.Clock.Stop();
        row.Seconds = lab.Clock.Elapsed.TotalSeconds;
    }

    private static void RunChecks(GradeSetup setup, GradeSandbox sandbox, CheckFolders folders, string log, StudentRow row, Func<TimeSpan> left, CancellationToken cancellation)
    {
        // The test host, where the lab's code runs, in a sandbox of its own: the checks and the results read-only to it.
        folders.Launcher = sandbox.TestHostLauncher(Path.Combine(folders.Checks, ".testhost"), [folders.Checks, folders.Results]);
        var excluded = new List<string>();
        RunCheckRuns(setup, sandbox, folders, log, row, left, excluded, cancellation);
        if (excluded.Count > 0)
        {
            ListLeftOut(sandbox, folders, log, row, left, excluded, cancellation);
        }
    }

    /// <summary>
    /// The lab's uses of other assemblies that the checks' list refuses: each fails the sections it names, and the row
    /// says so with the first of them.
    /// </summary>
    private static void ScanUses(GradeSetup setup, string assembly, StudentRow row)
    {
        if (setup.Uses is null)
        {
            return;
        }

        AssemblyUses uses;
        try
        {
            uses = AssemblyUses.Read(assembly);
        }
        catch (BadImageFormatException e)
        {
            row.Problems.Add("not its own code");
            row.Detail ??= $"the built lab is not a .NET assembly this grader can read: {e.Message}";
            foreach (string section in setup.Uses.Sections.Values.Distinct(StringComparer.Ordinal))
            {
                row.Refused.TryAdd(section, "the built lab cannot be read");
            }

            return;
        }

        foreach (UseFinding finding in setup.Uses.Check(uses))
        {
            row.Uses.Add(finding.Line(polish: false));
            foreach (string section in finding.Sections)
            {
                row.Refused.TryAdd(section, finding.Message(polish: false));
            }
        }

        if (row.Uses.Count > 0)
        {
            row.Problems.Add("not its own code");
            row.Detail ??= row.Uses[0];
        }
    }

    /// <summary>
    /// A run leaves out a stopped check's whole test method (a filter names methods, not a theory's cases), so the cases
    /// of that method which had no result by then never ran: listed by the test platform, they count as not run, and
    /// the row's checks add up to the lab's.
    /// </summary>
    private static void ListLeftOut(GradeSandbox sandbox, CheckFolders folders, string log, StudentRow row, Func<TimeSpan> left, List<string> excluded, CancellationToken cancellation)
    {
        if (left() <= TimeSpan.Zero)
        {
            return;
        }

        ChildRun list = sandbox.Run(folders.Results, log, Min(left(), TimeSpan.FromMinutes(1)), "dotnet",
            ["test", .. folders.TestAssemblyArgs, "--list-tests", "--filter", string.Join('|', excluded.Select(n => $"FullyQualifiedName={n}")), .. folders.HostSettings], cancellation,
            readOnly: [folders.Checks], nested: folders.Nested);
        cancellation.ThrowIfCancellationRequested();
        if (list.TimedOut || list.ExitCode != 0)
        {
            return;
        }

        foreach (string display in ListedTests(list.Output))
        {
            row.Checks.TryAdd(display, "NotRun");
        }
    }

    /// <summary>
    /// The display names <c>dotnet test --list-tests</c> prints: the lines indented by four spaces after "The following
    /// Tests are available:", among which the test adapter's own lines ("[xUnit.net …]") may fall.
    /// </summary>
    /// <param name="output">The command's output.</param>
    /// <returns>The listed display names, in order.</returns>
    internal static IEnumerable<string> ListedTests(string output)
    {
        ArgumentNullException.ThrowIfNull(output);
        bool listing = false;
        foreach (string line in output.Split('\n'))
        {
            string text = line.TrimEnd('\r');
            if (text.StartsWith("The following Tests are available:", StringComparison.Ordinal))
            {
                listing = true;
            }
            else if (listing && text.StartsWith("    ", StringComparison.Ordinal) && text.Trim().Length > 0)
            {
                yield return text[4..];
            }
        }
    }

    // Long: one loop over the runs of the checks, with what each run's files say.
    private static void RunCheckRuns(GradeSetup setup, GradeSandbox sandbox, CheckFolders folders, string log, StudentRow row, Func<TimeSpan> left, List<string> excluded, CancellationToken cancellation)
    {
        // The checks a run left without a result because one of them ended it (LabStoppedRun): the next run runs them alone.
        List<string>? missing = null, listed = null;
        int unrecorded = 0;
        for (int attempt = 1; ; attempt++)
        {
            if (left() <= TimeSpan.Zero)
            {
                row.Problems.Add("submission time limit");
                return;
            }

            string lab = folders.Results;
            string results = Path.Combine(lab, $"results-{attempt}");
            List<string> args = ["test", .. folders.TestAssemblyArgs, "--logger", "trx;LogFileName=checks.trx", "--results-directory", results,
                "--blame-hang-timeout", string.Create(CultureInfo.InvariantCulture, $"{(int)Math.Ceiling(setup.Request.CheckTimeout.TotalSeconds)}s"), "--blame-hang-dump-type", "none"];
            if (missing is not null)
            {
                args.AddRange(["--filter", DisplayNameFilter(missing)]);
            }
            else if (excluded.Count > 0)
            {
                args.AddRange(["--filter", string.Join('&', excluded.Select(n => $"FullyQualifiedName!={n}"))]);
            }

            args.AddRange(folders.HostSettings);
            ChildRun test = sandbox.Run(lab, log, left(), "dotnet", args, cancellation, readOnly: [folders.Checks], nested: folders.Nested);
            cancellation.ThrowIfCancellationRequested();
            if (test.Limit is not SandboxLimit.None and not SandboxLimit.Memory)
            {
                row.Problems.Add($"check {GradeSandbox.LimitName(test.Limit)}");
                row.Detail ??= FirstErrors(test.Output, lab);
            }

            if (OutOfMemory(test.Output) || test.Limit == SandboxLimit.Memory)
            {
                row.Problems.Add("check memory limit");
                row.Detail ??= OutOfMemoryDetail(setup, "a check");
            }

            string trx = Path.Combine(results, "checks.trx");
            bool labStopped = false;
            if (File.Exists(trx))
            {
                foreach (CheckResult result in CheckRunFiles.Results(trx))
                {
                    labStopped |= result.Message?.Contains(LabStoppedRun, StringComparison.Ordinal) == true;
                    row.Checks[result.Display] = result.Result;
                    if (result.Message is not null)
                    {
                        row.Messages.TryAdd(result.Display, result.Message);
                    }
                }
            }

            bool hang = test.Output.Contains("inactivity time", StringComparison.Ordinal);
            var stopped = Directory.Exists(results)
                ? Directory.EnumerateFiles(results, "Sequence_*.xml", SearchOption.AllDirectories).SelectMany(CheckRunFiles.Unfinished).ToList()
                : [];
            foreach ((string fullName, string display) in stopped)
            {
                row.Checks[display] = hang ? "Timeout" : "Crashed";
                row.Detail ??= $"{(hang ? "ran past --check-timeout" : "crashed the test process")}: {display}";
                if (!excluded.Contains(fullName))
                {
                    excluded.Add(fullName);
                }
            }

            if (test.TimedOut)
            {
                row.Problems.Add("submission time limit");
                return;
            }

            bool labLimit = test.Limit != SandboxLimit.None || OutOfMemory(test.Output);
            CheckRunVerdict verdict = JudgeCheckRun(new CheckRunOutcome(File.Exists(trx), row.Checks.Count, stopped.Count, hang, labLimit), attempt, unrecorded, () => FirstErrors(test.Output, lab));
            if (verdict.Unrecorded)
            {
                // Nothing of the lab's stopped it: the machine did (a test host too slow to start beside other work).
                unrecorded++;
                GradeSandbox.AppendLog(log, "raylab grade:", string.Create(CultureInfo.InvariantCulture,
                    $"run {attempt} of the checks recorded no check and hit no limit of the lab's own: they run again ({unrecorded} of at most {MaxUnrecordedReruns} such runs)"), "");
                continue;
            }

            if (unrecorded > 0)
            {
                row.Notes.Add(string.Create(CultureInfo.InvariantCulture,
                    $"the checks ran again {unrecorded} time{(unrecorded == 1 ? "" : "s")} after a run that recorded no check and hit no limit of the lab's own (a busy machine, not the lab){(row.Checks.Count == 0 ? ", and recorded none" : "")}"));
            }

            if (verdict.Problem is not null)
            {
                row.Problems.Add(verdict.Problem);
            }

            row.Detail ??= verdict.Detail;
            missing = null;
            if (!verdict.RunAgain && labStopped && verdict.Problem is null && attempt < MaxCheckRuns)
            {
                // A check ended the run after its result, with the student's code that could not be stopped: the
                // checks it left without a result run again, without it.
                listed ??= ListChecks(sandbox, folders, log, left, cancellation);
                missing = [.. listed.Where(display => !row.Checks.ContainsKey(display))];
                if (missing.Count == 0)
                {
                    return;
                }
            }
            else if (!verdict.RunAgain)
            {
                return;
            }
        }
    }

    /// <summary>
    /// The words of an exercise lab's check that ended its run (<c>Check.RunStopped</c> in the lab's checks): its
    /// student's method ran past the lab's time limit and could not be stopped, so the check ended the test process
    /// after its own result, and the checks not yet started have none.
    /// </summary>
    internal const string LabStoppedRun = "Check.StopRun";

    /// <summary>Every check's display name, as <c>dotnet test --list-tests</c> gives them; none where the listing fails.</summary>
    private static List<string> ListChecks(GradeSandbox sandbox, CheckFolders folders, string log, Func<TimeSpan> left, CancellationToken cancellation)
    {
        if (left() <= TimeSpan.Zero)
        {
            return [];
        }

        ChildRun list = sandbox.Run(folders.Results, log, Min(left(), TimeSpan.FromMinutes(1)), "dotnet",
            ["test", .. folders.TestAssemblyArgs, "--list-tests", .. folders.HostSettings], cancellation,
            readOnly: [folders.Checks], nested: folders.Nested);
        cancellation.ThrowIfCancellationRequested();
        return list.TimedOut || list.ExitCode != 0 ? [] : [.. ListedTests(list.Output)];
    }

    /// <summary>
    /// A <c>dotnet test --filter</c> that selects the checks with these display names, each escaped as the test
    /// platform's filter syntax needs (a backslash before <c>\ ( ) &amp; | = ! ~</c>).
    /// </summary>
    /// <param name="displayNames">The checks' display names.</param>
    /// <returns>The filter.</returns>
    internal static string DisplayNameFilter(IEnumerable<string> displayNames)
    {
        ArgumentNullException.ThrowIfNull(displayNames);
        return string.Join('|', displayNames.Select(name => "DisplayName=" + string.Concat(name.Select(c => "\\()&|=!~".Contains(c, StringComparison.Ordinal) ? $"\\{c}" : c.ToString()))));
    }

    /// <summary>How many times the checks run at most, each without the checks that stopped the runs before it.</summary>
    internal const int MaxCheckRuns = 50;

    /// <summary>
    /// How many times the checks run again after a run that recorded no check, left none unfinished and hit no limit
    /// of the lab's own (<see cref="JudgeCheckRun"/>).
    /// </summary>
    internal const int MaxUnrecordedReruns = 2;

    /// <summary>
    /// What one <c>dotnet test</c> run of the checks comes to. Checks that stopped the run (a hang, a crash) are left
    /// out of the next run, so the rest still get a result. A run that recorded no check (no TRX file, or one with no
    /// check in it), left none unfinished and hit no limit of the lab's own (memory, processes, disk, CPU time) was
    /// stopped by the machine, not the lab: a test host slow to start beside other work. It runs again, at most
    /// <see cref="MaxUnrecordedReruns"/> times; after that, or after a run that hit a limit, the row says "checks did
    /// not run": it must never read "ok" with no checks.
    /// </summary>
    /// <param name="run">What the run left: its TRX file, the checks recorded so far, those it left unfinished, whether it hit a limit.</param>
    /// <param name="attempt">This run's number, from 1.</param>
    /// <param name="unrecorded">How many runs before it recorded nothing and ran again.</param>
    /// <param name="firstErrors">The run's first error lines, read from its output when the verdict needs them.</param>
    internal static CheckRunVerdict JudgeCheckRun(CheckRunOutcome run, int attempt, int unrecorded, Func<string> firstErrors)
    {
        ArgumentNullException.ThrowIfNull(firstErrors);
        if (run.Stopped > 0 && attempt < MaxCheckRuns)
        {
            return new CheckRunVerdict(true, run.Hang ? "check time limit" : "checks crashed", null);
        }

        if ((!run.TrxWritten || run.ChecksRecorded == 0) && run.Stopped == 0 && !run.LabLimit && unrecorded < MaxUnrecordedReruns && attempt < MaxCheckRuns)
        {
            return new CheckRunVerdict(true, null, null, Unrecorded: true);
        }

        if (!run.TrxWritten)
        {
            return new CheckRunVerdict(false, "checks did not run", firstErrors());
        }

        if (run.ChecksRecorded == 0)
        {
            return new CheckRunVerdict(false, "checks did not run", run.Hang
                ? "the test run was stopped for inactivity before any check finished: give --check-timeout more room"
                : firstErrors());
        }

        return new CheckRunVerdict(false, null, null);
    }

    /// <summary>
    /// Whether a child's output shows a .NET process that ran out of managed memory: an exception's name (a check
    /// that failed with it), or the runtime's own line for one nobody caught (the process then exits 134).
    /// </summary>
    private static bool OutOfMemory(string output) =>
        output.Contains("System.OutOfMemoryException", StringComparison.Ordinal) || OutOfMemoryLine().IsMatch(output);

    private static string OutOfMemoryDetail(GradeSetup setup, string what) => string.Create(CultureInfo.InvariantCulture,
        $"{what} ran out of memory: {setup.Request.MemoryLimitMegabytes} MB (--memory-limit)");

    /// <summary>
    /// The rays per pixel the program's own lines claim for the timed method, kept as the lab's own report: shown
    /// and labelled so, never graded (the checks count the rays themselves). Their times are not read: the grader
    /// times the program itself.
    /// </summary>
    private static void ReadTimings(GradeSetup setup, string output, StudentRow row)
    {
        foreach (Match m in RenderLine().Matches(output))
        {
            if (m.Groups["method"].Value == setup.TimedMethod
                && double.TryParse(m.Groups["rpp"].Value, NumberStyles.Float, CultureInfo.InvariantCulture, out double rpp))
            {
                row.LabRaysPerPixel[m.Groups["camera"].Value] = rpp;
            }
        }
    }

    /// <summary>
    /// Each picture read back from the lab's copy as untrusted (<see cref="ReadPicture"/>: no link, a capped size,
    /// the header checked before any pixel is decoded), then scored against the exact image.
    /// </summary>
    private static void ScorePictures(GradeSetup setup, GradeReference reference, string lab, string folder, StudentRow row)
    {
        bool missing = false;
        foreach ((string camera, string file) in setup.Pictures)
        {
            Image exact = reference.Exact[camera];
            PictureRead read = ReadPicture(lab, file, exact.Width, exact.Height);
            if (read.Missing)
            {
                missing = true;
                continue;
            }

            if (read.Status is not null)
            {
                row.Problems.Add(read.Status);
            }

            if (read.Picture is not { } picture)
            {
                row.Pictures[camera] = new PictureScore(double.NaN, double.NaN, read.Problem ?? $"{file} does not decode");
                continue;
            }

            if (picture.Width != exact.Width || picture.Height != exact.Height)
            {
                row.Pictures[camera] = new PictureScore(double.NaN, double.NaN,
                    $"{file} is {picture.Width}×{picture.Height}, the exact image {exact.Width}×{exact.Height}");
                continue;
            }

            FlipResult flip = Flip.Compute(exact, picture);
            ImageError error = ImageError.Measure(picture, exact);
            picture.Save(Path.Combine(folder, $"{camera}.png"));
            FlipMap.Render(flip).Save(Path.Combine(folder, $"{camera}-flip.png"));
            row.Pictures[camera] = new PictureScore(error.Rmse, flip.Mean, null);
        }

        if (missing)
        {
            row.Problems.Add("pictures missing");
        }
    }

    /// <summary>The lab's root: the submission itself when it holds src/Lab, else its one subfolder that does (a zip's top folder).</summary>
    private static string? FindLab(string submission)
    {
        static bool IsLab(string folder) =>
            Directory.Exists(Path.Combine(folder, "src", "Lab")) && Directory.EnumerateFiles(Path.Combine(folder, "src", "Lab"), "*.csproj").Any();
        if (IsLab(submission))
        {
            return submission;
        }

        string[] inner = [.. Directory.EnumerateDirectories(submission).Where(d => !Path.GetFileName(d).StartsWith('.') && IsLab(d))];
        return inner.Length == 1 ? inner[0] : null;
    }

    /// <summary>Copies a lab without build output, version control or links (a link could point anywhere).</summary>
    internal static void CopyLab(string from, string to)
    {
        Directory.CreateDirectory(to);
        foreach (FileSystemInfo entry in new DirectoryInfo(from).EnumerateFileSystemInfos())
        {
            if (entry.LinkTarget is not null)
            {
                continue;
            }

            string target = Path.Combine(to, entry.Name);
            if (entry is DirectoryInfo)
            {
                if (!SkippedFolders.Contains(entry.Name, StringComparer.OrdinalIgnoreCase))
                {
                    CopyLab(entry.FullName, target);
                }
            }
            else
            {
                File.Copy(entry.FullName, target, overwrite: true);
            }
        }
    }

    /// <summary>
    /// The instructor's build settings in place of the student's for the lab's own build: the root
    /// Directory.Build.props, no root file that could change how it builds (Directory.Build.targets,
    /// Directory.Packages.props, global.json, another nuget.config), the kit's feed as the only source; the student's
    /// tests/ left out (the checks are built elsewhere, <see cref="GradeChecks"/>).
    /// </summary>
    /// <returns>The lab's root namespace where it differs from the checks' (to bring into the checks' scope), or null.</returns>
    private static string? PinBuildFiles(GradeSetup setup, string lab)
    {
        string tests = Path.Combine(lab, "tests");
        if (Directory.Exists(tests))
        {
            Directory.Delete(tests, recursive: true);
        }

        foreach (string file in Directory.EnumerateFiles(lab))
        {
            string fileName = Path.GetFileName(file);
            if (new[] { "Directory.Build.props", "Directory.Build.targets", "Directory.Packages.props", "Directory.Build.rsp", "global.json", "nuget.config" }
                .Contains(fileName, StringComparer.OrdinalIgnoreCase))
            {
                File.Delete(file);
            }
        }

        File.Copy(Path.Combine(setup.Checks, "Directory.Build.props"), Path.Combine(lab, "Directory.Build.props"));
        WriteNuGetConfig(lab, setup.Feed);
        string? project = Directory.EnumerateFiles(Path.Combine(lab, "src", "Lab"), "*.csproj").Order(StringComparer.Ordinal).FirstOrDefault();
        string? space = project is null ? null : RootNamespace().Match(File.ReadAllText(project)) is { Success: true } m ? m.Groups[1].Value.Trim() : null;
        return space is not null && space != setup.ChecksNamespace && Identifier().IsMatch(space) ? space : null;
    }

    private static void WriteNuGetConfig(string lab, string feed) => File.WriteAllText(Path.Combine(lab, "nuget.config"), NuGetConfig(feed));

    /// <summary>A nuget.config whose only package source is the kit's feed.</summary>
    private static string NuGetConfig(string feed) => $"""
        <?xml version="1.0" encoding="utf-8"?>
        <configuration>
          <packageSources>
            <clear />
            <add key="class-kit" value="{System.Security.SecurityElement.Escape(feed)}" />
          </packageSources>
        </configuration>
        """;

    /// <summary>
    /// A section's result from its checks' outcomes: fail where the lab uses what it may not (<paramref name="refused"/>);
    /// then timeout, crashed or not run where a check did; pass where every check passed; not written where the others
    /// passed and at least one was skipped (the exercise lab's checks skip a section still throwing
    /// NotImplementedException), which earns nothing, as a fail does; otherwise fail; "" when none of its checks ran.
    /// </summary>
    internal static string SectionResult(IReadOnlyCollection<string> outcomes, bool refused)
    {
        ArgumentNullException.ThrowIfNull(outcomes);
        return refused ? "fail"
            : outcomes.Count == 0 ? ""
            : outcomes.Contains("Timeout") ? "timeout"
            : outcomes.Contains("Crashed") ? "crashed"
            : outcomes.Contains("NotRun") ? "not run"
            : outcomes.All(o => o is "Passed") ? "pass"
            : outcomes.All(o => o is "Passed" or "Skipped") ? "not written"
            : "fail";
    }

    /// <summary>
    /// A check's lab section: the display name's first word where it is a section number or <c>own</c>
    /// ("3.2 Kamera perspektywiczna: …" → 3.2), else its class ("MyLab.Tests.CameraTests.Frame" → CameraTests).
    /// </summary>
    /// <param name="display">The check's display name.</param>
    /// <returns>The section.</returns>
    internal static string SectionOf(string display)
    {
        ArgumentNullException.ThrowIfNull(display);
        Match m = SectionPrefix().Match(display);
        if (m.Success)
        {
            return m.Groups[1].Value;
        }

        string name = display.Split('(')[0];
        string[] parts = name.Split('.');
        return parts.Length >= 2 ? parts[^2] : name;
    }

    /// <summary>The first few error lines of a child's output, with the lab's path left out.</summary>
    private static string FirstErrors(string output, string lab)
    {
        string[] lines = output.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        string[] errors = [.. lines.Where(l => l.Contains("error", StringComparison.OrdinalIgnoreCase) || l.Contains("exception", StringComparison.OrdinalIgnoreCase))
            .Select(l => l.Replace(lab + Path.DirectorySeparatorChar, "", StringComparison.Ordinal).Replace(lab, ".", StringComparison.Ordinal))
            .Distinct().Take(3)];
        return errors.Length > 0 ? string.Join(" | ", errors) : string.Join(" | ", lines.TakeLast(3));
    }

    private static string SafeName(string name)
    {
        var safe = new StringBuilder();
        foreach (char c in name)
        {
            safe.Append(char.IsAsciiLetterOrDigit(c) || c is '-' or '_' or '.' ? c : '_');
        }

        return safe.Length == 0 || safe[0] == '.' ? "_" + safe : safe.ToString();
    }

    private static TimeSpan Min(TimeSpan a, TimeSpan b) => a < b ? a : b;

    [GeneratedRegex(@"^Out of memory\.\r?$", RegexOptions.Multiline)]
    private static partial Regex OutOfMemoryLine();

    [GeneratedRegex(@"^((?:\d+(?:\.\d+)*)|own)\s")]
    private static partial Regex SectionPrefix();

    [GeneratedRegex(@"<RootNamespace>\s*([^<]+?)\s*</RootNamespace>")]
    private static partial Regex RootNamespace();

    [GeneratedRegex(@"^[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*$")]
    private static partial Regex Identifier();

    /// <summary>The lab's line per render: "&lt;camera&gt; &lt;method&gt; N rays (X per pixel) T ms …", or in the Polish lab "… N promieni (X na piksel) …".</summary>
    [GeneratedRegex(@"(?m)^(?<camera>\S+)\s+(?<method>\S+)\s+[\d,. ]+\s+(?:rays|promieni)\s+\(\s*(?<rpp>[\d.]+)\s+(?:per pixel|na piksel)\)\s+(?<ms>[\d.]+)\s+ms")]
    private static partial Regex RenderLine();
}

/// <summary>A submission in the grader's work: its row, its copy, its log and report folder, and the time its own steps took.</summary>
/// <param name="Row">The student's row.</param>
/// <param name="Path">The copy with the pinned checks.</param>
/// <param name="Log">The log of its steps.</param>
/// <param name="ReportFolder">Its folder in the report.</param>
internal sealed record GradedLab(StudentRow Row, string Path, string Log, string ReportFolder)
{
    /// <summary>Runs while one of this submission's steps runs, so waiting for the others does not count against its limit.</summary>
    public Stopwatch Clock { get; } = new();

    /// <summary>Whether it built (and its checks ran): its program runs.</summary>
    public bool Built { get; set; }

    /// <summary>What is left of the submission's limit.</summary>
    public TimeSpan Left(GradeSetup setup) => setup.Request.SubmissionTimeout - Clock.Elapsed;
}

/// <summary>One student's row of the class table.</summary>
/// <param name="Name">The submission folder's name, or the student's full name in a Moodle download.</param>
/// <param name="Folder">That name made safe for a file path (the report's folder of the student's pictures and log).</param>
internal sealed record StudentRow(string Name, string Folder)
{
    /// <summary>Moodle's participant id, or null.</summary>
    public string? ParticipantId { get; init; }

    /// <summary>Why the upload was refused, in Polish (the feedback), or null.</summary>
    public string? PolishRefusal { get; set; }

    /// <summary>Each check that did not pass: the first line of its message, where it left one.</summary>
    public Dictionary<string, string> Messages { get; } = new(StringComparer.Ordinal);

    /// <summary>The grade: the points of the sections that pass and of the pictures within the thresholds (<see cref="GradingScheme"/>).</summary>
    public double Grade { get; set; }

    /// <summary>What went wrong (build, limits, program), in order; empty when everything ran.</summary>
    public List<string> Problems { get; } = [];

    /// <summary>The first errors of the failing step, or null.</summary>
    public string? Detail { get; set; }

    /// <summary>What the grader did about the machine rather than the lab (checks run again after a run that recorded nothing), one line each.</summary>
    public List<string> Notes { get; } = [];

    /// <summary>The lab's uses of other assemblies that the checks' list refuses, one line each ("3.1: LabOrthoCamera.GetRay uses …").</summary>
    public List<string> Uses { get; } = [];

    /// <summary>Each section a refused use fails, with the first refused use's message.</summary>
    public SortedDictionary<string, string> Refused { get; } = new(StringComparer.Ordinal);

    /// <summary>
    /// Each check's display name and outcome: Passed, Failed, Skipped, Timeout, Crashed, or NotRun (a case of a test method
    /// left out of the runs after another of its cases timed out or crashed).
    /// </summary>
    public SortedDictionary<string, string> Checks { get; } = new(StringComparer.Ordinal);

    /// <summary>Each camera's picture score.</summary>
    public Dictionary<string, PictureScore> Pictures { get; } = [];

    /// <summary>Each camera's rays per pixel of the timed method as the program's own lines claim them: the lab's report, not graded.</summary>
    public Dictionary<string, double> LabRaysPerPixel { get; } = [];

    /// <summary>How the program's seconds (<see cref="Steps"/>' "program") were taken, or null when it did not run.</summary>
    public string? ProgramTimedBy { get; set; }

    /// <summary>The submission's wall time in the grader: its own steps, not the time it waited for others.</summary>
    public double Seconds { get; set; }

    /// <summary>Each step's seconds: build, checks, program (those that ran).</summary>
    public SortedDictionary<string, double> Steps { get; } = new(StringComparer.Ordinal);

    /// <summary>When the program started, in seconds after the grading began; null when it did not run.</summary>
    public double? ProgramStart { get; set; }

    /// <summary>A short status: "ok", or the problems joined.</summary>
    public string Status => Problems.Count == 0 ? "ok" : string.Join("; ", Problems.Distinct());

    /// <summary>"checks N passed, N failed, N timed out", then ", N not written", ", N crashed" and ", N not run" where there are any, for the grader's lines.</summary>
    public string CheckCounts => string.Create(CultureInfo.InvariantCulture,
        $"checks {Count("Passed")} passed, {Count("Failed")} failed, {Count("Timeout")} timed out{(Count("Skipped") > 0 ? $", {Count("Skipped")} not written" : "")}{(Count("Crashed") > 0 ? $", {Count("Crashed")} crashed" : "")}{(Count("NotRun") > 0 ? $", {Count("NotRun")} not run" : "")}");

    /// <summary>How many checks ended with <paramref name="outcome"/>.</summary>
    public int Count(string outcome) => Checks.Values.Count(v => v == outcome);

    /// <summary>A section's result (<see cref="GradeJob.SectionResult"/>), from its checks' outcomes.</summary>
    public string Section(string section) =>
        GradeJob.SectionResult([.. Checks.Where(c => GradeJob.SectionOf(c.Key) == section).Select(c => c.Value)], Refused.ContainsKey(section));
}

/// <summary>A picture against the exact image: RMSE in 8-bit levels and mean FLIP, or why it has none.</summary>
internal sealed record PictureScore(double Rmse, double Flip, string? Problem);

/// <summary>What one run of the checks left (<see cref="GradeJob.JudgeCheckRun"/>).</summary>
/// <param name="TrxWritten">Whether the run wrote its TRX file.</param>
/// <param name="ChecksRecorded">The checks with a result so far, this run's and the runs' before it.</param>
/// <param name="Stopped">The checks this run left unfinished (the blame data's sequence files).</param>
/// <param name="Hang">Whether the run was stopped for inactivity (<c>--blame-hang-timeout</c>), not by a crash.</param>
/// <param name="LabLimit">Whether the run hit a limit of the lab's own: memory, processes, disk or CPU time.</param>
internal readonly record struct CheckRunOutcome(bool TrxWritten, int ChecksRecorded, int Stopped, bool Hang, bool LabLimit);

/// <summary>What one run of the checks comes to (<see cref="GradeJob.JudgeCheckRun"/>).</summary>
/// <param name="RunAgain">Whether the checks run again, without those that stopped this run.</param>
/// <param name="Problem">The row's problem, or null for none.</param>
/// <param name="Detail">The row's detail, or null for none.</param>
/// <param name="Unrecorded">Whether the run recorded no check, and nothing of the lab's stopped it: it runs again as it was.</param>
internal readonly record struct CheckRunVerdict(bool RunAgain, string? Problem, string? Detail, bool Unrecorded = false);

/// <summary>Where a submission's checks run: their built folder (read-only to the run) and the folder the run writes, its results.</summary>
/// <param name="Checks">The checks' folder (<see cref="GradeChecks.Prepare"/>), built.</param>
/// <param name="Results">The run's writable folder: its home, its TRX files and the test platform's blame data.</param>
/// <param name="Tests">The checks' built test assembly (<see cref="GradeChecks.BuiltTests"/>).</param>
internal sealed record CheckFolders(string Checks, string Results, string Tests)
{
    /// <summary>
    /// What names the checks in a <c>dotnet test</c> command: their built assembly (the test platform alone, no MSBuild
    /// run to find it), with the settings the project gives <c>dotnet test</c> itself: its run settings file and the
    /// console logger at its verbosity (<see cref="GradeChecks.ProjectTestSettings"/>).
    /// </summary>
    public IEnumerable<string> TestAssemblyArgs => [Tests, .. _settings ??= GradeChecks.ProjectTestSettings(Checks)];

    /// <summary>The project's settings for <c>dotnet test</c>, read from it once for all of the submission's runs.</summary>
    private IReadOnlyList<string>? _settings;

    /// <summary>The launcher of the test host in a sandbox of its own (<see cref="GradeSandbox.TestHostLauncher"/>), or null.</summary>
    public string? Launcher { get; set; }

    /// <summary>Whether the run's sandbox lets the test host's launcher make its own (one user namespace inside it).</summary>
    public bool Nested => Launcher is not null;

    /// <summary>The arguments that end a <c>dotnet test</c> command: the test platform's dotnet host, the launcher.</summary>
    public IEnumerable<string> HostSettings => Launcher is null ? [] : ["--", $"RunConfiguration.DotNetHostPath={Launcher}"];
}
