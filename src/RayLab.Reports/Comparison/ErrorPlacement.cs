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
    public static ErrorPlacement Measure(Image image, Image exact) => new(
        ErrorLocation.LowPassRmse(image, exact, 1), ErrorLocation.LowPassRmse(image, exact, 2), ErrorLocation.Spectrum(image, exact));
}
