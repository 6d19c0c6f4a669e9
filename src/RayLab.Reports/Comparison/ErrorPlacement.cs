using RayLab.Metrics;

namespace RayLab.Reports.Comparison;

/// <summary>Where an image's error sits, by <see cref="ErrorLocation"/>'s two measures.</summary>
/// <param name="LowPass1">The RMSE in levels after a Gaussian blur of σ = 1 pixel.</param>
/// <param name="LowPass2">The RMSE in levels after a Gaussian blur of σ = 2 pixels.</param>
/// <param name="Spectrum">The error's radially averaged power spectrum.</param>
public sealed record ErrorPlacement(double LowPass1, double LowPass2, ErrorSpectrum Spectrum)
{
    /// <summary>Measures <paramref name="image"/> against <paramref name="exact"/>.</summary>
    /// <param name="image">The image.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <returns>The two low-pass errors and the spectrum.</returns>
    public static ErrorPlacement Measure(Image image, Image exact) => Measure(image, exact, -1);

    /// <summary>Measures <paramref name="image"/> against <paramref name="exact"/> on up to <paramref name="maxDegreeOfParallelism"/> threads (the same result at any count).</summary>
    /// <param name="image">The image.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <param name="maxDegreeOfParallelism">−1 for every core, or ≥ 1.</param>
    /// <returns>The two low-pass errors and the spectrum.</returns>
    public static ErrorPlacement Measure(Image image, Image exact, int maxDegreeOfParallelism) => new(
        ErrorLocation.LowPassRmse(image, exact, 1, maxDegreeOfParallelism), ErrorLocation.LowPassRmse(image, exact, 2, maxDegreeOfParallelism),
        ErrorLocation.Spectrum(image, exact, maxDegreeOfParallelism));
}
