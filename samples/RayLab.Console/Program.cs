using System.CommandLine;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Cli;

/// <summary>
/// The <c>raylab</c> console app. With no arguments it renders the lab's two-sphere scene with both cameras
/// into <c>out/</c>; <c>raylab render SCENE.json -o OUT.png [options]</c> renders one scene.
/// </summary>
public static class Program
{
    /// <summary>Entry point.</summary>
    /// <param name="args">Command-line arguments.</param>
    /// <returns>0 on success, 1 for bad input or a failed render, 2 for a bad command line.</returns>
    public static int Main(string[] args) => Run(args, Console.Out, Console.Error);

    /// <summary>Runs the app with the given output writers (tests call this in-process).</summary>
    /// <param name="args">Command-line arguments.</param>
    /// <param name="stdout">Where results go.</param>
    /// <param name="stderr">Where errors go: one line each.</param>
    /// <returns>The exit code.</returns>
    public static int Run(string[] args, TextWriter stdout, TextWriter stderr)
    {
        RootCommand root = BuildCommands(stdout, stderr);
        ParseResult parsed = root.Parse(args);
        if (parsed.Errors.Count > 0)
        {
            stderr.WriteLine(CommandLineError.Describe(parsed));
            return 2;
        }

        try
        {
            return parsed.Invoke(new InvocationConfiguration { Output = stdout, Error = stderr, EnableDefaultExceptionHandler = false });
        }
        catch (Exception e)
        {
            // A bug, not bad input: still one line and no stack trace, but a distinct exit code.
            stderr.WriteLine($"raylab: internal error: {e.GetType().Name}: {e.Message}");
            return 70;
        }
    }

    private static RootCommand BuildCommands(TextWriter stdout, TextWriter stderr)
    {
        var scene = new Argument<string>("scene") { Description = "The scene file (JSON; see the README for its fields)." };
        var output = new Option<string>("--output", "-o") { Description = "The image to write; the format follows the extension (.png, .bmp).", Required = true };
        var camera = new Option<string?>("--camera") { Description = "Override the scene's camera type.", HelpName = string.Join('|', CameraSettings.Types) };
        var sampler = new Option<string?>("--sampler") { Description = "Override the scene's sampler.", HelpName = string.Join('|', SamplerSettings.Types) };
        var samples = new Option<int?>("--samples") { Description = "Samples per pixel, ≥ 1 (a perfect square for regular and jittered).", HelpName = "N" };
        var seed = new Option<uint?>("--seed") { Description = "The sampler's seed, 0 to 4294967295.", HelpName = "S" };
        var threads = new Option<int?>("--threads") { Description = "Render threads, ≥ 1 (default: all cores).", HelpName = "T" };
        var width = new Option<int?>("--width") { Description = "Override the image width, ≥ 1.", HelpName = "W" };
        var height = new Option<int?>("--height") { Description = "Override the image height, ≥ 1.", HelpName = "H" };
        var stats = new Option<string?>("--stats") { Description = "Also write render statistics as JSON (rays, renderMs, encodeMs, …).", HelpName = "STATS.json" };
        var minDepth = new Option<int?>("--min-depth") { Description = $"Adaptive: subdivide every pixel at least this deep, 0 to the maximum depth (default 0).", HelpName = "M" };
        var maxDepth = new Option<int?>("--max-depth") { Description = $"Adaptive: never subdivide deeper, 0 to {AdaptiveSampler.MaxSupportedDepth} (default 3).", HelpName = "D" };
        var contrast = new Option<double?>("--contrast") { Description = "Adaptive: split where values differ by more than this in a channel, ≥ 0 (default 0.1).", HelpName = "C" };
        var kernel = new Option<string?>("--kernel") { Description = "Point samplers: the render loop; auto (default) takes the widest SIMD packet the CPU runs, scalar the double-precision reference loop.", HelpName = string.Join('|', RenderJob.Kernels) };
        var quincunx = new Option<bool>("--quincunx") { Description = "Adaptive: trace every pixel's centre, even where its corners agree (≈ 1 ray per pixel more)." };
        var heatmap = new Option<string?>("--heatmap") { Description = "Also write the primary rays spent per pixel as a picture with a legend (.png, .bmp).", HelpName = "HEAT.png" };

        var render = new Command("render", "Render a scene file into an image.")
        {
            scene, output, camera, sampler, samples, seed, threads, width, height, stats, minDepth, maxDepth, contrast, quincunx, heatmap, kernel,
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
                result.GetValue(quincunx)),
            stdout,
            stderr));

        var root = new RootCommand(
            "RayLab: the photorealistic-rendering lab's ray tracer. With no command, renders the two-sphere scene "
            + "with the orthographic and the perspective camera, adaptive antialiasing, into out/ (with heat maps).")
        {
            render,
        };
        root.SetAction(_ => RenderJob.RunDefault(stdout, stderr));
        return root;
    }
}
