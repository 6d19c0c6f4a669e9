using System.Globalization;
using RayLab.Reports.Imaging;
using RayLab.Metrics;

namespace RayLab.Reports.Comparison;

/// <summary>
/// Speed against error: renders a scene with each setting (built-in samplers or methods of your own), measures each
/// image against the exact image (RMSE in 8-bit levels and mean FLIP), and writes the report: <c>results.csv</c>,
/// <c>results.md</c>, four log-log charts, every image, error image and FLIP map, and <c>index.html</c>.
/// </summary>
public static class CompareRunner
{
    /// <summary>
    /// The most render time a setting's repeats are extended to: a quick setting whose renders disagree
    /// (<see cref="AgreeWithin"/>) is rendered again until they agree, they add up to this, or <see cref="MaximumRenders"/>.
    /// </summary>
    public static readonly TimeSpan MinimumMeasured = TimeSpan.FromMilliseconds(250);

    /// <summary>The most renders of one setting.</summary>
    public const int MaximumRenders = 64;

    /// <summary>
    /// A render at least this long is its setting's time on its own: at a quarter of a second the timer's error is a
    /// part in a million and a preemption of the scheduler's slice (a few milliseconds) about one per cent; the repeats
    /// are for renders short enough for those to matter (at 1920×1080 the renders of 64 samples per pixel and more, most
    /// of a comparison's render time, are timed once).
    /// </summary>
    public static readonly TimeSpan LongRender = TimeSpan.FromMilliseconds(250);

    /// <summary>
    /// How closely a quick setting's renders must agree for their median to be its time: the renders on either side of
    /// the median (the middle three of three or five, …) within this share of it; renders that do not are repeated.
    /// </summary>
    internal const double AgreeWithin = 0.05;

