using System.CommandLine;
using System.Globalization;
using RayLab.Reports.Imaging;
using RayLab.Metrics;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab flip REF TEST [-o MAP.png] [--ppd N]</c>: the error a viewer sees between two pictures of the same size
/// (mean LDR-FLIP, <see cref="Flip"/>), their RMSE in 8-bit levels (<see cref="ImageError"/>), where the error sits
/// (<see cref="ErrorLocation"/>: the low-pass RMSE and the low-frequency share), and with
/// <c>-o</c> the FLIP map in the magma colours of NVIDIA's tool (<see cref="FlipMap.Render"/>). The pictures are read
/// by SkiaSharp (<see cref="SkiaBitmaps"/>): PNG, JPEG, WebP, BMP or GIF.
/// </summary>
public static class FlipCommand
{
    /// <summary>Builds the command.</summary>
    /// <param name="stdout">Where the two measures go.</param>
    /// <param name="stderr">Where errors go, one line each.</param>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var reference = new Argument<string>("reference") { Description = "The reference picture (e.g. the exact render): PNG, JPEG, WebP, BMP or GIF." };
        var test = new Argument<string>("test") { Description = "The picture judged, of the reference's size." };
        var output = new Option<string?>("--output", "-o") { Description = $"Also write the FLIP map in magma colours (black: no visible difference, pale yellow: 1), {string.Join(", ", ImageFormats.Extensions)}. Default: none.", HelpName = "MAP.png" };
        var ppd = new Option<double?>("--ppd") { Description = string.Create(CultureInfo.InvariantCulture, $"The observer's pixels per degree of visual angle, {FlipOptions.MinPixelsPerDegree:0} to {FlipOptions.MaxPixelsPerDegree:0}. Default: the FLIP paper's {FlipOptions.DefaultPixelsPerDegree:F2} (0.7 m from a 0.7 m wide display of 3840 pixels)."), HelpName = "N" };
        var flip = new Command("flip", "Compare two pictures of the same size: print the mean FLIP (the difference a viewer sees flipping between them), the RMSE in 8-bit levels and where the error sits (low-pass RMSE, low-frequency share), and write the FLIP map.")
        {
            reference, test, output, ppd,
        };
        flip.SetAction(result => CommandExit.Run(
            stderr,
            () =>
            {
                Run(result.GetRequiredValue(reference), result.GetRequiredValue(test), result.GetValue(output), result.GetValue(ppd), stdout);
                return CommandExit.Done;
            },
            cancelled: "no map written",
            tooLarge: "compare pictures this large",
            CancellationToken.None));
        return flip;
    }

    private static void Run(string referencePath, string testPath, string? mapPath, double? ppd, TextWriter stdout)
    {
        // Every check comes before anything is written: the map appears whole (Image.Save writes it under a
        // temporary name and renames it) or not at all.
        if (ppd is { } p && (!double.IsFinite(p) || p < FlipOptions.MinPixelsPerDegree || p > FlipOptions.MaxPixelsPerDegree))
        {
            throw new UsageException(string.Create(CultureInfo.InvariantCulture,
                $"--ppd: expected {FlipOptions.MinPixelsPerDegree:0} to {FlipOptions.MaxPixelsPerDegree:0} pixels per degree, got {p}"));
        }

        if (mapPath is not null)
        {
            CheckMapPath(mapPath, referencePath, testPath);
        }

        Image reference = Read(referencePath);
        Image test = Read(testPath);
        if (test.Width != reference.Width || test.Height != reference.Height)
        {
            throw new UsageException(
                $"{testPath}: the picture is {test.Width}×{test.Height} but the reference {referencePath} is {reference.Width}×{reference.Height}; FLIP compares pictures of the same size");
        }

        var options = new FlipOptions { PixelsPerDegree = ppd ?? FlipOptions.DefaultPixelsPerDegree };
        FlipResult flip = Flip.Compute(reference, test, options);
        ImageError error = ImageError.Measure(test, reference);
        if (mapPath is not null)
        {
            FlipMap.Render(flip).Save(mapPath);
        }

        CultureInfo inv = CultureInfo.InvariantCulture;
        stdout.WriteLine(string.Create(inv, $"mean FLIP {flip.Mean:F6} (LDR-FLIP, {flip.PixelsPerDegree:F2} pixels per degree; 0 = no visible difference)"));
        stdout.WriteLine(string.Create(inv,
            $"RMSE {error.Rmse:F4} levels (8-bit; mean abs. {error.MeanAbsolute:F4}, max {error.Max}, {100 * error.FractionOverOneLevel:F3}% of pixels more than 1 level off)"));
        ErrorSpectrum spectrum = ErrorLocation.Spectrum(test, reference);
        stdout.WriteLine(string.Create(inv,
            $"low-pass RMSE {ErrorLocation.LowPassRmse(test, reference, 1):F4} levels (Gaussian blur σ = 1 px), {ErrorLocation.LowPassRmse(test, reference, 2):F4} (σ = 2 px); low share {spectrum.LowFrequencyShare:F4} (of the error's power, at periods of 8 px or more; white noise 0.049)"));
        if (mapPath is not null)
        {
            stdout.WriteLine($"wrote {mapPath}: the FLIP map, {reference.Width}×{reference.Height}, magma colours (black = no visible difference, pale yellow = 1)");
        }
    }

    private static Image Read(string path)
    {
        if (string.IsNullOrWhiteSpace(path))
        {
            throw new UsageException("a picture's path is empty");
        }

        if (Directory.Exists(path))
        {
            throw new UsageException($"{path}: is a folder, not a picture");
        }

        if (!File.Exists(path))
        {
            throw new UsageException($"{path}: no such file");
        }

        try
        {
            return Image.Load(path);
        }
        catch (InvalidDataException e)
        {
            throw new UsageException(e.Message); // it names the file
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"{path}: cannot be read: {e.Message}");
        }
    }

    private static void CheckMapPath(string mapPath, string referencePath, string testPath)
    {
        if (string.IsNullOrWhiteSpace(mapPath))
        {
            throw new UsageException("--output: the path is empty");
        }

        try
        {
            ImageFormat.FromPath(mapPath);
        }
        catch (NotSupportedException e)
        {
            throw new UsageException($"--output: {e.Message}");
        }

        string full = Path.GetFullPath(mapPath);
        if (full == Path.GetFullPath(referencePath) || full == Path.GetFullPath(testPath))
        {
            throw new UsageException($"--output: '{mapPath}' is one of the pictures compared; the map would overwrite it");
        }

        if (Directory.Exists(mapPath))
        {
            throw new UsageException($"--output: '{mapPath}' is a folder, not a file");
        }

        string folder = Path.GetDirectoryName(full) ?? ".";
        if (!Directory.Exists(folder))
        {
            throw new UsageException($"--output: the folder '{folder}' does not exist");
        }
    }
}
