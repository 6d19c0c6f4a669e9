namespace RayLab.Sampling;

/// <summary>Shared checks for samplers that use an n×n grid of cells.</summary>
public abstract class GridSampler : IPixelSampler
{
    /// <summary>Creates a grid sampler with <paramref name="samplesPerPixel"/> = n² cells.</summary>
    /// <param name="samplesPerPixel">A perfect square ≥ 1.</param>
    /// <param name="seed">The seed.</param>
    /// <exception cref="ArgumentException"><paramref name="samplesPerPixel"/> is not a positive perfect square.</exception>
    protected GridSampler(int samplesPerPixel, uint seed)
    {
        if (samplesPerPixel < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(samplesPerPixel), samplesPerPixel, "Samples per pixel must be at least 1.");
        }

        int n = (int)Math.Round(Math.Sqrt(samplesPerPixel));
        if (n * n != samplesPerPixel)
        {
            throw new ArgumentException(
                $"An n×n grid needs a perfect square number of samples (1, 4, 9, 16, …), got {samplesPerPixel}.",
                nameof(samplesPerPixel));
        }

        GridSize = n;
        SamplesPerPixel = samplesPerPixel;
        Seed = seed;
    }

    /// <summary>n: cells per side.</summary>
    public int GridSize { get; }

    /// <inheritdoc />
    public abstract string Name { get; }

    /// <inheritdoc />
    public int SamplesPerPixel { get; }

    /// <inheritdoc />
    public uint Seed { get; }

    /// <inheritdoc />
    public abstract SamplePoint GetSample(int x, int y, int index);
}
