using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace RayLab.Simd;

// The operations that read the same at every register width, written once for Vector128. This file is also the
// template of Lanes256 and Lanes512: the build's source generator (src/RayLab.Generators, LanesGenerator) writes
// them from it by renaming Vector128 and Lanes128. What differs per width is in Lanes128.Isa.cs, Lanes256.Isa.cs
// and Lanes512.Isa.cs.
internal readonly partial record struct Lanes128(Vector128<float> V) : ILanes<Lanes128>
{
    public static int Count => Vector128<float>.Count;

    public static bool IsHardwareAccelerated => Vector128.IsHardwareAccelerated;

    public static Lanes128 Indices => new(Vector128<float>.Indices);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Broadcast(float value) => new(Vector128.Create(value));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 operator +(Lanes128 a, Lanes128 b) => new(a.V + b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 operator -(Lanes128 a, Lanes128 b) => new(a.V - b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 operator *(Lanes128 a, Lanes128 b) => new(a.V * b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 operator /(Lanes128 a, Lanes128 b) => new(a.V / b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 operator &(Lanes128 a, Lanes128 b) => new(a.V & b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 operator |(Lanes128 a, Lanes128 b) => new(a.V | b.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 MultiplyAdd(Lanes128 a, Lanes128 b, Lanes128 c) =>
        new(Fma.IsSupported ? Vector128.FusedMultiplyAdd(a.V, b.V, c.V) : (a.V * b.V) + c.V);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Sqrt(Lanes128 x) => new(Vector128.Sqrt(x.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Abs(Lanes128 x) => new(Vector128.Abs(x.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Min(Lanes128 a, Lanes128 b) => new(Vector128.MinNative(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 LessThanOrEqual(Lanes128 a, Lanes128 b) => new(Vector128.LessThanOrEqual(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 LessThan(Lanes128 a, Lanes128 b) => new(Vector128.LessThan(a.V, b.V));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Load(ReadOnlySpan<float> source) => new(Vector128.Create(source));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Store(Span<float> destination) => V.CopyTo(destination);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void StoreRgb(Lanes128 red, Lanes128 green, Lanes128 blue, Span<uint> destination)
    {
        Vector128<uint> r = Vector128.ConvertToInt32Native(red.V).AsUInt32();
        Vector128<uint> g = Vector128.ConvertToInt32Native(green.V).AsUInt32();
        Vector128<uint> b = Vector128.ConvertToInt32Native(blue.V).AsUInt32();
        (r | (g << 8) | (b << 16)).CopyTo(destination);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 BroadcastBits(uint bits) => new(Vector128.Create(bits).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 SequenceBits(uint start) => new((Vector128.Create(start) + Vector128<uint>.Indices).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Xor(Lanes128 a, Lanes128 b) => new(a.V ^ b.V);

    /// <summary>lowbias32's first multiplier (<see cref="Sampling.CounterHash.Multiplier1"/>; the lane tests hold the two equal).</summary>
    private const uint HashMultiplier1 = 0x7feb352du;

    /// <summary>lowbias32's second multiplier (<see cref="Sampling.CounterHash.Multiplier2"/>).</summary>
    private const uint HashMultiplier2 = 0x846ca68bu;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Hash(Lanes128 bits)
    {
        Vector128<uint> x = bits.V.AsUInt32();
        x ^= x >>> 16;
        x *= HashMultiplier1;
        x ^= x >>> 15;
        x *= HashMultiplier2;
        x ^= x >>> 16;
        return new(x.AsSingle());
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 ToUnit(Lanes128 bits) => new(Top24(bits).V * (1f / 16777216f));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 Top24(Lanes128 bits) => new(Vector128.ConvertToSingle((bits.V.AsUInt32() >>> 8).AsInt32()));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 AddBits(Lanes128 a, Lanes128 b) => new((a.V.AsUInt32() + b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 SubtractBits(Lanes128 a, Lanes128 b) => new((a.V.AsUInt32() - b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 MultiplyBits(Lanes128 a, Lanes128 b) => new((a.V.AsUInt32() * b.V.AsUInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 ShiftLeftBits(Lanes128 bits, int count) => new((bits.V.AsUInt32() << count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 ShiftRightBits(Lanes128 bits, int count) => new((bits.V.AsUInt32() >>> count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 MultiplyHalves(Lanes128 a, Lanes128 b) => new((a.V.AsUInt16() * b.V.AsUInt16()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 ShiftRightHalves(Lanes128 bits, int count) => new((bits.V.AsUInt16() >>> count).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 LessThanBits(Lanes128 a, Lanes128 b) => new(Vector128.LessThan(a.V.AsInt32(), b.V.AsInt32()).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 BitsToFloat(Lanes128 bits) => new(Vector128.ConvertToSingle(bits.V.AsInt32()));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 TruncateToBits(Lanes128 x) => new(Vector128.ConvertToInt32Native(x.V).AsSingle());

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 InDouble<TF>(in TF formula, Lanes128 a, Lanes128 b, Lanes128 c, Lanes128 d)
        where TF : struct, IDoubleFormula
    {
        (Vector128<double> aLow, Vector128<double> aHigh) = Vector128.Widen(a.V);
        (Vector128<double> bLow, Vector128<double> bHigh) = Vector128.Widen(b.V);
        (Vector128<double> cLow, Vector128<double> cHigh) = Vector128.Widen(c.V);
        (Vector128<double> dLow, Vector128<double> dHigh) = Vector128.Widen(d.V);
        return new(Vector128.Narrow(formula.Apply(aLow, bLow, cLow, dLow), formula.Apply(aHigh, bHigh, cHigh, dHigh)));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Lanes128 InDoubleFromBits<TF>(in TF formula, Lanes128 a, Lanes128 jitter, Lanes128 c)
        where TF : struct, IDoubleFormula
    {
        (Vector128<double> aLow, Vector128<double> aHigh) = ToDouble(a.V.AsInt32());
        (Vector128<double> jLow, Vector128<double> jHigh) = ToDouble((jitter.V.AsUInt32() ^ Vector128.Create(0x80000000u)).AsInt32());
        (Vector128<double> cLow, Vector128<double> cHigh) = ToDouble(c.V.AsInt32());
        Vector128<double> offset = Vector128.Create(2147483648.0);
        return new(Vector128.Narrow(formula.Apply(aLow, jLow + offset, cLow, default), formula.Apply(aHigh, jHigh + offset, cHigh, default)));
    }

    /// <summary>The bit reversal by five swaps of halves, for hardware without a byte shuffle.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Lanes128 ReverseBitsBySwaps(Lanes128 bits)
    {
        Vector128<uint> x = bits.V.AsUInt32();
        x = (x << 16) | (x >>> 16);
        x = ((x & Vector128.Create(0x00ff00ffu)) << 8) | ((x >>> 8) & Vector128.Create(0x00ff00ffu));
        x = ((x & Vector128.Create(0x0f0f0f0fu)) << 4) | ((x >>> 4) & Vector128.Create(0x0f0f0f0fu));
        x = ((x & Vector128.Create(0x33333333u)) << 2) | ((x >>> 2) & Vector128.Create(0x33333333u));
        x = ((x & Vector128.Create(0x55555555u)) << 1) | ((x >>> 1) & Vector128.Create(0x55555555u));
        return new(x.AsSingle());
    }
}
