using System.Globalization;
using RayLab.Sampling;
using RayLab.Reports.Comparison;
using RayLab.Scenes;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab compare</c>: renders a scene with every sampler over a range of budgets (the adaptive sampler over
/// maximum depths and contrasts), measures each image against the exact image, and writes a report folder:
/// <c>results.csv</c>, <c>results.md</c>, two log-log charts, every image and error image, and <c>index.html</c>.
/// </summary>
public static class CompareJob
{
    /// <summary>Runs the comparison; prints the table, or one error line and returns non-zero.</summary>
    /// <param name="request">What to compare.</param>
    /// <param name="stdout">Where the table goes.</param>
    /// <param name="stderr">Where errors go.</param>
    /// <param name="cancellation">Cancels the comparison: the report folder is left as it was and the result is <see cref="Program.CancelledExitCode"/>.</param>
    /// <returns>0 on success, 1 on bad input or a failed write, 130 when cancelled.</returns>
    public static int Run(CompareRequest request, TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        var clock = new CompareClock();
        string? staging = null;
        string[] created = [];
        bool done = false;
        try
        {
            return CommandExit.Run(stderr, Work, $"no report written to {request.OutputFolder}", $"compare {request.ScenePath} at the requested size", cancellation);
        }
        finally
        {
            CleanUp(staging, done ? [] : created);
        }

        int Work()
        {
            (PreparedScene scene, CompareCase[] cases, List<string> notes) = Plan(request);
            RenderDevice device = DeviceChoice.Open(request.Device); // before anything is written: a missing GPU is a usage error
            created = MissingFolders(request.OutputFolder);
            string hidden = Path.Combine(request.OutputFolder, $".raylab-compare-{Guid.NewGuid():N}.tmp");
            try
            {
                Directory.CreateDirectory(request.OutputFolder);
                Directory.CreateDirectory(hidden);
                staging = hidden;
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // Before the renders, naming the option: a folder this user cannot write in (read-only, or /proc).
                throw OutputFolders.CannotWrite("--out", request.OutputFolder, e, hidden);
            }

            TimeSpan? firstLaunch = device.IsCpu ? null : clock.Time(FirstLaunchStage, () => DeviceChoice.FirstLaunch(device));
            CompareMeasurement measured = Measure(request, stdout, scene, cases, staging, clock, device, cancellation);
            var report = new CompareReport(Heading(request, scene, measured.Exact) + DeviceNote(device, firstLaunch), Command(request), measured.Results, notes) { Clock = clock };
            report.WriteTo(staging);
            cancellation.ThrowIfCancellationRequested(); // the last chance to leave the folder untouched
            clock.Time(PublishStage, () => ReportFolder.Publish(staging, request.OutputFolder));
            done = true;
            if (request.StatsPath is { } statsPath)
            {
                WriteStats(statsPath, request, scene, measured.Results.Count, clock, device, firstLaunch);
            }

            stdout.Write(report.Table());
            stdout.WriteLine($"wrote {Path.Combine(request.OutputFolder, "index.html")} ({measured.Results.Count} settings; results.md, results.csv, charts, images)");
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"total time {clock.Elapsed.TotalSeconds:F1} s ({TimeSummary(clock)})"));
            return CommandExit.Done;
        }
    }

    // Every check happens here, before anything is rendered or written.
    private static (PreparedScene Scene, CompareCase[] Cases, List<string> Notes) Plan(CompareRequest r)
    {
        const NumberStyles Digits = NumberStyles.None;
        CultureInfo inv = CultureInfo.InvariantCulture;
        int[] budgets = ParseList(r.Budgets, "--budgets", $"a whole number from 1 to {SceneFile.MaxSamples}",
            s => (int.TryParse(s, Digits, inv, out int b) && b is >= 1 and <= SceneFile.MaxSamples, b));
        int[] depths = ParseList(r.MaxDepths, "--max-depths", $"a whole number from 0 to {AdaptiveSampler.MaxSupportedDepth}",
            s => (int.TryParse(s, Digits, inv, out int d) && d <= AdaptiveSampler.MaxSupportedDepth, d));
        double[] contrasts = ParseList(r.Contrasts, "--contrasts", "a number ≥ 0",
            s => (double.TryParse(s, NumberStyles.Float, inv, out double c) && c >= 0 && double.IsFinite(c), c));
        string[] samplers = ParseList(r.Samplers ?? string.Join(',', ComparePlan.Compared), "--samplers",
            $"one of {string.Join(", ", ComparePlan.Compared)}", s => (ComparePlan.Compared.Contains(s, StringComparer.Ordinal), s));
        if (r.Repeats < 1)
        {
            throw new UsageException($"--repeats: must be at least 1, got {r.Repeats}");
        }

        if (r.Threads is < 1)
        {
            throw new UsageException($"--threads: must be at least 1, got {r.Threads}");
        }

        DeviceChoice.Check(r.Device);
        CheckOutputFolder(r.OutputFolder);
        if (r.StatsPath is not null)
        {
            RenderJob.CheckOutputPath(r.StatsPath, "--stats", requireImageFormat: false);
        }

        PreparedScene scene = Prepare(r);
        uint seed = r.Seed ?? scene.Description.Sampler.Seed;

        var notes = new List<string>();
        List<CompareCase> cases = [.. ComparePlan.BuiltIn(samplers, budgets, depths, contrasts, seed, notes), .. r.Methods ?? []];
        if (ComparePlan.SharedFileStem(cases) is { } stem)
        {
            throw new UsageException($"two settings would both write the image {stem}.png; give your methods distinct names");
        }

        return (scene, [.. cases], notes);
    }

    private static CompareMeasurement Measure(
        CompareRequest r, TextWriter stdout, PreparedScene scene, CompareCase[] cases, string staging, CompareClock clock, RenderDevice device, CancellationToken cancellation)
    {
        CompareMeasurement measured = null!;
        CompareProgress.Run(stdout, 1 + (cases.Length * r.Repeats), progress =>
        {
            var renderer = new Renderer { MaxDegreeOfParallelism = r.Threads ?? -1, Progress = progress.Rows, CancellationToken = cancellation, Device = device };
            measured = CompareRunner.Measure(scene.Scene, scene.Camera, scene.Description.Width, scene.Description.Height, cases, staging,
                new CompareSettings(r.Repeats, renderer, progress) { Clock = clock }, cancellation);
        });
        return measured;
    }

    /// <summary>The stage that compiles and loads a device's kernels, before the renders (none on the CPU).</summary>
    private const string FirstLaunchStage = "device first launch";

    /// <summary>The heading's words on the device: <c>; renders on cuda: NVIDIA …, its first launch (kernels compiled and loaded) 412 ms, in no render's time</c>.</summary>
    private static string DeviceNote(RenderDevice device, TimeSpan? firstLaunch) => firstLaunch is { } first
        ? string.Create(CultureInfo.InvariantCulture, $"; renders on {device.Name} (the exact image, and methods of your own, on the CPU), its first launch (kernels compiled and loaded) {first.TotalMilliseconds:F0} ms, in no render's time")
        : $"; renders on {device.Name}";

    /// <summary>The stage that moves the finished report from its staging folder into place.</summary>
    private const string PublishStage = "report into place";

    /// <summary>The stages' times in one line, longest first: <c>renders 30.1 s, error spectrum 12.0 s, …</c>.</summary>
    private static string TimeSummary(CompareClock clock) => string.Join(", ", clock.Stages.OrderByDescending(s => s.Time)
        .Select(s => string.Create(CultureInfo.InvariantCulture, $"{s.Name} {s.Time.TotalSeconds:F1} s")));

    /// <summary>Writes <c>--stats</c>: where the time went, as JSON.</summary>
    private static void WriteStats(string path, CompareRequest r, PreparedScene scene, int settings, CompareClock clock, RenderDevice device, TimeSpan? firstLaunch)
    {
        var stats = new CompareStatsFile
        {
            Scene = r.ScenePath,
            Width = scene.Description.Width,
            Height = scene.Description.Height,
            Threads = r.Threads,
            ProcessorCount = Environment.ProcessorCount,
            Settings = settings,
            TimeRule = CompareRunner.TimeRule(r.Repeats),
            Device = device.Name,
            FirstLaunchMs = firstLaunch is { } first ? Math.Round(first.TotalMilliseconds, 1) : null,
            Stages = [.. clock.Stages.Select(s => new CompareStatsStage(s.Name, Math.Round(s.Time.TotalSeconds, 4), s.Calls))],
            TotalS = Math.Round(clock.Elapsed.TotalSeconds, 3),
        };
        try
        {
            File.WriteAllText(path, System.Text.Json.JsonSerializer.Serialize(stats, CompareStatsJson.Default.CompareStatsFile));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new IOException($"--stats: cannot write '{path}' (the report is in place): {e.Message}", e);
        }
    }

    /// <summary>Splits a comma-separated option; every item must parse and appear once.</summary>
    private static T[] ParseList<T>(string text, string option, string what, Func<string, (bool Ok, T Value)> parse)
    {
        var items = new List<T>();
        foreach (string raw in text.Split(','))
        {
            string item = raw.Trim();
            (bool ok, T value) = parse(item);
            if (!ok)
            {
                throw new UsageException(item.Length == 0
                    ? $"{option}: an empty item in '{text}'; give a comma-separated list"
                    : $"{option}: '{item}' is not {what}");
            }

            if (items.Contains(value))
            {
                throw new UsageException($"{option}: '{item}' appears twice");
            }

            items.Add(value);
        }

        return [.. items];
    }

    private static void CheckOutputFolder(string folder)
    {
        if (string.IsNullOrWhiteSpace(folder))
        {
            throw new UsageException("--out: the path is empty");
        }

        // The folder and its missing parents are created; nothing on the way may be a file.
        for (string? path = Path.GetFullPath(folder); path is not null; path = Path.GetDirectoryName(path))
        {
            if (File.Exists(path))
            {
                throw new UsageException($"--out: '{path}' is a file, not a folder");
            }
        }
    }

    /// <summary>The folders that creating <paramref name="folder"/> will make, deepest first.</summary>
    private static string[] MissingFolders(string folder)
    {
        var missing = new List<string>();
        for (string? path = Path.GetFullPath(folder); path is not null && !Directory.Exists(path); path = Path.GetDirectoryName(path))
        {
            missing.Add(path);
        }

        return [.. missing];
    }

    private static PreparedScene Prepare(CompareRequest r)
    {
        // The scene's own sampler is not used; preparing it as "exact" checks that the exact reference can draw
        // the scene (a sphere behind the eye is an error naming spheres[i]) before anything is rendered.
        SceneDescription d = SceneFile.Load(CarriedScenes.Resolve(r.ScenePath));
        return new SceneOverrides(r.Width, r.Height).Prepare(d with { Sampler = d.Sampler with { Type = "exact" } });
    }

    private static string Heading(CompareRequest r, PreparedScene scene, RenderStatistics exact) => string.Create(CultureInfo.InvariantCulture,
        $"{Path.GetFileName(r.ScenePath)}, {scene.Description.Width}×{scene.Description.Height}, {scene.Camera.Name} camera, "
        + $"seed {r.Seed ?? scene.Description.Sampler.Seed}, {(r.Threads is { } t ? $"{t} threads" : $"all {Environment.ProcessorCount} cores")}, "
        + $"{CompareRunner.TimeRule(r.Repeats)}; "
        + $"exact image (RenderMethod.Exact) in {exact.RenderTime.TotalMilliseconds:F0} ms");

    /// <summary>The command line that reproduces the run, every list spelled out.</summary>
    private static string Command(CompareRequest r)
    {
        var parts = new List<string> { "raylab", "compare", r.ScenePath, "--out", r.OutputFolder, "--budgets", r.Budgets.Replace(" ", "", StringComparison.Ordinal) };
        if (r.Width is { } w)
        {
            parts.AddRange(["--width", w.ToString(CultureInfo.InvariantCulture)]);
        }

        if (r.Height is { } h)
        {
            parts.AddRange(["--height", h.ToString(CultureInfo.InvariantCulture)]);
        }

        parts.AddRange(["--repeats", r.Repeats.ToString(CultureInfo.InvariantCulture)]);
        if (r.Samplers is not null)
        {
            parts.AddRange(["--samplers", r.Samplers.Replace(" ", "", StringComparison.Ordinal)]);
        }

        parts.AddRange(["--max-depths", r.MaxDepths.Replace(" ", "", StringComparison.Ordinal), "--contrasts", r.Contrasts.Replace(" ", "", StringComparison.Ordinal)]);
        if (r.Seed is { } seed)
        {
            parts.AddRange(["--seed", seed.ToString(CultureInfo.InvariantCulture)]);
        }

        if (r.Threads is { } threads)
        {
            parts.AddRange(["--threads", threads.ToString(CultureInfo.InvariantCulture)]);
        }

        if (r.Device is { } device)
        {
            parts.AddRange(["--device", device]);
        }

        return string.Join(' ', parts);
    }

    /// <summary>Moves every file from the staging folder into place, <c>index.html</c> last (each move is a rename).</summary>
    private static void CleanUp(string? staging, string[] createdFolders)
    {
        try
        {
            if (staging is not null && Directory.Exists(staging))
            {
                Directory.Delete(staging, recursive: true);
            }

            foreach (string folder in createdFolders.Where(f => Directory.Exists(f) && !Directory.EnumerateFileSystemEntries(f).Any()))
            {
                Directory.Delete(folder);
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // Best effort: the error that brought us here is the one to report.
        }
    }
}
