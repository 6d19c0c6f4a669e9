namespace RayLab;

/// <summary>
/// How far an image is from the exact image, in 8-bit levels. The error of one channel of one pixel is its
/// level minus the exact image's level, both by the lab's rule <c>int(256·I)</c>
/// (<see cref="EightBit.Level"/>): so "every pixel within one level of the exact image" means every byte
/// of the two pictures differs by at most 1, which anyone can check with the two files, and a perfect render
/// scores 0.
/// </summary>
/// <remarks>
/// Because both images are quantised, a linear error δ smaller than a level shows as 0 or ±1 (±1 with
/// probability about |δ|). <see cref="MeanAbsolute"/> keeps following δ there, while <see cref="Rmse"/>
/// falls only as √|δ|.
/// </remarks>
/// <param name="Rmse">Root mean square of the per-channel errors over every pixel and channel.</param>
/// <param name="MeanAbsolute">Mean of the absolute per-channel errors.</param>
/// <param name="Max">The largest absolute per-channel error.</param>
/// <param name="FractionOverOneLevel">The fraction of pixels with some channel more than one level off (|error| ≥ 2).</param>
public readonly record struct ImageError(double Rmse, double MeanAbsolute, int Max, double FractionOverOneLevel)
{
    /// <summary>Measures <paramref name="image"/> against <paramref name="exact"/>.</summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <returns>The error.</returns>
    /// <exception cref="ArgumentException">The sizes differ.</exception>
    public static ImageError Measure(Image image, Image exact)
    {
        CheckSizes(image, exact);
        ReadOnlySpan<byte> a = image.PixelBytes, b = exact.PixelBytes;
        long squares = 0, absolutes = 0, pixelsOver = 0;
        int max = 0;
        for (int i = 0; i < a.Length; i += 3)
        {
            int worst = 0;
            for (int c = i; c < i + 3; c++)
            {
                int d = Math.Abs(a[c] - b[c]);
                squares += d * d;
                absolutes += d;
                worst = Math.Max(worst, d);
            }

            max = Math.Max(max, worst);
            pixelsOver += worst > 1 ? 1 : 0;
        }

        double pixels = (double)image.Width * image.Height;
        return new ImageError(Math.Sqrt(squares / (3 * pixels)), absolutes / (3 * pixels), max, pixelsOver / pixels);
    }

    /// <summary>
    /// The error image: for each pixel, the largest absolute per-channel error in levels, W·H, row 0 first
    /// (the <c>RayLab.Reports</c> package draws it as a heat map).
    /// </summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <exception cref="ArgumentException">The sizes differ.</exception>
    public static float[] PerPixel(Image image, Image exact)
    {
        CheckSizes(image, exact);
        var errors = new float[(long)image.Width * image.Height];
        PerPixel(image, exact, errors);
        return errors;
    }

    /// <summary>
    /// The error image (<see cref="PerPixel(Image, Image)"/>) into <paramref name="errors"/>, for a caller that measures
    /// many images of one size into one buffer.
    /// </summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <param name="errors">W·H values, row 0 first; every one is written.</param>
    /// <exception cref="ArgumentException">The sizes differ, or <paramref name="errors"/> does not hold W·H values.</exception>
    public static void PerPixel(Image image, Image exact, Span<float> errors)
    {
        CheckSizes(image, exact);
        if (errors.Length != (long)image.Width * image.Height)
        {
            throw new ArgumentException($"Expected {image.Width}×{image.Height} values, got {errors.Length}.", nameof(errors));
        }

        ReadOnlySpan<byte> a = image.PixelBytes, b = exact.PixelBytes;
        for (int p = 0; p < errors.Length; p++)
        {
            int i = 3 * p;
            errors[p] = Math.Max(Math.Abs(a[i] - b[i]), Math.Max(Math.Abs(a[i + 1] - b[i + 1]), Math.Abs(a[i + 2] - b[i + 2])));
        }
    }

    private static void CheckSizes(Image image, Image exact)
    {
        ArgumentNullException.ThrowIfNull(image);
        ArgumentNullException.ThrowIfNull(exact);
        if (image.Width != exact.Width || image.Height != exact.Height)
        {
            throw new ArgumentException(
                $"The image is {image.Width}×{image.Height} but the exact image is {exact.Width}×{exact.Height}.", nameof(image));
        }
    }
}