    /// <summary>
    /// Compares <paramref name="cases"/> on the scene and writes the whole report into <paramref name="folder"/>
    /// (created if missing; files already there with the report's names are replaced).
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">Image width in pixels, ≥ 1.</param>
    /// <param name="height">Image height in pixels, ≥ 1.</param>
    /// <param name="cases">The settings, e.g. <see cref="CompareCase.Sampled"/> and <see cref="CompareCase.Custom"/>; at least one, no two with one <see cref="CompareCase.FileStem"/>.</param>
    /// <param name="folder">The report's folder.</param>
    /// <param name="settings">Repeats, renderer and progress; null for the defaults.</param>
    /// <param name="cancellation">Stops between renders (give the renderer the same token to stop within one).</param>
    /// <returns>The report that was written.</returns>
    /// <exception cref="OperationCanceledException"><paramref name="cancellation"/> was cancelled; the folder may hold part of the report.</exception>
    public static CompareReport Run(
        Scene scene, Camera camera, int width, int height, IReadOnlyList<CompareCase> cases, string folder,
        CompareSettings? settings = null, CancellationToken cancellation = default)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(folder);
        settings ??= new CompareSettings();
        Directory.CreateDirectory(folder);
        CompareMeasurement measured = Measure(scene, camera, width, height, cases, folder, settings, cancellation);
        string threads = settings.Renderer is { MaxDegreeOfParallelism: > 0 and var t } ? $"{t} threads" : $"all {Environment.ProcessorCount} cores";
        string heading = string.Create(CultureInfo.InvariantCulture,
            $"{width}×{height}, {camera.Name} camera, {threads}, {TimeRule(settings.Repeats)}; "
            + $"exact image (RenderMethod.Exact) in {measured.Exact.RenderTime.TotalMilliseconds:F0} ms");
        var report = new CompareReport(heading, "", measured.Results, []);
        report.WriteTo(folder);
        return report;
    }

    /// <summary>
    /// Renders the exact image and each setting, times each setting (the median of its renders), measures it against
    /// the exact image (<see cref="ImageError"/>, <see cref="Flip"/> and <see cref="ErrorPlacement"/>, once each), and saves <c>images/exact.png</c>,
    /// <c>images/STEM.png</c>, the error heat map <c>errors/STEM.png</c> and the FLIP map <c>flip/STEM.png</c> into
    /// <paramref name="folder"/>; the tables and charts are <see cref="CompareReport.WriteTo"/>'s.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">Image width in pixels, ≥ 1.</param>
    /// <param name="height">Image height in pixels, ≥ 1.</param>
    /// <param name="cases">The settings; at least one, no two with one <see cref="CompareCase.FileStem"/>.</param>
    /// <param name="folder">An existing folder.</param>
    /// <param name="settings">Repeats, renderer and progress.</param>
    /// <param name="cancellation">Stops between renders.</param>
    /// <returns>The exact render and a result per setting.</returns>
    public static CompareMeasurement Measure(
        Scene scene, Camera camera, int width, int height, IReadOnlyList<CompareCase> cases, string folder,
        CompareSettings settings, CancellationToken cancellation = default)
    {
        Validate(scene, camera, width, height, cases, folder, settings);
        Renderer renderer = settings.Renderer ?? new Renderer { CancellationToken = cancellation };
        ICompareProgress progress = settings.Progress ?? new Unobserved();
        string images = Directory.CreateDirectory(Path.Combine(folder, "images")).FullName;
        string errors = Directory.CreateDirectory(Path.Combine(folder, "errors")).FullName;
        string flipMaps = Directory.CreateDirectory(Path.Combine(folder, "flip")).FullName;
        var flipOptions = new FlipOptions { MaxDegreeOfParallelism = renderer.MaxDegreeOfParallelism };

        CompareClock clock = settings.Clock ?? new CompareClock();
        var exact = new Image(width, height);
        RenderStatistics exactStats = clock.Time(CompareClock.ExactImage, () => progress.Render("exact image", () => renderer.Render(scene, camera, RenderMethod.Exact, exact)));
        clock.Time(ImageFiles, () => exact.Save(Path.Combine(images, "exact.png")));

        var image = new Image(width, height);
        var drawn = new DrawnImages(width, height);
        var results = new CompareResult[cases.Count];
        var estimate = new CompareEstimate(cases, settings.Repeats);
        for (int i = 0; i < cases.Count; i++)
        {
            CompareCase c = cases[i] ?? throw new ArgumentException($"cases[{i}] is null", nameof(cases));
            (RenderStatistics stats, List<TimeSpan> times) = TimeRenders(c, renderer, scene, camera, image, settings.Repeats, progress, clock, cancellation);
            long measuring = System.Diagnostics.Stopwatch.GetTimestamp();
            results[i] = MeasureImage(c, image, exact, clock, flipOptions, drawn, (images, errors, flipMaps)) with
            {
                Rays = stats.PrimaryRays,
                RaysPerPixel = stats.PrimaryRays / ((double)width * height),
                Time = Median([.. times]),
                Kernel = stats.Kernel,
                Renders = times.Count,
                Retimed = times.Count > settings.Repeats,
                TimedOnce = times.Count < settings.Repeats,
            };
            estimate.Done(i, Median([.. times]), System.Diagnostics.Stopwatch.GetElapsedTime(measuring), (long)width * height);
            progress.Setting(i + 1, cases.Count, clock.Elapsed, estimate.SecondsLeft(i, (long)width * height) is { } left ? TimeSpan.FromSeconds(left) : null);
        }

        return new CompareMeasurement(exactStats, results);
    }

    /// <summary>The stage that computes the 8-bit error and its per-pixel image.</summary>
    internal const string EightBitError = "8-bit error";

    /// <summary>The stage that computes the FLIP maps.</summary>
    internal const string FlipStage = "FLIP";

    /// <summary>The stage that computes the low-pass errors.</summary>
    internal const string LowPass = "low-pass error";

    /// <summary>The stage that computes the error spectra.</summary>
    internal const string SpectrumStage = "error spectrum";

    /// <summary>The stage that draws the error images and FLIP maps with their colour bars.</summary>
    internal const string ErrorImages = "error images";

    /// <summary>The stage that writes the pictures, error images and FLIP maps.</summary>
    internal const string ImageFiles = "image files";

    /// <summary>Measures one rendered image against the exact image and saves it, its error image and its FLIP map; the render's fields are the caller's.</summary>
    private static CompareResult MeasureImage(
        CompareCase c, Image image, Image exact, CompareClock clock, FlipOptions flipOptions, DrawnImages drawn, (string Images, string Errors, string Flip) folders)
    {
        ImageError error = clock.Time(EightBitError, () => ImageError.Measure(image, exact));
        float[] perPixel = drawn.PerPixel;
        clock.Time(EightBitError, () => ImageError.PerPixel(image, exact, perPixel));
        FlipResult flip = clock.Time(FlipStage, () => Flip.Compute(exact, image, flipOptions));
        int threads = flipOptions.MaxDegreeOfParallelism;
        using ErrorPlanes planes = clock.Time(LowPass, () => ErrorPlanes.Of(image, exact, threads));
        (double low1, double low2) = clock.Time(LowPass, () => (
            ErrorLocation.LowPassRmse(planes, 1, threads),
            ErrorLocation.LowPassRmse(planes, 2, threads)));
        ErrorSpectrum spectrum = clock.Time(SpectrumStage, () => ErrorLocation.Spectrum(planes, threads));
        Image heat = drawn.Heat, flipMap = drawn.FlipMap;
        clock.Time(ErrorImages, () =>
        {
            HeatMap.Render(perPixel, image.Width, image.Height, "levels", heat);
            FlipMap.RenderWithLegend(flip, flipMap);
        });
        clock.Time(ImageFiles, () =>
        {
            image.Save(Path.Combine(folders.Images, c.FileStem + ".png"));
            heat.Save(Path.Combine(folders.Errors, c.FileStem + ".png"));
            flipMap.Save(Path.Combine(folders.Flip, c.FileStem + ".png"));
        });
        return new CompareResult(c, 0, 0, TimeSpan.Zero, error, default)
        {
            MeanFlip = flip.Mean,
            Placement = new ErrorPlacement(low1, low2, spectrum),
        };
    }

    /// <summary>
    /// The buffers every picture's error image and FLIP map are drawn into, made once for the run: each is written whole
    /// per picture, and fresh ones for each of a hundred 1080p pictures would fault in some 20 MB of new pages apiece.
    /// </summary>
    private sealed class DrawnImages(int width, int height)
    {
        public float[] PerPixel { get; } = new float[width * height];

        public Image Heat { get; } = NewMap(width, height);

        public Image FlipMap { get; } = NewMap(width, height);

        private static Image NewMap(int width, int height)
        {
            (int w, int h) = HeatMap.SizeFor(width, height);
            return new Image(w, h);
        }
    }

    /// <summary>The arguments' checks for <see cref="Measure"/>.</summary>
    private static void Validate(Scene scene, Camera camera, int width, int height, IReadOnlyList<CompareCase> cases, string folder, CompareSettings settings)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        ArgumentNullException.ThrowIfNull(cases);
        ArgumentException.ThrowIfNullOrWhiteSpace(folder);
        ArgumentNullException.ThrowIfNull(settings);
        if (cases.Count == 0)
        {
            throw new ArgumentException("give at least one setting to compare", nameof(cases));
        }

        if (ComparePlan.SharedFileStem(cases) is { } stem)
        {
            throw new ArgumentException($"two settings would both write the image {stem}.png; give your methods distinct names", nameof(cases));
        }

        if (settings.Repeats < 1)
        {
            throw new ArgumentException($"Repeats must be at least 1, got {settings.Repeats}", nameof(settings));
        }
    }

    /// <summary>
    /// Renders one setting <paramref name="repeats"/> times (once when the first render is long), then again outside
    /// the progress count until the renders add up to a time worth measuring; returns the last render's statistics and every time.
    /// </summary>
    private static (RenderStatistics Stats, List<TimeSpan> Times) TimeRenders(
        CompareCase c, Renderer renderer, Scene scene, Camera camera, Image image, int repeats, ICompareProgress progress, CompareClock clock, CancellationToken cancellation)
    {
        var times = new List<TimeSpan>(repeats);
        RenderStatistics stats = default;
        for (int k = 0; k < repeats; k++)
        {
            cancellation.ThrowIfCancellationRequested();
            stats = clock.Time(CompareClock.Renders, () => progress.Render($"{c.Series}, {c.Setting} ({k + 1}/{repeats})", () => c.Render(renderer, scene, camera, image)));
            times.Add(stats.RenderTime);
            if (k == 0 && repeats > 1 && stats.RenderTime >= LongRender)
            {
                progress.Skipped(repeats - 1);
                break;
            }
        }

        // Quick renders that disagree (a preemption, a tier of the JIT arriving) are rendered again (outside the
        // progress count) until the median's neighbours agree with it or the renders add up to a time worth
        // measuring; the report says which were.
        TimeSpan measured = times.Aggregate(TimeSpan.Zero, (sum, t) => sum + t);
        while (times[0] < LongRender && measured < MinimumMeasured && times.Count < MaximumRenders && !Agree(times))
        {
            cancellation.ThrowIfCancellationRequested();
            TimeSpan again = clock.Time(CompareClock.Renders, () => c.Render(renderer, scene, camera, image)).RenderTime;
            times.Add(again);
            measured += again;
        }

        return (stats, times);
    }

    /// <summary>
    /// Whether a setting's renders so far pin their median: at least three, and the renders on either side of the
    /// median within <see cref="AgreeWithin"/> of it.
    /// </summary>
    /// <param name="times">The setting's render times, in any order.</param>
    internal static bool Agree(IReadOnlyList<TimeSpan> times)
    {
        if (times.Count < 3)
        {
            return false;
        }

        TimeSpan[] sorted = [.. times];
        Array.Sort(sorted);
        int n = sorted.Length;
        double median = Median(sorted).TotalSeconds;
        double below = sorted[((n - 1) / 2) - 1].TotalSeconds, above = sorted[(n / 2) + 1].TotalSeconds;
        return above - below <= AgreeWithin * median;
    }

    /// <summary>How the report's times were taken, for its heading: <c>time = median of 3 renders (1 for a render of 0.25 s or more)</c>.</summary>
    /// <param name="repeats">The repeats asked for.</param>
    public static string TimeRule(int repeats) => repeats == 1
        ? "time = one render"
        : string.Create(CultureInfo.InvariantCulture, $"time = median of {repeats} renders (1 for a render of {LongRender.TotalSeconds:0.##} s or more)");

    private static TimeSpan Median(TimeSpan[] times)
    {
        Array.Sort(times);
        int m = times.Length / 2;
        return times.Length % 2 == 1 ? times[m] : (times[m - 1] + times[m]) / 2;
    }

    private sealed class Unobserved : ICompareProgress
    {
        public RenderStatistics Render(string label, Func<RenderStatistics> render) => render();
    }
}
