using System.CommandLine;
using RayLab.Grading;
using RayLab.Reports.Output;
using RayLab.Scenes;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab grade SUBMISSIONS --checks KIT/checks/KIND --out DIR [--feed KIT/feed] [--check-timeout S]
/// [--run-timeout S] [--submission-timeout S] [--jobs N] [--memory-limit MB] [--process-limit N] [--disk-limit MB]
/// [--cpu-limit S] [--unsafe-no-limit LIMIT] [--moodle-worksheet CSV] [--unsafe-no-sandbox]</c>: builds, checks and runs every
/// submitted lab in a sandbox with the instructor's pinned checks and writes one class table (<see cref="GradeJob"/>).
/// </summary>
public static class GradeCommand
{
    /// <summary>Builds the command; its action runs <see cref="GradeJob.Run"/> with these writers.</summary>
    /// <param name="stdout">Where one line per submission goes.</param>
    /// <param name="stderr">Where errors go, one line each.</param>
    /// <param name="cancellation">Cancels the run (Ctrl+C): the submission in progress is stopped and no report is written.</param>
    public static Command Create(TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        var submissions = new Argument<string>("submissions") { Description = "The submitted labs: a folder of one folder per student (the folder's name is the student's row; GitHub Classroom's clones too), or a Moodle assignment's \"Download all submissions\" folder or zip (one Full Name_12345_assignsubmission_file_ folder per student; the full name is the row). Each holds a lab with src/Lab (or one folder holding it), or the zip of one, unpacked safely." };
        var checks = new Option<string>("--checks") { Description = "The instructor's pinned checks: a class kit's checks/exercise or checks/method (a lab whose tests/Lab.Tests, Directory.Build.props and grading.json replace the student's).", Required = true, HelpName = "DIR" };
        var feed = new Option<string?>("--feed") { Description = "The folder feed every package comes from, the only package source. Default: the kit's feed/ (two folders above --checks).", HelpName = "DIR" };
        var output = new Option<string>("--out") { Description = "The folder for the report: grades.csv, grades.json, index.html, each student's pictures, error maps and logs (created if missing).", Required = true, HelpName = "DIR" };
        var checkTimeout = new Option<int>("--check-timeout") { Description = "Seconds one check may run before it is stopped and counted as timed out; the other checks go on.", DefaultValueFactory = _ => 60, HelpName = "S" };
        var runTimeout = new Option<int>("--run-timeout") { Description = "Seconds the lab's built program (the pictures) may run.", DefaultValueFactory = _ => 180, HelpName = "S" };
        var submissionTimeout = new Option<int>("--submission-timeout") { Description = "Seconds one submission may take in all (build, checks, program); what is left is stopped and the row says so.", DefaultValueFactory = _ => 600, HelpName = "S" };
        var jobs = new Option<int>("--jobs", "-j") { Description = "How many submissions are built and checked at once (each takes about two cores); the programs, whose times the report compares, then run one at a time. Default: half the processor count, at least 1.", DefaultValueFactory = _ => GradeRequest.DefaultJobs, HelpName = "N" };
        var memoryLimit = new Option<int>("--memory-limit") { Description = "Megabytes of memory, native and managed, a submission's step may hold: all its processes together where the machine delegates a cgroup v2, else each process (RLIMIT_DATA); each .NET process's GC heap is capped the same. Past it the row says so.", DefaultValueFactory = _ => GradeRequest.DefaultMemoryLimitMegabytes, HelpName = "MB" };
        var processLimit = new Option<int>("--process-limit") { Description = "Processes and threads a submission's step may run at once (a pids cgroup v2, else RLIMIT_NPROC in the sandbox's user namespace); a fork loop stops there and the row says so.", DefaultValueFactory = _ => GradeRequest.DefaultProcessLimit, HelpName = "N" };
        var diskLimit = new Option<int>("--disk-limit") { Description = "Megabytes the lab's writable copy may hold (a tmpfs of that size; needs root), and its /tmp each; a lab that fills it gets a row that says so.", DefaultValueFactory = _ => GradeRequest.DefaultDiskLimitMegabytes, HelpName = "MB" };
        var cpuLimit = new Option<int>("--cpu-limit") { Description = "Seconds of CPU time each process of a submission may use (RLIMIT_CPU).", DefaultValueFactory = _ => GradeRequest.DefaultCpuLimitSeconds, HelpName = "S" };
        var unsafeNoLimit = new Option<string[]>("--unsafe-no-limit") { Description = "Grade without a limit this machine cannot hold: memory, processes, disk or cpu (repeat it for more); without it the grader refuses to start.", HelpName = "LIMIT", AllowMultipleArgumentsPerToken = false };
        var moodleWorksheet = new Option<string?>("--moodle-worksheet") { Description = "The Moodle assignment's offline grading worksheet (CSV): the report folder gets moodle-worksheet.csv, the same file with each graded student's Grade and Feedback comments (in Polish) filled, for \"Upload grading worksheet\".", HelpName = "CSV" };
        var unsafeNoSandbox = new Option<bool>("--unsafe-no-sandbox") { Description = "Run the submissions' code without a sandbox, with this user's rights and network: only for labs you trust, or where bubblewrap cannot run (Windows, macOS)." };
        var grade = new Command("grade", "Grade a folder of submitted labs against the instructor's pinned checks: each one built, tested and run in a sandbox (bubblewrap: read-only system, no network, its own folder writable), its pictures scored against the exact image; writes grades.csv, grades.json and index.html.")
        {
            submissions, checks, feed, output, checkTimeout, runTimeout, submissionTimeout, jobs, memoryLimit, processLimit, diskLimit, cpuLimit, unsafeNoLimit, moodleWorksheet, unsafeNoSandbox,
        };
        grade.SetAction(result => Run(
            new GradeRequest(
                result.GetRequiredValue(submissions),
                result.GetRequiredValue(checks),
                result.GetValue(feed),
                result.GetRequiredValue(output),
                TimeSpan.FromSeconds(result.GetRequiredValue(checkTimeout)),
                TimeSpan.FromSeconds(result.GetRequiredValue(runTimeout)),
                TimeSpan.FromSeconds(result.GetRequiredValue(submissionTimeout)),
                result.GetValue(unsafeNoSandbox))
            {
                Jobs = result.GetRequiredValue(jobs),
                MemoryLimitMegabytes = result.GetRequiredValue(memoryLimit),
                ProcessLimit = result.GetRequiredValue(processLimit),
                DiskLimitMegabytes = result.GetRequiredValue(diskLimit),
                CpuLimitSeconds = result.GetRequiredValue(cpuLimit),
                UnsafeNoLimit = result.GetValue(unsafeNoLimit) ?? [],
                MoodleWorksheet = result.GetValue(moodleWorksheet),
            },
            stdout,
            stderr,
            cancellation));
        return grade;
    }

    /// <summary>Runs <see cref="GradeJob.Run"/> and turns what it throws into one line on <paramref name="stderr"/> and the exit code.</summary>
    /// <param name="request">What to grade.</param>
    /// <param name="stdout">One line per submission, then the report's path.</param>
    /// <param name="stderr">Errors, one line each.</param>
    /// <param name="cancellation">Stops the submission in progress; no report is written.</param>
    /// <returns>0 when the report is written (whatever the grades), 1 for bad input, 130 when cancelled.</returns>
    public static int Run(GradeRequest request, TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        try
        {
            return GradeJob.Run(request, stdout, cancellation);
        }
        catch (Exception e) when (e is UsageException or SandboxUnavailableException)
        {
            stderr.WriteLine($"raylab: error: {SceneFileException.OneLine(e.Message)}");
            return 1;
        }
        catch (SceneFileException e)
        {
            stderr.WriteLine($"raylab: error: --checks: {SceneFileException.OneLine(e.Message)}");
            return 1;
        }
        catch (OperationCanceledException)
        {
            stderr.WriteLine("raylab: grading cancelled; no report written");
            return Program.CancelledExitCode;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"raylab: error: {SceneFileException.OneLine(e.Message)}");
            return 1;
        }
    }
}
