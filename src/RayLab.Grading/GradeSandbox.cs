using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using System.Text;
using System.Text.RegularExpressions;

namespace RayLab.Grading;

/// <summary>A limit of the sandbox that stopped a child (<see cref="ChildRun.Limit"/>).</summary>
public enum SandboxLimit
{
    /// <summary>No limit of the sandbox stopped it (it may still have run past its wall time: <see cref="ChildRun.TimedOut"/>).</summary>
    None,

    /// <summary>It ran out of memory: the submission's memory limit (cgroup v2, or RLIMIT_DATA per process) or the GC's heap limit.</summary>
    Memory,

    /// <summary>It could not start another process or thread: the submission's process limit.</summary>
    Processes,

    /// <summary>It filled its copy's disk space (or the sandbox's /tmp).</summary>
    Disk,

    /// <summary>One of its processes used up its CPU time (RLIMIT_CPU).</summary>
    CpuTime,
}

/// <summary>How a child process of <c>raylab grade</c> ended.</summary>
/// <param name="ExitCode">Its exit code; -1 when it was stopped.</param>
/// <param name="TimedOut">Whether it ran past its limit and was stopped (with every process it started).</param>
/// <param name="Output">Its stdout and stderr, interleaved as they came.</param>
/// <param name="Elapsed">Its wall time.</param>
public sealed record ChildRun(int ExitCode, bool TimedOut, string Output, TimeSpan Elapsed)
{
    /// <summary>The sandbox's limit it ran into, or <see cref="SandboxLimit.None"/>; the caller names it in the row (<see cref="GradeSandbox.LimitName"/>).</summary>
    public SandboxLimit Limit { get; init; }
}

/// <summary>
/// The limits of a submission in the sandbox; a null limit is none (only with the instructor's <c>--unsafe-no-limit</c>).
/// </summary>
public sealed record GradeLimits
{
    /// <summary>
    /// Megabytes of memory: for all of a submission's processes together where the machine delegates a cgroup v2
    /// (<c>systemd-run --scope -p MemoryMax</c>), else for each process (RLIMIT_DATA, native and managed alike); each
    /// .NET process's GC heap is capped at the same figure, so that managed memory ends in an OutOfMemoryException.
    /// </summary>
    public int? MemoryMegabytes { get; init; }

    /// <summary>Processes and threads of one step of a submission (its build, a run of its checks, its program) together.</summary>
    public int? Processes { get; init; }

    /// <summary>Megabytes of the lab's writable copy (a sized tmpfs), and of its /tmp and /dev/shm each.</summary>
    public int? DiskMegabytes { get; init; }

    /// <summary>Seconds of CPU time each process may use (RLIMIT_CPU).</summary>
    public int? CpuSeconds { get; init; }
}

/// <summary>
/// Runs a submission's commands (<c>dotnet build</c>, <c>dotnet test</c>, <c>dotnet run</c>) inside Debian's
/// bubblewrap, in a view built up from an empty root: the SDK (the dotnet root in use), the system's programs and
/// libraries (<c>/usr</c> and the <c>/bin</c>, <c>/lib*</c> beside it), a few files of <c>/etc</c> (the loader's
/// cache, the TLS certificates, the time zone, and a passwd and group of the sandbox's own), the package folder
/// read-only, the lab's own copy writable, an empty /tmp, a minimal /dev, its own /proc. Nothing else exists inside:
/// no home folder, no kit, no other submission, no report, no grader's work. No network (only a loopback of its own),
/// its own user, process, IPC and UTS namespaces, no further user namespaces, no capabilities; run by root, it runs
/// as an unprivileged uid of its own (<see cref="SandboxUid"/>). Every process is killed when the wall-time limit
/// passes or the grader dies. The limits (<see cref="GradeLimits"/>) hold through the mechanisms this machine has
/// (<see cref="Mechanisms"/>). With <c>--unsafe-no-sandbox</c> the same commands run as plain children, with only the
/// wall time and the GC heap limited.
/// </summary>
public sealed partial class GradeSandbox : IDisposable
{
    /// <summary>The uid (and gid) a sandbox runs as when the grader is root: unprivileged, and the owner of nothing outside.</summary>
    public const int SandboxUid = 1_900_000_001;

    /// <summary>Files of the host's /etc the SDK, MSBuild and the lab's programs read, bound read-only where they exist.</summary>
    private static readonly string[] EtcFiles = ["ld.so.cache", "ld.so.conf", "ld.so.conf.d", "os-release", "localtime", "alternatives", "ssl", "ca-certificates", "mime.types"];

    private readonly string? _bwrap;
    private readonly IReadOnlyList<string> _hidden;
    private readonly string _packages;
    private readonly GradeLimits _limits;
    private readonly string? _setpriv;
    private readonly string? _prlimit;
    private readonly string? _systemdRun;
    private readonly bool _userScope;
    private readonly bool _tmpfsCopies;
    private readonly string? _etc;
    private readonly string? _perl;
    private readonly int _landlock;
    private readonly string _dotnetRoot = "";
    private readonly HashSet<string> _mounted = new(StringComparer.Ordinal);
    private readonly Lock _gate = new();

