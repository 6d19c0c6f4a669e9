using System.Runtime.CompilerServices;

namespace RayLab.Sampling;

/// <summary>
/// The counter-based hash every random number in RayLab comes from: no shared <see cref="Random"/>, so a
/// sample depends only on (pixel, sample index, seed) and a render is byte-identical whatever the thread count.
/// </summary>
/// <remarks>
/// The mixer is Chris Wellons' <c>lowbias32</c>, the one the native anchors in <c>benchmarks/anchors</c> use:
/// two rounds of xor-shift and multiply, a bijection on 32-bit integers.
/// </remarks>
internal static class CounterHash
{
    /// <summary>The golden-ratio increment that spreads sample indices before hashing.</summary>
    public const uint Golden = 0x9e3779b9u;

    /// <summary>lowbias32's first multiplier (the lanes' hash uses the same).</summary>
    public const uint Multiplier1 = 0x7feb352du;

    /// <summary>lowbias32's second multiplier.</summary>
    public const uint Multiplier2 = 0x846ca68bu;

    /// <summary>2⁻²⁴: the step of <see cref="ToUnit"/>'s numbers.</summary>
    public const double UnitStep = 1.0 / 16777216.0;

    /// <summary>Mixes 32 bits (lowbias32).</summary>
    /// <param name="x">The input.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint Hash(uint x)
    {
        x ^= x >> 16;
        x *= Multiplier1;
        x ^= x >> 15;
        x *= Multiplier2;
        x ^= x >> 16;
        return x;
    }

    /// <summary>
    /// The key of one pixel under one seed: distinct for distinct (x, y) below 65 536 × 65 536. The seed is salted
    /// before hashing so that seed 0 does not give pixel (0, 0) the key 0 (lowbias32 maps 0 to 0), which would put
    /// its first sample at exactly (0, 0) and make derived patterns degenerate.
    /// </summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="y">The pixel row.</param>
    /// <param name="seed">The render's seed.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint PixelKey(int x, int y, uint seed) => Hash(((uint)y << 16) ^ (uint)x ^ Hash(seed + Golden));

    /// <summary>The first hash of sample <paramref name="index"/> of a pixel; hash it again for a second number.</summary>
    /// <param name="pixelKey">The pixel's key from <see cref="PixelKey"/>.</param>
    /// <param name="index">The sample index.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint SampleHash(uint pixelKey, int index) => Hash(pixelKey ^ ((uint)index * Golden));

    /// <summary>A number in [0, 1) from the top 24 bits of a hash (exact in float and double).</summary>
    /// <param name="hash">A hash value.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double ToUnit(uint hash) => (hash >> 8) * UnitStep;
}
