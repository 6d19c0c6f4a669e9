using System.Diagnostics;
using System.Globalization;
using System.Runtime.CompilerServices;
using System.Text.Json;
using RayLab.Reports.Imaging;
using RayLab.Scenes;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>One render from a scene file to an image file, with the console's checks and messages.</summary>
public static class RenderJob
{
    /// <summary>The scene the no-argument run renders (copied beside the app).</summary>
    public static string DefaultScenePath => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    /// <summary>
    /// The no-argument run: the two-sphere scene with the orthographic and the perspective camera and the scene's
    /// adaptive sampler, into <c>out/two-spheres-orthographic.png</c> and <c>out/two-spheres-perspective.png</c>,
    /// with the heat maps <c>out/two-spheres-{camera}-heatmap.png</c>.
    /// </summary>
    /// <param name="stdout">Where the summary lines go.</param>
    /// <param name="stderr">Where errors go.</param>
    /// <param name="cancellation">Cancels the renders (Ctrl+C).</param>
    /// <returns>The exit code.</returns>
    public static int RunDefault(TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        int created = CommandExit.Run(
            stderr,
            () =>
            {
                if (File.Exists("out"))
                {
                    throw new UsageException($"out: '{Path.GetFullPath("out")}' is a file; the pictures go into a folder of that name");
                }

                Directory.CreateDirectory("out");
                return CommandExit.Done;
            },
            cancelled: "nothing written",
            tooLarge: "create the folder out",
            cancellation);
        if (created != CommandExit.Done)
        {
            return created;
        }

        foreach (string camera in CameraSettings.Types.Reverse())
        {
            var request = new RenderRequest(DefaultScenePath, Path.Combine("out", $"two-spheres-{camera}.png"), Camera: camera,
                HeatmapPath: Path.Combine("out", $"two-spheres-{camera}-heatmap.png"));
            int code = Run(request, stdout, stderr, cancellation);
            if (code != 0)
            {
                return code;
            }
        }

        return 0;
    }

    /// <summary>Runs one render; prints one summary line, or one error line and returns non-zero.</summary>
    /// <param name="request">What to render.</param>
    /// <param name="stdout">Where the summary goes.</param>
    /// <param name="stderr">Where errors go.</param>
    /// <param name="cancellation">Cancels the render: no file is written and the result is <see cref="Program.CancelledExitCode"/>.</param>
    /// <returns>0 on success, 1 on bad input or a failed render, 130 when cancelled.</returns>
    public static int Run(RenderRequest request, TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        return CommandExit.Run(
            stderr,
            () =>
            {
                RunOrThrow(request, stdout, stderr, cancellation);
                return CommandExit.Done;
            },
            cancelled: $"{request.OutputPath} not written",
            tooLarge: $"render {request.ScenePath} at the requested size",
            cancellation);
    }