    private GradeSandbox(string? bwrap, IReadOnlyList<string> hidden, string packages, GradeLimits limits, SandboxHost? host = null)
    {
        host ??= SandboxHost.This;
        _bwrap = bwrap;
        _hidden = hidden;
        _packages = packages;
        _limits = limits;
        if (bwrap is null || !OperatingSystem.IsLinux())
        {
            return;
        }

        _dotnetRoot = DotnetRoot();
        _prlimit = FindOnPath("prlimit");
        if (Environment.IsPrivilegedProcess)
        {
            _setpriv = FindOnPath("setpriv");
            _tmpfsCopies = FindOnPath("mount") is not null;
        }

        // Landlock, which the test host's launcher enters through perl's syscall (perl-base is part of every Debian).
        if (FindOnPath("perl") is { } perl && perl.StartsWith("/usr/", StringComparison.Ordinal))
        {
            _perl = perl;
            _landlock = LandlockAbi(perl);
        }

        // cgroup v2 with a systemd that makes scopes: the memory and process limits hold for a step's processes together.
        if (host.CgroupV2 && host.SystemdRun is { } systemdRun && (limits.MemoryMegabytes is not null || limits.Processes is not null))
        {
            bool user = !Environment.IsPrivilegedProcess;
            List<string> probe = user ? ["--user"] : [];
            probe.AddRange(["--quiet", "--scope", "-p", "MemoryMax=64M", "-p", "TasksMax=16", "--", "true"]);
            if (Probe(systemdRun, probe))
            {
                _systemdRun = systemdRun;
                _userScope = user;
            }
        }

        // A passwd and group of the sandbox's own: MSBuild waits forever without its user's entry.
        _etc = Directory.CreateTempSubdirectory("raylab-sandbox-etc-").FullName;
        int uid = RunsAs();
        File.WriteAllText(Path.Combine(_etc, "passwd"), string.Create(CultureInfo.InvariantCulture, $"root:x:0:0:root:/nonexistent:/usr/sbin/nologin\nlab:x:{uid}:{uid}:lab:/nonexistent:/bin/sh\nnobody:x:65534:65534:nobody:/nonexistent:/usr/sbin/nologin\n"));
        File.WriteAllText(Path.Combine(_etc, "group"), string.Create(CultureInfo.InvariantCulture, $"root:x:0:\nlab:x:{uid}:\nnogroup:x:65534:\n"));
        File.WriteAllText(Path.Combine(_etc, "hosts"), "127.0.0.1 localhost\n::1 localhost\n");
        File.WriteAllText(Path.Combine(_etc, "nsswitch.conf"), "passwd: files\ngroup: files\nhosts: files\n");
        OpenToSandbox(_etc, false);
        foreach (string file in Directory.EnumerateFiles(_etc))
        {
            File.SetUnixFileMode(file, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead | UnixFileMode.OtherRead);
        }
    }

    /// <summary>Whether the commands run inside bubblewrap.</summary>
    public bool IsSandboxed => _bwrap is not null;

    /// <summary>The managed memory each command's .NET processes may hold, in megabytes (the GC's hard limit), or null for none.</summary>
    public int? MemoryLimitMegabytes => _limits.MemoryMegabytes;

    /// <summary>
    /// One line per limit, "memory limit: …", "process limit: …", "disk limit: …", "CPU time limit: …", each naming
    /// the mechanism that holds it on this machine, or "none"; and one for the view and the user.
    /// </summary>
    public IReadOnlyList<string> Mechanisms
    {
        get
        {
            if (_bwrap is null)
            {
                return [$"sandbox: none (--unsafe-no-sandbox): the submissions run as you, with your files and network",
                    _limits.MemoryMegabytes is { } m ? $"memory limit: {m} MB of managed memory per .NET process (the GC's heap limit); native memory unlimited" : "memory limit: none",
                    "process limit: none", "disk limit: none", "CPU time limit: none"];
            }

            return [
                $"sandbox: bubblewrap, a view built from an empty root (the SDK at {_dotnetRoot}, /usr, the packages, the lab's copy); no network; "
                    + (_setpriv is not null ? string.Create(CultureInfo.InvariantCulture, $"as uid {SandboxUid} (setpriv)") : "as you, in a user namespace of its own"),
                MemoryMechanism() is { } memory ? $"memory limit: {memory}" : "memory limit: none",
                ProcessMechanism() is { } processes ? $"process limit: {processes}" : "process limit: none",
                DiskMechanism() is { } disk ? $"disk limit: {disk}" : "disk limit: none",
                CpuMechanism() is { } cpu ? $"CPU time limit: {cpu}" : "CPU time limit: none",
                "test host (where a lab's code runs during the checks): a sandbox of its own inside the step's, the checks and results read-only, no user namespaces, the tasks already running hidden from /proc; "
                    + (_landlock > 0 ? string.Create(CultureInfo.InvariantCulture, $"Landlock (ABI {_landlock}): no ptrace of, and no signal to, any process outside it")
                        : "no Landlock on this machine: a thread the test platform starts after the test host is reachable through /proc"),
            ];
        }
    }

    /// <summary>The name of a limit in a row's status: "memory limit", "process limit", "disk limit", "CPU time limit".</summary>
    /// <param name="limit">The limit.</param>
    /// <returns>Its name; "" for <see cref="SandboxLimit.None"/>.</returns>
    public static string LimitName(SandboxLimit limit) => limit switch
    {
        SandboxLimit.Memory => "memory limit",
        SandboxLimit.Processes => "process limit",
        SandboxLimit.Disk => "disk limit",
        SandboxLimit.CpuTime => "CPU time limit",
        _ => "",
    };

    /// <summary>
    /// The sandbox for this machine: bubblewrap where it runs, with every limit in <paramref name="limits"/> held by a
    /// mechanism of this machine; else a <see cref="SandboxUnavailableException"/> that says what is missing and the option that
    /// goes without it (<c>--unsafe-no-sandbox</c>, <c>--unsafe-no-limit LIMIT</c>).
    /// </summary>
    /// <param name="unsafeNoSandbox">Run unsandboxed (then only the wall time and the GC heap are limited).</param>
    /// <param name="hidden">Folders the submission must not see (others' labs, the report, the grader's work): none is in the view; any that lies under a folder the view shows is covered by an empty one.</param>
    /// <param name="packages">The NuGet package folder, bound read-only.</param>
    /// <param name="limits">The limits; null for none (the instructor's own, trusted restore).</param>
    /// <returns>The sandbox; dispose it to unmount the copies' file systems.</returns>
    public static GradeSandbox Create(bool unsafeNoSandbox, IReadOnlyList<string> hidden, string packages, GradeLimits? limits = null) =>
        Create(unsafeNoSandbox, hidden, packages, limits, SandboxHost.This);

