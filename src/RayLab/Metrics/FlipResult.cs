namespace RayLab.Metrics;

/// <summary>
/// The result of <see cref="Flip.Compute(RayLab.Image, RayLab.Image, FlipOptions?)"/>: the per-pixel FLIP error map, each value in [0, 1] (0 where the two
/// images cannot be told apart when flipped between, 1 for the largest difference), and its mean.
/// </summary>
public sealed class FlipResult
{
    private readonly float[] _map;

    internal FlipResult(int width, int height, float[] map, double mean, double pixelsPerDegree)
    {
        Width = width;
        Height = height;
        _map = map;
        Mean = mean;
        PixelsPerDegree = pixelsPerDegree;
    }

    /// <summary>The map's width in pixels (the images' width).</summary>
    public int Width { get; }

    /// <summary>The map's height in pixels (the images' height).</summary>
    public int Height { get; }

    /// <summary>The mean of the error map, the number FLIP papers report ("mean FLIP").</summary>
    public double Mean { get; }

    /// <summary>The pixels per degree the map was computed for.</summary>
    public double PixelsPerDegree { get; }

    /// <summary>The error map, <see cref="Width"/>×<see cref="Height"/> values row by row, the top row first.</summary>
    public ReadOnlySpan<float> Map => _map;

    /// <summary>The error at pixel (x, y).</summary>
    /// <param name="x">Column, 0 at the left.</param>
    /// <param name="y">Row, 0 at the top.</param>
    /// <exception cref="ArgumentOutOfRangeException">(x, y) is outside the map.</exception>
    public float this[int x, int y]
    {
        get
        {
            ArgumentOutOfRangeException.ThrowIfNegative(x);
            ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(x, Width);
            ArgumentOutOfRangeException.ThrowIfNegative(y);
            ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, Height);
            return _map[(y * Width) + x];
        }
    }

    /// <summary>A copy of the error map (see <see cref="Map"/>).</summary>
    /// <returns>A new array of <see cref="Width"/>·<see cref="Height"/> values.</returns>
    public float[] ToArray() => (float[])_map.Clone();
}
