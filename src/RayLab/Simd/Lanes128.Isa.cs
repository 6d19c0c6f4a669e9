using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace RayLab.Simd;

/// <summary>4 float lanes (SSE or Arm NEON). See <see cref="ILanes{TSelf}"/>. This file holds what differs per width; the rest is Lanes128.cs, written once.</summary>
internal readonly partial record struct Lanes128
{
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 NegatedMultiplyAdd(Lanes128 a, Lanes128 b, Lanes128 c) =>
        new(Fma.IsSupported ? Fma.MultiplyAddNegated(a.V, b.V, c.V) : c.V - (a.V * b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 MinAbs(Lanes128 smallest, Lanes128 x) =>
        new(Avx512DQ.VL.IsSupported ? Avx512DQ.VL.Range(smallest.V, x.V, 0b1010) : Vector128.MinNative(smallest.V, Vector128.Abs(x.V)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Select(Lanes128 mask, Lanes128 whenTrue, Lanes128 whenFalse) =>
        new(Sse41.IsSupported ? Sse41.BlendVariable(whenFalse.V, whenTrue.V, mask.V) : Vector128.ConditionalSelect(mask.V, whenTrue.V, whenFalse.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 SelectWhereLess(Lanes128 a, Lanes128 b, Lanes128 whenTrue, Lanes128 whenFalse) => Select(LessThan(a, b), whenTrue, whenFalse);

    public static bool BlendsByMaskRegister => false;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint MaskBits(Lanes128 mask) => mask.V.ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint LessThanOrEqualBits(Lanes128 a, Lanes128 b) => Vector128.LessThanOrEqual(a.V, b.V).ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 ShiftRightBitsVariable(Lanes128 bits, Lanes128 counts)
    {
        Vector128<uint> b = bits.V.AsUInt32(), c = counts.V.AsUInt32();
        return new((Avx2.IsSupported
            ? Avx2.ShiftRightLogicalVariable(b, c)
            : Vector128.Create(b[0] >> (int)c[0], b[1] >> (int)c[1], b[2] >> (int)c[2], b[3] >> (int)c[3])).AsSingle());
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static (Vector128<double> Low, Vector128<double> High) ToDouble(Vector128<int> v) => Sse2.IsSupported
        ? (Sse2.ConvertToVector128Double(v), Sse2.ConvertToVector128Double(Sse2.UnpackHigh(v.AsInt64(), v.AsInt64()).AsInt32()))
        : (Vector128.ConvertToDouble(Vector128.WidenLower(v)), Vector128.ConvertToDouble(Vector128.WidenUpper(v)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 ReverseBits(Lanes128 bits)
    {
        if (Gfni.IsSupported && Ssse3.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by one affine transform over
            // GF(2): the matrix whose row i picks bit 7 − i.
            Vector128<byte> reversed = Ssse3.Shuffle(bits.V.AsByte(), Vector128.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            return new(Gfni.GaloisFieldAffineTransform(reversed, Vector128.Create(0x8040201008040201ul).AsByte(), 0).AsSingle());
        }

        if (Ssse3.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by its two nibbles' lookups.
            Vector128<byte> swapped = Ssse3.Shuffle(bits.V.AsByte(), Vector128.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            Vector128<byte> nibble = Vector128.Create((byte)0x0f);
            Vector128<byte> low = Ssse3.Shuffle(Vector128.Create(0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0), swapped & nibble);
            Vector128<byte> high = Ssse3.Shuffle(Vector128.Create((byte)0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf), (swapped.AsUInt16() >>> 4).AsByte() & nibble);
            return new((low | high).AsSingle());
        }

        return ReverseBitsBySwaps(bits);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static unsafe Lanes128 GatherBits(uint* table, Lanes128 indices)
    {
        Vector128<int> i = indices.V.AsInt32();
        return Avx2.IsSupported
            ? new(Avx2.GatherVector128(table, i, 4).AsSingle())
            : new(Vector128.Create(table[i.GetElement(0)], table[i.GetElement(1)], table[i.GetElement(2)], table[i.GetElement(3)]).AsSingle());
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static unsafe void GatherPairs(uint* table, Lanes128 indices, out Lanes128 first, out Lanes128 second)
    {
        Vector128<int> i = indices.V.AsInt32();
        if (Avx2.IsSupported)
        {
            // Pairs of lanes 0, 1 and of lanes 2, 3, each pair one 64-bit element, split into the evens and the odds.
            Vector128<float> low = Avx2.GatherVector128((ulong*)table, i, 4).AsSingle();
            Vector128<float> high = Avx2.GatherVector128((ulong*)table, Sse2.Shuffle(i, 0b11_10_11_10), 4).AsSingle();
            first = new(Sse.Shuffle(low, high, 0b10_00_10_00));
            second = new(Sse.Shuffle(low, high, 0b11_01_11_01));
            return;
        }

        first = GatherBits(table, indices);
        second = GatherBits(table + 1, indices);
    }
}
