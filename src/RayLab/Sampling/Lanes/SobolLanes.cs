using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling.Lanes;

/// <summary>
/// <see cref="SobolSampler"/> in lanes: integer arithmetic only. Each nested uniform scramble reverses its input's
/// bits first and its output's last; the reversals between two scrambles, and the one that ends the second Sobol'
/// dimension, cancel, so only three reversals a sample remain. The second dimension itself is a superset XOR over
/// the index's bits (the Pascal matrix mod 2: C(k, j) is odd exactly when j's bits are a subset of k's), five
/// shift–mask–xor steps.
/// </summary>
internal struct SobolLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();

    private readonly uint _salt;
    private TL _indexSeed, _xSeed, _ySeed;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public SobolLanes(SobolSampler sampler) => _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row)
    {
        _indexSeed = TL.Hash(TL.Xor(LaneHash.PixelKeys<TL>(x0, row, _salt), TL.BroadcastBits(SobolSampler.IndexSalt)));
        _xSeed = TL.Hash(_indexSeed);
        _ySeed = TL.Hash(_xSeed);
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, SobolLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => false;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        // i = NUS(index) = R(LK(R(index) + seed)), R the bit reversal, LK the Laine–Karras mix.
        a = Reverse(LaineKarras(TL.AddBits(TL.BroadcastBits(LowDiscrepancy.ReverseBits((uint)index)), _indexSeed)));
        b = default;
        c = default;
    }

    /// <inheritdoc />
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        TL i = a;

        // NUS(R(i)) = R(LK(i + seed)); NUS(D₁(i)) = R(LK(R(D₁(i)) + seed)) with R(D₁(i)) the superset XOR.
        sx = TL.ToUnit(Reverse(LaineKarras(TL.AddBits(i, _xSeed))));
        sy = TL.ToUnit(Reverse(LaineKarras(TL.AddBits(SupersetXor(i), _ySeed))));
    }

    /// <summary>The middle of <see cref="LowDiscrepancy.NestedUniformScramble"/>, between its two reversals (the seed already added).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static TL LaineKarras(TL x)
    {
        x = TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras1)));
        x = TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras2)));
        x = TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras3)));
        return TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras4)));
    }

    /// <summary>Bit j of the result is the XOR of the bits k ⊇ j of <paramref name="x"/>: <see cref="LowDiscrepancy.SobolDimension1"/> before its final reversal.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static TL SupersetXor(TL x)
    {
        x = TL.Xor(x, TL.ShiftRightBits(x, 1) & TL.BroadcastBits(0x55555555u));
        x = TL.Xor(x, TL.ShiftRightBits(x, 2) & TL.BroadcastBits(0x33333333u));
        x = TL.Xor(x, TL.ShiftRightBits(x, 4) & TL.BroadcastBits(0x0f0f0f0fu));
        x = TL.Xor(x, TL.ShiftRightBits(x, 8) & TL.BroadcastBits(0x00ff00ffu));
        return TL.Xor(x, TL.ShiftRightBits(x, 16));
    }

    /// <summary><see cref="LowDiscrepancy.ReverseBits"/> in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static TL Reverse(TL x) => TL.ReverseBits(x);
}
