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
    internal static uint SobolDimension1(uint index)
    {
        uint v = 0x80000000u, result = 0;
        for (; index != 0; index >>= 1, v ^= v >> 1)
        {
            if ((index & 1) != 0)
            {
                result ^= v;
            }
        }

        return result;
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
        x ^= x * 0x6c50b47cu;
        x ^= x * 0xb82f1e52u;
        x ^= x * 0xc7afe638u;
        x ^= x * 0x8d22f6e6u;
        return ReverseBits(x);
    }
}