    /// <summary><see cref="Create(bool, IReadOnlyList{string}, string, GradeLimits?)"/> with <paramref name="host"/>'s cgroup v2 and systemd-run.</summary>
    /// <param name="unsafeNoSandbox">Run unsandboxed.</param>
    /// <param name="hidden">Folders the submission must not see.</param>
    /// <param name="packages">The NuGet package folder, bound read-only.</param>
    /// <param name="limits">The limits; null for none.</param>
    /// <param name="host">What the machine offers for cgroup v2 limits.</param>
    /// <returns>The sandbox.</returns>
    // Long: one check per mechanism (bubblewrap, setpriv, each limit), each refusal with its own message and option, in the order raylab grade prints them.
    internal static GradeSandbox Create(bool unsafeNoSandbox, IReadOnlyList<string> hidden, string packages, GradeLimits? limits, SandboxHost host)
    {
        ArgumentNullException.ThrowIfNull(hidden);
        ArgumentException.ThrowIfNullOrEmpty(packages);
        limits ??= new GradeLimits();
        foreach ((string name, int? value) in new[] { ("memory", limits.MemoryMegabytes), ("processes", limits.Processes), ("disk", limits.DiskMegabytes), ("cpu", limits.CpuSeconds) })
        {
            if (value is { } v)
            {
                ArgumentOutOfRangeException.ThrowIfLessThan(v, 1, name);
            }
        }

        if (unsafeNoSandbox)
        {
            return new GradeSandbox(null, hidden, packages, limits, host);
        }

        if (!OperatingSystem.IsLinux())
        {
            throw new SandboxUnavailableException(
                $"grade: no sandbox on {RuntimeInformation.OSDescription}: raylab grade sandboxes with Linux's bubblewrap. Grade in a Linux machine "
                + "(WSL 2 on Windows, a Linux VM on macOS) with bubblewrap installed, or pass --unsafe-no-sandbox to run the submissions' code as yourself, with network (only for labs you trust)");
        }

        string? bwrap = FindOnPath("bwrap");
        if (bwrap is null)
        {
            throw new SandboxUnavailableException(
                "grade: bubblewrap (bwrap) is not installed, and it is the sandbox that keeps a submission off the network and out of your files: "
                + "install it (Debian/Ubuntu: sudo apt-get install bubblewrap), or pass --unsafe-no-sandbox (only for labs you trust)");
        }

        var sandbox = new GradeSandbox(bwrap, hidden, packages, limits, host);
        try
        {
            if (Environment.IsPrivilegedProcess && sandbox._setpriv is null)
            {
                throw new SandboxUnavailableException("grade: run as root, the sandbox drops to an unprivileged uid with setpriv (util-linux), which is not on PATH: install util-linux, or grade as an ordinary user");
            }

            foreach ((string name, int? value, string? mechanism, string hint) in new[]
            {
                ("memory", limits.MemoryMegabytes, sandbox.MemoryMechanism(), "install util-linux (prlimit)"),
                ("processes", limits.Processes, sandbox.ProcessMechanism(), "install util-linux (prlimit)"),
                ("disk", limits.DiskMegabytes, sandbox.DiskMechanism(), "grade as root (sudo), which gives each lab's copy a tmpfs of that size"),
                ("cpu", limits.CpuSeconds, sandbox.CpuMechanism(), "install util-linux (prlimit)"),
            })
            {
                if (value is not null && mechanism is null)
                {
                    throw new SandboxUnavailableException($"grade: no {(name == "processes" ? "process" : name == "cpu" ? "CPU time" : name)} limit can hold on this machine: {hint}, or pass --unsafe-no-limit {name} to grade without it");
                }
            }

            ChildRun probe = sandbox.Run(sandbox._etc!, null, TimeSpan.FromSeconds(30), "true", [], CancellationToken.None);
            if (probe.ExitCode != 0)
            {
                throw new SandboxUnavailableException(
                    $"grade: bubblewrap does not run here ({OneLine(probe.Output.Trim())}): it needs unprivileged user namespaces; "
                    + "or pass --unsafe-no-sandbox (only for labs you trust)");
            }
        }
        catch
        {
            sandbox.Dispose();
            throw;
        }

        return sandbox;
    }

    /// <summary>
    /// Runs <paramref name="command"/> with <paramref name="args"/> in <paramref name="lab"/> (writable inside the
    /// sandbox), stopping it and every process it started after <paramref name="limit"/>. Sandboxed and run by root,
    /// the lab's folder becomes, the first time, a tmpfs of the disk limit holding what it held, and is owned by the
    /// sandbox's uid before each command.
    /// </summary>
    /// <param name="lab">The working folder, the one writable folder (with /tmp, empty).</param>
    /// <param name="log">A file to append the command line and its output to, or null.</param>
    /// <param name="limit">The wall-time limit.</param>
    /// <param name="command">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <param name="cancellation">Stops the child as the limit would.</param>
    /// <param name="readOnly">Folders besides the view the command reads, shown read-only at their own paths (the grader's own programs, say); none by default.</param>
    /// <param name="nested">Whether the command may make one user namespace more: a check run whose test host has a sandbox of its own (<see cref="TestHostLauncher"/>).</param>
    /// <returns>How it ended.</returns>
    public ChildRun Run(string lab, string? log, TimeSpan limit, string command, IReadOnlyList<string> args, CancellationToken cancellation, IReadOnlyList<string>? readOnly = null, bool nested = false)
    {
        ArgumentException.ThrowIfNullOrEmpty(lab);
        ArgumentException.ThrowIfNullOrEmpty(command);
        ArgumentNullException.ThrowIfNull(args);
        lab = Path.GetFullPath(lab).TrimEnd(Path.DirectorySeparatorChar);
        bool copyFull = false;
        if (_bwrap is not null && lab != _etc)
        {
            copyFull = !PrepareCopy(lab);
        }

        ProcessStartInfo start = StartInfo(lab, command, args, readOnly, nested);
        var output = new StringBuilder();
        var clock = Stopwatch.StartNew();
        using var process = new Process { StartInfo = start };
        process.OutputDataReceived += (_, e) => Append(output, e.Data);
        process.ErrorDataReceived += (_, e) => Append(output, e.Data);
        process.Start();
        process.StandardInput.Close();
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();
        bool timedOut = false;
        using (cancellation.Register(() => Kill(process)))
        {
            if (!process.WaitForExit(limit))
            {
                timedOut = true;
                Kill(process);
            }

            process.WaitForExit(); // the readers drain
        }

        clock.Stop();
        string text;
        lock (output)
        {
            text = output.ToString();
        }

        bool stopped = timedOut || cancellation.IsCancellationRequested;
        int exitCode = stopped ? -1 : process.ExitCode;
        SandboxLimit hit = stopped ? SandboxLimit.None : copyFull ? SandboxLimit.Disk : Judge(exitCode, text, lab);
        var run = new ChildRun(exitCode, timedOut, text, clock.Elapsed) { Limit = hit };
        if (log is not null)
        {
            string end = timedOut ? $"stopped after the limit of {limit.TotalSeconds:0} s"
                : hit != SandboxLimit.None ? $"exit {run.ExitCode}, {LimitName(hit)}"
                : $"exit {run.ExitCode}";
            AppendLog(log, $"$ {command} {string.Join(' ', args)}", text, $"[{end}, {clock.Elapsed.TotalSeconds:0.0} s]");
        }

        return run;
    }

