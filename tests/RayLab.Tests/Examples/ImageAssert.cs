// A starting point for your own tests: copy the Examples folder into an xUnit project that references the RayLab
// package (see the README's quick start, "Tests"). ImageAssert needs only RayLab: it throws ImageAssertException,
// which any test framework reports as a failure with its message.
using System.Globalization;

namespace RayLab.Tests.Examples;

/// <summary>
/// Assertions on rendered images that say where they fail: the first differing pixel (rows from the top, each
/// row left to right), its expected and actual RGB levels, and how many pixels differ.
/// </summary>
public static class ImageAssert
{
    /// <summary>Asserts that pixel (x, y) (y = 0 is the top row) is <paramref name="expected"/>, within <paramref name="tolerance"/> levels per channel.</summary>
    /// <param name="expected">The expected levels.</param>
    /// <param name="actual">The image.</param>
    /// <param name="x">The column.</param>
    /// <param name="y">The row, 0 at the top.</param>
    /// <param name="tolerance">How far each channel may be from the expected level, 0 to 255.</param>
    /// <exception cref="ImageAssertException">The pixel is another colour.</exception>
    /// <exception cref="ArgumentOutOfRangeException">(x, y) is outside the image, or the tolerance is outside 0–255.</exception>
    public static void PixelEqual(Rgb24 expected, Image actual, int x, int y, int tolerance = 0)
    {
        ArgumentNullException.ThrowIfNull(actual);
        ArgumentOutOfRangeException.ThrowIfNegative(x);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(x, actual.Width);
        ArgumentOutOfRangeException.ThrowIfNegative(y);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, actual.Height);
        CheckTolerance(tolerance);
        Rgb24 pixel = actual.GetPixel(x, y);
        if (Difference(expected, pixel) > tolerance)
        {
            throw new ImageAssertException(
                $"Pixel (x={x}, y={y}): expected {Show(expected)}, actual {Show(pixel)}{Within(tolerance)}.");
        }
    }

    /// <summary>
    /// Asserts that pixel (x, y) shows <paramref name="expected"/> as the lab's 8-bit rule stores it
    /// (<see cref="Rgb24.FromIntensity"/>), within <paramref name="tolerance"/> levels per channel.
    /// </summary>
    /// <param name="expected">The expected intensity.</param>
    /// <param name="actual">The image.</param>
    /// <param name="x">The column.</param>
    /// <param name="y">The row, 0 at the top.</param>
    /// <param name="tolerance">How far each channel may be from the expected level, 0 to 255.</param>
    /// <exception cref="ImageAssertException">The pixel is another colour.</exception>
    /// <exception cref="ArgumentOutOfRangeException">(x, y) is outside the image, or the tolerance is outside 0–255.</exception>
    public static void PixelEqual(Intensity expected, Image actual, int x, int y, int tolerance = 0) =>
        PixelEqual(Rgb24.FromIntensity(expected), actual, x, y, tolerance);

    /// <summary>Asserts that two images have the same size and every channel of every pixel within <paramref name="tolerance"/> levels.</summary>
    /// <param name="expected">The expected image.</param>
    /// <param name="actual">The image under test.</param>
    /// <param name="tolerance">How far each channel may be from the expected level, 0 (the default: the same bytes) to 255.</param>
    /// <exception cref="ImageAssertException">The sizes differ, or some pixel is further off than the tolerance.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The tolerance is outside 0–255.</exception>
    public static void Equal(Image expected, Image actual, int tolerance = 0)
    {
        CheckSameSize(expected, actual);
        CheckTolerance(tolerance);
        (int X, int Y)? first = null;
        long count = 0;
        for (int y = 0; y < expected.Height; y++)
        {
            ReadOnlySpan<Rgb24> e = expected.GetRowSpan(y), a = actual.GetRowSpan(y);
            for (int x = 0; x < e.Length; x++)
            {
                if (Difference(e[x], a[x]) > tolerance)
                {
                    first ??= (x, y);
                    count++;
                }
            }
        }

        if (first is (int fx, int fy))
        {
            throw new ImageAssertException(
                $"{count:N0} of {Pixels(expected):N0} pixels differ{Within(tolerance)}; the first at (x={fx}, y={fy}): "
                + $"expected {Show(expected.GetPixel(fx, fy))}, actual {Show(actual.GetPixel(fx, fy))}.");
        }
    }

    /// <summary>
    /// Asserts that the mean absolute difference over every channel of every pixel, in levels, is at most
    /// <paramref name="maxMean"/>: a measure of error for images that may not match pixel for pixel (sampling
    /// noise against an exact reference). On failure the message also names the worst pixel.
    /// </summary>
    /// <param name="expected">The reference image.</param>
    /// <param name="actual">The image under test.</param>
    /// <param name="maxMean">The largest acceptable mean error in levels, ≥ 0.</param>
    /// <returns>The mean error, for a test to print or compare.</returns>
    /// <exception cref="ImageAssertException">The sizes differ, or the mean error exceeds <paramref name="maxMean"/>.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="maxMean"/> is negative or NaN.</exception>
    public static double MeanErrorAtMost(Image expected, Image actual, double maxMean)
    {
        CheckSameSize(expected, actual);
        if (!(maxMean >= 0))
        {
            throw new ArgumentOutOfRangeException(nameof(maxMean), maxMean, "The mean error allowed must be ≥ 0.");
        }
        long sum = 0;
        (int X, int Y, int Difference) worst = (0, 0, -1);
        for (int y = 0; y < expected.Height; y++)
        {
            ReadOnlySpan<Rgb24> e = expected.GetRowSpan(y), a = actual.GetRowSpan(y);
            for (int x = 0; x < e.Length; x++)
            {
                sum += Math.Abs(e[x].R - a[x].R) + Math.Abs(e[x].G - a[x].G) + Math.Abs(e[x].B - a[x].B);
                int difference = Difference(e[x], a[x]);
                if (difference > worst.Difference)
                {
                    worst = (x, y, difference);
                }
            }
        }

        double mean = sum / (3.0 * Pixels(expected));
        if (mean > maxMean)
        {
            throw new ImageAssertException(string.Create(CultureInfo.InvariantCulture,
                $"Mean error {mean:F3} levels per channel, more than {maxMean:G} allowed; the worst pixel (x={worst.X}, y={worst.Y}): "
                + $"expected {Show(expected.GetPixel(worst.X, worst.Y))}, actual {Show(actual.GetPixel(worst.X, worst.Y))}."));
        }

        return mean;
    }

    private static void CheckSameSize(Image expected, Image actual)
    {
        ArgumentNullException.ThrowIfNull(expected);
        ArgumentNullException.ThrowIfNull(actual);
        if (expected.Width != actual.Width || expected.Height != actual.Height)
        {
            throw new ImageAssertException(
                $"Image sizes differ: expected {expected.Width}×{expected.Height}, actual {actual.Width}×{actual.Height}.");
        }
    }

    private static void CheckTolerance(int tolerance)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(tolerance);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(tolerance, 255);
    }

    /// <summary>The largest difference of a channel, in levels.</summary>
    private static int Difference(Rgb24 a, Rgb24 b) => Math.Max(Math.Abs(a.R - b.R), Math.Max(Math.Abs(a.G - b.G), Math.Abs(a.B - b.B)));

    private static long Pixels(Image image) => (long)image.Width * image.Height;

    private static string Show(Rgb24 p) => $"RGB ({p.R}, {p.G}, {p.B})";

    private static string Within(int tolerance) => tolerance == 0 ? "" : $" by more than {tolerance} levels";
}
