using System.Diagnostics;
using System.Text;

namespace RayLab.Cli.Tests;

/// <summary>Runs the console app with captured output: in-process, as the CLI tests do, or as a child process.</summary>
internal static class ConsoleRunner
{
    public static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    /// <summary>
    /// Runs the built app (raylab.dll beside the tests) as a child process in <paramref name="workingDirectory"/>,
    /// its standard output and error redirected: there <see cref="Console.Out"/> is the real, redirected output.
    /// </summary>
    public static async Task<(int Code, string Out, string Err)> RunChildAsync(string workingDirectory, params string[] args)
    {
        CancellationToken cancel = TestContext.Current.CancellationToken;
        using Process process = StartChild(workingDirectory, args);
        Task<string> stdout = process.StandardOutput.ReadToEndAsync(cancel);
        Task<string> stderr = process.StandardError.ReadToEndAsync(cancel);
        await process.WaitForExitAsync(cancel);
        return (process.ExitCode, await stdout, await stderr);
    }

    /// <summary>
    /// Starts the built app as a child process, as <see cref="RunChildAsync"/> does, and returns it running with its
    /// output redirected and unread: the caller reads it (and must, or a full pipe stalls the child) and waits.
    /// </summary>
    public static Process StartChild(string workingDirectory, params string[] args)
    {
        string app = Path.Combine(AppContext.BaseDirectory, "raylab.dll");
        Assert.True(File.Exists(app), $"{app} is missing");
        var start = new ProcessStartInfo(DotnetHost())
        {
            WorkingDirectory = workingDirectory,
            UseShellExecute = false,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
        };
        start.ArgumentList.Add(app);
        foreach (string arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        return Process.Start(start) ?? throw new InvalidOperationException("could not start dotnet");
    }

    /// <summary>Sends SIGINT (what Ctrl+C sends) to <paramref name="process"/> with the system's <c>kill</c>.</summary>
    public static async Task InterruptAsync(Process process)
    {
        using Process kill = Process.Start(new ProcessStartInfo("kill", ["-INT", process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]) { UseShellExecute = false })
            ?? throw new InvalidOperationException("could not start kill");
        await kill.WaitForExitAsync(TestContext.Current.CancellationToken);
        Assert.Equal(0, kill.ExitCode);
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
}
