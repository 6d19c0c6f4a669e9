using System.Diagnostics;

namespace RayLab.Cli.Tests;

/// <summary>
/// Ctrl+C (SIGINT) during <c>raylab render</c> or <c>raylab compare</c> cancels the render, leaves no output file
/// (nor a temporary one), prints one line and exits 130. In-process with a cancelled token, and in a child process
/// with a real signal sent while it renders.
/// </summary>
public sealed class CancelTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-cancel-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    [Fact]
    public void ACancelledRenderWritesNothingAndReturns130()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        string output = Path.Combine(_dir, "a.png");

        int code = Program.Run(["render", Scene, "-o", output, "--stats", Path.Combine(_dir, "a.json"), "--heatmap", Path.Combine(_dir, "h.png")],
            stdout, stderr, new CancellationToken(canceled: true));

        Assert.Equal(130, code);
        Assert.Equal($"raylab: cancelled; {output} not written", stderr.ToString().TrimEnd());
        Assert.Equal("", stdout.ToString());
        Assert.Empty(Directory.EnumerateFileSystemEntries(_dir));
    }

    [Fact]
    public void ACancelledComparisonWritesNothingAndReturns130()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        string report = Path.Combine(_dir, "new", "report");

        int code = Program.Run(["compare", Scene, "--out", report, "--samplers", "jittered", "--budgets", "1", "--repeats", "1", "--width", "16", "--height", "12"],
            stdout, stderr, new CancellationToken(canceled: true));

        Assert.Equal(130, code);
        Assert.Equal($"raylab: cancelled; no report written to {report}", stderr.ToString().TrimEnd());
        Assert.Empty(Directory.EnumerateFileSystemEntries(_dir)); // the folders it created, and its hidden staging folder, are gone
    }

    [Fact]
    public async Task CtrlCDuringARenderLeavesNoImageAndExits130()
    {
        Assert.SkipWhen(OperatingSystem.IsWindows(), "sends SIGINT with kill");
        // The scalar kernel at 4000×3000 and 64 samples: about a minute of CPU, stopped within a row. --guard does not
        // apply to random: the one-line note saying so is the gate.
        using Process child = ConsoleChild.Start(_dir, "render", Scene, "-o", "big.png", "--width", "4000", "--height", "3000",
            "--sampler", "random", "--samples", "64", "--kernel", "scalar", "--threads", "2", "--guard");
        using var _ = ConsoleChild.EndOnFailure(child);
        Task<string> stdout = child.StandardOutput.ReadToEndAsync(TestContext.Current.CancellationToken);

        // Redirected, the render prints nothing until it ends, but the note comes first on stderr: after the child
        // registered for SIGINT (first thing) and loaded the scene, before the image, the warm-up and the render, so
        // that the signal meets the job with about a minute of rendering left and nothing written.
        string? note = await child.StandardError.ReadLineAsync(TestContext.Current.CancellationToken);
        Assert.Equal("raylab: note: --guard applies to the adaptive sampler only, not random (ignored)", note);
        Task<string> stderr = child.StandardError.ReadToEndAsync(TestContext.Current.CancellationToken);

        await ConsoleChild.InterruptAndWaitAsync(child, TimeSpan.FromMinutes(3));

        Assert.Equal("raylab: cancelled; big.png not written", (await stderr).TrimEnd());
        Assert.Equal(130, child.ExitCode);
        Assert.Equal("", await stdout);
        Assert.Empty(Directory.EnumerateFileSystemEntries(_dir));
    }

    [Fact]
    public async Task CtrlCDuringAComparisonLeavesNoReportAndExits130()
    {
        Assert.SkipWhen(OperatingSystem.IsWindows(), "sends SIGINT with kill");
        // After the exact image, random at 4096 samples per pixel on 1600×1200: minutes of work, stopped within a row.
        using Process child = ConsoleChild.Start(_dir, "compare", Scene, "--out", "report", "--samplers", "random", "--budgets", "4096",
            "--repeats", "1", "--width", "1600", "--height", "1200", "--threads", "2");
        using var _ = ConsoleChild.EndOnFailure(child);
        Task<string> stderr = child.StandardError.ReadToEndAsync(TestContext.Current.CancellationToken);

        // Redirected, compare prints a line per finished render: the first says the exact image is done.
        string? line = await child.StandardOutput.ReadLineAsync(TestContext.Current.CancellationToken);
        Assert.StartsWith("[1/2] exact image: ", line, StringComparison.Ordinal);
        Task<string> rest = child.StandardOutput.ReadToEndAsync(TestContext.Current.CancellationToken);

        await ConsoleChild.InterruptAndWaitAsync(child, TimeSpan.FromMinutes(3));

        Assert.Equal("raylab: cancelled; no report written to report", (await stderr).TrimEnd());
        Assert.Equal(130, child.ExitCode);
        Assert.Equal("", await rest);
        Assert.Empty(Directory.EnumerateFileSystemEntries(_dir)); // no report folder, no staging folder
    }
}
