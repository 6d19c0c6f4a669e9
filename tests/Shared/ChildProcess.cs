using System.Diagnostics;
using System.Text;

namespace RayLab.Tests.Shared;

/// <summary>What a child process left when it ended: its exit code, its two outputs and the command that ran.</summary>
/// <param name="ExitCode">The child's exit code.</param>
/// <param name="Output">What it wrote to standard output.</param>
/// <param name="Errors">What it wrote to standard error.</param>
/// <param name="Command">The command line and folder, for failure messages.</param>
internal readonly record struct ChildResult(int ExitCode, string Output, string Errors, string Command)
{
    /// <summary>The command, its exit code and both outputs, as a failure message shows them.</summary>
    public override string ToString() => $"exit code {ExitCode}: {Command}\n--- stdout\n{Output}\n--- stderr\n{Errors}";
}

/// <summary>
/// Runs a program (<c>dotnet pack</c>, <c>dotnet new</c>, a packed tool) to completion for the tests that drive
/// the SDK from the outside: the package, template and browser tests. The child gets a clean build environment
/// (no MSBuild variables inherited from the outer <c>dotnet test</c>) and the variables the caller sets.
/// </summary>
internal static class ChildProcess
{
    /// <summary>A short digest of the caller's variables, the same for the same variables in any order.</summary>
    private static string Salt(IReadOnlyDictionary<string, string?> environment) =>
        Convert.ToHexString(System.Security.Cryptography.SHA256.HashData(Encoding.UTF8.GetBytes(
            string.Join('\n', environment.OrderBy(e => e.Key, StringComparer.Ordinal).Select(e => $"{e.Key}={e.Value}")))))[..16];

    /// <summary>Runs <paramref name="fileName"/> and waits for it, whatever its exit code.</summary>
    /// <param name="workingDirectory">Where it runs.</param>
    /// <param name="environment">Variables to set (a null value removes the variable).</param>
    /// <param name="timeout">How long it may run before it is killed with its process tree and the test fails.</param>
    /// <param name="fileName">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <returns>Its exit code and outputs.</returns>
    public static async Task<ChildResult> RunAsync(
        string workingDirectory, IReadOnlyDictionary<string, string?> environment, TimeSpan timeout, string fileName, params string[] args)
    {
        var psi = new ProcessStartInfo(fileName)
        {
            WorkingDirectory = workingDirectory,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
        };
        foreach (string arg in args)
        {
            psi.ArgumentList.Add(arg);
        }

        // What the test host inherited from the outer `dotnet test` build must not steer the child builds.
        foreach (string key in psi.Environment.Keys.Where(k => k.StartsWith("MSBuild", StringComparison.OrdinalIgnoreCase)).ToList())
        {
            psi.Environment.Remove(key);
        }

        // An MSBuild worker node left waiting serves the next build that shakes hands with it, whatever that build's
        // environment, and NuGet in it keeps the home it found first: a build with another DOTNET_CLI_HOME restored into
        // the first one's folder (921 MB into a class kit's deleted folder). The salt lets a node serve only children
        // whose variables, as the caller sets them, are the same, and they still reuse it (`dotnet build
        // samples/RayLab.OwnMethod --no-incremental`, two projects, on 2 cores: 10–11 s with its node waiting, 22 s with
        // node reuse off).
        psi.Environment["MSBUILDNODEHANDSHAKESALT"] = Salt(environment);
        psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        psi.Environment["DOTNET_NOLOGO"] = "1";
        psi.Environment["DOTNET_SKIP_FIRST_TIME_EXPERIENCE"] = "1";
        foreach ((string key, string? value) in environment)
        {
            if (value is null)
            {
                psi.Environment.Remove(key);
            }
            else
            {
                psi.Environment[key] = value;
            }
        }

        using var process = new Process { StartInfo = psi };
        var stdout = new StringBuilder();
        var stderr = new StringBuilder();
        process.OutputDataReceived += (_, e) => { if (e.Data is not null) { lock (stdout) { stdout.AppendLine(e.Data); } } };
        process.ErrorDataReceived += (_, e) => { if (e.Data is not null) { lock (stderr) { stderr.AppendLine(e.Data); } } };
        process.Start();
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();

        string command = $"{fileName} {string.Join(' ', args)} (in {workingDirectory})";
        using var limit = CancellationTokenSource.CreateLinkedTokenSource(TestContext.Current.CancellationToken);
        limit.CancelAfter(timeout);
        try
        {
            await process.WaitForExitAsync(limit.Token);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"timed out after {timeout} or cancelled: {command}\n--- stdout\n{stdout}\n--- stderr\n{stderr}");
        }

        process.WaitForExit(); // drains the redirected streams
        return new ChildResult(process.ExitCode, stdout.ToString(), stderr.ToString(), command);
    }

    /// <summary>Runs <paramref name="fileName"/> as <see cref="RunAsync"/> does and fails the test unless it exits 0.</summary>
    /// <returns>What the child wrote to standard output.</returns>
    public static async Task<string> RunCheckedAsync(
        string workingDirectory, IReadOnlyDictionary<string, string?> environment, TimeSpan timeout, string fileName, params string[] args)
    {
        ChildResult result = await RunAsync(workingDirectory, environment, timeout, fileName, args);
        Assert.True(result.ExitCode == 0, result.ToString());
        return result.Output;
    }
}

/// <summary>Where the repository is, seen from a test assembly's folder.</summary>
internal static class RepoPaths
{
    /// <summary>The repository's folder: the first one above the test assembly that holds RayLab.sln.</summary>
    public static string Root()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "RayLab.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException($"RayLab.sln not found above {AppContext.BaseDirectory}");
    }
}
