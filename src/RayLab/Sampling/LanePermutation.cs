using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// One of Kensler's permutations (<see cref="Permutation.PermutationElement"/>) per lane: the lane's pattern
/// number and the values derived from it that every element of that permutation needs, made once per packet.
/// </summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal struct LanePermutation<TL>
    where TL : struct, ILanes<TL>
{
    private PermutationKey<TL, LaneMath<TL>> _key;
    private TL _rotation;

    /// <summary>Sets the lanes' pattern numbers.</summary>
    /// <param name="patterns">Each lane's pattern number p.</param>
    /// <param name="length">The permutations' common length l.</param>
    /// <param name="scratch">Room for <see cref="ILanes{TSelf}.Count"/> values.</param>
    public void Set(TL patterns, in LaneLength<TL> length, Span<uint> scratch)
    {
        _key = new PermutationKey<TL, LaneMath<TL>>(patterns);
        TL p = patterns;

        // The final rotation (v + p) mod l, with v < l, is v + (p mod l) less l if that reaches l: p mod l is
        // made here once per pixel, a mask when l is a power of two, else Lemire's multiply-only remainder.
        if (length.IsPowerOfTwo)
        {
            _rotation = p & length.Last;
        }
        else
        {
            p.Store(MemoryMarshal.Cast<uint, float>(scratch));
            for (int lane = 0; lane < scratch.Length; lane++)
            {
                scratch[lane] = length.Remainder(scratch[lane]);
            }

            _rotation = TL.Load(MemoryMarshal.Cast<uint, float>(scratch));
        }
    }

    /// <summary>
    /// Element <paramref name="i"/> of each lane's permutation, bit for bit the scalar one. With l a power of two
    /// one round always lands below l and this is inlined; otherwise it calls <see cref="Walk"/>.
    /// </summary>
    /// <param name="i">Each lane's position, 0 ≤ i &lt; l.</param>
    /// <param name="length">The lengths l (all lanes equal, l ≤ 2³⁰).</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly TL Element(TL i, in LaneLength<TL> length)
    {
        if (length.IsPowerOfTwo)
        {
            // w = l − 1: the rotation wraps with the mask.
            TL w = length.Mask;
            return TL.AddBits(Round(i, w), _rotation) & w;
        }

        return Walk(i, length);
    }

    /// <summary>
    /// <see cref="Element"/> of two permutations at once. Each round is a chain of dependent multiplies, so its
    /// latency, not its instruction count, sets the time; two independent chains side by side overlap. With both
    /// lengths powers of two (one round each) the two chains are written out here; otherwise each is an
    /// <see cref="Element"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static (TL A, TL B) Pair(in LanePermutation<TL> a, TL ia, in LaneLength<TL> la, in LanePermutation<TL> b, TL ib, in LaneLength<TL> lb)
    {
        if (la.IsPowerOfTwo && lb.IsPowerOfTwo)
        {
            TL wa = la.Mask, wb = lb.Mask;
            TL va = a.Round(ia, wa);
            TL vb = b.Round(ib, wb);
            return (TL.AddBits(va, a._rotation) & wa, TL.AddBits(vb, b._rotation) & wb);
        }

        return Apart(a, ia, la, b, ib, lb);
    }

    /// <summary><see cref="Pair"/> when a length is not a power of two: two <see cref="Element"/>s, in a call of its own (inlined, the JIT's inlining budget runs out).</summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static (TL A, TL B) Apart(in LanePermutation<TL> a, TL ia, in LaneLength<TL> la, in LanePermutation<TL> b, TL ib, in LaneLength<TL> lb) =>
        (a.Element(ia, la), b.Element(ib, lb));

    /// <summary>
    /// Kensler's cycle walking for a length that is not a power of two: a loop that runs until every lane has left
    /// the range [l, w], lanes that are done kept as they are.
    /// </summary>
    /// <remarks>A call of its own: inlined into a sampler's stage beside the power-of-two rounds it would use up the JIT's inlining budget.</remarks>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private readonly TL Walk(TL i, in LaneLength<TL> length)
    {
        TL w = length.Mask, last = length.Last;
        TL v = i;
        TL pending = TL.BroadcastBits(uint.MaxValue);
        do
        {
            TL next = Round(v, w);
            v = TL.Select(pending, next, v);
            pending = TL.LessThanBits(last, v);
        }
        while (TL.MaskBits(pending) != 0);

        TL rotated = TL.AddBits(v, _rotation);
        return TL.Select(TL.LessThanBits(last, rotated), TL.SubtractBits(rotated, length.Length), rotated);
    }

    /// <summary>One round of the cycle walk, <see cref="PermutationKey{TV, TM}.Round"/>, in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private readonly TL Round(TL v, TL w) => _key.Round(v, w);
}

