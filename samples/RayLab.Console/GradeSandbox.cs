using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using System.Text;
using RayLab.Scenes;

namespace RayLab.Cli;

/// <summary>How a child process of <c>raylab grade</c> ended.</summary>
/// <param name="ExitCode">Its exit code; -1 when it was stopped.</param>
/// <param name="TimedOut">Whether it ran past its limit and was stopped (with every process it started).</param>
/// <param name="Output">Its stdout and stderr, interleaved as they came.</param>
/// <param name="Elapsed">Its wall time.</param>
public sealed record ChildRun(int ExitCode, bool TimedOut, string Output, TimeSpan Elapsed);

/// <summary>
/// Runs a submission's commands (<c>dotnet build</c>, <c>dotnet test</c>, <c>dotnet run</c>) inside Debian's
/// bubblewrap: the whole file system read-only, the lab's own folder writable, the folders of the other submissions,
/// of the report and of the grader's work hidden (empty), the package folder read-only, no network (only a loopback
/// of its own), its own process and IPC namespaces, and every process killed when the limit passes or the grader
/// dies. With <c>--unsafe-no-sandbox</c> the same commands run as plain children. Either way each .NET process's
/// managed memory can be capped (<c>--memory-limit</c>).
/// </summary>
public sealed class GradeSandbox
{
    private readonly string? _bwrap;
    private readonly IReadOnlyList<string> _hidden;
    private readonly string _packages;

    private GradeSandbox(string? bwrap, IReadOnlyList<string> hidden, string packages, int? memoryLimitMegabytes)
    {
        _bwrap = bwrap;
        _hidden = hidden;
        _packages = packages;
        MemoryLimitMegabytes = memoryLimitMegabytes;
    }

    /// <summary>Whether the commands run inside bubblewrap.</summary>
    public bool IsSandboxed => _bwrap is not null;

    /// <summary>The managed memory each command's .NET processes may hold, in megabytes (the GC's hard limit), or null for none.</summary>
    public int? MemoryLimitMegabytes { get; }

    /// <summary>
    /// The sandbox for this machine: bubblewrap where it runs, else a <see cref="UsageException"/> that says what to
    /// do, unless <paramref name="unsafeNoSandbox"/>.
    /// </summary>
    /// <param name="unsafeNoSandbox">Run unsandboxed.</param>
    /// <param name="hidden">Folders the submission must not see (others' labs, the report, the grader's work).</param>
    /// <param name="packages">The NuGet package folder, bound read-only.</param>
    /// <param name="memoryLimitMegabytes">
    /// The managed memory (the .NET GC heap) each .NET process a command starts may hold, in megabytes
    /// (<c>DOTNET_GCHeapHardLimit</c>); past it that process gets an <see cref="OutOfMemoryException"/>. Null for no limit.
    /// </param>
    /// <returns>The sandbox.</returns>
    public static GradeSandbox Create(bool unsafeNoSandbox, IReadOnlyList<string> hidden, string packages, int? memoryLimitMegabytes = null)
    {
        ArgumentNullException.ThrowIfNull(hidden);
        ArgumentException.ThrowIfNullOrEmpty(packages);
        if (memoryLimitMegabytes is { } limit)
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(limit, 1, nameof(memoryLimitMegabytes));
        }

        if (unsafeNoSandbox)
        {
            return new GradeSandbox(null, hidden, packages, memoryLimitMegabytes);
        }

        if (!OperatingSystem.IsLinux())
        {
            throw new UsageException(
                $"grade: no sandbox on {RuntimeInformation.OSDescription}: raylab grade sandboxes with Linux's bubblewrap. Grade in a Linux machine "
                + "(WSL 2 on Windows, a Linux VM on macOS) with bubblewrap installed, or pass --unsafe-no-sandbox to run the submissions' code as yourself, with network (only for labs you trust)");
        }

        string? bwrap = FindOnPath("bwrap");
        if (bwrap is null)
        {
            throw new UsageException(
                "grade: bubblewrap (bwrap) is not installed, and it is the sandbox that keeps a submission off the network and out of your files: "
                + "install it (Debian/Ubuntu: sudo apt-get install bubblewrap), or pass --unsafe-no-sandbox (only for labs you trust)");
        }