    /// <summary>
    /// The same environment with and without the sandbox: a home inside the lab, the prepared package folder, no
    /// MSBuild or compiler server outliving the step, no telemetry, no first-run work, the GC heap's limit.
    /// </summary>
    private Dictionary<string, string> ChildEnvironment(string home)
    {
        var environment = new Dictionary<string, string>
        {
            ["HOME"] = home,
            ["DOTNET_CLI_HOME"] = home,
            ["NUGET_PACKAGES"] = _packages,
            ["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1",
            ["DOTNET_NOLOGO"] = "1",
            ["DOTNET_SKIP_FIRST_TIME_EXPERIENCE"] = "1",
            ["DOTNET_GENERATE_ASPNET_CERTIFICATE"] = "false",
            ["MSBUILDDISABLENODEREUSE"] = "1",
            ["DOTNET_CLI_USE_MSBUILD_SERVER"] = "0",
            ["UseSharedCompilation"] = "false",
            ["TMPDIR"] = "/tmp", // the sandbox's own, empty /tmp
        };
        if (_limits.MemoryMegabytes is { } megabytes)
        {
            // The runtime reads it as hexadecimal bytes, in every .NET process of the command: MSBuild, the compiler,
            // the test host, the lab's program.
            environment["DOTNET_GCHeapHardLimit"] = ((long)megabytes << 20).ToString("x", CultureInfo.InvariantCulture);
        }

        return environment;
    }

    /// <summary>The whole command line of a sandboxed step: the limits outside, bubblewrap and its view, the limits inside, the command.</summary>
    private List<string> BubblewrapCommand(string lab, string command, IReadOnlyList<string> args, IReadOnlyList<string>? readOnly, bool nested, Dictionary<string, string> environment)
    {
        List<string> a = [.. Outside(), _bwrap!, .. View(lab)];
        foreach (string folder in (readOnly ?? []).Select(Path.GetFullPath))
        {
            Reachable(folder);
            a.AddRange(["--ro-bind", folder, folder]);
        }

        // A step whose test host has a sandbox of its own (TestHostLauncher) may make that one user namespace; the
        // inner sandbox forbids any more.
        a.AddRange(nested ? ["--unshare-all", "--unshare-user"] : ["--unshare-all", "--unshare-user", "--disable-userns"]);
        a.AddRange(["--die-with-parent", "--new-session", "--clearenv"]);
        a.AddRange(["--setenv", "PATH", $"{_dotnetRoot}:/usr/local/bin:/usr/bin:/bin", "--setenv", "DOTNET_ROOT", _dotnetRoot]);
        if (Environment.GetEnvironmentVariable("LANG") is { Length: > 0 } language)
        {
            a.AddRange(["--setenv", "LANG", language]);
        }

        foreach ((string key, string value) in environment)
        {
            a.AddRange(["--setenv", key, value]);
        }

        a.Add("--");
        a.AddRange(Inside());
        a.Add(command);
        a.AddRange(args);
        return a;
    }

    /// <summary>How <see cref="Run"/> starts its command: plain, or inside bubblewrap with the limits and the view.</summary>
    private ProcessStartInfo StartInfo(string lab, string command, IReadOnlyList<string> args, IReadOnlyList<string>? readOnly, bool nested)
    {
        var start = new ProcessStartInfo
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            RedirectStandardInput = true,
            UseShellExecute = false,
            WorkingDirectory = lab,
        };
        string home = Path.Combine(lab, ".home");
        if (lab != _etc)
        {
            Directory.CreateDirectory(home);
        }

        if (_setpriv is not null && lab != _etc)
        {
            Own(lab);
        }

        Dictionary<string, string> environment = ChildEnvironment(home);
        if (_bwrap is null)
        {
            start.FileName = command;
            foreach (string a in args)
            {
                start.ArgumentList.Add(a);
            }

            // MSBuild's variables of a build this grader may run under (dotnet test) would steer the children's builds.
            foreach (string key in start.Environment.Keys.Where(k => k.StartsWith("MSBuild", StringComparison.OrdinalIgnoreCase)).ToList())
            {
                start.Environment.Remove(key);
            }

            foreach ((string key, string value) in environment)
            {
                start.Environment[key] = value;
            }
        }
        else
        {
            List<string> a = BubblewrapCommand(lab, command, args, readOnly, nested, environment);
            start.FileName = a[0];
            foreach (string arg in a.Skip(1))
            {
                start.ArgumentList.Add(arg);
            }
        }

        return start;
    }

    /// <summary>
    /// Writes the launcher of a check run's test host, the process where the lab's code runs, into
    /// <paramref name="folder"/>: a script, given to the test platform as its dotnet host, that starts the test host in a
    /// sandbox of its own inside the step's (<see cref="Run"/> with <c>nested</c>). There the folders in
    /// <paramref name="readOnly"/> and the packages are read-only, /tmp and the home are its own, the processes and threads
    /// already running (the test platform's) are hidden from /proc, and no user namespace can be made. The test platform,
    /// outside it, writes the results where the lab's code cannot.
    /// </summary>
    /// <param name="folder">A folder the step sees and the lab's code never writes (the checks').</param>
    /// <param name="readOnly">The folders the test host sees read-only: the checks and the run's results.</param>
    /// <returns>The launcher's path, or null where the commands run without a sandbox.</returns>
    public string? TestHostLauncher(string folder, IReadOnlyList<string> readOnly) =>
        LauncherOf(folder, readOnly, _bwrap is null ? "" : Path.Combine(_dotnetRoot, "dotnet"));

