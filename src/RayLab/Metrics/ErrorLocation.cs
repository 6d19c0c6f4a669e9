using System.Buffers;
using System.Numerics;

namespace RayLab.Metrics;

/// <summary>
/// Where in the picture an image's error sits, from its signed error against the exact image: per pixel and channel,
/// the image's 8-bit level minus the exact image's (<see cref="EightBit.Level"/>), as <see cref="ImageError"/>
/// counts them. RMSE cannot tell error spread as fine grain from error in smooth patches; these two can.
/// </summary>
/// <remarks>
/// <para>
/// The <b>low-pass error</b> is the RMSE of the error after a Gaussian blur of σ pixels (weights e^(−d²/2σ²) out to
/// 3σ, renormalised where the kernel leaves the image, so a constant error stays itself): what is left for an eye
/// that stands back far enough to blur σ pixels together. Fine-grained error (blue noise) cancels under the blur;
/// error in patches survives it. White noise of standard deviation s keeps s/(2σ√π) of it.
/// </para>
/// <para>
/// The <b>error spectrum</b> (<see cref="ErrorSpectrum"/>) is the periodogram of each channel's error,
/// |X(u, v)|²/(W·H) with X its discrete Fourier transform, averaged over the three channels and over rings of equal
/// frequency, in levels². By Parseval the periodogram's mean over all (u, v) is the mean square error, so the
/// spectrum splits RMSE² by frequency; its low-frequency share is the part at |f| ≤ <see cref="LowFrequencyLimit"/>
/// cycles per pixel (the mean, a bias, included).
/// </para>
/// </remarks>
public static class ErrorLocation
{
    /// <summary>The edge of "low frequency", in cycles per pixel: a period of 8 pixels or more.</summary>
    public const double LowFrequencyLimit = 0.125;

    /// <summary>The rings of <see cref="ErrorSpectrum.RadialMean"/> are this wide, in cycles per pixel.</summary>
    public const double RingWidth = 1.0 / 64;

    /// <summary>The RMSE, in levels, of <paramref name="image"/>'s signed error against <paramref name="exact"/> after a Gaussian blur of <paramref name="sigma"/> pixels, over every pixel and channel.</summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <param name="sigma">The blur's standard deviation in pixels, &gt; 0.</param>
    /// <exception cref="ArgumentException">The sizes differ, or <paramref name="sigma"/> is not positive.</exception>
    public static double LowPassRmse(Image image, Image exact, double sigma) => Compute(image, exact, [sigma], spectrum: false, -1).LowPass[0];

    /// <summary>The RMSE of one error plane (<paramref name="width"/>·<paramref name="height"/> values, row 0 first) after a Gaussian blur of <paramref name="sigma"/> pixels.</summary>
    /// <param name="error">The signed error, row by row.</param>
    /// <param name="width">The plane's width, ≥ 1.</param>
    /// <param name="height">The plane's height, ≥ 1.</param>
    /// <param name="sigma">The blur's standard deviation in pixels, &gt; 0.</param>
    /// <exception cref="ArgumentException">The sizes do not match the plane's length, or <paramref name="sigma"/> is not positive.</exception>
    public static double LowPassRmse(ReadOnlySpan<double> error, int width, int height, double sigma)
    {
        CheckPlane(error, width, height);
        CheckSigma(sigma);
        return Math.Sqrt(SquaredAfterBlur(error.ToArray(), width, height, sigma, -1) / ((double)width * height));
    }

    /// <summary>The error spectrum of <paramref name="image"/> against <paramref name="exact"/>, the three channels' periodograms averaged.</summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <exception cref="ArgumentException">The sizes differ.</exception>
    public static ErrorSpectrum Spectrum(Image image, Image exact) => Compute(image, exact, [], spectrum: true, -1).Spectrum!;

    /// <summary>The error spectrum of one error plane.</summary>
    /// <param name="error">The signed error, row by row.</param>
    /// <param name="width">The plane's width, ≥ 1.</param>
    /// <param name="height">The plane's height, ≥ 1.</param>
    /// <exception cref="ArgumentException">The sizes do not match the plane's length.</exception>
    public static ErrorSpectrum Spectrum(ReadOnlySpan<double> error, int width, int height)
    {
        CheckPlane(error, width, height);
        return ErrorSpectrumTransform.Of([error.ToArray()], width, height, -1);
    }

