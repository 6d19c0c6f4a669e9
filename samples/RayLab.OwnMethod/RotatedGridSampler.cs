using RayLab.Sampling;

namespace RayLab.OwnMethod;

/// <summary>
/// A point sampler of your own: the n×n grid rotated so that no two samples share a column or a row of the pixel
/// (RGSS, the rotated-grid supersampling of graphics hardware, for n = 2). A nearly vertical or horizontal edge
/// then crosses n² distinct sample columns or rows, where the lab's regular grid has only n.
/// </summary>
public sealed class RotatedGridSampler : IPixelSampler
{
    private readonly int _n;

    /// <summary>Creates an n×n rotated grid.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <exception cref="ArgumentOutOfRangeException">Not a positive perfect square.</exception>
    public RotatedGridSampler(int samplesPerPixel)
    {
        _n = (int)Math.Round(Math.Sqrt(samplesPerPixel));
        if (samplesPerPixel < 1 || _n * _n != samplesPerPixel)
        {
            throw new ArgumentOutOfRangeException(nameof(samplesPerPixel), samplesPerPixel, "The rotated grid needs n² samples.");
        }

        SamplesPerPixel = samplesPerPixel;
    }

    /// <inheritdoc />
    public string Name => "rotated-grid";

    /// <inheritdoc />
    public int SamplesPerPixel { get; }

    /// <summary>Always 0: the rotated grid has no randomness.</summary>
    public uint Seed => 0;

    /// <summary>
    /// Cell (i, j) of the n×n grid holds the point (i/n + (j + ½)/n², j/n + (n − 1 − i + ½)/n²): the lattice
    /// spanned by (1/n, −1/n²) and (1/n², 1/n), a square grid turned by atan(1/n).
    /// </summary>
    /// <param name="x">The pixel column (the grid is the same in every pixel).</param>
    /// <param name="y">The pixel row.</param>
    /// <param name="index">The sample index, i + n·j.</param>
    public SamplePoint GetSample(int x, int y, int index) => At(_n, index % _n, index / _n);

    /// <summary>The point of cell (<paramref name="i"/>, <paramref name="j"/>) of the n×n rotated grid.</summary>
    /// <param name="n">The grid size.</param>
    /// <param name="i">The cell column.</param>
    /// <param name="j">The cell row.</param>
    public static SamplePoint At(int n, int i, int j) =>
        new((i + ((j + 0.5) / n)) / n, (j + ((n - 1 - i + 0.5) / n)) / n);
}