    /// <summary>The launcher of <see cref="TestHostLauncher"/>, starting <paramref name="host"/> in place of dotnet.</summary>
    internal string? LauncherOf(string folder, IReadOnlyList<string> readOnly, string host)
    {
        ArgumentException.ThrowIfNullOrEmpty(folder);
        ArgumentNullException.ThrowIfNull(readOnly);
        if (_bwrap is null || !OperatingSystem.IsLinux())
        {
            return null;
        }

        // Where the kernel has Landlock, the test host enters a domain of its own before it starts: from there no
        // process outside it can be traced (/proc/ID/mem, environ) or signalled, whenever that process started.
        string landlock = _landlock > 0 ? $"{Quoted(_perl!)} -e {Quoted(LandlockExec)} -- " : "";

        // A /dev of its own (device nodes bound from outside cannot be opened in a nested user namespace), and a /tmp
        // and /dev/shm of its own, each no larger than the disk limit, as in the step's view.
        string size = _limits.DiskMegabytes is { } d ? string.Create(CultureInfo.InvariantCulture, $" --size {(long)d << 20}") : "";
        string scratch = $" --dev /dev --remount-ro /dev{size} --tmpfs /dev/shm{size} --tmpfs /tmp";

        var binds = new StringBuilder();
        foreach (string path in readOnly.Append(_packages).Select(Path.GetFullPath).Distinct())
        {
            binds.Append(CultureInfo.InvariantCulture, $" --ro-bind {Quoted(path)} {Quoted(path)}");
        }

        string script = $$"""
            #!/bin/sh
            # The test host, where the lab's code runs, in a sandbox of its own (raylab grade writes this file).
            hide=""
            for task in /proc/[0-9]*/task/[0-9]*; do
              hide="$hide --tmpfs /proc/${task##*/}"
            done
            # Not exec: the sandbox dies with this shell, which the test platform stops when a check hangs.
            # shellcheck disable=SC2086
            {{Quoted(_bwrap)}} --bind / /{{scratch}}{{binds}} $hide --unshare-user --disable-userns --die-with-parent               --setenv HOME /tmp --setenv DOTNET_CLI_HOME /tmp --setenv TMPDIR /tmp -- {{landlock}}{{Quoted(host)}} "$@"
            """;
        string launcher = Path.Combine(Directory.CreateDirectory(folder).FullName, "testhost.sh");
        File.WriteAllText(launcher, script.ReplaceLineEndings("\n") + "\n");
        File.SetUnixFileMode(launcher, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute
            | UnixFileMode.GroupRead | UnixFileMode.GroupExecute | UnixFileMode.OtherRead | UnixFileMode.OtherExecute);
        return launcher;
    }

    /// <summary>
    /// Perl that enters a Landlock domain and runs its arguments: a ruleset that handles only the making of block
    /// devices (which nothing needs) and, from ABI 6, scopes signals and abstract Unix sockets to the domain. Any domain
    /// keeps ptrace, and so /proc/ID/mem, inside it. Syscalls 444 and 446 (landlock_create_ruleset,
    /// landlock_restrict_self) have these numbers on every architecture; bubblewrap has already set no_new_privs.
    /// </summary>
    private const string LandlockExec =
        "my $v = syscall(444, 0, 0, 1); "
        + "my $r = $v >= 6 ? pack(\"QQQ\", 2048, 0, 3) : pack(\"Q\", 2048); "
        + "my $fd = syscall(444, $r, length($r), 0); "
        + "die \"landlock_create_ruleset: $!\\n\" if $fd < 0; "
        + "die \"landlock_restrict_self: $!\\n\" if syscall(446, $fd, 0) != 0; "
        + "exec { $ARGV[0] } @ARGV or die \"exec $ARGV[0]: $!\\n\";";

    /// <summary>The kernel's Landlock ABI version, asked through perl; 0 where it has none.</summary>
    private static int LandlockAbi(string perl)
    {
        try
        {
            ChildRun run = Plain(perl, ["-e", "print syscall(444, 0, 0, 1)"]);
            return run.ExitCode == 0 && int.TryParse(run.Output.Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, out int abi) && abi > 0 ? abi : 0;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return 0;
        }
    }

    private static string Quoted(string text) => "'" + text.Replace("'", "'\\''", StringComparison.Ordinal) + "'";

    /// <summary>Unmounts the copies' file systems and removes the sandbox's own /etc files.</summary>
    public void Dispose()
    {
        lock (_gate)
        {
            foreach (string mount in _mounted)
            {
                Probe("umount", ["-l", mount]);
            }

            _mounted.Clear();
        }

        if (_etc is not null)
        {
            try
            {
                Directory.Delete(_etc, recursive: true);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // a temporary folder is not worth failing for
            }
        }
    }

    private string? MemoryMechanism() =>
        _limits.MemoryMegabytes is not { } m ? null
        : _systemdRun is not null ? string.Create(CultureInfo.InvariantCulture, $"{m} MB for all of a step's processes together (cgroup v2: systemd-run{(_userScope ? " --user" : "")} --scope -p MemoryMax), and the GC heap of each .NET process")
        : _prlimit is not null ? string.Create(CultureInfo.InvariantCulture, $"{m} MB per process (RLIMIT_DATA: prlimit --data; no cgroup v2 delegated here), and the GC heap of each .NET process")
        : null;

    private string? ProcessMechanism() =>
        _limits.Processes is not { } n ? null
        : _systemdRun is not null ? string.Create(CultureInfo.InvariantCulture, $"{n} processes and threads for a step together (cgroup v2: TasksMax)")
        : _prlimit is not null && (!Environment.IsPrivilegedProcess || _setpriv is not null)
            ? string.Create(CultureInfo.InvariantCulture, $"{n} processes and threads for a step together (RLIMIT_NPROC set inside the sandbox's user namespace{(_setpriv is not null ? $", as uid {SandboxUid}" : "")})")
        : null;

    private string? DiskMechanism() =>
        _limits.DiskMegabytes is not { } d ? null
        : _tmpfsCopies ? string.Create(CultureInfo.InvariantCulture, $"{d} MB for each lab's copy (a tmpfs of that size), and for its /tmp and /dev/shm each")
        : null;

    private string? CpuMechanism() =>
        _limits.CpuSeconds is not { } s ? null
        : _prlimit is not null ? string.Create(CultureInfo.InvariantCulture, $"{s} s of CPU time per process (RLIMIT_CPU: prlimit --cpu)")
        : null;

    /// <summary>What wraps bwrap outside it: the cgroup v2 scope, the drop to the sandbox's uid.</summary>
    private IEnumerable<string> Outside()
    {
        if (_systemdRun is not null)
        {
            yield return _systemdRun;
            if (_userScope)
            {
                yield return "--user";
            }

            yield return "--quiet";
            yield return "--scope";
            if (_limits.MemoryMegabytes is { } m)
            {
                yield return "-p";
                yield return string.Create(CultureInfo.InvariantCulture, $"MemoryMax={m}M");
                yield return "-p";
                yield return "MemorySwapMax=0";
            }

            if (_limits.Processes is { } n)
            {
                yield return "-p";
                yield return string.Create(CultureInfo.InvariantCulture, $"TasksMax={n}");
            }

            yield return "--";
        }

        if (_setpriv is not null)
        {
            yield return _setpriv;
            yield return string.Create(CultureInfo.InvariantCulture, $"--reuid={SandboxUid}");
            yield return string.Create(CultureInfo.InvariantCulture, $"--regid={SandboxUid}");
            yield return "--clear-groups";
            yield return "--";
        }
    }

