namespace RayLab.Metrics;

/// <summary>
/// The viewing conditions and the parallelism of <see cref="Flip.Compute(RayLab.Image, RayLab.Image, FlipOptions?)"/>. FLIP is a function of the angle a pixel
/// subtends at the eye: its filters are specified in cycles per degree and scaled by <see cref="PixelsPerDegree"/>.
/// </summary>
public sealed class FlipOptions
{
    /// <summary>The smallest <see cref="PixelsPerDegree"/> accepted.</summary>
    public const double MinPixelsPerDegree = 1;

    /// <summary>The largest <see cref="PixelsPerDegree"/> accepted (the filters grow with it: 1 000 gives filters of 273 taps).</summary>
    public const double MaxPixelsPerDegree = 1000;

    /// <summary>The paper's viewing distance: 0.7 m.</summary>
    public const double DefaultDistanceMeters = 0.7;

    /// <summary>The paper's display width: 0.7 m.</summary>
    public const double DefaultDisplayWidthMeters = 0.7;

    /// <summary>The paper's display width in pixels: 3 840 (a 4K display).</summary>
    public const int DefaultDisplayWidthPixels = 3840;

    private readonly double _pixelsPerDegree = DefaultPixelsPerDegree;
    private readonly int _maxDegreeOfParallelism = -1;

    /// <summary>
    /// The paper's default, ≈ 67.02 pixels per degree: a 0.7 m wide display of 3 840 pixels seen from 0.7 m
    /// (<see cref="ComputePixelsPerDegree"/>).
    /// </summary>
    public static double DefaultPixelsPerDegree { get; } =
        ComputePixelsPerDegree(DefaultDistanceMeters, DefaultDisplayWidthMeters, DefaultDisplayWidthPixels);

    /// <summary>
    /// The observer's pixels per degree of visual angle, <see cref="MinPixelsPerDegree"/>–<see cref="MaxPixelsPerDegree"/>;
    /// <see cref="DefaultPixelsPerDegree"/> unless set.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not finite or outside the range.</exception>
    public double PixelsPerDegree
    {
        get => _pixelsPerDegree;
        init
        {
            if (!double.IsFinite(value) || value < MinPixelsPerDegree || value > MaxPixelsPerDegree)
            {
                throw new ArgumentOutOfRangeException(nameof(PixelsPerDegree), value, $"Pixels per degree must be between {MinPixelsPerDegree} and {MaxPixelsPerDegree}.");
            }

            _pixelsPerDegree = value;
        }
    }

    /// <summary>
    /// The most threads used: −1 (the default) lets the runtime choose, otherwise a count ≥ 1. The result is the
    /// same, bit for bit, at every count.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is neither −1 nor ≥ 1.</exception>
    public int MaxDegreeOfParallelism
    {
        get => _maxDegreeOfParallelism;
        init => _maxDegreeOfParallelism = value == -1 || value >= 1
            ? value
            : throw new ArgumentOutOfRangeException(nameof(MaxDegreeOfParallelism), value, "Use −1 (all cores) or a count ≥ 1.");
    }

    /// <summary>
    /// Options for an observer <paramref name="distanceMeters"/> from a display <paramref name="displayWidthMeters"/>
    /// wide showing <paramref name="displayWidthPixels"/> pixels across.
    /// </summary>
    /// <param name="distanceMeters">The distance from the eye to the display, in metres (&gt; 0).</param>
    /// <param name="displayWidthMeters">The display's width in metres (&gt; 0).</param>
    /// <param name="displayWidthPixels">The display's width in pixels (≥ 1).</param>
    /// <returns>Options with <see cref="PixelsPerDegree"/> from <see cref="ComputePixelsPerDegree"/>.</returns>
    /// <exception cref="ArgumentOutOfRangeException">An argument is out of range, or the pixels per degree it gives is.</exception>
    public static FlipOptions ForDisplay(double distanceMeters, double displayWidthMeters, int displayWidthPixels) =>
        new() { PixelsPerDegree = ComputePixelsPerDegree(distanceMeters, displayWidthMeters, displayWidthPixels) };

    /// <summary>
    /// Pixels per degree of visual angle, as the FLIP paper computes it (small-angle approximation):
    /// d · (pixels / width) · π / 180.
    /// </summary>
    /// <param name="distanceMeters">The distance from the eye to the display, in metres (&gt; 0).</param>
    /// <param name="displayWidthMeters">The display's width in metres (&gt; 0).</param>
    /// <param name="displayWidthPixels">The display's width in pixels (≥ 1).</param>
    /// <returns>The pixels per degree.</returns>
    /// <exception cref="ArgumentOutOfRangeException">An argument is not finite or out of range (the exception names it).</exception>
    public static double ComputePixelsPerDegree(double distanceMeters, double displayWidthMeters, int displayWidthPixels)
    {
        if (!double.IsFinite(distanceMeters) || distanceMeters <= 0)
        {
            throw new ArgumentOutOfRangeException(nameof(distanceMeters), distanceMeters, "The viewing distance must be a positive number of metres.");
        }

        if (!double.IsFinite(displayWidthMeters) || displayWidthMeters <= 0)
        {
            throw new ArgumentOutOfRangeException(nameof(displayWidthMeters), displayWidthMeters, "The display width must be a positive number of metres.");
        }

        ArgumentOutOfRangeException.ThrowIfLessThan(displayWidthPixels, 1);
        return distanceMeters * (displayWidthPixels / displayWidthMeters) * (Math.PI / 180);
    }
}
