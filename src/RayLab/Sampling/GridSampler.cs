namespace RayLab.Sampling;

/// <summary>Shared checks for samplers that use an n×n grid of cells.</summary>
public abstract class GridSampler : PixelSampler
{
    /// <summary>Creates a grid sampler with <paramref name="samplesPerPixel"/> = n² cells.</summary>
    /// <param name="samplesPerPixel">A perfect square ≥ 1.</param>
    /// <param name="seed">The seed.</param>
    /// <exception cref="ArgumentException"><paramref name="samplesPerPixel"/> is not a positive perfect square.</exception>
    protected GridSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
        int n = (int)Math.Round(Math.Sqrt(samplesPerPixel));
        if (n * n != samplesPerPixel)
        {
            throw new ArgumentException(
                $"An n×n grid needs a perfect square number of samples (1, 4, 9, 16, …), got {samplesPerPixel}.",
                nameof(samplesPerPixel));
        }

        GridSize = n;
    }

    /// <summary>n: cells per side.</summary>
    public int GridSize { get; }
}
