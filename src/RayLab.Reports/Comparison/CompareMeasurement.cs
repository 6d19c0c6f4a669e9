
namespace RayLab.Reports.Comparison;

/// <summary>What <see cref="CompareRunner.Measure"/> found: the exact reference's render and one result per setting.</summary>
/// <param name="Exact">The exact image's render (its time goes in the report's heading).</param>
/// <param name="Results">The settings' results, in the order they were given.</param>
public sealed record CompareMeasurement(RenderStatistics Exact, IReadOnlyList<CompareResult> Results);
