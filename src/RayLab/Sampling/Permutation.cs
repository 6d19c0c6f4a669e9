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
        var w = new ScalarLane(Mask(length), 0);
        var key = new PermutationKey<ScalarLane, ScalarMath>(new ScalarLane(p, 0));
        uint v = (uint)i;
        do
        {
            v = key.Round(new ScalarLane(v, 0), w).Bits;
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

/// <summary>
/// A pattern number p of <see cref="Permutation.PermutationElement"/> and what every round of its cycle walk takes
/// from it, made once: one permutation (<see cref="ScalarMath"/>) or one per lane (<see cref="LaneMath{TL}"/>).
/// </summary>
/// <typeparam name="TV">One pixel's value or one per lane.</typeparam>
/// <typeparam name="TM">Its arithmetic.</typeparam>
internal readonly struct PermutationKey<TV, TM>
    where TV : struct
    where TM : IPointMath<TV>
{
    private readonly TV _p, _p16, _p8, _p23, _multiplier;

    /// <summary>The key of pattern number <paramref name="p"/>.</summary>
    /// <param name="p">The pattern number.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public PermutationKey(TV p)
    {
        _p = p;
        _p16 = TM.ShiftRightBits(p, 16);
        _p8 = TM.ShiftRightBits(p, 8);
        _p23 = TM.ShiftRightBits(p, 23);

        // The listing multiplies by 1 | (p ≫ 27) and then by Kensler.PermuteMultiplier3; products modulo 2³²
        // associate, so one multiplier does both.
        _multiplier = TM.MultiplyBits(TM.Or(TM.ShiftRightBits(p, 27), TM.BroadcastBits(1)), TM.BroadcastBits(Kensler.PermuteMultiplier3));
    }

    /// <summary>One round of Kensler's hash of <paramref name="v"/> under mask <paramref name="w"/>: a bijection on 0 … w.</summary>
    /// <param name="v">The value, ≤ w.</param>
    /// <param name="w">The mask: the next power of two ≥ l, less one.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public TV Round(TV v, TV w)
    {
        v = TM.Xor(v, _p);
        v = TM.MultiplyBits(v, TM.BroadcastBits(Kensler.PermuteMultiplier1));
        v = TM.Xor(v, _p16);
        v = TM.Xor(v, TM.ShiftRightBits(TM.And(v, w), 4));
        v = TM.Xor(v, _p8);
        v = TM.MultiplyBits(v, TM.BroadcastBits(Kensler.PermuteMultiplier2));
        v = TM.Xor(v, _p23);
        v = TM.Xor(v, TM.ShiftRightBits(TM.And(v, w), 1));
        v = TM.MultiplyBits(v, _multiplier);
        v = TM.Xor(v, TM.ShiftRightBits(TM.And(v, w), 11));
        v = TM.MultiplyBits(v, TM.BroadcastBits(Kensler.PermuteMultiplier4));
        v = TM.Xor(v, TM.ShiftRightBits(TM.And(v, w), 2));
        v = TM.MultiplyBits(v, TM.BroadcastBits(Kensler.PermuteMultiplier5));
        v = TM.Xor(v, TM.ShiftRightBits(TM.And(v, w), 2));
        v = TM.MultiplyBits(v, TM.BroadcastBits(Kensler.PermuteMultiplier6));
        v = TM.And(v, w);
        return TM.Xor(v, TM.ShiftRightBits(v, 5));
    }
}
