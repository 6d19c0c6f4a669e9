using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace RayLab.Simd;

/// <summary>16 float lanes (AVX-512). See <see cref="ILanes{TSelf}"/>. This file holds what differs per width; the rest is Lanes128.cs, written once.</summary>
internal readonly partial record struct Lanes512
{
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 NegatedMultiplyAdd(Lanes512 a, Lanes512 b, Lanes512 c) =>
        new(Avx512F.IsSupported ? Avx512F.FusedMultiplyAddNegated(a.V, b.V, c.V) : Fma.IsSupported ? Vector512.FusedMultiplyAdd(-a.V, b.V, c.V) : c.V - (a.V * b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 MinAbs(Lanes512 smallest, Lanes512 x) =>
        new(Avx512DQ.IsSupported ? Avx512DQ.Range(smallest.V, x.V, 0b1010) : Vector512.MinNative(smallest.V, Vector512.Abs(x.V)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Select(Lanes512 mask, Lanes512 whenTrue, Lanes512 whenFalse) =>
        new(Vector512.ConditionalSelect(mask.V, whenTrue.V, whenFalse.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 SelectWhereLess(Lanes512 a, Lanes512 b, Lanes512 whenTrue, Lanes512 whenFalse) =>
        new(Avx512F.IsSupported ? Avx512F.BlendVariable(whenFalse.V, whenTrue.V, Vector512.LessThan(a.V, b.V)) : Vector512.ConditionalSelect(Vector512.LessThan(a.V, b.V), whenTrue.V, whenFalse.V));

    public static bool BlendsByMaskRegister => Avx512F.IsSupported;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint MaskBits(Lanes512 mask) => (uint)mask.V.ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint LessThanOrEqualBits(Lanes512 a, Lanes512 b) => (uint)Vector512.LessThanOrEqual(a.V, b.V).ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ShiftRightBitsVariable(Lanes512 bits, Lanes512 counts) =>
        Avx512F.IsSupported
            ? new(Avx512F.ShiftRightLogicalVariable(bits.V.AsUInt32(), counts.V.AsUInt32()).AsSingle())
            : new(Vector512.Create(
                Lanes256.ShiftRightBitsVariable(new(bits.V.GetLower()), new(counts.V.GetLower())).V,
                Lanes256.ShiftRightBitsVariable(new(bits.V.GetUpper()), new(counts.V.GetUpper())).V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static (Vector512<double> Low, Vector512<double> High) ToDouble(Vector512<int> v) => Avx512F.IsSupported
        ? (Avx512F.ConvertToVector512Double(v.GetLower()), Avx512F.ConvertToVector512Double(v.GetUpper()))
        : (Vector512.ConvertToDouble(Vector512.WidenLower(v)), Vector512.ConvertToDouble(Vector512.WidenUpper(v)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ReverseBits(Lanes512 bits)
    {
        if (Gfni.V512.IsSupported && Avx512BW.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by one affine transform over
            // GF(2): the matrix whose row i picks bit 7 − i.
            Vector512<byte> reversed = Avx512BW.Shuffle(bits.V.AsByte(), Vector512.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            return new(Gfni.V512.GaloisFieldAffineTransform(reversed, Vector512.Create(0x8040201008040201ul).AsByte(), 0).AsSingle());
        }

        if (Avx512BW.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by its two nibbles' lookups.
            Vector512<byte> swapped = Avx512BW.Shuffle(bits.V.AsByte(), Vector512.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            Vector512<byte> nibble = Vector512.Create((byte)0x0f);
            Vector512<byte> low = Avx512BW.Shuffle(Vector512.Create(0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0), swapped & nibble);
            Vector512<byte> high = Avx512BW.Shuffle(Vector512.Create((byte)0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf), (swapped.AsUInt16() >>> 4).AsByte() & nibble);
            return new((low | high).AsSingle());
        }

        return ReverseBitsBySwaps(bits);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static unsafe Lanes512 GatherBits(uint* table, Lanes512 indices) =>
        new(Vector512.Create(Lanes256.GatherBits(table, new(indices.V.GetLower())).V, Lanes256.GatherBits(table, new(indices.V.GetUpper())).V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static unsafe void GatherPairs(uint* table, Lanes512 indices, out Lanes512 first, out Lanes512 second)
    {
        if (Avx2.IsSupported && Avx512F.IsSupported)
        {
            // Four 64-bit gathers of four pairs each, lanes 0 … 7 and 8 … 15 side by side, then one two-source permute
            // each for the firsts (the even 32-bit elements) and the seconds (the odd ones).
            Vector256<int> low = indices.V.GetLower().AsInt32(), high = indices.V.GetUpper().AsInt32();
            Vector512<uint> pairsLow = Vector512.Create(
                Avx2.GatherVector256((ulong*)table, low.GetLower(), 4), Avx2.GatherVector256((ulong*)table, low.GetUpper(), 4)).AsUInt32();
            Vector512<uint> pairsHigh = Vector512.Create(
                Avx2.GatherVector256((ulong*)table, high.GetLower(), 4), Avx2.GatherVector256((ulong*)table, high.GetUpper(), 4)).AsUInt32();
            first = new(Avx512F.PermuteVar16x32x2(pairsLow, Vector512.Create(0u, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30), pairsHigh).AsSingle());
            second = new(Avx512F.PermuteVar16x32x2(pairsLow, Vector512.Create(1u, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31), pairsHigh).AsSingle());
            return;
        }

        Lanes256.GatherPairs(table, new(indices.V.GetLower()), out Lanes256 firstLow, out Lanes256 secondLow);
        Lanes256.GatherPairs(table, new(indices.V.GetUpper()), out Lanes256 firstHigh, out Lanes256 secondHigh);
        first = new(Vector512.Create(firstLow.V, firstHigh.V));
        second = new(Vector512.Create(secondLow.V, secondHigh.V));
    }
}
