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
    public static double LowPassRmse(Image image, Image exact, double sigma)
    {
        double[][] planes = Planes(image, exact);
        double sum = 0;
        foreach (double[] plane in planes)
        {
            sum += SquaredAfterBlur(plane, image.Width, image.Height, sigma);
        }

        return Math.Sqrt(sum / (3.0 * image.Width * image.Height));
    }

    /// <summary>The RMSE of one error plane (<paramref name="width"/>·<paramref name="height"/> values, row 0 first) after a Gaussian blur of <paramref name="sigma"/> pixels.</summary>
    /// <param name="error">The signed error, row by row.</param>
    /// <param name="width">The plane's width, ≥ 1.</param>
    /// <param name="height">The plane's height, ≥ 1.</param>
    /// <param name="sigma">The blur's standard deviation in pixels, &gt; 0.</param>
    /// <exception cref="ArgumentException">The sizes do not match the plane's length, or <paramref name="sigma"/> is not positive.</exception>
    public static double LowPassRmse(ReadOnlySpan<double> error, int width, int height, double sigma)
    {
        CheckPlane(error, width, height);
        return Math.Sqrt(SquaredAfterBlur(error.ToArray(), width, height, sigma) / ((double)width * height));
    }

    /// <summary>The error spectrum of <paramref name="image"/> against <paramref name="exact"/>, the three channels' periodograms averaged.</summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <exception cref="ArgumentException">The sizes differ.</exception>
    public static ErrorSpectrum Spectrum(Image image, Image exact) => SpectrumOf(Planes(image, exact), image.Width, image.Height);

    /// <summary>The error spectrum of one error plane.</summary>
    /// <param name="error">The signed error, row by row.</param>
    /// <param name="width">The plane's width, ≥ 1.</param>
    /// <param name="height">The plane's height, ≥ 1.</param>
    /// <exception cref="ArgumentException">The sizes do not match the plane's length.</exception>
    public static ErrorSpectrum Spectrum(ReadOnlySpan<double> error, int width, int height)
    {
        CheckPlane(error, width, height);
        return SpectrumOf([error.ToArray()], width, height);
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

    /// <summary>The three channels' signed errors in levels, one plane each.</summary>
    private static double[][] Planes(Image image, Image exact)
    {
        ArgumentNullException.ThrowIfNull(image);
        ArgumentNullException.ThrowIfNull(exact);
        if (image.Width != exact.Width || image.Height != exact.Height)
        {
            throw new ArgumentException(
                $"The image is {image.Width}×{image.Height} but the exact image is {exact.Width}×{exact.Height}.", nameof(image));
        }

        ReadOnlySpan<byte> a = image.PixelBytes, b = exact.PixelBytes;
        int pixels = image.Width * image.Height;
        double[][] planes = [new double[pixels], new double[pixels], new double[pixels]];
        for (int p = 0; p < pixels; p++)
        {
            for (int c = 0; c < 3; c++)
            {
                planes[c][p] = a[(3 * p) + c] - b[(3 * p) + c];
            }
        }

        return planes;
    }

    /// <summary>The sum of squares of <paramref name="plane"/> after the blur (separable: rows, then columns).</summary>
    private static double SquaredAfterBlur(double[] plane, int width, int height, double sigma)
    {
        if (!(sigma > 0) || double.IsInfinity(sigma))
        {
            throw new ArgumentOutOfRangeException(nameof(sigma), sigma, "The blur's σ must be a positive number of pixels.");
        }

        int radius = (int)Math.Ceiling(3 * sigma);
        var weights = new double[(2 * radius) + 1];
        for (int d = -radius; d <= radius; d++)
        {
            weights[d + radius] = Math.Exp(-(d * d) / (2 * sigma * sigma));
        }

        var rows = new double[plane.Length];
        for (int y = 0; y < height; y++)
        {
            Blur1D(plane.AsSpan(y * width, width), 1, rows.AsSpan(y * width, width), 1, weights, radius);
        }

        var blurred = new double[plane.Length];
        for (int x = 0; x < width; x++)
        {
            Blur1D(rows.AsSpan(x), width, blurred.AsSpan(x), width, weights, radius);
        }

        double sum = 0;
        foreach (double v in blurred)
        {
            sum += v * v;
        }

        return sum;
    }

    /// <summary>One line of the blur: every <paramref name="stride"/>-th value, the kernel renormalised at the ends.</summary>
    private static void Blur1D(ReadOnlySpan<double> source, int stride, Span<double> target, int targetStride, double[] weights, int radius)
    {
        int n = ((source.Length - 1) / stride) + 1;
        for (int i = 0; i < n; i++)
        {
            double sum = 0, total = 0;
            for (int j = Math.Max(0, i - radius); j <= Math.Min(n - 1, i + radius); j++)
            {
                double w = weights[j - i + radius];
                sum += w * source[j * stride];
                total += w;
            }

            target[i * targetStride] = sum / total;
        }
    }

    private static ErrorSpectrum SpectrumOf(double[][] planes, int width, int height)
    {
        var rowTransform = new Fourier(width);
        var columnTransform = new Fourier(height);
        var power = new double[width * height];
        var data = new Complex[width * height];
        var column = new Complex[height];
        foreach (double[] plane in planes)
        {
            for (int i = 0; i < data.Length; i++)
            {
                data[i] = plane[i];
            }

            for (int y = 0; y < height; y++)
            {
                rowTransform.Transform(data.AsSpan(y * width, width));
            }

            for (int x = 0; x < width; x++)
            {
                for (int y = 0; y < height; y++)
                {
                    column[y] = data[(y * width) + x];
                }

                columnTransform.Transform(column);
                for (int y = 0; y < height; y++)
                {
                    // The periodogram |X|²/(W·H), averaged over the planes.
                    double m = column[y].Magnitude;
                    power[(y * width) + x] += m * m / ((double)width * height * planes.Length);
                }
            }
        }

        int rings = (int)Math.Ceiling(Math.Sqrt(0.5) / RingWidth) + 1;
        var ringSum = new double[rings];
        var ringCount = new int[rings];
        double total = 0, low = 0;
        for (int v = 0; v < height; v++)
        {
            double fv = (v <= height / 2 ? v : v - height) / (double)height;
            for (int u = 0; u < width; u++)
            {
                double fu = (u <= width / 2 ? u : u - width) / (double)width;
                double f = Math.Sqrt((fu * fu) + (fv * fv));
                double p = power[(v * width) + u];
                int ring = (int)Math.Round(f / RingWidth);
                ringSum[ring] += p;
                ringCount[ring]++;
                total += p;
                low += f <= LowFrequencyLimit ? p : 0;
            }
        }

        double[] mean = [.. ringSum.Select((s, r) => ringCount[r] > 0 ? s / ringCount[r] : double.NaN)];
        int n = width * height;
        return new ErrorSpectrum(mean, total / n, total > 0 ? low / total : 0);
    }
}