    /// <summary>
    /// <see cref="LowPassRmse(Image, Image, double)"/> on up to <paramref name="maxDegreeOfParallelism"/> threads: rows
    /// shared out, every value computed by the same operations and the squares summed per row, then the rows in
    /// order, so the result is the same at any thread count.
    /// </summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <param name="sigma">The blur's standard deviation in pixels, &gt; 0.</param>
    /// <param name="maxDegreeOfParallelism">−1 for every core, or ≥ 1.</param>
    /// <exception cref="ArgumentException">The sizes differ, <paramref name="sigma"/> is not positive, or the thread count is 0 or below −1.</exception>
    public static double LowPassRmse(Image image, Image exact, double sigma, int maxDegreeOfParallelism) =>
        Compute(image, exact, [sigma], spectrum: false, maxDegreeOfParallelism).LowPass[0];

    /// <summary>
    /// <see cref="Spectrum(Image, Image)"/> on up to <paramref name="maxDegreeOfParallelism"/> threads: rows, then
    /// columns, shared out; each frequency's power computed by one task and the rings summed in one order, so the
    /// spectrum is the same at any thread count.
    /// </summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <param name="maxDegreeOfParallelism">−1 for every core, or ≥ 1.</param>
    /// <exception cref="ArgumentException">The sizes differ, or the thread count is 0 or below −1.</exception>
    public static ErrorSpectrum Spectrum(Image image, Image exact, int maxDegreeOfParallelism) =>
        Compute(image, exact, [], spectrum: true, maxDegreeOfParallelism).Spectrum!;

    private static (double[] LowPass, ErrorSpectrum? Spectrum) Compute(Image image, Image exact, IReadOnlyList<double> sigmas, bool spectrum, int maxDegreeOfParallelism)
    {
        if (maxDegreeOfParallelism is 0 or < -1)
        {
            throw new ArgumentOutOfRangeException(nameof(maxDegreeOfParallelism), maxDegreeOfParallelism, "Must be -1 (every core) or at least 1.");
        }

        foreach (double sigma in sigmas)
        {
            CheckSigma(sigma);
        }

        using ErrorPlanes planes = ErrorPlanes.Of(image, exact, maxDegreeOfParallelism);
        double[] lowPass = [.. sigmas.Select(sigma => LowPassRmse(planes, sigma, maxDegreeOfParallelism))];
        return (lowPass, spectrum ? Spectrum(planes, maxDegreeOfParallelism) : null);
    }

    /// <summary>The low-pass error of the three channels' error planes, for a caller that measures several σ and the spectrum from one set of planes.</summary>
    internal static double LowPassRmse(ErrorPlanes planes, double sigma, int maxDegreeOfParallelism)
    {
        ArgumentNullException.ThrowIfNull(planes);
        CheckSigma(sigma);
        int width = planes.Width, height = planes.Height;
        return Math.Sqrt(planes.Values.Sum(plane => SquaredAfterBlur(plane, width, height, sigma, maxDegreeOfParallelism)) / (3.0 * width * height));
    }

    /// <summary>The error spectrum of the three channels' error planes.</summary>
    internal static ErrorSpectrum Spectrum(ErrorPlanes planes, int maxDegreeOfParallelism)
    {
        ArgumentNullException.ThrowIfNull(planes);
        return ErrorSpectrumTransform.Of(planes.Values, planes.Width, planes.Height, maxDegreeOfParallelism);
    }

    private static void CheckSigma(double sigma)
    {
        if (!(sigma > 0) || double.IsInfinity(sigma))
        {
            throw new ArgumentOutOfRangeException(nameof(sigma), sigma, "The blur's σ must be a positive number of pixels.");
        }
    }

    private static void CheckPlane(ReadOnlySpan<double> error, int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        if (error.Length != (long)width * height)
        {
            throw new ArgumentException($"The error plane has {error.Length} values, not {width}×{height}.", nameof(error));
        }
    }

