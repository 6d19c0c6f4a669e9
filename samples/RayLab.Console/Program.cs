using System.CommandLine;
using System.CommandLine.Help;
using System.Globalization;
using System.Runtime.InteropServices;
using RayLab.Reports.Imaging;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Cli;

/// <summary>
/// The <c>raylab</c> console app. With no arguments it renders the lab's two-sphere scene with both cameras
/// into <c>out/</c>; <c>raylab render SCENE.json -o OUT.png [options]</c> renders one scene.
/// </summary>
public static class Program
{
    /// <summary>The exit code of a run cancelled by Ctrl+C (SIGINT): 128 + 2, as a shell reports a process the signal ended.</summary>
    public const int CancelledExitCode = 130;

    /// <summary>Entry point. Ctrl+C (SIGINT) cancels the render, which leaves no output and exits with <see cref="CancelledExitCode"/>.</summary>
    /// <param name="args">Command-line arguments.</param>
    /// <returns>0 on success, 1 for bad input or a failed render, 2 for a bad command line, 130 when cancelled.</returns>
    public static int Main(string[] args)
    {
        using var cancel = new CancellationTokenSource();
        // The first Ctrl+C asks the render to stop (rows in flight finish, then the job cleans up); a second one,
        // once cancellation is under way, ends the process at once as usual.
        using PosixSignalRegistration interrupt = PosixSignalRegistration.Create(PosixSignal.SIGINT, context =>
        {
            if (!cancel.IsCancellationRequested)
            {
                context.Cancel = true;
                cancel.Cancel();
            }
        });
        return Run(args, Console.Out, Console.Error, cancel.Token);
    }

    /// <summary>Runs the app with the given output writers (tests call this in-process).</summary>
    /// <param name="args">Command-line arguments.</param>
    /// <param name="stdout">Where results go.</param>
    /// <param name="stderr">Where errors go: one line each.</param>
    /// <param name="cancellation">Cancels a render or comparison: it then leaves no output and the run returns <see cref="CancelledExitCode"/>.</param>
    /// <returns>The exit code.</returns>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        ReportsImageFormats.Register(); // .webp for -o and --heatmap
        RootCommand root = BuildCommands(stdout, stderr, cancellation);
        ParseResult parsed = root.Parse(args);
        if (parsed.Errors.Count > 0)
        {
            stderr.WriteLine(SceneFileException.OneLine(CommandLineError.Describe(parsed)));
            return CommandExit.BadCommandLine;
        }

