namespace RayLab.Sampling;

/// <summary>The shared part of RayLab's point samplers: a sample count ≥ 1 and a seed, checked once.</summary>
public abstract class PixelSampler : IPixelSampler
{
    /// <summary>Creates a sampler with <paramref name="samplesPerPixel"/> samples in every pixel.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    protected PixelSampler(int samplesPerPixel, uint seed)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(samplesPerPixel, 1);
        SamplesPerPixel = samplesPerPixel;
        Seed = seed;
    }

    /// <inheritdoc />
    public abstract string Name { get; }

    /// <inheritdoc />
    public int SamplesPerPixel { get; }

    /// <inheritdoc />
    public uint Seed { get; }

    /// <inheritdoc />
    public abstract SamplePoint GetSample(int x, int y, int index);
}
