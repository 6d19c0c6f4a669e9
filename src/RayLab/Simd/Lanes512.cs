using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using RayLab.Sampling;

namespace RayLab.Simd;

/// <summary>16 float lanes (AVX-512). See <see cref="ILanes{TSelf}"/>.</summary>
/// <param name="V">The register.</param>
internal readonly record struct Lanes512(Vector512<float> V) : ILanes<Lanes512>
{
    public static int Count => Vector512<float>.Count;

    public static bool IsHardwareAccelerated => Vector512.IsHardwareAccelerated;

    public static Lanes512 Indices => new(Vector512<float>.Indices);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Broadcast(float value) => new(Vector512.Create(value));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 operator +(Lanes512 a, Lanes512 b) => new(a.V + b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 operator -(Lanes512 a, Lanes512 b) => new(a.V - b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 operator *(Lanes512 a, Lanes512 b) => new(a.V * b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 operator /(Lanes512 a, Lanes512 b) => new(a.V / b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 operator &(Lanes512 a, Lanes512 b) => new(a.V & b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 operator |(Lanes512 a, Lanes512 b) => new(a.V | b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 MultiplyAdd(Lanes512 a, Lanes512 b, Lanes512 c) =>
        new(Fma.IsSupported ? Vector512.FusedMultiplyAdd(a.V, b.V, c.V) : (a.V * b.V) + c.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 NegatedMultiplyAdd(Lanes512 a, Lanes512 b, Lanes512 c) =>
        new(Avx512F.IsSupported ? Avx512F.FusedMultiplyAddNegated(a.V, b.V, c.V) : Fma.IsSupported ? Vector512.FusedMultiplyAdd(-a.V, b.V, c.V) : c.V - (a.V * b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Sqrt(Lanes512 x) => new(Vector512.Sqrt(x.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Abs(Lanes512 x) => new(Vector512.Abs(x.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 MinAbs(Lanes512 smallest, Lanes512 x) =>
        new(Avx512DQ.IsSupported ? Avx512DQ.Range(smallest.V, x.V, 0b1010) : Vector512.MinNative(smallest.V, Vector512.Abs(x.V)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Min(Lanes512 a, Lanes512 b) => new(Vector512.MinNative(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 LessThanOrEqual(Lanes512 a, Lanes512 b) => new(Vector512.LessThanOrEqual(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 LessThan(Lanes512 a, Lanes512 b) => new(Vector512.LessThan(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Select(Lanes512 mask, Lanes512 whenTrue, Lanes512 whenFalse) =>
        new(Vector512.ConditionalSelect(mask.V, whenTrue.V, whenFalse.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint MaskBits(Lanes512 mask) => (uint)mask.V.ExtractMostSignificantBits();

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Load(ReadOnlySpan<float> source) => new(Vector512.Create(source));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Store(Span<float> destination) => V.CopyTo(destination);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void StoreRgb(Lanes512 red, Lanes512 green, Lanes512 blue, Span<uint> destination)
    {
        Vector512<uint> r = Vector512.ConvertToInt32Native(red.V).AsUInt32();
        Vector512<uint> g = Vector512.ConvertToInt32Native(green.V).AsUInt32();
        Vector512<uint> b = Vector512.ConvertToInt32Native(blue.V).AsUInt32();
        (r | (g << 8) | (b << 16)).CopyTo(destination);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 BroadcastBits(uint bits) => new(Vector512.Create(bits).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 SequenceBits(uint start) => new((Vector512.Create(start) + Vector512<uint>.Indices).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Xor(Lanes512 a, Lanes512 b) => new(a.V ^ b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Hash(Lanes512 bits)
    {
        Vector512<uint> x = bits.V.AsUInt32();
        x ^= x >>> 16;
        x *= CounterHash.Multiplier1;
        x ^= x >>> 15;
        x *= CounterHash.Multiplier2;
        x ^= x >>> 16;
        return new(x.AsSingle());
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ToUnit(Lanes512 bits) => new(Top24(bits).V * (1f / 16777216f));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 Top24(Lanes512 bits) => new(Vector512.ConvertToSingle((bits.V.AsUInt32() >>> 8).AsInt32()));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 AddBits(Lanes512 a, Lanes512 b) => new((a.V.AsUInt32() + b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 SubtractBits(Lanes512 a, Lanes512 b) => new((a.V.AsUInt32() - b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 MultiplyBits(Lanes512 a, Lanes512 b) => new((a.V.AsUInt32() * b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ShiftLeftBits(Lanes512 bits, int count) => new((bits.V.AsUInt32() << count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ShiftRightBits(Lanes512 bits, int count) => new((bits.V.AsUInt32() >>> count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ShiftRightBitsVariable(Lanes512 bits, Lanes512 counts) =>
        Avx512F.IsSupported
            ? new(Avx512F.ShiftRightLogicalVariable(bits.V.AsUInt32(), counts.V.AsUInt32()).AsSingle())
            : new(Vector512.Create(
                Lanes256.ShiftRightBitsVariable(new(bits.V.GetLower()), new(counts.V.GetLower())).V,
                Lanes256.ShiftRightBitsVariable(new(bits.V.GetUpper()), new(counts.V.GetUpper())).V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 LessThanBits(Lanes512 a, Lanes512 b) => new(Vector512.LessThan(a.V.AsInt32(), b.V.AsInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 BitsToFloat(Lanes512 bits) => new(Vector512.ConvertToSingle(bits.V.AsInt32()));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 TruncateToBits(Lanes512 x) => new(Vector512.ConvertToInt32Native(x.V).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 InDouble<TF>(in TF formula, Lanes512 a, Lanes512 b, Lanes512 c, Lanes512 d)
        where TF : struct, IDoubleFormula
    {
        (Vector512<double> aLow, Vector512<double> aHigh) = Vector512.Widen(a.V);
        (Vector512<double> bLow, Vector512<double> bHigh) = Vector512.Widen(b.V);
        (Vector512<double> cLow, Vector512<double> cHigh) = Vector512.Widen(c.V);
        (Vector512<double> dLow, Vector512<double> dHigh) = Vector512.Widen(d.V);
        return new(Vector512.Narrow(formula.Apply(aLow, bLow, cLow, dLow), formula.Apply(aHigh, bHigh, cHigh, dHigh)));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 InDoubleFromBits<TF>(in TF formula, Lanes512 a, Lanes512 jitter, Lanes512 c)
        where TF : struct, IDoubleFormula
    {
        (Vector512<double> aLow, Vector512<double> aHigh) = ToDouble(a.V.AsInt32());
        (Vector512<double> jLow, Vector512<double> jHigh) = ToDouble((jitter.V.AsUInt32() ^ Vector512.Create(0x80000000u)).AsInt32());
        (Vector512<double> cLow, Vector512<double> cHigh) = ToDouble(c.V.AsInt32());
        Vector512<double> offset = Vector512.Create(2147483648.0);
        return new(Vector512.Narrow(formula.Apply(aLow, jLow + offset, cLow, default), formula.Apply(aHigh, jHigh + offset, cHigh, default)));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static (Vector512<double> Low, Vector512<double> High) ToDouble(Vector512<int> v) => Avx512F.IsSupported
        ? (Avx512F.ConvertToVector512Double(v.GetLower()), Avx512F.ConvertToVector512Double(v.GetUpper()))
        : (Vector512.ConvertToDouble(Vector512.WidenLower(v)), Vector512.ConvertToDouble(Vector512.WidenUpper(v)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes512 ReverseBits(Lanes512 bits)
    {
        if (Avx512BW.IsSupported)
        {
            // The bytes of each lane in reverse order, then each byte's bits reversed by its two nibbles' lookups.
            Vector512<byte> swapped = Avx512BW.Shuffle(bits.V.AsByte(), Vector512.Create((byte)3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
            Vector512<byte> nibble = Vector512.Create((byte)0x0f);
            Vector512<byte> low = Avx512BW.Shuffle(Vector512.Create(0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0), swapped & nibble);
            Vector512<byte> high = Avx512BW.Shuffle(Vector512.Create((byte)0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf), (swapped.AsUInt16() >>> 4).AsByte() & nibble);
            return new((low | high).AsSingle());
        }

        Vector512<uint> x = bits.V.AsUInt32();
        x = (x << 16) | (x >>> 16);
        x = ((x & Vector512.Create(0x00ff00ffu)) << 8) | ((x >>> 8) & Vector512.Create(0x00ff00ffu));
        x = ((x & Vector512.Create(0x0f0f0f0fu)) << 4) | ((x >>> 4) & Vector512.Create(0x0f0f0f0fu));
        x = ((x & Vector512.Create(0x33333333u)) << 2) | ((x >>> 2) & Vector512.Create(0x33333333u));
        x = ((x & Vector512.Create(0x55555555u)) << 1) | ((x >>> 1) & Vector512.Create(0x55555555u));
        return new(x.AsSingle());
    }
}
