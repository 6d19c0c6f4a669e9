using System.Runtime.CompilerServices;

namespace RayLab.Sampling;

/// <summary>
/// Bit-level building blocks of the low-discrepancy samplers: base-2 radical inverse, the second Sobol'
/// dimension and Burley's hash-based Owen scrambling. All work on 32-bit binary fractions (value · 2⁻³²).
/// </summary>
internal static class LowDiscrepancy
{
    /// <summary>2⁻³², the weight of the lowest bit of a 32-bit binary fraction.</summary>
    internal const double TwoToMinus32 = 1.0 / 4294967296.0;

    /// <summary>The Laine–Karras permutation's first multiplier (Burley's constants; the lanes use the same).</summary>
    internal const uint LaineKarras1 = 0x6c50b47cu;

    /// <summary>The Laine–Karras permutation's second multiplier.</summary>
    internal const uint LaineKarras2 = 0xb82f1e52u;

    /// <summary>The Laine–Karras permutation's third multiplier.</summary>
    internal const uint LaineKarras3 = 0xc7afe638u;

    /// <summary>The Laine–Karras permutation's fourth multiplier.</summary>
    internal const uint LaineKarras4 = 0x8d22f6e6u;

    /// <summary>Reverses the order of the 32 bits of <paramref name="x"/>.</summary>
    /// <param name="x">The input.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static uint ReverseBits(uint x)
    {
        x = (x << 16) | (x >> 16);
        x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
        x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
        x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
        x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
        return x;
    }

    /// <summary>
    /// The van der Corput radical inverse in base 2, φ₂(i): the binary digits of i mirrored about the point.
    /// Exact: the bit reversal times 2⁻³² is representable in a double.
    /// </summary>
    /// <param name="i">The index.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static double RadicalInverse2(uint i) => ReverseBits(i) * TwoToMinus32;

    /// <summary>
    /// The second dimension of the Sobol' sequence as a 32-bit fraction: the xor of the direction numbers
    /// v_k (v₀ = 2³¹, v_k = v_{k−1} ⊕ (v_{k−1} ≫ 1), the Pascal matrix mod 2) of the set bits k of
    /// <paramref name="index"/>. With <see cref="ReverseBits"/> as the first dimension this is the (0, 2)-sequence
    /// in base 2.
    /// </summary>
    /// <param name="index">The index.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static uint SobolDimension1(uint index) =>
        Dimension1Bytes[index & 0xff] ^ Dimension1Bytes[256 + ((index >> 8) & 0xff)]
        ^ Dimension1Bytes[512 + ((index >> 16) & 0xff)] ^ Dimension1Bytes[768 + (index >> 24)];

    /// <summary>
    /// <see cref="SobolDimension1"/> a byte at a time: entry 256·k + b is the XOR of the generator columns for the
    /// set bits of byte b in position k. Four lookups instead of a loop over up to 32 bits: scrambled indices use all
    /// 32, and a loop over them takes a step per set bit.
    /// </summary>
    private static readonly uint[] Dimension1Bytes = BuildDimension1Bytes();

    private static uint[] BuildDimension1Bytes()
    {
        var columns = new uint[32];
        uint v = 0x80000000u;
        for (int k = 0; k < 32; k++, v ^= v >> 1)
        {
            columns[k] = v;
        }

        var table = new uint[4 * 256];
        for (int k = 0; k < 4; k++)
        {
            for (int b = 0; b < 256; b++)
            {
                uint result = 0;
                for (int bit = 0; bit < 8; bit++)
                {
                    if ((b & (1 << bit)) != 0)
                    {
                        result ^= columns[(8 * k) + bit];
                    }
                }

                table[(256 * k) + b] = result;
            }
        }

        return table;
    }

    /// <summary>
    /// Burley's nested uniform (Owen) scramble of a 32-bit fraction ("Practical Hash-based Owen Scrambling",
    /// JCGT 9(4), 2020): the Laine–Karras permutation, in which each bit is flipped by a hash of the bits
    /// below it, applied to the bit-reversed value, so that each digit of the fraction is flipped by a hash of
    /// the digits before it. A bijection that preserves every elementary interval structure (nets stay nets).
    /// </summary>
    /// <param name="x">The 32-bit fraction.</param>
    /// <param name="seed">The scramble's seed.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static uint NestedUniformScramble(uint x, uint seed)
    {
        x = ReverseBits(x);
        x += seed;
        x ^= x * LaineKarras1;
        x ^= x * LaineKarras2;
        x ^= x * LaineKarras3;
        x ^= x * LaineKarras4;
        return ReverseBits(x);
    }
}
