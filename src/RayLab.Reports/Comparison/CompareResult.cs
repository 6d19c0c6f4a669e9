
namespace RayLab.Reports.Comparison;

/// <summary>What a comparison measured for one setting.</summary>
/// <param name="Case">The setting.</param>
/// <param name="Rays">Primary rays traced by one render.</param>
/// <param name="RaysPerPixel">Rays divided by W·H.</param>
/// <param name="Time">The median render time of the renders (the render loop only).</param>
/// <param name="Error">The image's error against the exact image.</param>
/// <param name="Kernel">The render loop that ran (packet or scalar).</param>
public sealed record CompareResult(CompareCase Case, long Rays, double RaysPerPixel, TimeSpan Time, ImageError Error, RenderKernel Kernel)
{
    /// <summary>How many renders <see cref="Time"/> is the median of: the repeats asked for, one where the first took <see cref="CompareRunner.LongRender"/> or more, or more where they were too quick to time.</summary>
    public int Renders { get; init; } = 1;

    /// <summary>True when the setting was rendered again past the repeats asked for because its renders were too quick to time.</summary>
    public bool Retimed { get; init; }

    /// <summary>
    /// The image's mean FLIP against the exact image (<see cref="RayLab.Metrics.Flip"/>, LDR, the paper's viewing
    /// conditions), 0 to 1; null where it was not measured.
    /// </summary>
    public double? MeanFlip { get; init; }

    /// <summary>
    /// Where the error sits (<see cref="RayLab.Metrics.ErrorLocation"/>): the RMSE after a Gaussian blur of σ = 1 and
    /// σ = 2 pixels, and the error spectrum with its low-frequency share; null where it was not measured.
    /// </summary>
    public ErrorPlacement? Placement { get; init; }

    /// <summary>True when the setting's first render took <see cref="CompareRunner.LongRender"/> or more and was its only one (fewer than the repeats asked for).</summary>
    public bool TimedOnce { get; init; }
}
