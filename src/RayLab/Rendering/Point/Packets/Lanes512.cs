using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace RayLab.Rendering.Point.Packets;

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
        x *= 0x7feb352du;
        x ^= x >>> 15;
        x *= 0x846ca68bu;
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
}
