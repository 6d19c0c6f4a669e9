using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace RayLab.Simd;

/// <summary>8 float lanes (AVX2). See <see cref="ILanes{TSelf}"/>. This file holds what differs per width; the rest is Lanes128.cs, written once.</summary>
internal readonly partial record struct Lanes256
{
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 NegatedMultiplyAdd(Lanes256 a, Lanes256 b, Lanes256 c) =>
        new(Fma.IsSupported ? Fma.MultiplyAddNegated(a.V, b.V, c.V) : c.V - (a.V * b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 MinAbs(Lanes256 smallest, Lanes256 x) =>
        new(Avx512DQ.VL.IsSupported ? Avx512DQ.VL.Range(smallest.V, x.V, 0b1010) : Vector256.MinNative(smallest.V, Vector256.Abs(x.V)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Select(Lanes256 mask, Lanes256 whenTrue, Lanes256 whenFalse) =>
        new(Avx.IsSupported ? Avx.BlendVariable(whenFalse.V, whenTrue.V, mask.V) : Vector256.ConditionalSelect(mask.V, whenTrue.V, whenFalse.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 SelectWhereLess(Lanes256 a, Lanes256 b, Lanes256 whenTrue, Lanes256 whenFalse) => Select(LessThan(a, b), whenTrue, whenFalse);

    public static bool BlendsByMaskRegister => false;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint MaskBits(Lanes256 mask) => mask.V.ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint LessThanOrEqualBits(Lanes256 a, Lanes256 b) => Vector256.LessThanOrEqual(a.V, b.V).ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ShiftRightBitsVariable(Lanes256 bits, Lanes256 counts) =>
        Avx2.IsSupported
            ? new(Avx2.ShiftRightLogicalVariable(bits.V.AsUInt32(), counts.V.AsUInt32()).AsSingle())
            : new(Vector256.Create(
                Lanes128.ShiftRightBitsVariable(new(bits.V.GetLower()), new(counts.V.GetLower())).V,
                Lanes128.ShiftRightBitsVariable(new(bits.V.GetUpper()), new(counts.V.GetUpper())).V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static (Vector256<double> Low, Vector256<double> High) ToDouble(Vector256<int> v) => Avx.IsSupported
        ? (Avx.ConvertToVector256Double(v.GetLower()), Avx.ConvertToVector256Double(v.GetUpper()))
        : (Vector256.ConvertToDouble(Vector256.WidenLower(v)), Vector256.ConvertToDouble(Vector256.WidenUpper(v)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ReverseBits(Lanes256 bits)
    {
        if (Gfni.V256.IsSupported && Avx2.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by one affine transform over
            // GF(2): the matrix whose row i picks bit 7 − i.
            Vector256<byte> reversed = Avx2.Shuffle(bits.V.AsByte(), Vector256.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            return new(Gfni.V256.GaloisFieldAffineTransform(reversed, Vector256.Create(0x8040201008040201ul).AsByte(), 0).AsSingle());
        }

        if (Avx2.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by its two nibbles' lookups.
            Vector256<byte> swapped = Avx2.Shuffle(bits.V.AsByte(), Vector256.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            Vector256<byte> nibble = Vector256.Create((byte)0x0f);
            Vector256<byte> low = Avx2.Shuffle(Vector256.Create(0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0), swapped & nibble);
            Vector256<byte> high = Avx2.Shuffle(Vector256.Create((byte)0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf), (swapped.AsUInt16() >>> 4).AsByte() & nibble);
            return new((low | high).AsSingle());
        }

        return ReverseBitsBySwaps(bits);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static unsafe Lanes256 GatherBits(uint* table, Lanes256 indices) =>
        Avx2.IsSupported
            ? new(Avx2.GatherVector256(table, indices.V.AsInt32(), 4).AsSingle())
            : new(Vector256.Create(Lanes128.GatherBits(table, new(indices.V.GetLower())).V, Lanes128.GatherBits(table, new(indices.V.GetUpper())).V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static unsafe void GatherPairs(uint* table, Lanes256 indices, out Lanes256 first, out Lanes256 second)
    {
        if (Avx2.IsSupported)
        {
            Vector256<float> low = Avx2.GatherVector256((ulong*)table, indices.V.GetLower().AsInt32(), 4).AsSingle();
            Vector256<float> high = Avx2.GatherVector256((ulong*)table, indices.V.GetUpper().AsInt32(), 4).AsSingle();
            Split(low, high, out first, out second);
            return;
        }

        Lanes128.GatherPairs(table, new(indices.V.GetLower()), out Lanes128 firstLow, out Lanes128 secondLow);
        Lanes128.GatherPairs(table, new(indices.V.GetUpper()), out Lanes128 firstHigh, out Lanes128 secondHigh);
        first = new(Vector256.Create(firstLow.V, firstHigh.V));
        second = new(Vector256.Create(secondLow.V, secondHigh.V));
    }

    /// <summary>Lanes 0 … 3 and 4 … 7 as (first, second) pairs of 32 bits in <paramref name="low"/> and <paramref name="high"/>, split into the firsts and the seconds (AVX2).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Split(Vector256<float> low, Vector256<float> high, out Lanes256 first, out Lanes256 second)
    {
        // Within each 128-bit half: low's two pairs, then high's; the 64-bit order 0, 2, 1, 3 puts lanes 0 … 7 in place.
        first = new(Avx2.Permute4x64(Avx.Shuffle(low, high, 0b10_00_10_00).AsDouble(), 0b11_01_10_00).AsSingle());
        second = new(Avx2.Permute4x64(Avx.Shuffle(low, high, 0b11_01_11_01).AsDouble(), 0b11_01_10_00).AsSingle());
    }
}