    /// <summary>What runs inside bwrap before the command: the per-process limits (prlimit), set inside the sandbox's user namespace so that the process count is the sandbox's own.</summary>
    private IEnumerable<string> Inside()
    {
        if (_prlimit is null)
        {
            yield break;
        }

        var limits = new List<string>();
        if (_limits.CpuSeconds is { } s)
        {
            // SIGXCPU at the soft limit, SIGKILL a few seconds later for a process that ignores it.
            limits.Add(string.Create(CultureInfo.InvariantCulture, $"--cpu={s}:{s + 5}"));
        }

        if (_limits.MemoryMegabytes is { } m && _systemdRun is null)
        {
            limits.Add(string.Create(CultureInfo.InvariantCulture, $"--data={(long)m << 20}"));
        }

        if (_limits.Processes is { } n && _systemdRun is null)
        {
            limits.Add(string.Create(CultureInfo.InvariantCulture, $"--nproc={n}"));
        }

        if (limits.Count == 0)
        {
            yield break;
        }

        yield return _prlimit;
        foreach (string l in limits)
        {
            yield return l;
        }

        yield return "--";
    }

    /// <summary>The view, from an empty root (bwrap's default): only what a build, its checks and its program need.</summary>
    private List<string> View(string lab)
    {
        List<string> a = ["--dev", "/dev", "--remount-ro", "/dev", "--proc", "/proc"];
        string? size = _limits.DiskMegabytes is { } d ? ((long)d << 20).ToString(CultureInfo.InvariantCulture) : null;
        foreach (string scratch in new[] { "/dev/shm", "/tmp" })
        {
            if (size is not null)
            {
                a.AddRange(["--size", size]);
            }

            a.AddRange(["--tmpfs", scratch]);
        }

        a.AddRange(["--ro-bind", "/usr", "/usr"]);
        foreach (string top in new[] { "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32" })
        {
            var info = new DirectoryInfo(top);
            if (info.LinkTarget is { } target)
            {
                a.AddRange(["--symlink", target, top]);
            }
            else if (info.Exists)
            {
                a.AddRange(["--ro-bind", top, top]);
            }
        }

        foreach (string file in EtcFiles)
        {
            a.AddRange(["--ro-bind-try", Path.Combine("/etc", file), Path.Combine("/etc", file)]);
        }

        foreach (string file in new[] { "passwd", "group", "hosts", "nsswitch.conf" })
        {
            a.AddRange(["--ro-bind", Path.Combine(_etc!, file), Path.Combine("/etc", file)]);
        }

        if (!IsUnder(_dotnetRoot, "/usr"))
        {
            a.AddRange(["--ro-bind", _dotnetRoot, _dotnetRoot]);
        }

        // A hidden folder can only be in the view where it lies under a folder the view shows (the SDK's, say).
        foreach (string folder in _hidden.Where(Directory.Exists).Select(Path.GetFullPath).Distinct().OrderBy(f => f.Length))
        {
            if ((IsUnder(folder, "/usr") || IsUnder(folder, _dotnetRoot)) && !IsUnder(lab, folder) && !IsUnder(_packages, folder))
            {
                a.AddRange(["--tmpfs", folder]);
            }
        }

        a.AddRange(["--ro-bind", _packages, _packages, "--bind", lab, lab, "--chdir", lab]);
        return a;
    }

    /// <summary>
    /// Gives a lab's copy its disk limit, once: a tmpfs of that size mounted on its folder, holding what the folder held.
    /// </summary>
    /// <returns>False when what the folder held did not fit.</returns>
    private bool PrepareCopy(string lab)
    {
        if (!_tmpfsCopies || _limits.DiskMegabytes is not { } megabytes)
        {
            OpenToSandbox(lab, true);
            return true;
        }

        lock (_gate)
        {
            if (_mounted.Contains(lab))
            {
                return true;
            }
        }

        string held = lab + ".held";
        Directory.CreateDirectory(lab);
        Directory.Move(lab, held);
        Directory.CreateDirectory(lab);
        ChildRun mount = Plain("mount", ["-t", "tmpfs", "-o", string.Create(CultureInfo.InvariantCulture, $"size={megabytes}m,mode=0700,nosuid,nodev,uid={SandboxUid},gid={SandboxUid}"), "raylab-lab", lab]);
        if (mount.ExitCode != 0)
        {
            Directory.Delete(lab);
            Directory.Move(held, lab);
            throw new SandboxUnavailableException($"grade: cannot mount the lab copy's tmpfs of --disk-limit {megabytes} MB ({OneLine(mount.Output.Trim())}); or pass --unsafe-no-limit disk");
        }

        lock (_gate)
        {
            _mounted.Add(lab);
        }

        OpenToSandbox(lab, true);
        bool fits = true;
        try
        {
            CopyTree(held, lab);
        }
        catch (IOException)
        {
            fits = false; // the copy holds what fitted; the step runs and the row says the disk limit was reached
        }

        Directory.Delete(held, recursive: true);
        return fits;
    }

    private static void CopyTree(string from, string to)
    {
        Directory.CreateDirectory(to);
        foreach (FileSystemInfo entry in new DirectoryInfo(from).EnumerateFileSystemInfos())
        {
            string target = Path.Combine(to, entry.Name);
            if (entry.LinkTarget is not null)
            {
                continue;
            }

            if (entry is DirectoryInfo)
            {
                CopyTree(entry.FullName, target);
            }
            else
            {
                File.Copy(entry.FullName, target, overwrite: true);
            }
        }
    }

