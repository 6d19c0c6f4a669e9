using System.Globalization;

namespace RayLab.PrecisionReport;

/// <summary>
/// <c>RayLab.PrecisionReport [--size N] [--out FILE]</c>: runs the hard cases and writes docs/precision.md's
/// markdown to FILE (atomically) or to standard output.
/// </summary>
public static class Program
{
    /// <summary>The default image side: 100×100 rays per case.</summary>
    public const int DefaultSize = 100;

    /// <summary>Entry point.</summary>
    /// <param name="args">Command-line arguments.</param>
    /// <returns>0 on success, 1 when the file cannot be written, 2 for a bad command line.</returns>
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs the tool with its output and messages going to the writers given (the tests read them).</summary>
    /// <param name="args">Command-line arguments.</param>
    /// <param name="stdout">Where the markdown goes when there is no <c>--out</c>.</param>
    /// <param name="stderr">Where errors and the "wrote" line go.</param>
    /// <returns>0 on success, 1 when the file cannot be written, 2 for a bad command line.</returns>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        ArgumentNullException.ThrowIfNull(args);
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        int size = DefaultSize;
        string? output = null;
        for (int i = 0; i < args.Length; i++)
        {
            string? value = i + 1 < args.Length ? args[i + 1] : null;
            switch (args[i])
            {
                case "--size" when int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out size) && size is >= 1 and <= 4096:
                    i++;
                    break;
                case "--out" when !string.IsNullOrWhiteSpace(value):
                    output = value;
                    i++;
                    break;
                default:
                    stderr.WriteLine($"precision-report: error: unexpected '{args[i]}'; usage: [--size N (1 to 4096)] [--out FILE]");
                    return 2;
            }
        }

        string markdown = PrecisionReport.ToMarkdown(PrecisionReport.Run(size), size);
        if (output is null)
        {
            stdout.Write(markdown);
            return 0;
        }

        string full = Path.GetFullPath(output);
        string folder = Path.GetDirectoryName(full)!;
        if (!Directory.Exists(folder))
        {
            stderr.WriteLine($"precision-report: error: {output}: the folder '{folder}' does not exist");
            return 1;
        }

        string temp = Path.Combine(folder, $".{Path.GetFileName(full)}.{Guid.NewGuid():N}.tmp");
        try
        {
            File.WriteAllText(temp, markdown);
            File.Move(temp, full, overwrite: true);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            if (File.Exists(temp))
            {
                File.Delete(temp);
            }

            stderr.WriteLine($"precision-report: error: {output}: {e.Message}");
            return 1;
        }

        stderr.WriteLine($"precision-report: wrote {output} ({size}×{size} rays per case)");
        return 0;
    }
}
