using RayLab.Reports.Comparison;

namespace RayLab.Cli;

/// <summary>The parsed <c>raylab compare</c> command line; lists are still text, checked by <see cref="CompareJob"/>.</summary>
/// <param name="ScenePath">The scene file.</param>
/// <param name="OutputFolder">The folder that receives the report.</param>
/// <param name="Budgets">Samples per pixel for the point samplers, comma-separated.</param>
/// <param name="Repeats">Renders per setting; the time is their median.</param>
/// <param name="Samplers">The samplers to compare, comma-separated (point sampler names and <c>adaptive</c>).</param>
/// <param name="MaxDepths">The adaptive sampler's maximum depths, comma-separated.</param>
/// <param name="Contrasts">The adaptive sampler's contrasts, comma-separated: one line on the chart each.</param>
/// <param name="Seed">Seed override.</param>
/// <param name="Threads">Thread count.</param>
/// <param name="Width">Width override.</param>
/// <param name="Height">Height override.</param>
/// <param name="StatsPath">Where to write where the time went, as JSON (<see cref="CompareStatsFile"/>); null for nowhere.</param>
/// <param name="Device">Where the renders run, <c>cpu</c>, <c>gpu</c> or <c>auto</c> (as <c>raylab render --device</c>); null for the CPU.</param>
/// <param name="Methods">
/// Methods of your own, rendered and measured beside the built-in ones (<see cref="CompareCase.Sampled"/> for a point
/// sampler, <see cref="CompareCase.Custom"/> for a pixel method); the console passes none.
/// </param>
public sealed record CompareRequest(
    string ScenePath, string OutputFolder, string Budgets = CompareRequest.DefaultBudgets, int Repeats = 3,
    string? Samplers = null, string MaxDepths = CompareRequest.DefaultMaxDepths, string Contrasts = CompareRequest.DefaultContrasts,
    uint? Seed = null, int? Threads = null, int? Width = null, int? Height = null, IReadOnlyList<CompareCase>? Methods = null,
    string? StatsPath = null, string? Device = null)
{
    /// <summary>The default budgets: powers of 4 from 1 to 1024 (all perfect squares).</summary>
    public const string DefaultBudgets = "1,4,16,64,256,1024";

    /// <summary>The default adaptive maximum depths.</summary>
    public const string DefaultMaxDepths = "0,1,2,3,4,5,6";

    /// <summary>The default adaptive contrasts.</summary>
    public const string DefaultContrasts = "0.01,0.1,0.5";
}