    /// <summary>Makes the folders above <paramref name="path"/> in the grader's temporary folder passable for the sandbox's uid (not listable).</summary>
    private void OpenToSandbox(string path, bool ancestorsOnly)
    {
        if (_setpriv is null || !OperatingSystem.IsLinux())
        {
            return;
        }

        string temp = Path.GetFullPath(Path.GetTempPath()).TrimEnd(Path.DirectorySeparatorChar);
        var folder = new DirectoryInfo(ancestorsOnly ? Path.GetDirectoryName(path)! : path);
        while (folder is not null && IsUnder(folder.FullName, temp) && folder.FullName.TrimEnd(Path.DirectorySeparatorChar) != temp)
        {
            if (folder.Exists && folder.LinkTarget is null && (folder.UnixFileMode & UnixFileMode.OtherExecute) == 0)
            {
                folder.UnixFileMode |= UnixFileMode.OtherExecute;
            }

            folder = folder.Parent;
        }

        // The packages folder: read by the sandbox's uid.
        foreach (string packages in new[] { _packages })
        {
            var info = new DirectoryInfo(packages);
            for (DirectoryInfo? up = info; up is not null && IsUnder(up.FullName, temp) && up.FullName.TrimEnd(Path.DirectorySeparatorChar) != temp; up = up.Parent)
            {
                if (up.Exists && (up.UnixFileMode & UnixFileMode.OtherExecute) == 0)
                {
                    up.UnixFileMode |= UnixFileMode.OtherExecute | (up.FullName == info.FullName ? UnixFileMode.OtherRead : 0);
                }
            }
        }
    }

    /// <summary>
    /// Makes a folder the sandbox is shown read-only reachable by the sandbox's uid where it lies in the temporary
    /// folder; elsewhere a folder above it closed to other users is an error that names it, not bwrap's "Can't find
    /// source path".
    /// </summary>
    private void Reachable(string folder)
    {
        if (_setpriv is null || !OperatingSystem.IsLinux())
        {
            return;
        }

        OpenToSandbox(folder, ancestorsOnly: true);
        ChildRun probe = Plain(_setpriv, [string.Create(CultureInfo.InvariantCulture, $"--reuid={SandboxUid}"), string.Create(CultureInfo.InvariantCulture, $"--regid={SandboxUid}"), "--clear-groups", "--", "test", "-x", folder]);
        if (probe.ExitCode != 0)
        {
            string closed = folder;
            for (var up = new DirectoryInfo(folder); up is not null; up = up.Parent)
            {
                if (up.Exists && (up.UnixFileMode & UnixFileMode.OtherExecute) == 0)
                {
                    closed = up.FullName;
                }
            }

            throw new IOException(string.Create(CultureInfo.InvariantCulture,
                $"the sandbox's uid {SandboxUid} cannot reach {folder}: {closed} is closed to other users; open it (chmod o+x) or keep the folder elsewhere"));
        }
    }

    /// <summary>The copy owned by the sandbox's uid (links themselves, never what they point to).</summary>
    private static void Own(string lab)
    {
        string owner = string.Create(CultureInfo.InvariantCulture, $"{SandboxUid}:{SandboxUid}");
        ChildRun chown = Plain("chown", ["-R", "-P", "-h", owner, lab]);
        if (chown.ExitCode != 0)
        {
            throw new IOException($"cannot give the lab's copy to the sandbox's uid: {OneLine(chown.Output.Trim())}");
        }
    }

    /// <summary>Which limit a child that ended by itself ran into, from its exit status, its output and its copy's free space.</summary>
    private SandboxLimit Judge(int exitCode, string output, string lab)
    {
        if (_limits.DiskMegabytes is not null && _tmpfsCopies && (NoSpace().IsMatch(output) || Full(lab)))
        {
            return SandboxLimit.Disk;
        }

        if (_limits.CpuSeconds is not null && _prlimit is not null && (exitCode == 128 + 24 || CpuLine().IsMatch(output)))
        {
            return SandboxLimit.CpuTime;
        }

        if (_limits.Processes is not null && ProcessLine().IsMatch(output))
        {
            return SandboxLimit.Processes;
        }

        if (_limits.MemoryMegabytes is not null && (MemoryLine().IsMatch(output) || (_systemdRun is not null && exitCode == 128 + 9)))
        {
            return SandboxLimit.Memory;
        }

        return SandboxLimit.None;
    }

    private static bool Full(string lab)
    {
        try
        {
            var drive = new DriveInfo(lab);
            return drive.AvailableFreeSpace < Math.Max(1L << 20, drive.TotalSize / 100);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException)
        {
            return false;
        }
    }

    private static bool Probe(string program, IReadOnlyList<string> args)
    {
        try
        {
            return Plain(program, args).ExitCode == 0;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return false;
        }
    }

