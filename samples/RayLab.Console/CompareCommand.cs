using System.CommandLine;
using RayLab.Reports.Comparison;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab compare SCENE.json --out DIR [--budgets 1,4,16,64,256,1024] [--repeats R] [--samplers …]
/// [--max-depths …] [--contrasts …] [--seed S] [--threads T] [--width W] [--height H] [--device D] [--stats FILE]</c>.
/// </summary>
public static class CompareCommand
{
    /// <summary>Builds the command; its action runs <see cref="CompareJob.Run"/> with these writers.</summary>
    /// <param name="stdout">Where the table goes.</param>
    /// <param name="stderr">Where errors go.</param>
    /// <param name="cancellation">Cancels the comparison (Ctrl+C).</param>
    public static Command Create(TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        var scene = new Argument<string>("scene") { Description = "The scene file, or the name of a scene raylab carries (its camera and size; its sampler is ignored)." };
        var seed = new Option<uint?>("--seed") { Description = "The samplers' seed, 0 to 4294967295 (default: the scene's).", HelpName = "S" };
        var threads = new Option<int?>("--threads") { Description = "Render threads, ≥ 1 (default: all cores).", HelpName = "T" };
        var width = new Option<int?>("--width") { Description = "Override the image width, ≥ 1.", HelpName = "W" };
        var height = new Option<int?>("--height") { Description = "Override the image height, ≥ 1.", HelpName = "H" };
        var output = new Option<string>("--out") { Description = "The folder for the report (created, with its parents, if missing).", Required = true, HelpName = "DIR" };
        var budgets = new Option<string>("--budgets") { Description = "Samples per pixel for the point samplers, 1 to 65536 each, comma-separated (grid samplers use the nearest square below).", DefaultValueFactory = _ => CompareRequest.DefaultBudgets };
        var repeats = new Option<int>("--repeats") { Description = "Renders per setting; the time is their median.", DefaultValueFactory = _ => 3, HelpName = "R" };
        var samplers = new Option<string?>("--samplers") { Description = "The samplers to compare, comma-separated (default: all).", HelpName = string.Join(',', ComparePlan.Compared) };
        var maxDepths = new Option<string>("--max-depths") { Description = "Adaptive: the maximum depths, comma-separated.", DefaultValueFactory = _ => CompareRequest.DefaultMaxDepths };
        var contrasts = new Option<string>("--contrasts") { Description = "Adaptive: the contrasts, comma-separated (one chart line each).", DefaultValueFactory = _ => CompareRequest.DefaultContrasts };
        var device = new Option<string?>("--device") { Description = "Where the renders run: cpu, gpu or auto (as raylab render --device). The device's kernels are compiled once, before the renders; that first launch's time is reported apart. Not in the native build. Default: cpu.", HelpName = "DEVICE" };
        var stats = new Option<string?>("--stats") { Description = "Also write where the time went (each stage's wall time) as JSON. Default: none.", HelpName = "STATS.json" };
        var compare = new Command("compare", "Render a scene with every sampler over a range of budgets, measure each against the exact image, and write a report (table, charts, images).")
        {
            scene, output, budgets, repeats, samplers, maxDepths, contrasts, seed, threads, width, height, device, stats,
        };
        compare.SetAction(result => CompareJob.Run(
            new CompareRequest(
                result.GetRequiredValue(scene),
                result.GetRequiredValue(output),
                result.GetRequiredValue(budgets),
                result.GetRequiredValue(repeats),
                result.GetValue(samplers),
                result.GetRequiredValue(maxDepths),
                result.GetRequiredValue(contrasts),
                result.GetValue(seed),
                result.GetValue(threads),
                result.GetValue(width),
                result.GetValue(height),
                StatsPath: result.GetValue(stats),
                Device: result.GetValue(device)),
            stdout,
            stderr,
            cancellation));
        return compare;
    }
}