        var sandbox = new GradeSandbox(bwrap, hidden, packages, memoryLimitMegabytes);
        ChildRun probe = sandbox.Run(Path.GetTempPath(), null, TimeSpan.FromSeconds(30), "true", [], CancellationToken.None);
        if (probe.ExitCode != 0)
        {
            throw new UsageException(
                $"grade: bubblewrap does not run here ({SceneFileException.OneLine(probe.Output.Trim())}): it needs unprivileged user namespaces or root; "
                + "or pass --unsafe-no-sandbox (only for labs you trust)");
        }

        return sandbox;
    }

    /// <summary>
    /// Runs <paramref name="command"/> with <paramref name="args"/> in <paramref name="lab"/> (writable inside the
    /// sandbox), stopping it and every process it started after <paramref name="limit"/>.
    /// </summary>
    /// <param name="lab">The working folder, the one writable folder (with /tmp, empty).</param>
    /// <param name="log">A file to append the command line and its output to, or null.</param>
    /// <param name="limit">The wall-time limit.</param>
    /// <param name="command">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <param name="cancellation">Stops the child as the limit would.</param>
    /// <returns>How it ended.</returns>
    public ChildRun Run(string lab, string? log, TimeSpan limit, string command, IReadOnlyList<string> args, CancellationToken cancellation)
    {
        ArgumentException.ThrowIfNullOrEmpty(lab);
        ArgumentException.ThrowIfNullOrEmpty(command);
        ArgumentNullException.ThrowIfNull(args);
        var start = new ProcessStartInfo
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            RedirectStandardInput = true,
            UseShellExecute = false,
            WorkingDirectory = lab,
        };
        string home = Path.Combine(lab, ".home");
        Directory.CreateDirectory(home);
        // The same environment with and without the sandbox: a home inside the lab, the prepared package folder,
        // no MSBuild or compiler server outliving the step, no telemetry, no first-run work.
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
        if (MemoryLimitMegabytes is { } megabytes)
        {
            // The runtime reads it as hexadecimal bytes, in every .NET process of the command: MSBuild, the compiler,
            // the test host, the lab's program.
            environment["DOTNET_GCHeapHardLimit"] = ((long)megabytes << 20).ToString("x", CultureInfo.InvariantCulture);
        }
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
            start.FileName = _bwrap;
            List<string> a = ["--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc", "--tmpfs", "/tmp"];
            foreach (string folder in _hidden.Where(Directory.Exists).Select(Path.GetFullPath).Distinct().OrderBy(f => f.Length))
            {
                a.AddRange(["--tmpfs", folder]);
            }

            a.AddRange(["--ro-bind", _packages, _packages, "--bind", lab, lab, "--chdir", lab]);
            a.AddRange(["--unshare-net", "--unshare-pid", "--unshare-ipc", "--unshare-uts", "--die-with-parent", "--new-session", "--clearenv"]);
            a.AddRange(["--setenv", "PATH", Environment.GetEnvironmentVariable("PATH") ?? "/usr/bin:/bin"]);
            foreach (string name in new[] { "DOTNET_ROOT", "LANG" })
            {
                if (Environment.GetEnvironmentVariable(name) is { Length: > 0 } value)
                {
                    a.AddRange(["--setenv", name, value]);
                }
            }

            foreach ((string key, string value) in environment)
            {
                a.AddRange(["--setenv", key, value]);
            }

            a.Add("--");
            a.Add(command);
            a.AddRange(args);
            foreach (string arg in a)
            {
                start.ArgumentList.Add(arg);
            }
        }

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

        var run = new ChildRun(timedOut || cancellation.IsCancellationRequested ? -1 : process.ExitCode, timedOut, text, clock.Elapsed);
        if (log is not null)
        {
            AppendLog(log, $"$ {command} {string.Join(' ', args)}", text,
                $"[{(timedOut ? $"stopped after the limit of {limit.TotalSeconds:0} s" : $"exit {run.ExitCode}")}, {clock.Elapsed.TotalSeconds:0.0} s]");
        }

        return run;
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

    private static string? FindOnPath(string name)
    {
        foreach (string folder in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
        {
            string candidate = Path.Combine(folder, name);
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        return null;
    }
}
