using RayLab.Cli;

namespace RayLab.Tests.Cli;

/// <summary>Runs the console app in-process with captured output, as the CLI tests do.</summary>
internal static class ConsoleRunner
{
    public static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }
}
