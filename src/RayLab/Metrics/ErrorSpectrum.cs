namespace RayLab.Metrics;

/// <summary>
/// The radially averaged power spectrum of an error image (<see cref="ErrorLocation.Spectrum(Image, Image)"/>):
/// the periodogram in levels², averaged over rings of frequency <see cref="ErrorLocation.RingWidth"/> cycles per
/// pixel wide, and the share of the error's power at low frequencies.
/// </summary>
public sealed class ErrorSpectrum
{
    private readonly double[] _radialMean;

    internal ErrorSpectrum(double[] radialMean, double meanSquare, double lowFrequencyShare)
    {
        _radialMean = radialMean;
        MeanSquare = meanSquare;
        LowFrequencyShare = lowFrequencyShare;
    }

    /// <summary>
    /// The periodogram's mean over ring r, the frequencies with round(|f| / <see cref="ErrorLocation.RingWidth"/>) = r
    /// (|f| in cycles per pixel, up to √½ in the corners), in levels²; NaN for a ring with no frequency (tiny images).
    /// White noise of variance s² is flat at s².
    /// </summary>
    public IReadOnlyList<double> RadialMean => _radialMean;

    /// <summary>The periodogram's mean over every frequency: the mean square error (Parseval), in levels².</summary>
    public double MeanSquare { get; }

    /// <summary>The share of the error's power at |f| ≤ <see cref="ErrorLocation.LowFrequencyLimit"/> (0 … 1; 0 for an error-free image). White noise: about π/64 ≈ 0.049.</summary>
    public double LowFrequencyShare { get; }

    /// <summary>Ring r's centre frequency in cycles per pixel.</summary>
    /// <param name="ring">The ring's number, 0 … <see cref="RadialMean"/>.Count − 1.</param>
    public static double Frequency(int ring) => ring * ErrorLocation.RingWidth;
}