    /// <summary>A short command of the grader's own, outside any sandbox.</summary>
    private static ChildRun Plain(string program, IReadOnlyList<string> args)
    {
        var start = new ProcessStartInfo(program) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (string a in args)
        {
            start.ArgumentList.Add(a);
        }

        using Process process = Process.Start(start)!;
        Task<string> stdout = process.StandardOutput.ReadToEndAsync();
        Task<string> stderr = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromMinutes(1)))
        {
            Kill(process);
            process.WaitForExit();
        }

        return new ChildRun(process.ExitCode, false, stdout.Result + stderr.Result, TimeSpan.Zero);
    }

    /// <summary>The uid the sandbox's processes have inside: the sandbox's own when run by root, else the grader's.</summary>
    private int RunsAs() => _setpriv is not null ? SandboxUid : Environment.IsPrivilegedProcess ? 0 : GetUid();

    /// <summary>This process's real uid, from /proc/self/status ("Uid: real effective saved filesystem").</summary>
    private static int GetUid()
    {
        foreach (string line in File.ReadLines("/proc/self/status"))
        {
            if (line.StartsWith("Uid:", StringComparison.Ordinal)
                && int.TryParse(line[4..].Split('\t', ' ', StringSplitOptions.RemoveEmptyEntries)[0], NumberStyles.None, CultureInfo.InvariantCulture, out int uid))
            {
                return uid;
            }
        }

        return 65534;
    }

    /// <summary>The dotnet root in use: DOTNET_ROOT, else the folder of the <c>dotnet</c> on PATH, its links followed.</summary>
    private static string DotnetRoot()
    {
        if (Environment.GetEnvironmentVariable("DOTNET_ROOT") is { Length: > 0 } root && File.Exists(Path.Combine(root, "dotnet")))
        {
            return Path.GetFullPath(root).TrimEnd(Path.DirectorySeparatorChar);
        }

        string? dotnet = FindOnPath("dotnet");
        if (dotnet is null)
        {
            return Path.GetDirectoryName(Environment.ProcessPath) ?? "/usr/share/dotnet";
        }

        FileSystemInfo? target = new FileInfo(dotnet).ResolveLinkTarget(returnFinalTarget: true);
        return Path.GetDirectoryName(target?.FullName ?? dotnet)!;
    }

    private static bool IsUnder(string path, string folder)
    {
        string relative = Path.GetRelativePath(folder, path);
        return relative == "." || (!relative.StartsWith("..", StringComparison.Ordinal) && !Path.IsPathRooted(relative));
    }

    /// <summary>The most characters of one step's output the log keeps: its first and last halves, and a line that says how much was left out between them.</summary>
    public const int LogStepLimit = 64 * 1024;

    /// <summary>The most bytes a submission's log holds in all; past it, one line says that the rest was left out.</summary>
    public const int LogTotalLimit = 1024 * 1024;

    /// <summary>The line a log ends with once it reaches <see cref="LogTotalLimit"/>.</summary>
    public static readonly string LogFullLine = string.Create(CultureInfo.InvariantCulture,
        $"[the log is cut here: it reached its limit of {LogTotalLimit / 1024:N0} KiB; the rest of this submission's output is left out]");

    /// <summary>
    /// Appends one step to a submission's log: its command line, its output (the lab's own words: control characters,
    /// terminal escapes among them, as '?'; at most <see cref="LogStepLimit"/> characters, the cut said where it is),
    /// and how it ended; the whole log at most <see cref="LogTotalLimit"/> bytes, the cut said at its end.
    /// </summary>
    /// <param name="log">The log file.</param>
    /// <param name="commandLine">The step's command line.</param>
    /// <param name="output">The step's output.</param>
    /// <param name="end">How the step ended, one line.</param>
    public static void AppendLog(string log, string commandLine, string output, string end)
    {
        ArgumentException.ThrowIfNullOrEmpty(log);
        ArgumentNullException.ThrowIfNull(commandLine);
        ArgumentNullException.ThrowIfNull(output);
        ArgumentNullException.ThrowIfNull(end);
        string kept = output;
        if (kept.Length > LogStepLimit)
        {
            int half = LogStepLimit / 2;
            kept = string.Create(CultureInfo.InvariantCulture,
                $"{kept[..half]}\n[… {kept.Length - (2 * half):N0} characters of this step's output left out here: the log keeps the first and the last {half:N0} of each step …]\n{kept[^half..]}");
        }

        var clean = new StringBuilder(kept.Length);
        foreach (char c in kept)
        {
            clean.Append(char.IsControl(c) && c is not '\n' and not '\t' ? '?' : c);
        }

        byte[] entry = Encoding.UTF8.GetBytes($"{commandLine}\n{clean}\n{end}\n\n");
        byte[] full = Encoding.UTF8.GetBytes("\n" + LogFullLine + "\n");
        long used = File.Exists(log) ? new FileInfo(log).Length : 0;
        using var stream = new FileStream(log, FileMode.Append, FileAccess.Write);
        if (used + entry.Length <= LogTotalLimit - full.Length)
        {
            stream.Write(entry);
            return;
        }

        long room = LogTotalLimit - full.Length - used;
        if (room < 0)
        {
            return; // already cut
        }

        // As much of the step as fits, cut before a character's first byte, and the line that says so.
        int take = (int)room;
        while (take > 0 && take < entry.Length && (entry[take] & 0xC0) == 0x80)
        {
            take--;
        }

        stream.Write(entry.AsSpan(0, take));
        stream.Write(full);
    }

    private static void Append(StringBuilder output, string? line)
    {
        if (line is null)
        {
            return;
        }

        lock (output)
        {
            if (output.Length < OutputLimit)
            {
                output.AppendLine(line);
            }
            else if (!output.ToString(output.Length - NotKept.Length, NotKept.Length).Equals(NotKept, StringComparison.Ordinal))
            {
                output.Append(NotKept);
            }
        }
    }

    /// <summary>The most characters of a child's output kept in memory.</summary>
    private const int OutputLimit = 4_000_000;

    /// <summary>The line that ends a child's output past <see cref="OutputLimit"/>.</summary>
    private static readonly string NotKept = string.Create(CultureInfo.InvariantCulture, $"[output past {OutputLimit:N0} characters not kept]\n");

    private static void Kill(Process process)
    {
        try
        {
            process.Kill(entireProcessTree: true);
        }
        catch (InvalidOperationException)
        {
            // it has already exited
        }
    }

    /// <summary>A child's output on one line, for a message: its lines joined with "; ".</summary>
    private static string OneLine(string text) =>
        string.Join("; ", text.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries));

    /// <summary>The first <paramref name="name"/> on PATH or in the system's program folders, or null.</summary>
    internal static string? FindOnPath(string name)
    {
        foreach (string folder in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries).Concat(["/usr/sbin", "/usr/bin", "/sbin", "/bin"]))
        {
            string candidate = Path.Combine(folder, name);
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        return null;
    }

    [GeneratedRegex(@"No space left on device|Disk quota exceeded|File size limit exceeded")]
    private static partial Regex NoSpace();

    [GeneratedRegex(@"CPU time limit exceeded")]
    private static partial Regex CpuLine();

    [GeneratedRegex(@"Resource temporarily unavailable|fork: retry|Cannot fork|pthread_create failed")]
    private static partial Regex ProcessLine();

    [GeneratedRegex(@"System\.OutOfMemoryException|^Out of memory\.\r?$|[Cc]annot allocate memory|xrealloc: cannot allocate|xmalloc: cannot allocate|std::bad_alloc|MemoryError", RegexOptions.Multiline)]
    private static partial Regex MemoryLine();
}

/// <summary>
/// What the sandbox asks of the machine for its cgroup v2 limits: whether the machine mounts cgroup v2 at
/// /sys/fs/cgroup, and the systemd-run that makes a step's scope.
/// </summary>
/// <param name="CgroupV2">Whether cgroup v2 is the machine's hierarchy (/sys/fs/cgroup/cgroup.controllers exists).</param>
/// <param name="SystemdRun">systemd-run's path, or null where it is not installed.</param>
internal sealed record SandboxHost(bool CgroupV2, string? SystemdRun)
{
    /// <summary>This machine.</summary>
    public static SandboxHost This => new(File.Exists("/sys/fs/cgroup/cgroup.controllers"), GradeSandbox.FindOnPath("systemd-run"));
}
