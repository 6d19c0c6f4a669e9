using System.Diagnostics;
using System.Text;

namespace RayLab.Tests.Shared;

/// <summary>
/// The built console app (raylab.dll beside the tests) as a child process, as a terminal runs it, and Ctrl+C sent to
/// it: the CLI's cancellation tests and the grader's.
/// </summary>
internal static class ConsoleChild
{
    /// <summary>
    /// Starts raylab.dll with <paramref name="args"/> in <paramref name="workingDirectory"/> and returns it running with
    /// its output redirected and unread: the caller reads it (and must, or a full pipe stalls the child) and waits.
    /// </summary>
    public static Process Start(string workingDirectory, params string[] args)
    {
        string app = Path.Combine(AppContext.BaseDirectory, "raylab.dll");
        Assert.True(File.Exists(app), $"{app} is missing");
        // SIGINT at its default disposition in the child, whatever this test run inherited: a shell that starts a job
        // in the background without job control (`dotnet test … &` in a script, a CI runner) sets SIGINT to ignored,
        // every child inherits that, and the .NET runtime then leaves it ignored. The resetter execs the host, so the
        // child's process id is the host's.
        string[] host = [.. SigintResetter.Value ?? [], DotnetHost()];
        var start = new ProcessStartInfo(host[0])
        {
            WorkingDirectory = workingDirectory,
            UseShellExecute = false,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
        };
        foreach (string arg in host.Skip(1))
        {
            start.ArgumentList.Add(arg);
        }

        start.ArgumentList.Add(app);
        foreach (string arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        return Process.Start(start) ?? throw new InvalidOperationException("could not start dotnet");
    }

    /// <summary>
    /// Sends SIGINT (what Ctrl+C sends) to <paramref name="process"/> with the system's <c>kill</c> and waits for it to
    /// end; fails the test if it is still running after <paramref name="bound"/> (a generous bound, so that a child
    /// that ignores the signal ends the test rather than hangs it).
    /// </summary>
    public static async Task InterruptAndWaitAsync(Process process, TimeSpan bound)
    {
        Assert.False(process.HasExited, "the child ended before it could be interrupted");
        using (Process kill = Process.Start(new ProcessStartInfo("kill", ["-INT", process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]) { UseShellExecute = false })
            ?? throw new InvalidOperationException("could not start kill"))
        {
            await kill.WaitForExitAsync(TestContext.Current.CancellationToken);
            Assert.Equal(0, kill.ExitCode);
        }

        using var limit = CancellationTokenSource.CreateLinkedTokenSource(TestContext.Current.CancellationToken);
        limit.CancelAfter(bound);
        try
        {
            await process.WaitForExitAsync(limit.Token);
        }
        catch (OperationCanceledException)
        {
            Assert.Fail($"the child was still running {bound.TotalMinutes:0.#} minutes after SIGINT");
        }
    }

    /// <summary>
    /// Kills <paramref name="child"/> and its process tree when disposed if it still runs: a failed assertion must not
    /// leave a child working for minutes.
    /// </summary>
    public static IDisposable EndOnFailure(Process child) => new Finally(() =>
    {
        if (!child.HasExited)
        {
            child.Kill(entireProcessTree: true);
        }
    });

    /// <summary>
    /// A command line that runs its arguments with SIGINT at its default disposition: coreutils' <c>env
    /// --default-signal=INT</c> where it has that option (coreutils 8.31 and later), else perl's <c>$SIG{INT}</c>;
    /// null on Windows or where neither runs.
    /// </summary>
    private static readonly Lazy<string[]?> SigintResetter = new(() =>
    {
        if (OperatingSystem.IsWindows())
        {
            return null;
        }

        string[][] candidates =
        [
            ["env", "--default-signal=INT"],
            ["perl", "-e", "$SIG{INT} = 'DEFAULT'; exec { $ARGV[0] } @ARGV or die \"exec $ARGV[0]: $!\\n\";"],
        ];
        return candidates.FirstOrDefault(c => Runs([.. c, "true"]));
    });

    /// <summary>Whether <paramref name="command"/> runs and exits 0 (a probe: its output is dropped).</summary>
    private static bool Runs(string[] command)
    {
        var start = new ProcessStartInfo(command[0]) { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true };
        foreach (string arg in command.Skip(1))
        {
            start.ArgumentList.Add(arg);
        }

        try
        {
            using Process probe = Process.Start(start) ?? throw new InvalidOperationException($"could not start {command[0]}");
            Task<string> stdout = probe.StandardOutput.ReadToEndAsync();
            Task<string> stderr = probe.StandardError.ReadToEndAsync();
            probe.WaitForExit();
            Task.WaitAll(stdout, stderr);
            return probe.ExitCode == 0;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return false;
        }
    }

    /// <summary>The dotnet host running these tests (so the child uses the same runtime), else dotnet on the PATH.</summary>
    private static string DotnetHost()
    {
        if (Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host && File.Exists(host))
        {
            return host;
        }

        string? current = Environment.ProcessPath;
        return current is not null && Path.GetFileNameWithoutExtension(current) == "dotnet" ? current : "dotnet";
    }

    private sealed class Finally(Action action) : IDisposable
    {
        public void Dispose() => action();
    }
}