/// <summary>
/// Two of Kensler's permutations of one length l, a power of two ≤ 2¹⁵, side by side: one in the low 16-bit half of
/// every lane, the other in the high half. A round's low 16 bits depend only on the low 16 bits of its inputs (its
/// multiplies keep low bits, its right shifts act on values masked below l), so each half computes its own
/// permutation's element, bit for bit, with 16-bit multiplies and shifts: one round for two elements.
/// </summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal struct LanePermutationPair<TL>
    where TL : struct, ILanes<TL>
{
    private TL _p, _p16, _p8, _p23, _multiplier, _rotation;

    /// <summary>True when a pair of permutations of length <paramref name="length"/> fits the halves: a power of two ≤ 2¹⁵.</summary>
    public static bool Fits(int length) => int.IsPow2(length) && length <= 1 << 15;

    /// <summary>Both halves' mask w = l − 1 for a length that <see cref="Fits"/>.</summary>
    public static TL Mask(int length) => TL.BroadcastBits((uint)(length - 1) * 0x10001u);

    /// <summary>The low 16 bits of <paramref name="i"/> in both halves.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Both(uint i) => TL.BroadcastBits((i & 0xffffu) * 0x10001u);

    /// <summary>
    /// Sets the pair from each lane's two pattern numbers: <paramref name="low"/>'s permutation in the low halves,
    /// <paramref name="high"/>'s in the high ones, both of length <paramref name="length"/> (one that <see cref="Fits"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Set(TL low, TL high, int length)
    {
        TL lowHalf = TL.BroadcastBits(0xffffu), highHalf = TL.BroadcastBits(0xffff0000u);
        _p = (low & lowHalf) | TL.ShiftLeftBits(high, 16);
        _p16 = TL.ShiftRightBits(low, 16) | (high & highHalf);
        _p8 = (TL.ShiftRightBits(low, 8) & lowHalf) | (TL.ShiftLeftBits(high, 8) & highHalf);
        _p23 = TL.ShiftRightBits(low, 23) | TL.ShiftLeftBits(TL.ShiftRightBits(high, 23), 16);
        _multiplier = (Multiplier(low) & lowHalf) | TL.ShiftLeftBits(Multiplier(high), 16);
        TL last = TL.BroadcastBits((uint)length - 1);
        _rotation = (low & last) | TL.ShiftLeftBits(high & last, 16);
    }

    /// <summary>
    /// Element (low half of <paramref name="i"/>) of the low permutation and element (high half) of the high one, in
    /// their halves; <paramref name="w"/> is <see cref="Mask"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly TL Elements(TL i, TL w)
    {
        TL v = TL.Xor(i, _p);
        v = TL.MultiplyHalves(v, Both(Kensler.PermuteMultiplier1));
        v = TL.Xor(v, _p16);
        v = TL.Xor(v, TL.ShiftRightHalves(v & w, 4));
        v = TL.Xor(v, _p8);
        v = TL.MultiplyHalves(v, Both(Kensler.PermuteMultiplier2));
        v = TL.Xor(v, _p23);
        v = TL.Xor(v, TL.ShiftRightHalves(v & w, 1));
        v = TL.MultiplyHalves(v, _multiplier);
        v = TL.Xor(v, TL.ShiftRightHalves(v & w, 11));
        v = TL.MultiplyHalves(v, Both(Kensler.PermuteMultiplier4));
        v = TL.Xor(v, TL.ShiftRightHalves(v & w, 2));
        v = TL.MultiplyHalves(v, Both(Kensler.PermuteMultiplier5));
        v = TL.Xor(v, TL.ShiftRightHalves(v & w, 2));
        v = TL.MultiplyHalves(v, Both(Kensler.PermuteMultiplier6));
        v &= w;
        v = TL.Xor(v, TL.ShiftRightHalves(v, 5));

        // The rotation (v + p) mod l: v and p mod l are below l ≤ 2¹⁵, so the low half's sum does not carry into the high half.
        return TL.AddBits(v, _rotation) & w;
    }

    /// <summary>The low half of each lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Low(TL both) => both & TL.BroadcastBits(0xffffu);

    /// <summary>The high half of each lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL High(TL both) => TL.ShiftRightBits(both, 16);

    /// <summary>A round's pattern multiplier, (1 | (p ≫ 27)) · <see cref="Kensler.PermuteMultiplier3"/> (<see cref="PermutationKey{TV, TM}"/>'s).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL Multiplier(TL p) => TL.MultiplyBits(TL.ShiftRightBits(p, 27) | TL.BroadcastBits(1), TL.BroadcastBits(Kensler.PermuteMultiplier3));
}

/// <summary>A permutation length l in every lane, with l − 1 and Kensler's mask w (the next power of two ≥ l, less one).</summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal readonly struct LaneLength<TL>
    where TL : struct, ILanes<TL>
{
    private readonly uint _length;
    private readonly ulong _remainderMultiplier;

    /// <summary>Broadcasts <paramref name="length"/> (1 … 2³⁰) and the values derived from it.</summary>
    /// <param name="length">The permutation length.</param>
    public LaneLength(int length)
    {
        _length = (uint)length;
        _remainderMultiplier = unchecked((ulong.MaxValue / _length) + 1);
        IsPowerOfTwo = int.IsPow2(length);
        Length = TL.BroadcastBits((uint)length);
        Last = TL.BroadcastBits((uint)length - 1);
        Mask = TL.BroadcastBits(Permutation.Mask((uint)length));
    }

    /// <summary>True when l is a power of two (p mod l is p and (l − 1)).</summary>
    public bool IsPowerOfTwo { get; }

    /// <summary>l.</summary>
    public TL Length { get; }

    /// <summary>l − 1.</summary>
    public TL Last { get; }

    /// <summary>w.</summary>
    public TL Mask { get; }

    /// <summary>
    /// <paramref name="p"/> mod l without a division (Lemire, Kaser and Kurz, "Faster remainder by direct
    /// computation", 2019: exact for every 32-bit p and l).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public uint Remainder(uint p) => (uint)Math.BigMul(unchecked(_remainderMultiplier * p), _length, out _);
}
