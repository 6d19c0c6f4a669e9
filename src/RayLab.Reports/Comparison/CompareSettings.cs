
namespace RayLab.Reports.Comparison;

/// <summary>How <see cref="CompareRunner"/> renders and times the settings.</summary>
/// <param name="Repeats">Renders per setting; the time is their median (more where they are too quick to time, see <see cref="CompareRunner.MinimumMeasured"/>).</param>
/// <param name="Renderer">The renderer (threads, row progress, cancellation); null for one on all cores.</param>
/// <param name="Progress">Told about each counted render; null for none.</param>
public sealed record CompareSettings(int Repeats = 3, Renderer? Renderer = null, ICompareProgress? Progress = null)
{
    /// <summary>Where the stages' times are recorded (<see cref="CompareClock"/>); null for a clock of the run's own, not shown.</summary>
    public CompareClock? Clock { get; init; }
}
