using System.Runtime.CompilerServices;

namespace RayLab.Sampling;

/// <summary>
/// Random permutations that need no table: element <c>i</c> of a permutation of 0 … l − 1 chosen by a 32-bit
/// pattern number, computed on its own in a few nanoseconds.
/// </summary>
/// <remarks>
/// This is Andrew Kensler's <c>permute(i, l, p)</c> ("Correlated Multi-Jittered Sampling", Pixar Technical
/// Memo 13-01, 2013), which pbrt-v4 ships unchanged as <c>PermutationElement</c>. A hash that is a bijection on
/// the integers below the next power of two ≥ l (xor with the pattern, multiplication by odd constants, and
/// xor-shifts of the bits kept by the mask) is applied repeatedly until the value falls below l
/// ("cycle walking"), which makes it a bijection on 0 … l − 1; a final rotation by the pattern number finishes it.
/// Different pattern numbers give (practically) independent permutations. The one change from the listing: the
/// final rotation is summed in 64 bits, see the comment there.
/// </remarks>
internal static class Permutation
{
    /// <summary>
    /// Element <paramref name="i"/> of the permutation of 0 … <paramref name="l"/> − 1 selected by
    /// <paramref name="p"/>: for a fixed (l, p) the map i ↦ result is a bijection of 0 … l − 1.
    /// </summary>
    /// <param name="i">The position, 0 ≤ i &lt; l.</param>
    /// <param name="l">The permutation's length, ≥ 1.</param>
    /// <param name="p">The pattern number (any value; usually a hash of the pixel and seed).</param>
    /// <returns>The permuted value, in 0 … l − 1.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static int PermutationElement(int i, int l, uint p)
    {
        uint length = (uint)l;
        uint w = Mask(length);
        uint v = (uint)i;
        do
        {
            v ^= p;
            v *= Kensler.PermuteMultiplier1;
            v ^= p >> 16;
            v ^= (v & w) >> 4;
            v ^= p >> 8;
            v *= Kensler.PermuteMultiplier2;
            v ^= p >> 23;
            v ^= (v & w) >> 1;
            v *= 1u | (p >> 27);
            v *= Kensler.PermuteMultiplier3;
            v ^= (v & w) >> 11;
            v *= Kensler.PermuteMultiplier4;
            v ^= (v & w) >> 2;
            v *= Kensler.PermuteMultiplier5;
            v ^= (v & w) >> 2;
            v *= Kensler.PermuteMultiplier6;
            v &= w;
            v ^= v >> 5;
        }
        while (v >= length);

        // Kensler and pbrt-v4 write (i + p) % l in 32 bits; the sum wraps when p > 2³² − 1 − i, and as 2³² is
        // not a multiple of l the result then repeats values (p = 0xffffffff, l = 3 gives 1, 0, 0). Summing in
        // 64 bits gives Kensler's value whenever his sum does not wrap and keeps the map a bijection always.
        return (int)(((ulong)v + p) % length);
    }

    /// <summary>Kensler's mask w for a permutation of <paramref name="length"/> elements: the next power of two ≥ l, less one.</summary>
    /// <param name="length">l, ≥ 1.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static uint Mask(uint length)
    {
        uint w = length - 1;
        w |= w >> 1;
        w |= w >> 2;
        w |= w >> 4;
        w |= w >> 8;
        w |= w >> 16;
        return w;
    }
}
