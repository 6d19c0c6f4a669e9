namespace RayLab.Grading;

/// <summary>What <c>raylab grade</c> was asked to do.</summary>
/// <param name="Submissions">The folder of submitted labs.</param>
/// <param name="Checks">The pinned checks' lab.</param>
/// <param name="Feed">The package folder, or null for the kit's.</param>
/// <param name="Output">The report folder.</param>
/// <param name="CheckTimeout">The limit on one check.</param>
/// <param name="RunTimeout">The limit on the lab's program.</param>
/// <param name="SubmissionTimeout">The limit on one submission in all.</param>
/// <param name="UnsafeNoSandbox">Run without bubblewrap.</param>
public sealed record GradeRequest(
    string Submissions,
    string Checks,
    string? Feed,
    string Output,
    TimeSpan CheckTimeout,
    TimeSpan RunTimeout,
    TimeSpan SubmissionTimeout,
    bool UnsafeNoSandbox)
{
    /// <summary>Half the processor count, at least 1: a submission's build and checks take about two cores.</summary>
    public static int DefaultJobs { get; } = Math.Max(1, Environment.ProcessorCount / 2);

    /// <summary>How many submissions are built and checked at once (the programs run one at a time).</summary>
    public int Jobs { get; init; } = DefaultJobs;

    /// <summary>The default of <see cref="MemoryLimitMegabytes"/>: 2048 MB.</summary>
    public const int DefaultMemoryLimitMegabytes = 2048;

    /// <summary>
    /// The memory, native and managed, a submission's step may hold, in megabytes: all its processes together where
    /// the machine delegates a cgroup v2, else each process (RLIMIT_DATA); each .NET process's GC heap is capped the
    /// same, so that managed memory ends in an <see cref="OutOfMemoryException"/> instead of taking the machine.
    /// </summary>
    public int MemoryLimitMegabytes { get; init; } = DefaultMemoryLimitMegabytes;

    /// <summary>The default of <see cref="ProcessLimit"/>: 1024 (a lab's build, with MSBuild's and the compiler's threads, stays well below).</summary>
    public const int DefaultProcessLimit = 1024;

    /// <summary>The processes and threads a submission's step may run at once.</summary>
    public int ProcessLimit { get; init; } = DefaultProcessLimit;

    /// <summary>The default of <see cref="DiskLimitMegabytes"/>: 1024 MB (a built lab holds about 30 MB).</summary>
    public const int DefaultDiskLimitMegabytes = 1024;

    /// <summary>The megabytes the lab's writable copy may hold, and its /tmp each.</summary>
    public int DiskLimitMegabytes { get; init; } = DefaultDiskLimitMegabytes;

    /// <summary>The default of <see cref="CpuLimitSeconds"/>: 600 s.</summary>
    public const int DefaultCpuLimitSeconds = 600;

    /// <summary>The CPU time each of a submission's processes may use, in seconds.</summary>
    public int CpuLimitSeconds { get; init; } = DefaultCpuLimitSeconds;

    /// <summary>The limits the instructor grades without (<c>--unsafe-no-limit</c>): memory, processes, disk, cpu.</summary>
    public IReadOnlyList<string> UnsafeNoLimit { get; init; } = [];

    /// <summary>The names <c>--unsafe-no-limit</c> takes.</summary>
    public static IReadOnlyList<string> LimitNames { get; } = ["memory", "processes", "disk", "cpu"];

    /// <summary>The sandbox's limits: each one asked for, less those the instructor grades without.</summary>
    public GradeLimits Limits => new()
    {
        MemoryMegabytes = UnsafeNoLimit.Contains("memory") ? null : MemoryLimitMegabytes,
        Processes = UnsafeNoLimit.Contains("processes") ? null : ProcessLimit,
        DiskMegabytes = UnsafeNoLimit.Contains("disk") ? null : DiskLimitMegabytes,
        CpuSeconds = UnsafeNoLimit.Contains("cpu") ? null : CpuLimitSeconds,
    };

    /// <summary>Moodle's grading worksheet to fill, or null.</summary>
    public string? MoodleWorksheet { get; init; }
}
