using RayLab.Sampling.Lanes;
namespace RayLab.Sampling;

/// <summary>
/// The first two dimensions of the Sobol' sequence, Owen-scrambled and shuffled per pixel as in Burley's
/// "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020). When N is a power of two the N points of a pixel
/// form a (0, m, 2)-net in base 2: every box [a/2ʲ, (a+1)/2ʲ) × [b/2ᵏ, (b+1)/2ᵏ) with 2ʲ⁺ᵏ = N holds exactly one
/// point, so they are stratified as N × 1, …, 2 × N/2 and 1 × N grids at once. Any number of samples works;
/// powers of two are best.
/// </summary>
/// <remarks>
/// The index is first put through a nested uniform scramble (which maps 0 … 2ᵐ − 1 onto an aligned block of 2ᵐ
/// Sobol' indices, so the net property survives), then each coordinate through its own nested uniform scramble;
/// all three seeds come from the pixel's <see cref="CounterHash.PixelKey"/>. Coordinates keep the top 24 bits,
/// like <see cref="CounterHash.ToUnit"/>.
/// </remarks>
public sealed class SobolSampler : PixelSampler, ILaneSampled
{
    /// <summary>Xored into the pixel key for the seed of the index scramble (the lanes use the same).</summary>
    internal const uint IndexSalt = 0x1b873593u;

    /// <summary>Creates a scrambled Sobol' sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1 (a power of two for the full net property).</param>
    /// <param name="seed">The seed; different seeds give different scrambles.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public SobolSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
    }

    /// <inheritdoc />
    public override string Name => "sobol";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        uint indexSeed = CounterHash.Hash(CounterHash.PixelKey(x, y, Seed) ^ IndexSalt);
        uint xSeed = CounterHash.Hash(indexSeed);
        uint ySeed = CounterHash.Hash(xSeed);
        uint i = LowDiscrepancy.NestedUniformScramble((uint)index, indexSeed);
        uint sx = LowDiscrepancy.NestedUniformScramble(LowDiscrepancy.ReverseBits(i), xSeed);
        uint sy = LowDiscrepancy.NestedUniformScramble(LowDiscrepancy.SobolDimension1(i), ySeed);
        return new SamplePoint(CounterHash.ToUnit(sx), CounterHash.ToUnit(sy));
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new SobolLanes<TL>(this));
}
