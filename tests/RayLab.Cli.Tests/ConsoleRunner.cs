using System.Diagnostics;

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
        using Process process = ConsoleChild.Start(workingDirectory, args);
        Task<string> stdout = process.StandardOutput.ReadToEndAsync(cancel);
        Task<string> stderr = process.StandardError.ReadToEndAsync(cancel);
        await process.WaitForExitAsync(cancel);
        return (process.ExitCode, await stdout, await stderr);
    }
}