        try
        {
            // Each command's action returns through CommandExit.Run, which turns bad input, cancellation and lack of
            // memory into one line and its code.
            return parsed.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
        }
        catch (Exception e)
        {
            // A bug, not bad input: still one line and no stack trace, but a distinct exit code.
            return CommandExit.Bug(stderr, e);
        }
    }

    private static RootCommand BuildCommands(TextWriter stdout, TextWriter stderr, CancellationToken cancellation)
    {
        // Options override the scene file, so each says what it falls back to: the scene's field, and the value
        // a scene file that omits the field gets (SamplerSettings' defaults, as SceneFile reads them).
        SamplerSettings d = SamplerSettings.Default;
        var scene = new Argument<string>("scene") { Description = "The scene file: JSON with image, camera, spheres, … (see docs/scene-files.md), or the name of a scene raylab carries (see 'raylab scenes')." };
        var output = new Option<string>("--output", "-o") { Description = "The image to write, .png, .bmp, .jpg/.jpeg or .webp (the format follows the extension).", HelpName = "OUT.png", Required = true };
        var camera = new Option<string?>("--camera") { Description = $"{Choices(CameraSettings.Types)}. Default: the scene's camera.type.", HelpName = "TYPE" };
        var sampler = new Option<string?>("--sampler") { Description = $"{Choices(SamplerSettings.Types)}. Default: the scene's sampler.type; {d.Type} if omitted.", HelpName = "NAME" };
        var samples = new Option<int?>("--samples") { Description = $"Samples per pixel, 1 to {SceneFile.MaxSamples}; a perfect square (1, 4, 9, …) for regular, jittered and multijittered. Default: the scene's sampler.samples; {d.Samples} if omitted.", HelpName = "N" };
        var seed = new Option<uint?>("--seed") { Description = $"The sampler's seed, 0 to {uint.MaxValue}. Default: the scene's sampler.seed; {d.Seed} if omitted.", HelpName = "S" };
        var threads = new Option<int?>("--threads") { Description = $"Render threads, ≥ 1. Default: all cores ({Environment.ProcessorCount} here).", HelpName = "T" };
        var width = new Option<int?>("--width") { Description = $"Image width in pixels, 1 to {SceneFile.MaxImageSide}, with W·H·3 ≤ {Image.MaxBytes:N0} bytes. Default: the scene's image.width.", HelpName = "W" };
        var height = new Option<int?>("--height") { Description = $"Image height in pixels, 1 to {SceneFile.MaxImageSide}, with W·H·3 ≤ {Image.MaxBytes:N0} bytes. Default: the scene's image.height.", HelpName = "H" };
        var stats = new Option<string?>("--stats") { Description = "Also write render statistics as JSON (rays, renderMs, encodeMs, …). Default: none.", HelpName = "STATS.json" };
        var minDepth = new Option<int?>("--min-depth") { Description = $"Adaptive: subdivide every pixel at least this deep, 0 to the maximum depth. Default: the scene's sampler.minDepth; {d.MinDepth} if omitted.", HelpName = "M" };
        var maxDepth = new Option<int?>("--max-depth") { Description = $"Adaptive: never subdivide deeper, 0 to {AdaptiveSampler.MaxSupportedDepth}. Default: the scene's sampler.maxDepth; {d.MaxDepth} if omitted.", HelpName = "D" };
        var contrast = new Option<double?>("--contrast") { Description = $"Adaptive: subdivide where a channel differs by more than this, ≥ 0. Default: the scene's sampler.contrast; {d.Contrast.ToString(CultureInfo.InvariantCulture)} if omitted.", HelpName = "C" };
        var quincunx = new Option<bool>("--quincunx") { Description = $"Adaptive: trace every pixel's centre, even where its corners agree (≈ 1 ray per pixel more). Default: the scene's sampler.quincunx; {(d.Quincunx ? "true" : "false")} if omitted." };
        var guard = new Option<bool>("--guard") { Description = $"Adaptive: also refine, down to the maximum depth, every square a sphere's silhouette may cross although its points agree (never loses a small sphere or a sliver). Default: the scene's sampler.guard; {(d.Guard ? "true" : "false")} if omitted." };
        var kernel = new Option<string?>("--kernel") { Description = $"Point samplers and the adaptive sampler's traced points: the render loop, {Choices(RenderJob.Kernels)}; auto takes the widest SIMD packet the CPU runs, scalar is the double-precision reference loop. Default: auto.", HelpName = "KERNEL" };
        var device = new Option<string?>("--device") { Description = $"Point samplers and adaptive (plain and guarded): where the render runs, {Choices(DeviceChoice.Names)}; gpu is the first CUDA GPU (an error where there is none), auto the GPU where there is one, else the CPU. Same bytes (and heat map) on each; exact renders on the CPU. Not in the native build. Default: cpu.", HelpName = "DEVICE" };
        var heatmap = new Option<string?>("--heatmap") { Description = "Also write the primary rays spent per pixel as an image with a legend, .png, .bmp, .jpg/.jpeg or .webp. Default: none.", HelpName = "HEAT.png" };
        var warmup = new Option<bool>("--warmup") { Description = "For timing: render the scene scaled down first and commit the image's memory, so that the render's time (printed, and the stats file's renderMs) leaves out JIT compilation and page faults; the stats file gives them as warmupMs and commitMs. Default: off, the render is done once." };
        var quality = new Option<int?>("--quality") { Description = $"JPEG and WebP quality, 0 to 100 (higher keeps more detail in a larger file); PNG and BMP are lossless and ignore it. Default: {ImageFormats.DefaultQuality}.", HelpName = "Q" };

        var render = new Command("render", "Render a scene file into an image.")
        {
            scene, output, camera, sampler, samples, seed, minDepth, maxDepth, contrast, quincunx, guard, width, height, threads, kernel, device, stats, warmup, heatmap, quality,
        };
        render.SetAction(result => RenderJob.Run(
            new RenderRequest(
                result.GetRequiredValue(scene),
                result.GetRequiredValue(output),
                result.GetValue(camera),
                result.GetValue(sampler),
                result.GetValue(samples),
                result.GetValue(seed),
                result.GetValue(threads),
                result.GetValue(width),
                result.GetValue(height),
                result.GetValue(stats),
                result.GetValue(minDepth),
                result.GetValue(maxDepth),
                result.GetValue(contrast),
                result.GetValue(heatmap),
                result.GetValue(kernel),
                result.GetValue(quincunx),
                result.GetValue(guard),
                result.GetValue(quality),
                result.GetValue(warmup),
                result.GetValue(device)),
            stdout,
            stderr,
            cancellation));

        var compare = CompareCommand.Create(stdout, stderr, cancellation);
        var scenes = new Command("scenes", "List the scenes raylab carries; render one by name from any folder: raylab render two-spheres -o out.png.");
        scenes.SetAction(_ => CarriedScenes.List(stdout, stderr));
        var patterns = PatternsCommand.Create(stdout, stderr, cancellation);
        var chart = ChartCommand.Create(stdout, stderr);
        var flip = FlipCommand.Create(stdout, stderr);
        var grade = GradeCommand.Create(stdout, stderr, cancellation);

        var root = new RootCommand(
            "RayLab: the photorealistic-rendering lab's ray tracer. With no command, renders the two-sphere scene "
            + "with the orthographic and the perspective camera, adaptive antialiasing, into out/ (with heat maps). "
            + "'raylab render --help' lists the options of a render.")
        {
            render, compare, flip, scenes, patterns, chart, grade,
        };
        root.HelpName = "raylab"; // not the host's name (dotnet, testhost) in the usage lines
        root.SetAction(_ => RenderJob.RunDefault(stdout, stderr, cancellation));

        // Help wraps at the terminal's width, else at 80 columns (the parser's default for redirected output is one long line).
        if (root.Options.OfType<HelpOption>().FirstOrDefault()?.Action is HelpAction help)
        {
            help.MaxWidth = ProgressDisplay.IsTerminal(stdout) ? Math.Max(Console.WindowWidth, 40) : 80;
        }

        return root;
    }

    private static string Choices(IReadOnlyList<string> names) => $"{string.Join(", ", names.SkipLast(1))} or {names[^1]}";
}
