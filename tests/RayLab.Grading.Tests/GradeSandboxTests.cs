using RayLab.Tests.Shared;

namespace RayLab.Grading.Tests;

/// <summary>
/// <c>raylab grade</c>'s sandbox for real (bubblewrap, the limits of this machine), with small shell commands as the
/// submission: what it sees, and that each limit stops what goes past it and says which limit it was. Skipped, with
/// the grader's own reason, where the sandbox or a limit cannot run here.
/// </summary>
public sealed class GradeSandboxTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void ASubmissionSeesItsCopyButNoHomeFolderNoKitAndNoOtherSubmission()
    {
        // A kit and another student's lab beside this lab, in the same temporary folder, and a secret in each.
        string kit = Directory.CreateDirectory(_dir.File("kit/checks/exercise/src/Lab")).FullName;
        File.WriteAllText(Path.Combine(kit, "LabOrthoCamera.cs"), "the reference solution");
        string other = Directory.CreateDirectory(_dir.File("submissions/other")).FullName;
        File.WriteAllText(Path.Combine(other, "secret.txt"), "another student's lab");
        string lab = Directory.CreateDirectory(_dir.File("work/labs/anna")).FullName;
        File.WriteAllText(Path.Combine(lab, "own.txt"), "my own file");
        using GradeSandbox sandbox = Sandbox(new GradeLimits());

        ChildRun run = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "bash",
            ["-c", $"cat own.txt; echo; echo written > new.txt && echo wrote; ls -a /; for f in /root /home /work {kit}/LabOrthoCamera.cs {other}/secret.txt /etc/shadow; do test -e $f && echo \"SEES $f\"; done; cat {kit}/LabOrthoCamera.cs {other}/secret.txt /root/.bashrc 2>/dev/null; echo done"],
            TestContext.Current.CancellationToken);

        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Output}");
        Assert.Contains("my own file", run.Output, StringComparison.Ordinal);
        Assert.Contains("wrote", run.Output, StringComparison.Ordinal);
        Assert.Equal("written\n", File.ReadAllText(Path.Combine(lab, "new.txt")));
        Assert.Contains("done", run.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("SEES ", run.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("the reference solution", run.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("another student's lab", run.Output, StringComparison.Ordinal);
        Assert.Equal(SandboxLimit.None, run.Limit);
    }

    [Fact]
    public void NativeMemoryPastTheLimitIsStoppedAndTheRunSaysSo()
    {
        // bash holds 600 MB of command output in a variable (native memory, malloc): past a limit of 256 MB.
        string lab = Directory.CreateDirectory(_dir.File("lab")).FullName;
        using GradeSandbox sandbox = Sandbox(new GradeLimits { MemoryMegabytes = 256 });
        AssertNativeMemoryLimitHolds(sandbox, lab);
    }

    /// <summary>
    /// 600 MB of native memory (bash holding command output in a variable, malloc) is stopped at a 256 MB limit and the
    /// run says "memory"; 6 MB, the same command, runs.
    /// </summary>
    private static void AssertNativeMemoryLimitHolds(GradeSandbox sandbox, string lab)
    {
        ChildRun run = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "bash",
            ["-c", "x=$(head -c 600000000 /dev/zero | tr '\\0' a); echo \"held ${#x}\""], TestContext.Current.CancellationToken);
        Assert.False(run.TimedOut);
        Assert.DoesNotContain("held 600000000", run.Output, StringComparison.Ordinal);
        Assert.True(run.Limit == SandboxLimit.Memory, $"{run.Limit}, exit {run.ExitCode}: {run.Output}");

        // Within it, the same command runs.
        ChildRun small = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "bash",
            ["-c", "x=$(head -c 6000000 /dev/zero | tr '\\0' a); echo \"held ${#x}\""], TestContext.Current.CancellationToken);
        Assert.Contains("held 6000000", small.Output, StringComparison.Ordinal);
        Assert.Equal(SandboxLimit.None, small.Limit);
    }

    [Fact]
    public void AForkLoopStopsAtTheProcessLimitAndTheRunSaysSo()
    {
        // 500 sleeping processes, past a limit of 64; dash gives up at the first fork that fails.
        string lab = Directory.CreateDirectory(_dir.File("lab")).FullName;
        using GradeSandbox sandbox = Sandbox(new GradeLimits { Processes = 64 });
        AssertProcessLimitHolds(sandbox, lab);
    }

    /// <summary>500 sleeping processes stop at a limit of 64 (dash gives up at the first fork that fails), and the run says "processes".</summary>
    private static void AssertProcessLimitHolds(GradeSandbox sandbox, string lab)
    {
        ChildRun run = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "sh",
            ["-c", "i=0; while [ $i -lt 500 ]; do sleep 600 & i=$((i+1)); done; echo \"started $i\""], TestContext.Current.CancellationToken);
        Assert.False(run.TimedOut);
        Assert.DoesNotContain("started 500", run.Output, StringComparison.Ordinal);
        Assert.True(run.Limit == SandboxLimit.Processes, $"{run.Limit}, exit {run.ExitCode}: {run.Output}");
    }

    [Fact]
    public void ADiskFillerStopsAtTheDiskLimitAndTheRunSaysSo()
    {
        // 200 MB into the copy, past a limit of 64 MB; what the copy held before is still there.
        string lab = Directory.CreateDirectory(_dir.File("work/labs/filler")).FullName;
        File.WriteAllText(Path.Combine(lab, "own.txt"), "my own file");
        using GradeSandbox sandbox = Sandbox(new GradeLimits { DiskMegabytes = 64 });
        ChildRun run = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "bash",
            ["-c", "head -c 200000000 /dev/zero > fill.bin; echo \"exit $?\"; cat own.txt"], TestContext.Current.CancellationToken);
        Assert.False(run.TimedOut);
        Assert.Contains("my own file", run.Output, StringComparison.Ordinal);
        Assert.True(run.Limit == SandboxLimit.Disk, $"{run.Limit}, exit {run.ExitCode}: {run.Output}");
        Assert.InRange(new FileInfo(Path.Combine(lab, "fill.bin")).Length, 0, 64L << 20);

        // The sandbox's /tmp has the same cap.
        ChildRun temp = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "bash",
            ["-c", "rm fill.bin; head -c 200000000 /dev/zero > /tmp/fill.bin; ls -l /tmp/fill.bin"], TestContext.Current.CancellationToken);
        Assert.True(temp.Limit == SandboxLimit.Disk, $"{temp.Limit}, exit {temp.ExitCode}: {temp.Output}");
        Assert.DoesNotContain("200000000", temp.Output, StringComparison.Ordinal);
    }

    [Fact]
    public void ALoopPastTheCpuLimitIsStoppedAndTheRunSaysSo()
    {
        string lab = Directory.CreateDirectory(_dir.File("lab")).FullName;
        using GradeSandbox sandbox = Sandbox(new GradeLimits { CpuSeconds = 1 });
        ChildRun run = sandbox.Run(lab, null, TimeSpan.FromMinutes(2), "bash", ["-c", "while :; do :; done"], TestContext.Current.CancellationToken);
        Assert.False(run.TimedOut);
        Assert.True(run.Limit == SandboxLimit.CpuTime, $"{run.Limit}, exit {run.ExitCode}: {run.Output}");
    }

    [Fact]
    public void ATestHostCannotTraceOrSignalAProcessOfTheTestPlatformStartedAfterIt()
    {
        // The step's sandbox runs a test host through the launcher (sh in place of dotnet), then starts a process of its
        // own, as the test platform may start a thread after its test host: the test host finds its number and tries
        // to read its environment (what writing its memory through /proc/ID/mem needs too) and to signal it.
        string checks = Directory.CreateDirectory(_dir.File("checks")).FullName;
        string results = Directory.CreateDirectory(_dir.File("results")).FullName;
        using GradeSandbox sandbox = Sandbox(new GradeLimits());
        if (!sandbox.Mechanisms.Any(m => m.Contains("Landlock (ABI", StringComparison.Ordinal)))
        {
            Assert.Skip($"no Landlock here: {sandbox.Mechanisms[^1]}");
        }

        string launcher = sandbox.LauncherOf(Path.Combine(checks, ".testhost"), [checks, results], "/bin/sh")!;
        string host = "while [ ! -s target.pid ]; do sleep 0.1; done; p=$(cat target.pid); "
            + "if grep -aq PLATFORM_SECRET /proc/$p/environ; then echo READS; else echo NO-READ; fi; "
            + "if kill -0 $p 2>/dev/null; then echo SIGNALS; else echo NO-SIGNAL; fi";
        ChildRun run = sandbox.Run(results, null, TimeSpan.FromMinutes(1), "sh",
            ["-c", $"{launcher} -c '{host}' & h=$!; sleep 1; PLATFORM_SECRET=1 sleep 30 & t=$!; echo $t > target.pid; wait $h; kill $t"],
            TestContext.Current.CancellationToken, readOnly: [checks], nested: true);

        Assert.True(run.ExitCode == 0, $"exit {run.ExitCode}: {run.Output}");
        Assert.Contains("NO-READ", run.Output, StringComparison.Ordinal);
        Assert.Contains("NO-SIGNAL", run.Output, StringComparison.Ordinal);
    }

    [Fact]
    public void EachLimitNamesItsMechanism()
    {
        using GradeSandbox sandbox = Sandbox(new GradeLimits { MemoryMegabytes = 512, Processes = 256, DiskMegabytes = 128, CpuSeconds = 60 });
        string[] lines = [.. sandbox.Mechanisms];
        foreach (string limit in (string[])["memory limit: 512 MB", "process limit: 256 ", "disk limit: 128 MB", "CPU time limit: 60 s"])
        {
            Assert.Contains(lines, l => l.StartsWith(limit, StringComparison.Ordinal));
        }
    }

    [Fact]
    [System.Runtime.Versioning.SupportedOSPlatform("linux")]
    public void UnderCgroupV2AStepRunsInASystemdScopeThatHoldsItsMemoryAndProcessesTogether()
    {
        // A machine with cgroup v2 and systemd-run, played by this one: a stand-in systemd-run that records its
        // arguments and holds MemoryMax and TasksMax the way a scope does, in a cgroup of this kernel (v1's memory and
        // pids controllers, for the stand-in's processes and every one they start), then runs the command.
        if (!OperatingSystem.IsLinux() || !Environment.IsPrivilegedProcess || !Directory.Exists("/sys/fs/cgroup/memory") || !Directory.Exists("/sys/fs/cgroup/pids"))
        {
            Assert.Skip("the stand-in scope needs root and cgroup v1's memory and pids controllers");
        }

        string bin = Directory.CreateDirectory(_dir.File("bin")).FullName;
        string calls = Path.Combine(bin, "calls.txt");
        string scope = $"raylab-test-scope-{Guid.NewGuid():N}";
        string systemdRun = Path.Combine(bin, "systemd-run");
        File.WriteAllText(systemdRun, $$"""
            #!/bin/bash
            echo "$*" >> {{calls}}
            memory=""; tasks=""
            while [ $# -gt 0 ] && [ "$1" != "--" ]; do
              if [ "$1" = "-p" ]; then
                shift
                case "$1" in MemoryMax=*M) memory=${1#MemoryMax=}; memory=${memory%M};; TasksMax=*) tasks=${1#TasksMax=};; esac
              fi
              shift
            done
            shift
            group={{scope}}-$$
            if [ -n "$memory" ]; then
              mkdir /sys/fs/cgroup/memory/$group && echo $((memory << 20)) > /sys/fs/cgroup/memory/$group/memory.limit_in_bytes && echo $$ > /sys/fs/cgroup/memory/$group/cgroup.procs || exit 125
            fi
            if [ -n "$tasks" ]; then
              mkdir /sys/fs/cgroup/pids/$group && echo $tasks > /sys/fs/cgroup/pids/$group/pids.max && echo $$ > /sys/fs/cgroup/pids/$group/cgroup.procs || exit 125
            fi
            exec "$@"
            """.ReplaceLineEndings("\n"));
        File.SetUnixFileMode(systemdRun, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        try
        {
            string lab = Directory.CreateDirectory(_dir.File("lab")).FullName;
            GradeSandbox sandbox;
            try
            {
                sandbox = GradeSandbox.Create(unsafeNoSandbox: false, [_dir.File("kit")], Directory.CreateDirectory(_dir.File("packages")).FullName,
                    new GradeLimits { MemoryMegabytes = 256, Processes = 64 }, new SandboxHost(CgroupV2: true, SystemdRun: systemdRun));
            }
            catch (SandboxUnavailableException e)
            {
                Assert.Skip($"the sandbox cannot run here: {e.Message}");
                throw;
            }

            using (sandbox)
            {
                Assert.Contains("memory limit: 256 MB for all of a step's processes together (cgroup v2: systemd-run --scope -p MemoryMax), and the GC heap of each .NET process", sandbox.Mechanisms);
                Assert.Contains("process limit: 64 processes and threads for a step together (cgroup v2: TasksMax)", sandbox.Mechanisms);

                // Native memory past the limit: the kernel stops the step (SIGKILL), and the run says which limit;
                // within it the same command runs; and 500 sleeping processes stop at the scope's 64.
                AssertNativeMemoryLimitHolds(sandbox, lab);
                AssertProcessLimitHolds(sandbox, lab);
            }

            // Each step in its own scope with both limits, around the sandbox, and no per-process limit inside it: the
            // scope holds the step's processes together.
            string[] scopes = File.ReadAllLines(calls);
            Assert.Equal("--quiet --scope -p MemoryMax=64M -p TasksMax=16 -- true", scopes[0]); // the probe
            Assert.True(scopes.Length - 1 >= 3, string.Join('\n', scopes)); // the three runs, and the sandbox's own trial run
            Assert.All(scopes.Skip(1), line =>
            {
                Assert.StartsWith("--quiet --scope -p MemoryMax=256M -p MemorySwapMax=0 -p TasksMax=64 -- ", line, StringComparison.Ordinal);
                Assert.Contains("bwrap ", line, StringComparison.Ordinal);
                Assert.DoesNotContain("--data=", line, StringComparison.Ordinal);
                Assert.DoesNotContain("--nproc=", line, StringComparison.Ordinal);
            });
        }
        finally
        {
            foreach (string controller in (string[])["memory", "pids"])
            {
                foreach (string group in Directory.GetDirectories($"/sys/fs/cgroup/{controller}", scope + "-*"))
                {
                    try
                    {
                        Directory.Delete(group);
                    }
                    catch (IOException)
                    {
                        // a process of the group still ending
                    }
                }
            }
        }
    }

    [Fact]
    public void WithoutTheSandboxTheLimitsSayNone()
    {
        using GradeSandbox sandbox = GradeSandbox.Create(unsafeNoSandbox: true, [], Directory.CreateDirectory(_dir.File("packages")).FullName, new GradeLimits { MemoryMegabytes = 512 });
        Assert.False(sandbox.IsSandboxed);
        Assert.Contains("process limit: none", sandbox.Mechanisms);
        Assert.Contains("disk limit: none", sandbox.Mechanisms);
    }

    /// <summary>The grader's sandbox with <paramref name="limits"/>; the test is skipped with the grader's reason where it cannot run here.</summary>
    private GradeSandbox Sandbox(GradeLimits limits)
    {
        string packages = Directory.CreateDirectory(_dir.File("packages")).FullName;
        try
        {
            return GradeSandbox.Create(unsafeNoSandbox: false, [_dir.File("kit"), _dir.File("submissions")], packages, limits);
        }
        catch (SandboxUnavailableException e)
        {
            Assert.Skip($"the sandbox or a limit cannot run here: {e.Message}");
            throw;
        }
    }
}