    /// <summary>
    /// The sum of squares of <paramref name="plane"/> after the blur (separable: rows, then columns; each blurred value
    /// the weights' products added in the order of the taps, in lanes across the row). The squares are summed per row,
    /// then the rows in order, so the sum does not depend on the thread count.
    /// </summary>
    private static double SquaredAfterBlur(double[] plane, int width, int height, double sigma, int threads)
    {
        int radius = (int)Math.Ceiling(3 * sigma);
        var weights = new double[(2 * radius) + 1];
        for (int d = -radius; d <= radius; d++)
        {
            weights[d + radius] = Math.Exp(-(d * d) / (2 * sigma * sigma));
        }

        double[] rows = ArrayPool<double>.Shared.Rent(plane.Length);
        try
        {
            return SquaredAfterBlur(plane, rows, width, height, weights, radius, threads);
        }
        finally
        {
            ArrayPool<double>.Shared.Return(rows);
        }
    }

    /// <summary>The blur's two passes, the rows' pass into <paramref name="rows"/> (at least the plane's length).</summary>
    private static double SquaredAfterBlur(double[] plane, double[] rows, int width, int height, double[] weights, int radius, int threads)
    {
        var options = new ParallelOptions { MaxDegreeOfParallelism = threads };
        Parallel.For(0, height, options, y => BlurRow(plane.AsSpan(y * width, width), rows.AsSpan(y * width, width), weights, radius));
        var rowSums = new double[height];
        Parallel.For(0, height, options, () => new double[width], (y, _, line) =>
        {
            BlurColumns(rows, width, height, y, line, weights, radius);
            double sum = 0;
            foreach (double v in line)
            {
                sum += v * v;
            }

            rowSums[y] = sum;
            return line;
        }, _ => { });
        double total = 0;
        foreach (double rowSum in rowSums)
        {
            total += rowSum;
        }

        return total;
    }

    /// <summary>One row of the horizontal blur, the kernel renormalised at the row's ends; the middle in lanes.</summary>
    private static void BlurRow(ReadOnlySpan<double> source, Span<double> target, double[] weights, int radius)
    {
        int n = source.Length;
        double full = 0;
        foreach (double w in weights)
        {
            full += w;
        }

        int lanes = Vector<double>.Count;
        int x = radius;
        if (Vector.IsHardwareAccelerated)
        {
            var fullVector = new Vector<double>(full);
            for (; x + lanes <= n - radius; x += lanes)
            {
                Vector<double> sum = Vector<double>.Zero;
                for (int j = 0; j < weights.Length; j++)
                {
                    sum += new Vector<double>(weights[j]) * new Vector<double>(source.Slice(x - radius + j, lanes));
                }

                (sum / fullVector).CopyTo(target.Slice(x, lanes));
            }
        }

        for (int i = 0; i < n; i++)
        {
            if (i >= radius && i < x)
            {
                continue; // done in lanes
            }

            double sum = 0, total = 0;
            for (int j = Math.Max(0, i - radius); j <= Math.Min(n - 1, i + radius); j++)
            {
                double w = weights[j - i + radius];
                sum += w * source[j];
                total += w;
            }

            target[i] = sum / total;
        }
    }

    /// <summary>
    /// Output row <paramref name="y"/> of the vertical blur, every column at once (in lanes, each lane's taps summed in
    /// a register in the taps' order), the kernel renormalised at the top and bottom.
    /// </summary>
    private static void BlurColumns(double[] rows, int width, int height, int y, double[] line, double[] weights, int radius)
    {
        int top = Math.Max(0, y - radius), bottom = Math.Min(height - 1, y + radius);
        double total = 0;
        for (int j = top; j <= bottom; j++)
        {
            total += weights[j - y + radius];
        }

        int lanes = Vector<double>.Count;
        int x = 0;
        if (Vector.IsHardwareAccelerated)
        {
            var totalVector = new Vector<double>(total);
            for (; x + lanes <= width; x += lanes)
            {
                Vector<double> sum = Vector<double>.Zero;
                for (int j = top; j <= bottom; j++)
                {
                    sum += new Vector<double>(weights[j - y + radius]) * new Vector<double>(rows.AsSpan((j * width) + x, lanes));
                }

                (sum / totalVector).CopyTo(line.AsSpan(x, lanes));
            }
        }

        for (; x < width; x++)
        {
            double sum = 0;
            for (int j = top; j <= bottom; j++)
            {
                sum += weights[j - y + radius] * rows[(j * width) + x];
            }

            line[x] = sum / total;
        }
    }
}
