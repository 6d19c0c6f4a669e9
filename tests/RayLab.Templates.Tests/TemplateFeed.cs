using System.Diagnostics;
using System.Text;

namespace RayLab.Templates.Tests;

/// <summary>
/// Once for the test class: a temporary folder with its own DOTNET_CLI_HOME (so the template is installed nowhere
/// else) and an empty NUGET_PACKAGES (so no cached RayLab package can stand in for the one packed here); RayLab,
/// RayLab.Reports and RayLab.Templates packed from this checkout into a folder feed; the template package installed
/// from that feed by its id and version, as a student would.
/// </summary>
public sealed class TemplateFeed : IAsyncLifetime
{
    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(10);

    /// <summary>The temporary folder everything happens in.</summary>
    public string Root { get; } = Directory.CreateTempSubdirectory("raylab-templates-").FullName;

    /// <summary>The folder feed.</summary>
    public string Feed => Path.Combine(Root, "feed");

    /// <summary>The children's NUGET_PACKAGES, empty at the start.</summary>
    public string Packages => Path.Combine(Root, "nuget-packages");

    /// <summary>The children's DOTNET_CLI_HOME (where <c>dotnet new install</c> records templates).</summary>
    public string CliHome => Path.Combine(Root, "dotnet-home");

    /// <summary>The version the three packages were packed with (MinVer: the same for all three).</summary>
    public string Version { get; private set; } = "";

    public async ValueTask InitializeAsync()
    {
        string repo = RepoRoot();
        string artifacts = Path.Combine(Root, "artifacts");
        Directory.CreateDirectory(CliHome);
        foreach (string project in new[] { "src/RayLab/RayLab.csproj", "src/RayLab.Reports/RayLab.Reports.csproj", "templates/RayLab.Templates/RayLab.Templates.csproj" })
        {
            await RunAsync(Root, "dotnet", "pack", Path.Combine(repo, project), "-c", "Release", "-o", Feed, "--artifacts-path", artifacts);
        }

        string template = Assert.Single(Directory.GetFiles(Feed, "RayLab.Templates.*.nupkg"));
        Version = Path.GetFileNameWithoutExtension(template)["RayLab.Templates.".Length..];
        Assert.True(File.Exists(Path.Combine(Feed, $"RayLab.{Version}.nupkg")), $"RayLab {Version} is not in the feed");
        Assert.True(File.Exists(Path.Combine(Feed, $"RayLab.Reports.{Version}.nupkg")), $"RayLab.Reports {Version} is not in the feed");

        await RunAsync(Root, "dotnet", "new", "install", $"RayLab.Templates::{Version}", "--add-source", Feed);
    }

    public ValueTask DisposeAsync()
    {
        try
        {
            Directory.Delete(Root, recursive: true);
        }
        catch (IOException)
        {
            // A child killed on timeout may still hold a file; the temporary folder is not worth failing for.
        }

        return ValueTask.CompletedTask;
    }

    /// <summary>The repository's folder (the one with RayLab.sln) above the test assembly.</summary>
    public static string RepoRoot()
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

    /// <summary>Runs a child to completion; fails with its command line and output unless it exits 0.</summary>
    /// <returns>What the child wrote to stdout.</returns>
    public async Task<string> RunAsync(string workingDirectory, string fileName, params string[] args)
    {
        (int exit, string output, string errors) = await StartAsync(workingDirectory, fileName, args);
        Assert.True(exit == 0, $"exit code {exit}: {fileName} {string.Join(' ', args)} (in {workingDirectory})\n--- stdout\n{output}\n--- stderr\n{errors}");
        return output;
    }

    /// <summary>Runs a child to completion, whatever its exit code.</summary>
    /// <returns>Its exit code, and stdout followed by stderr.</returns>
    public async Task<(int ExitCode, string Output)> RunUncheckedAsync(string workingDirectory, string fileName, params string[] args)
    {
        (int exit, string output, string errors) = await StartAsync(workingDirectory, fileName, args);
        return (exit, output + errors);
    }

    private async Task<(int ExitCode, string Output, string Errors)> StartAsync(string workingDirectory, string fileName, string[] args)
    {
        var psi = new ProcessStartInfo(fileName)
        {
            WorkingDirectory = workingDirectory,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
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

        psi.Environment["DOTNET_CLI_HOME"] = CliHome;
        psi.Environment["NUGET_PACKAGES"] = Packages;
        psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        psi.Environment["DOTNET_NOLOGO"] = "1";
        psi.Environment["DOTNET_SKIP_FIRST_TIME_EXPERIENCE"] = "1";
        psi.Environment["DOTNET_GENERATE_ASPNET_CERTIFICATE"] = "false";

        using var process = new Process { StartInfo = psi };
        var stdout = new StringBuilder();
        var stderr = new StringBuilder();
        process.OutputDataReceived += (_, e) => { if (e.Data is not null) { lock (stdout) { stdout.AppendLine(e.Data); } } };
        process.ErrorDataReceived += (_, e) => { if (e.Data is not null) { lock (stderr) { stderr.AppendLine(e.Data); } } };
        process.Start();
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();

        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(TestContext.Current.CancellationToken);
        timeout.CancelAfter(ChildTimeout);
        try
        {
            await process.WaitForExitAsync(timeout.Token);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"timed out after {ChildTimeout} or cancelled: {fileName} {string.Join(' ', args)} (in {workingDirectory})\n--- stdout\n{stdout}\n--- stderr\n{stderr}");
        }

        process.WaitForExit(); // drains the redirected streams
        return (process.ExitCode, stdout.ToString(), stderr.ToString());
    }
}