    private static void RunOrThrow(RenderRequest request, TextWriter stdout, TextWriter stderr, CancellationToken cancellation)
    {
        if (string.IsNullOrWhiteSpace(request.ScenePath))
        {
            throw new UsageException("scene: the path is empty");
        }

        CheckOutputPath(request.OutputPath, "--output", requireImageFormat: true);
        if (request.StatsPath is not null)
        {
            CheckOutputPath(request.StatsPath, "--stats", requireImageFormat: false);
            CheckDistinct(request.StatsPath, "--stats", request.OutputPath, "--output");
        }

        if (request.HeatmapPath is not null)
        {
            CheckOutputPath(request.HeatmapPath, "--heatmap", requireImageFormat: true);
            CheckDistinct(request.HeatmapPath, "--heatmap", request.OutputPath, "--output");
            if (request.StatsPath is not null)
            {
                CheckDistinct(request.HeatmapPath, "--heatmap", request.StatsPath, "--stats");
            }
        }

        if (request.Quality is < 0 or > 100)
        {
            throw new UsageException($"--quality: {request.Quality} is out of range; expected 0 to 100");
        }

        CheckChoice(request.Camera, "--camera", "camera", CameraSettings.Types);
        CheckChoice(request.Sampler, "--sampler", "sampler", SamplerSettings.Types);
        CheckChoice(request.Kernel, "--kernel", "kernel", Kernels);
        DeviceChoice.Check(request.Device);

        if (request.Threads is < 1)
        {
            throw new UsageException($"--threads: must be at least 1, got {request.Threads}");
        }

        PreparedScene prepared = request.Overrides.Prepare(SceneFile.Load(CarriedScenes.Resolve(request.ScenePath)));
        foreach (string notice in NoticesFor(request, prepared.Description.Sampler))
        {
            stderr.WriteLine($"raylab: note: {notice}");
        }

        Image image = prepared.CreateImage();
        float[]? raysPerPixel = request.HeatmapPath is null ? null : new float[(long)image.Width * image.Height];
        var progress = new RenderProgress();
        var renderer = new Renderer
        {
            MaxDegreeOfParallelism = request.Threads ?? -1, Kernel = ParseKernel(request.Kernel), Progress = progress, CancellationToken = cancellation,
            Device = DeviceChoice.Open(request.Device),
        };
        // The measurement harness, only when asked for (--warmup; the timing tools pass it): a smaller render of the
        // same scene first, so that renderMs is the render and not the JIT compiling it (the native anchors are
        // compiled ahead of time too); its time is reported as warmupMs. It is the same picture scaled down, so it
        // meets the same edges and compiles the paths the render takes there. Then the image's memory is committed
        // before the clock, as the anchors' zero-filled buffer is (commitMs). Without --warmup the render is done
        // once, as asked, whether or not --stats reports it, and the printed time says what it includes.
        double? warmupMs = null;
        double? commitMs = null;
        if (request.Warmup)
        {
            var warmupClock = Stopwatch.StartNew();
            prepared.Render(renderer, WarmupImage(image.Width, image.Height, WarmupCostPerPixel(prepared.Description.Sampler)), null);
            warmupMs = warmupClock.Elapsed.TotalMilliseconds;

            var commitClock = Stopwatch.StartNew();
            CommitPages(image, request.Threads ?? Environment.ProcessorCount);
            commitMs = commitClock.Elapsed.TotalMilliseconds;
        }

        RenderStatistics stats;
        using (ProgressDisplay.ForTerminal(stdout, progress, Path.GetFileName(request.OutputPath)))
        {
            stats = prepared.Render(renderer, image, raysPerPixel);
        }

        // A request that came as the last row finished still stops the job; once writing starts, it completes.
        cancellation.ThrowIfCancellationRequested();

        // Every file is written or none, and a file the run would replace keeps its bytes unless every output is
        // written: each goes to a temporary file first, and they are moved into place together. When the heat map or
        // the stats cannot be written (a full disk, say), the error names the option whose file failed.
        double encodeMs;
        using (var outputs = new OutputFiles())
        {
            var encodeClock = Stopwatch.StartNew();
            int quality = request.Quality ?? ImageFormats.DefaultQuality;
            outputs.Write(request.OutputPath, "--output", stream => image.Save(stream, ImageFormat.FromPath(request.OutputPath), quality));
            encodeMs = encodeClock.Elapsed.TotalMilliseconds;
            if (raysPerPixel is not null)
            {
                outputs.Write(request.HeatmapPath!, "--heatmap",
                    stream => HeatMap.Render(raysPerPixel, image.Width, image.Height).Save(stream, ImageFormat.FromPath(request.HeatmapPath!), quality));
            }

            if (request.StatsPath is not null)
            {
                outputs.Write(request.StatsPath, "--stats", stream => stream.Write(StatsJson(request, prepared, stats, commitMs, encodeMs, warmupMs)));
            }

            outputs.Commit();
        }

        stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{request.OutputPath}: {image.Width}×{image.Height}, {prepared.Camera.Name} camera, {prepared.SamplerDescription}, "
            + $"{stats.PrimaryRays:N0} rays ({stats.PrimaryRays / ((double)image.Width * image.Height):F2}/px), render {stats.RenderTime.TotalMilliseconds:F1} ms ({stats.RaysPerSecond / 1e6:F1} Mrays/s{RenderTimeNote(warmupMs, RuntimeFeature.IsDynamicCodeCompiled)}), encode {encodeMs:F1} ms"));
    }

    /// <summary>What the printed render time includes beyond the render: nothing in the native build; JIT compilation under the JIT, unless a warm-up render ran first.</summary>
    /// <param name="warmupMs">The warm-up render's time, when one ran.</param>
    /// <param name="jit">Whether code is compiled at run time (the JIT build, not Native AOT).</param>
    /// <returns>"" or "; " and the note.</returns>
    public static string RenderTimeNote(double? warmupMs, bool jit) => warmupMs switch
    {
        double ms => string.Create(CultureInfo.InvariantCulture, $"; after a {ms:F1} ms warm-up render"),
        null when jit => "; JIT build: includes compiling what this run had not run before",
        null => "",
    };

    /// <summary>
    /// Commits the image's memory before the render's clock starts, as the anchors' zero-filled buffer is: the first
    /// write to each 4 KiB page of a fresh array costs a page fault (a few µs each on the lab's VM: milliseconds for a
    /// 1080p image; <c>--stats</c>' <c>commitMs</c>, docs/performance.md), so the pages are touched on every render
    /// thread at once, each clearing its own slice. It also starts the thread-pool threads the render will use, outside
    /// <c>renderMs</c>.
    /// </summary>
    private static void CommitPages(Image image, int threads)
    {
        long length = image.PixelBytes.Length;
        int slices = (int)Math.Clamp(length / CommitSliceBytes, 1, threads);
        if (slices == 1)
        {
            image.PixelBytes.Clear();
            return;
        }

        Parallel.For(0, slices, new ParallelOptions { MaxDegreeOfParallelism = slices }, slice =>
        {
            long start = length * slice / slices;
            long end = length * (slice + 1) / slices;
            image.PixelBytes[(int)start..(int)end].Clear();
        });
    }

    /// <summary>The least memory worth a thread of its own when committing the image: 1 MiB.</summary>
    private const long CommitSliceBytes = 1 << 20;

    internal static void CheckChoice(string? value, string option, string what, IReadOnlyList<string> allowed)
    {
        if (value is not null && !allowed.Contains(value, StringComparer.Ordinal))
        {
            throw new UsageException(
                $"{option}: unknown {what} '{value}'; expected one of: {string.Join(", ", allowed)}{Suggestions.DidYouMean(value, allowed)}");
        }
    }

    private static void CheckDistinct(string path, string option, string other, string otherOption)
    {
        if (string.Equals(Path.GetFullPath(path), Path.GetFullPath(other), StringComparison.Ordinal))
        {
            throw new UsageException($"{option}: '{path}' is the same file as {otherOption}");
        }
    }

    internal static void CheckOutputPath(string path, string option, bool requireImageFormat)
    {
        if (string.IsNullOrWhiteSpace(path))
        {
            throw new UsageException($"{option}: the path is empty");
        }

        if (requireImageFormat)
        {
            try
            {
                ImageFormat.FromPath(path);
            }
            catch (NotSupportedException e)
            {
                throw new UsageException($"{option}: {e.Message}");
            }
        }

        string folder;
        try
        {
            folder = Path.GetDirectoryName(Path.GetFullPath(path)) ?? ".";
        }
        catch (Exception e) when (e is ArgumentException or NotSupportedException or PathTooLongException)
        {
            throw new UsageException($"{option}: '{path}' is not a usable path: {e.Message}");
        }

        if (!Directory.Exists(folder))
        {
            throw new UsageException($"{option}: the folder '{folder}' does not exist");
        }

        if (Directory.Exists(path))
        {
            throw new UsageException($"{option}: '{path}' is a folder, not a file");
        }

        // Found now, not after the render: a folder this user cannot write in (read-only, or /proc).
        OutputFolders.Probe(option, folder);
    }

    /// <summary>The kernel names the console accepts, as <see cref="RenderKernel"/> values in lower case.</summary>
    public static IReadOnlyList<string> Kernels { get; } = [.. Enum.GetNames<RenderKernel>().Select(n => n.ToLowerInvariant())];

    private static RenderKernel ParseKernel(string? name) =>
        name is null ? RenderKernel.Auto : Enum.Parse<RenderKernel>(name, ignoreCase: true);

    /// <summary>
    /// The warm-up's image: the render's, scaled down by a whole factor until it takes at most
    /// <see cref="WarmupSamples"/> samples (the whole image when it is that small already).
    /// </summary>
    /// <param name="width">The render's width in pixels.</param>
    /// <param name="height">The render's height in pixels.</param>
    /// <param name="samplesPerPixel">The render's rays per pixel (<see cref="WarmupCostPerPixel"/>).</param>
    /// <returns>A new image for the warm-up render.</returns>
    public static Image WarmupImage(int width, int height, int samplesPerPixel)
    {
        double samples = (double)width * height * samplesPerPixel;
        int factor = (int)Math.Max(1, Math.Ceiling(Math.Sqrt(samples / WarmupSamples)));
        return new Image(Math.Max(1, width / factor), Math.Max(1, height / factor));
    }

    /// <summary>
    /// The rays per pixel the warm-up is sized by: the point sampler's samples; for the adaptive sampler the
    /// rays every pixel takes at its minimum depth (about 4^(minDepth + 1): corners and centres) times 4 for its edge
    /// pixels, 4^(minDepth + 2); 1 for the exact reference. So an adaptive warm-up costs about as much as a point
    /// sampler's (at most a sixteenth of a 1080p picture at the defaults), never the whole picture again.
    /// </summary>
    /// <param name="sampler">The render's sampler settings.</param>
    /// <returns>Rays per pixel, at least 1.</returns>
    public static int WarmupCostPerPixel(SamplerSettings sampler)
    {
        ArgumentNullException.ThrowIfNull(sampler);
        return sampler.IsAdaptive ? 1 << (2 * (Math.Min(sampler.MinDepth, 10) + 2))
            : sampler.IsExact ? 1
            : Math.Max(1, sampler.Samples);
    }

    /// <summary>One line for each option given that the chosen sampler does not use (the render goes on without it).</summary>
    /// <param name="request">The options.</param>
    /// <param name="sampler">The sampler settings the render uses.</param>
    /// <returns>The notices, none when every option applies.</returns>
    public static IEnumerable<string> NoticesFor(RenderRequest request, SamplerSettings sampler)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(sampler);
        if (request.Samples is not null && (sampler.IsAdaptive || sampler.IsExact))
        {
            yield return $"--samples does not apply to the {sampler.Type} sampler (ignored)";
        }

        if (!sampler.IsAdaptive)
        {
            foreach ((bool given, string option) in new[]
            {
                (request.MinDepth is not null, "--min-depth"), (request.MaxDepth is not null, "--max-depth"),
                (request.Contrast is not null, "--contrast"), (request.Quincunx, "--quincunx"), (request.Guard, "--guard"),
            })
            {
                if (given)
                {
                    yield return $"{option} applies to the adaptive sampler only, not {sampler.Type} (ignored)";
                }
            }
        }
    }

    /// <summary>The most samples the warm-up render takes: about 1/16 of the 1080p, 16 spp benchmark.</summary>
    public const double WarmupSamples = 1 << 21;

    private static byte[] StatsJson(RenderRequest request, PreparedScene prepared, RenderStatistics stats, double? commitMs, double encodeMs, double? warmupMs)
    {
        SamplerSettings sampler = prepared.Description.Sampler;
        var json = new RenderStatsFile
        {
            Scene = request.ScenePath,
            Output = request.OutputPath,
            Width = prepared.Description.Width,
            Height = prepared.Description.Height,
            Camera = prepared.Camera.Name,
            Sampler = prepared.SamplerName,
            SamplesPerPixel = prepared.SamplesPerPixel,
            Seed = sampler.IsAdaptive || sampler.IsExact ? 0 : sampler.Seed,
            MinDepth = sampler.IsAdaptive ? sampler.MinDepth : null,
            MaxDepth = sampler.IsAdaptive ? sampler.MaxDepth : null,
            Contrast = sampler.IsAdaptive ? sampler.Contrast : null,
            Quincunx = sampler.IsAdaptive ? sampler.Quincunx : null,
            Guard = sampler.IsAdaptive ? sampler.Guard : null,
            RaysPerPixel = stats.PrimaryRays / ((double)prepared.Description.Width * prepared.Description.Height),
            Threads = request.Threads ?? Environment.ProcessorCount,
            Rays = stats.PrimaryRays,
            RenderMs = stats.RenderTime.TotalMilliseconds,
            WarmupMs = warmupMs,
            CommitMs = commitMs,
            EncodeMs = encodeMs,
            Kernel = stats.Kernel.ToString().ToLowerInvariant(),
            RetracedSamples = stats.RetracedSamples,
            ScalarReason = stats.ScalarReason,
            Device = stats.Device ?? "cpu",
        };
        return System.Text.Encoding.UTF8.GetBytes(JsonSerializer.Serialize(json, RenderStatsJson.Default.RenderStatsFile) + Environment.NewLine);
    }

}
