using RayLab.Sampling.Lanes;
namespace RayLab.Sampling;

/// <summary>
/// The lab's jittered (stratified) sampling: an n×n grid with one uniformly random point in each cell.
/// </summary>
public sealed class JitteredSampler : GridSampler, ILaneSampled
{
    /// <summary>Creates an n×n jittered sampler.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentException">Not a positive perfect square.</exception>
    public JitteredSampler(int samplesPerPixel, uint seed) : base(samplesPerPixel, seed) { }

    /// <inheritdoc />
    public override string Name => "jittered";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        int n = GridSize;
        uint h1 = CounterHash.SampleHash(CounterHash.PixelKey(x, y, Seed), index);
        uint h2 = CounterHash.Hash(h1);
        return new SamplePoint(
            ((index % n) + CounterHash.ToUnit(h1)) / n,
            ((index / n) + CounterHash.ToUnit(h2)) / n);
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new JitteredLanes<TL>(this));
}
