using System.Globalization;
using RayLab.Imaging;
using RayLab.Rendering;
using RayLab.Sampling;
using RayLab.Scenes;
using RayLab.Rendering.Adaptive;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab compare</c>: renders a scene with every sampler over a range of budgets (the adaptive sampler over
/// maximum depths and contrasts), measures each image against the exact image, and writes a report folder:
/// <c>results.csv</c>, <c>results.md</c>, two log-log charts, every image and error image, and <c>index.html</c>.
/// </summary>
public static class CompareJob
{
    /// <summary>
    /// The least total render time a setting's time is taken from: a setting whose <c>--repeats</c> renders add up
    /// to less is rendered again until they reach it (or <see cref="MaximumRenders"/>).
    /// </summary>
    public static readonly TimeSpan MinimumMeasured = TimeSpan.FromMilliseconds(250);

    /// <summary>The most renders of one setting taken to reach <see cref="MinimumMeasured"/>.</summary>
    public const int MaximumRenders = 64;

    /// <summary>The samplers a comparison renders: every point sampler and adaptive (the exact one is the reference).</summary>
    public static IReadOnlyList<string> Compared { get; } = [.. Samplers.Names, "adaptive"];

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
        var clock = System.Diagnostics.Stopwatch.StartNew();
        string? staging = null;
        string[] created = [];
        bool done = false;
        try
        {
            (PreparedScene scene, CompareCase[] cases, List<string> notes) = Plan(request);
            created = MissingFolders(request.OutputFolder);
            Directory.CreateDirectory(request.OutputFolder);
            staging = Path.Combine(request.OutputFolder, $".raylab-compare-{Guid.NewGuid():N}.tmp");
            Directory.CreateDirectory(Path.Combine(staging, "images"));
            Directory.CreateDirectory(Path.Combine(staging, "errors"));

            (RenderStatistics exact, CompareResult[] results) = Measure(request, stdout, scene, cases, staging, cancellation);
            var report = new CompareReport(Heading(request, scene, exact), Command(request), results, notes);
            report.WriteTo(staging);
            cancellation.ThrowIfCancellationRequested(); // the last chance to leave the folder untouched
            Publish(staging, request.OutputFolder);
            done = true;

            stdout.Write(report.Table());
            stdout.WriteLine($"wrote {Path.Combine(request.OutputFolder, "index.html")} ({results.Length} settings; results.md, results.csv, charts, images)");
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture, $"total time {clock.Elapsed.TotalSeconds:F1} s"));
            return 0;
        }
        catch (Exception e) when (e is SceneFileException or UsageException or IOException or UnauthorizedAccessException)
        {
            stderr.WriteLine($"raylab: error: {e.Message}");
            return 1;
        }
        catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
        {
            stderr.WriteLine($"raylab: cancelled; no report written to {SceneFileException.OneLine(request.OutputFolder)}");
            return Program.CancelledExitCode;
        }
        catch (OutOfMemoryException)
        {
            stderr.WriteLine($"raylab: error: not enough memory to compare {request.ScenePath} at the requested size");
            return 1;
        }
        finally
        {
            CleanUp(staging, done ? [] : created);
        }
    }

    // Every check happens here, before anything is rendered or written.
    private static (PreparedScene Scene, CompareCase[] Cases, List<string> Notes) Plan(CompareRequest r)
    {
        const NumberStyles Digits = NumberStyles.None;
        CultureInfo inv = CultureInfo.InvariantCulture;
        int[] budgets = ParseList(r.Budgets, "--budgets", "a whole number ≥ 1",
            s => (int.TryParse(s, Digits, inv, out int b) && b >= 1, b));
        int[] depths = ParseList(r.MaxDepths, "--max-depths", $"a whole number from 0 to {AdaptiveSampler.MaxSupportedDepth}",
            s => (int.TryParse(s, Digits, inv, out int d) && d <= AdaptiveSampler.MaxSupportedDepth, d));
        double[] contrasts = ParseList(r.Contrasts, "--contrasts", "a number ≥ 0",
            s => (double.TryParse(s, NumberStyles.Float, inv, out double c) && c >= 0 && double.IsFinite(c), c));
        string[] samplers = ParseList(r.Samplers ?? string.Join(',', Compared), "--samplers",
            $"one of {string.Join(", ", Compared)}", s => (Compared.Contains(s, StringComparer.Ordinal), s));
        if (r.Repeats < 1)
        {
            throw new UsageException($"--repeats: must be at least 1, got {r.Repeats}");
        }

        if (r.Threads is < 1)
        {
            throw new UsageException($"--threads: must be at least 1, got {r.Threads}");
        }

        CheckOutputFolder(r.OutputFolder);
        PreparedScene scene = Prepare(r);
        uint seed = r.Seed ?? scene.Description.Sampler.Seed;

        var cases = new List<CompareCase>();
        var notes = new List<string>();
        foreach (string name in samplers.Where(s => s != "adaptive"))
        {
            bool grid = Samplers.Create(name, 1, seed) is GridSampler;
            var seen = new Dictionary<int, int>();
            foreach (int budget in budgets)
            {
                int spp = grid ? (int)Math.Pow(Math.Floor(Math.Sqrt(budget)), 2) : budget;
                if (seen.TryGetValue(spp, out int earlier))
                {
                    notes.Add($"{name}: budget {budget} would be {spp} samples (an n×n grid), as budget {earlier} is; left out.");
                    continue;
                }

                seen[spp] = budget;
                if (spp != budget)
                {
                    notes.Add($"{name}: budget {budget} runs as {spp} samples (an n×n grid needs a perfect square).");
                }

                cases.Add(CompareCase.Sampled(Samplers.Create(name, spp, seed), budget));
            }
        }

        if (samplers.Contains("adaptive"))
        {
            foreach (double contrast in contrasts)
            {
                foreach (int depth in depths)
                {
                    cases.Add(CompareCase.Adaptive(new AdaptiveSampler(0, depth, contrast)));
                }
            }

            // The guarded sampler beside the lab's rule, at the smallest contrast asked for.
            double finest = contrasts.Min();
            foreach (int depth in depths)
            {
                cases.Add(CompareCase.Adaptive(new AdaptiveSampler(0, depth, finest, guard: true)));
            }
        }

        cases.AddRange(r.Methods ?? []);
        if (cases.GroupBy(c => c.FileStem).FirstOrDefault(g => g.Count() > 1) is { } twice)
        {
            throw new UsageException($"two settings would both write the image {twice.Key}.png; give your methods distinct names");
        }

        return (scene, [.. cases], notes);
    }

    private static (RenderStatistics Exact, CompareResult[] Results) Measure(
        CompareRequest r, TextWriter stdout, PreparedScene scene, CompareCase[] cases, string staging, CancellationToken cancellation)
    {
        int width = scene.Description.Width, height = scene.Description.Height;
        Image exact = scene.CreateImage();
        RenderStatistics exactStats = default;
        var results = new CompareResult[cases.Length];
        CompareProgress.Run(stdout, 1 + (cases.Length * r.Repeats), progress =>
        {
            // The scene was prepared with the exact method: it renders the reference.
            var renderer = new Renderer { MaxDegreeOfParallelism = r.Threads ?? -1, Progress = progress.Rows, CancellationToken = cancellation };
            exactStats = progress.Render("exact image", () => scene.Render(renderer, exact));
            exact.Save(Path.Combine(staging, "images", "exact.png"));

            Image image = scene.CreateImage();
            for (int i = 0; i < cases.Length; i++)
            {
                CompareCase c = cases[i];
                var times = new List<TimeSpan>(r.Repeats);
                RenderStatistics stats = default;
                for (int k = 0; k < r.Repeats; k++)
                {
                    stats = progress.Render($"{c.Series}, {c.Setting} ({k + 1}/{r.Repeats})", () => c.Render(renderer, scene.Scene, scene.Camera, image));
                    times.Add(stats.RenderTime);
                }

                // A render of a few milliseconds is timer and scheduler noise: render again (outside the progress
                // count) until the renders add up to a time worth measuring; the report says which were.
                TimeSpan measured = times.Aggregate(TimeSpan.Zero, (sum, t) => sum + t);
                while (measured < MinimumMeasured && times.Count < MaximumRenders)
                {
                    TimeSpan again = c.Render(renderer, scene.Scene, scene.Camera, image).RenderTime;
                    times.Add(again);
                    measured += again;
                }

                ImageError error = ImageError.Measure(image, exact);
                image.Save(Path.Combine(staging, "images", c.FileStem + ".png"));
                HeatMap.Render(ImageError.PerPixel(image, exact), width, height, "levels").Save(Path.Combine(staging, "errors", c.FileStem + ".png"));
                results[i] = new CompareResult(c, stats.PrimaryRays, stats.PrimaryRays / ((double)width * height), Median([.. times]), error, stats.Kernel) { Renders = times.Count, Retimed = times.Count > r.Repeats };
            }
        });
        return (exactStats, results);
    }

    private static TimeSpan Median(TimeSpan[] times)
    {
        Array.Sort(times);
        int m = times.Length / 2;
        return times.Length % 2 == 1 ? times[m] : (times[m - 1] + times[m]) / 2;
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
        SceneDescription d = SceneFile.Load(r.ScenePath);
        return new SceneOverrides(r.Width, r.Height).Prepare(d with { Sampler = d.Sampler with { Type = "exact" } });
    }

    private static string Heading(CompareRequest r, PreparedScene scene, RenderStatistics exact) => string.Create(CultureInfo.InvariantCulture,
        $"{Path.GetFileName(r.ScenePath)}, {scene.Description.Width}×{scene.Description.Height}, {scene.Camera.Name} camera, "
        + $"seed {r.Seed ?? scene.Description.Sampler.Seed}, {(r.Threads is { } t ? $"{t} threads" : $"all {Environment.ProcessorCount} cores")}, "
        + $"time = median of {r.Repeats} render{(r.Repeats == 1 ? "" : "s")}; "
        + $"exact image (ExactRenderer) in {exact.RenderTime.TotalMilliseconds:F0} ms");

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

        return string.Join(' ', parts);
    }

    /// <summary>Moves every file from the staging folder into place, <c>index.html</c> last (each move is a rename).</summary>
    private static void Publish(string staging, string folder)
    {
        string[] files = [.. Directory.EnumerateFiles(staging, "*", SearchOption.AllDirectories)
            .OrderBy(f => Path.GetFileName(f) == "index.html").ThenBy(f => f, StringComparer.Ordinal)];
        // Check every target first, so a file or folder in the way stops the run before anything is moved.
        foreach (string file in files)
        {
            string target = Path.Combine(folder, Path.GetRelativePath(staging, file));
            string parent = Path.GetDirectoryName(target)!;
            if (File.Exists(parent))
            {
                throw new UsageException($"--out: '{parent}' is a file where the report needs a folder");
            }

            if (Directory.Exists(target))
            {
                throw new UsageException($"--out: '{target}' is a folder where the report writes a file");
            }
        }

        foreach (string file in files)
        {
            string target = Path.Combine(folder, Path.GetRelativePath(staging, file));
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.Move(file, target, overwrite: true);
        }
    }

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
