using RayLab.Sampling.Lanes;
namespace RayLab.Sampling;

/// <summary>
/// The lab's regular sampling: an n×n grid, one sample at the centre of each cell, the same pattern in every
/// pixel. Cheap, but it still aliases. One sample is the pixel centre.
/// </summary>
public sealed class RegularSampler : GridSampler, ILaneSampled
{
    /// <summary>Creates an n×n regular sampler.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <exception cref="ArgumentException">Not a positive perfect square.</exception>
    public RegularSampler(int samplesPerPixel) : base(samplesPerPixel, 0) { }

    /// <inheritdoc />
    public override string Name => "regular";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        int n = GridSize;
        return new SamplePoint(((index % n) + 0.5) / n, ((index / n) + 0.5) / n);
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new RegularLanes<TL>(this));
}
