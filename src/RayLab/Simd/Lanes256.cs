using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using RayLab.Sampling;

namespace RayLab.Simd;

/// <summary>8 float lanes (AVX2). See <see cref="ILanes{TSelf}"/>.</summary>
/// <param name="V">The register.</param>
internal readonly record struct Lanes256(Vector256<float> V) : ILanes<Lanes256>
{
    public static int Count => Vector256<float>.Count;

    public static bool IsHardwareAccelerated => Vector256.IsHardwareAccelerated;

    public static Lanes256 Indices => new(Vector256<float>.Indices);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Broadcast(float value) => new(Vector256.Create(value));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 operator +(Lanes256 a, Lanes256 b) => new(a.V + b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 operator -(Lanes256 a, Lanes256 b) => new(a.V - b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 operator *(Lanes256 a, Lanes256 b) => new(a.V * b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 operator /(Lanes256 a, Lanes256 b) => new(a.V / b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 operator &(Lanes256 a, Lanes256 b) => new(a.V & b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 operator |(Lanes256 a, Lanes256 b) => new(a.V | b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 MultiplyAdd(Lanes256 a, Lanes256 b, Lanes256 c) =>
        new(Fma.IsSupported ? Vector256.FusedMultiplyAdd(a.V, b.V, c.V) : (a.V * b.V) + c.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 NegatedMultiplyAdd(Lanes256 a, Lanes256 b, Lanes256 c) =>
        new(Fma.IsSupported ? Fma.MultiplyAddNegated(a.V, b.V, c.V) : c.V - (a.V * b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Sqrt(Lanes256 x) => new(Vector256.Sqrt(x.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Abs(Lanes256 x) => new(Vector256.Abs(x.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 MinAbs(Lanes256 smallest, Lanes256 x) =>
        new(Avx512DQ.VL.IsSupported ? Avx512DQ.VL.Range(smallest.V, x.V, 0b1010) : Vector256.MinNative(smallest.V, Vector256.Abs(x.V)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Min(Lanes256 a, Lanes256 b) => new(Vector256.MinNative(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 LessThanOrEqual(Lanes256 a, Lanes256 b) => new(Vector256.LessThanOrEqual(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 LessThan(Lanes256 a, Lanes256 b) => new(Vector256.LessThan(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Select(Lanes256 mask, Lanes256 whenTrue, Lanes256 whenFalse) =>
        new(Avx.IsSupported ? Avx.BlendVariable(whenFalse.V, whenTrue.V, mask.V) : Vector256.ConditionalSelect(mask.V, whenTrue.V, whenFalse.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint MaskBits(Lanes256 mask) => mask.V.ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Load(ReadOnlySpan<float> source) => new(Vector256.Create(source));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Store(Span<float> destination) => V.CopyTo(destination);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void StoreRgb(Lanes256 red, Lanes256 green, Lanes256 blue, Span<uint> destination)
    {
        Vector256<uint> r = Vector256.ConvertToInt32Native(red.V).AsUInt32();
        Vector256<uint> g = Vector256.ConvertToInt32Native(green.V).AsUInt32();
        Vector256<uint> b = Vector256.ConvertToInt32Native(blue.V).AsUInt32();
        (r | (g << 8) | (b << 16)).CopyTo(destination);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 BroadcastBits(uint bits) => new(Vector256.Create(bits).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 SequenceBits(uint start) => new((Vector256.Create(start) + Vector256<uint>.Indices).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Xor(Lanes256 a, Lanes256 b) => new(a.V ^ b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Hash(Lanes256 bits)
    {
        Vector256<uint> x = bits.V.AsUInt32();
        x ^= x >>> 16;
        x *= CounterHash.Multiplier1;
        x ^= x >>> 15;
        x *= CounterHash.Multiplier2;
        x ^= x >>> 16;
        return new(x.AsSingle());
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ToUnit(Lanes256 bits) => new(Top24(bits).V * (1f / 16777216f));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 Top24(Lanes256 bits) => new(Vector256.ConvertToSingle((bits.V.AsUInt32() >>> 8).AsInt32()));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 AddBits(Lanes256 a, Lanes256 b) => new((a.V.AsUInt32() + b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 SubtractBits(Lanes256 a, Lanes256 b) => new((a.V.AsUInt32() - b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 MultiplyBits(Lanes256 a, Lanes256 b) => new((a.V.AsUInt32() * b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ShiftLeftBits(Lanes256 bits, int count) => new((bits.V.AsUInt32() << count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ShiftRightBits(Lanes256 bits, int count) => new((bits.V.AsUInt32() >>> count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ShiftRightBitsVariable(Lanes256 bits, Lanes256 counts) =>
        Avx2.IsSupported
            ? new(Avx2.ShiftRightLogicalVariable(bits.V.AsUInt32(), counts.V.AsUInt32()).AsSingle())
            : new(Vector256.Create(
                Lanes128.ShiftRightBitsVariable(new(bits.V.GetLower()), new(counts.V.GetLower())).V,
                Lanes128.ShiftRightBitsVariable(new(bits.V.GetUpper()), new(counts.V.GetUpper())).V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 LessThanBits(Lanes256 a, Lanes256 b) => new(Vector256.LessThan(a.V.AsInt32(), b.V.AsInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 BitsToFloat(Lanes256 bits) => new(Vector256.ConvertToSingle(bits.V.AsInt32()));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 TruncateToBits(Lanes256 x) => new(Vector256.ConvertToInt32Native(x.V).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 InDouble<TF>(in TF formula, Lanes256 a, Lanes256 b, Lanes256 c, Lanes256 d)
        where TF : struct, IDoubleFormula
    {
        (Vector256<double> aLow, Vector256<double> aHigh) = Vector256.Widen(a.V);
        (Vector256<double> bLow, Vector256<double> bHigh) = Vector256.Widen(b.V);
        (Vector256<double> cLow, Vector256<double> cHigh) = Vector256.Widen(c.V);
        (Vector256<double> dLow, Vector256<double> dHigh) = Vector256.Widen(d.V);
        return new(Vector256.Narrow(formula.Apply(aLow, bLow, cLow, dLow), formula.Apply(aHigh, bHigh, cHigh, dHigh)));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 InDoubleFromBits<TF>(in TF formula, Lanes256 a, Lanes256 jitter, Lanes256 c)
        where TF : struct, IDoubleFormula
    {
        (Vector256<double> aLow, Vector256<double> aHigh) = ToDouble(a.V.AsInt32());
        (Vector256<double> jLow, Vector256<double> jHigh) = ToDouble((jitter.V.AsUInt32() ^ Vector256.Create(0x80000000u)).AsInt32());
        (Vector256<double> cLow, Vector256<double> cHigh) = ToDouble(c.V.AsInt32());
        Vector256<double> offset = Vector256.Create(2147483648.0);
        return new(Vector256.Narrow(formula.Apply(aLow, jLow + offset, cLow, default), formula.Apply(aHigh, jHigh + offset, cHigh, default)));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static (Vector256<double> Low, Vector256<double> High) ToDouble(Vector256<int> v) => Avx.IsSupported
        ? (Avx.ConvertToVector256Double(v.GetLower()), Avx.ConvertToVector256Double(v.GetUpper()))
        : (Vector256.ConvertToDouble(Vector256.WidenLower(v)), Vector256.ConvertToDouble(Vector256.WidenUpper(v)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes256 ReverseBits(Lanes256 bits)
    {
        if (Avx2.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by its two nibbles' lookups.
            Vector256<byte> swapped = Avx2.Shuffle(bits.V.AsByte(), Vector256.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            Vector256<byte> nibble = Vector256.Create((byte)0x0f);
            Vector256<byte> low = Avx2.Shuffle(Vector256.Create(0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0), swapped & nibble);
            Vector256<byte> high = Avx2.Shuffle(Vector256.Create((byte)0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf), (swapped.AsUInt16() >>> 4).AsByte() & nibble);
            return new((low | high).AsSingle());
        }

        Vector256<uint> x = bits.V.AsUInt32();
        x = (x << 16) | (x >>> 16);
        x = ((x & Vector256.Create(0x00ff00ffu)) << 8) | ((x >>> 8) & Vector256.Create(0x00ff00ffu));
        x = ((x & Vector256.Create(0x0f0f0f0fu)) << 4) | ((x >>> 4) & Vector256.Create(0x0f0f0f0fu));
        x = ((x & Vector256.Create(0x33333333u)) << 2) | ((x >>> 2) & Vector256.Create(0x33333333u));
        x = ((x & Vector256.Create(0x55555555u)) << 1) | ((x >>> 1) & Vector256.Create(0x55555555u));
        return new(x.AsSingle());
    }
}
