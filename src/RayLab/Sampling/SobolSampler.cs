using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The first two dimensions of the Sobol' sequence, Owen-scrambled and shuffled per pixel as in Burley's
/// "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020). When N is a power of two the N points of a pixel
/// form a (0, m, 2)-net in base 2: every box [a/2ʲ, (a+1)/2ʲ) × [b/2ᵏ, (b+1)/2ᵏ) with 2ʲ⁺ᵏ = N holds exactly one
/// point, so they are stratified as N × 1, …, 2 × N/2 and 1 × N grids at once. Any number of samples works;
/// powers of two are best.
/// </summary>
/// <remarks>
/// The index is first put through a nested uniform scramble (which maps 0 … 2ᵐ − 1 onto an aligned block of 2ᵐ
/// Sobol' indices, so the net property survives), then each coordinate through its own nested uniform scramble;
/// all three seeds come from the pixel's <see cref="CounterHash.PixelKey"/>. Coordinates keep the top 24 bits,
/// like <see cref="CounterHash.ToUnit"/>. Integer arithmetic only: each nested uniform scramble reverses its
/// input's bits first and its output's last; the reversals between two scrambles, and the one that ends the second
/// Sobol' dimension, cancel, so three reversals a sample remain. The second dimension itself is a superset XOR over
/// the index's bits (the Pascal matrix mod 2: C(k, j) is odd exactly when j's bits are a subset of k's), five
/// shift–mask–xor steps.
/// </remarks>
public sealed class SobolSampler : PixelSampler, ILaneSampled
{
    /// <summary>Xored into the pixel key for the seed of the index scramble.</summary>
    private const uint IndexSalt = 0x1b873593u;

    private readonly uint _salt;

    /// <summary>Creates a scrambled Sobol' sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1 (a power of two for the full net property).</param>
    /// <param name="seed">The seed; different seeds give different scrambles.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public SobolSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => _salt = PointHash.Salt(seed);

    /// <inheritdoc />
    public override string Name => "sobol";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        Formula.Point<ScalarLane, ScalarMath>(PointHash.PixelKeys<ScalarLane, ScalarMath>(x, y, _salt), index, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <summary>The scrambled Sobol' point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>Sample <paramref name="index"/> of the pixels whose keys are <paramref name="keys"/>: the seeds, the scrambled index, its point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(TV keys, int index, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            Seeds<TV, TM>(keys, out TV indexSeed, out TV xSeed, out TV ySeed);
            Coordinates<TV, TM>(ScrambledIndex<TV, TM>(index, indexSeed), xSeed, ySeed, out sx, out sy);
        }
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) => user.Run(() => new LaneForm<TL>(_salt));

    /// <summary>The three scrambles' seeds of the pixels whose keys are <paramref name="keys"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Seeds<TV, TM>(TV keys, out TV indexSeed, out TV xSeed, out TV ySeed)
        where TV : struct
        where TM : IPointMath<TV>
    {
        indexSeed = TM.Hash(TM.Xor(keys, TM.BroadcastBits(IndexSalt)));
        xSeed = TM.Hash(indexSeed);
        ySeed = TM.Hash(xSeed);
    }

    /// <summary>The Sobol' index of sample <paramref name="index"/>: i = NUS(index) = R(LK(R(index) + seed)), R the bit reversal, LK the Laine–Karras mix.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TV ScrambledIndex<TV, TM>(int index, TV indexSeed)
        where TV : struct
        where TM : IPointMath<TV> =>
        TM.ReverseBits(LaineKarras<TV, TM>(TM.AddBits(TM.BroadcastBits(LowDiscrepancy.ReverseBits((uint)index)), indexSeed)));

    /// <summary>
    /// The point of Sobol' index <paramref name="i"/>: NUS(R(i)) = R(LK(i + seed)) across and
    /// NUS(D₁(i)) = R(LK(R(D₁(i)) + seed)) down, with R(D₁(i)) the superset XOR.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static void Coordinates<TV, TM>(TV i, TV xSeed, TV ySeed, out TV sx, out TV sy)
        where TV : struct
        where TM : IPointMath<TV>
    {
        sx = TM.ToUnit(TM.ReverseBits(LaineKarras<TV, TM>(TM.AddBits(i, xSeed))));
        sy = TM.ToUnit(TM.ReverseBits(LaineKarras<TV, TM>(TM.AddBits(SupersetXor<TV, TM>(i), ySeed))));
    }

    /// <summary>The middle of <see cref="LowDiscrepancy.NestedUniformScramble"/>, between its two reversals (the seed already added).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TV LaineKarras<TV, TM>(TV x)
        where TV : struct
        where TM : IPointMath<TV>
    {
        x = TM.Xor(x, TM.MultiplyBits(x, TM.BroadcastBits(LowDiscrepancy.LaineKarras1)));
        x = TM.Xor(x, TM.MultiplyBits(x, TM.BroadcastBits(LowDiscrepancy.LaineKarras2)));
        x = TM.Xor(x, TM.MultiplyBits(x, TM.BroadcastBits(LowDiscrepancy.LaineKarras3)));
        return TM.Xor(x, TM.MultiplyBits(x, TM.BroadcastBits(LowDiscrepancy.LaineKarras4)));
    }

    /// <summary>Bit j of the result is the XOR of the bits k ⊇ j of <paramref name="x"/>: <see cref="LowDiscrepancy.SobolDimension1"/> before its final reversal.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static TV SupersetXor<TV, TM>(TV x)
        where TV : struct
        where TM : IPointMath<TV>
    {
        x = TM.Xor(x, TM.And(TM.ShiftRightBits(x, 1), TM.BroadcastBits(0x55555555u)));
        x = TM.Xor(x, TM.And(TM.ShiftRightBits(x, 2), TM.BroadcastBits(0x33333333u)));
        x = TM.Xor(x, TM.And(TM.ShiftRightBits(x, 4), TM.BroadcastBits(0x0f0f0f0fu)));
        x = TM.Xor(x, TM.And(TM.ShiftRightBits(x, 8), TM.BroadcastBits(0x00ff00ffu)));
        return TM.Xor(x, TM.ShiftRightBits(x, 16));
    }

    /// <summary>The points in lanes, made a block ahead (<see cref="PointBlock"/>): the index scramble, then the coordinates.</summary>
    private struct LaneForm<TL>(uint salt) : ILaneSampler<TL>, IStagedPoints<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private TL _indexSeed, _xSeed, _ySeed;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row) =>
            Seeds<TL, LaneMath<TL>>(PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, salt), out _indexSeed, out _xSeed, out _ySeed);

        public int Prepare(int start, int end) => PointBlock.Fill<TL, LaneForm<TL>>(ref this, _block, start, end);

        public static bool HasMiddle => false;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void First(int index, out TL a, out TL b, out TL c)
        {
            a = ScrambledIndex<TL, LaneMath<TL>>(index, _indexSeed);
            b = default;
            c = default;
        }

        public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
        {
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy) =>
            Coordinates<TL, LaneMath<TL>>(a, _xSeed, _ySeed, out sx, out sy);
    }
}
