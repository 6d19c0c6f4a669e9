using RayLab.Sampling.Lanes;
namespace RayLab.Sampling;

/// <summary>
/// The lab's random sampling (Suffern's <c>rand()</c> in the pixel): uniform, independent points. Any
/// number of samples; points may clump.
/// </summary>
public sealed class RandomSampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates a random sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public RandomSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
    }

    /// <inheritdoc />
    public override string Name => "random";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        uint h1 = CounterHash.SampleHash(CounterHash.PixelKey(x, y, Seed), index);
        return new SamplePoint(CounterHash.ToUnit(h1), CounterHash.ToUnit(CounterHash.Hash(h1)));
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new RandomLanes<TL>(this));
}
