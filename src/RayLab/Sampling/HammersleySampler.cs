using RayLab.Sampling.Lanes;
namespace RayLab.Sampling;

/// <summary>
/// The Hammersley point set, (i / N, φ₂(i)) for i = 0 … N − 1 with φ₂ the base-2 radical inverse, moved in each
/// pixel by its own toroidal shift (Cranley–Patterson rotation): every coordinate plus a per-pixel offset, wrapped
/// into [0, 1). The shift keeps the set's low discrepancy and stops every pixel using the same pattern, which
/// would alias. Any number of samples.
/// </summary>
public sealed class HammersleySampler : PixelSampler, ILaneSampled
{
    /// <summary>Xored into the pixel key for the pixel's random shift (the lanes use the same).</summary>
    internal const uint ShiftSalt = 0x68e31da4u;

    /// <summary>Creates a Hammersley sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different shifts.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public HammersleySampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
    }

    /// <inheritdoc />
    public override string Name => "hammersley";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        SamplePoint point = Unshifted(index), shift = Shift(x, y);
        return new SamplePoint(Wrap(point.X + shift.X), Wrap(point.Y + shift.Y));
    }

    /// <summary>Point <paramref name="index"/> of the unshifted Hammersley set: (index / N, φ₂(index)).</summary>
    /// <param name="index">The sample index.</param>
    internal SamplePoint Unshifted(int index) =>
        new((double)index / SamplesPerPixel, LowDiscrepancy.RadicalInverse2((uint)index));

    /// <summary>The toroidal shift of pixel (x, y), each coordinate in [0, 1).</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row.</param>
    internal SamplePoint Shift(int x, int y)
    {
        uint h1 = CounterHash.Hash(CounterHash.PixelKey(x, y, Seed) ^ ShiftSalt);
        return new SamplePoint(CounterHash.ToUnit(h1), CounterHash.ToUnit(CounterHash.Hash(h1)));
    }

    /// <summary>
    /// Wraps a sum of two numbers in [0, 1) into [0, 1). If rounding lifts a sum just below 1 to 1 it wraps to 0,
    /// and v − 1 is exact for v in [1, 2), so the result is always below 1.
    /// </summary>
    /// <param name="v">A value in [0, 2).</param>
    private static double Wrap(double v) => v >= 1.0 ? v - 1.0 : v;

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new HammersleyLanes<TL>(this));
}
