using System.Buffers;

namespace RayLab.Metrics;

/// <summary>
/// The three channels' signed errors of an image against the exact image, in levels, one plane each (width·height
/// values, row 0 first; the arrays may be longer). The arrays are rented from the shared pool, so that a report that
/// measures a hundred 1080p pictures does not allocate (and fault in) 48 MB of fresh pages for each: dispose the planes
/// to give them back.
/// </summary>
internal sealed class ErrorPlanes : IDisposable
{
    private double[][]? _values;

    /// <summary>The planes from rented arrays of at least <paramref name="width"/>·<paramref name="height"/> values, to be filled by the caller.</summary>
    private ErrorPlanes(int width, int height)
    {
        Width = width;
        Height = height;
        int pixels = width * height;
        _values = [ArrayPool<double>.Shared.Rent(pixels), ArrayPool<double>.Shared.Rent(pixels), ArrayPool<double>.Shared.Rent(pixels)];
    }

    /// <summary>The planes' width in pixels.</summary>
    public int Width { get; }

    /// <summary>The planes' height in pixels.</summary>
    public int Height { get; }

    /// <summary>The red, green and blue planes.</summary>
    /// <exception cref="ObjectDisposedException">The planes were given back.</exception>
    public double[][] Values => _values ?? throw new ObjectDisposedException(nameof(ErrorPlanes));

    /// <summary>The planes of <paramref name="image"/> against <paramref name="exact"/> (rows shared out over the cores: each value is a difference of two bytes).</summary>
    /// <param name="image">The image to judge.</param>
    /// <param name="exact">The exact image, of the same size.</param>
    /// <param name="maxDegreeOfParallelism">−1 for every core, or ≥ 1.</param>
    /// <exception cref="ArgumentException">The sizes differ.</exception>
    public static ErrorPlanes Of(Image image, Image exact, int maxDegreeOfParallelism)
    {
        ArgumentNullException.ThrowIfNull(image);
        ArgumentNullException.ThrowIfNull(exact);
        if (image.Width != exact.Width || image.Height != exact.Height)
        {
            throw new ArgumentException(
                $"The image is {image.Width}×{image.Height} but the exact image is {exact.Width}×{exact.Height}.", nameof(image));
        }

        int width = image.Width;
        var planes = new ErrorPlanes(image.Width, image.Height);
        double[][] values = planes.Values;
        Parallel.For(0, image.Height, new ParallelOptions { MaxDegreeOfParallelism = maxDegreeOfParallelism }, y =>
        {
            ReadOnlySpan<byte> a = image.PixelBytes.Slice(3 * y * width, 3 * width), b = exact.PixelBytes.Slice(3 * y * width, 3 * width);
            Span<double> red = values[0].AsSpan(y * width, width), green = values[1].AsSpan(y * width, width), blue = values[2].AsSpan(y * width, width);
            for (int x = 0; x < width; x++)
            {
                red[x] = a[3 * x] - b[3 * x];
                green[x] = a[(3 * x) + 1] - b[(3 * x) + 1];
                blue[x] = a[(3 * x) + 2] - b[(3 * x) + 2];
            }
        });

        return planes;
    }

    /// <summary>Gives the arrays back to the pool; the planes cannot be used after.</summary>
    public void Dispose()
    {
        if (_values is { } values)
        {
            _values = null;
            foreach (double[] plane in values)
            {
                ArrayPool<double>.Shared.Return(plane);
            }
        }
    }
}
