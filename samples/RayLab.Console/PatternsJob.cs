using System.Globalization;
using RayLab.Reports.Patterns;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab patterns</c>: checks the output folder, has <see cref="PatternsReport"/> write the report into a hidden
/// staging folder beside it, and moves the files into place (<c>index.html</c> last), so a cancelled or failed run
/// leaves nothing behind.
/// </summary>
public static class PatternsJob
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>Runs the job; prints a summary (the slopes), or one error line and returns non-zero.</summary>
    /// <param name="request">What to draw and measure.</param>
    /// <param name="stdout">Where the summary goes.</param>
    /// <param name="stderr">Where errors go.</param>
    /// <param name="cancellation">Cancels the run before the files are moved into place.</param>
    /// <returns>0 on success, 1 on bad input or a failed write, 130 when cancelled.</returns>
    public static int Run(PatternsRequest request, TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        string? staging = null;
        try
        {
            // The report's own argument checks (ArgumentException) are bad input here, not bugs.
            return CommandExit.Run(stderr, Work, $"nothing written to {request.OutputFolder}", $"draw the patterns of {request.Samples} samples", cancellation,
                alsoBadInput: e => e is ArgumentException);
        }
        finally
        {
            if (staging is not null && Directory.Exists(staging))
            {
                Directory.Delete(staging, recursive: true);
            }
        }

        int Work()
        {
            if (request.Samplers.Count == 0)
            {
                throw new UsageException("--sampler: no sampler to draw");
            }

            if (File.Exists(request.OutputFolder))
            {
                throw new UsageException($"--out: '{request.OutputFolder}' is a file, not a folder");
            }

            string hidden = Path.Combine(request.OutputFolder, $".raylab-patterns-{Guid.NewGuid():N}.tmp");
            try
            {
                Directory.CreateDirectory(request.OutputFolder);
                Directory.CreateDirectory(hidden);
                staging = hidden;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // Before any figure is drawn, naming the option (a folder this user cannot write in: read-only, or /proc).
                throw OutputFolders.CannotWrite("--out", request.OutputFolder, e, hidden);
            }

            var clock = System.Diagnostics.Stopwatch.StartNew();
            PatternsReport.Write(request, staging, stdout, cancellation);
            cancellation.ThrowIfCancellationRequested();
            int moved = ReportFolder.Publish(staging, request.OutputFolder);

            stdout.WriteLine(string.Create(Inv, $"wrote {Path.Combine(request.OutputFolder, "index.html")} ({moved - 1} files) in {clock.Elapsed.TotalSeconds:F1} s"));
            return CommandExit.Done;
        }
    }
}
