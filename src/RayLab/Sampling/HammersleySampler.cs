using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The Hammersley point set, (i / N, φ₂(i)) for i = 0 … N − 1 with φ₂ the base-2 radical inverse, moved in each
/// pixel by its own toroidal shift (Cranley–Patterson rotation): every coordinate plus a per-pixel offset, wrapped
/// into [0, 1). The shift keeps the set's low discrepancy and stops every pixel using the same pattern, which
/// would alias. Any number of samples.
/// </summary>
public sealed class HammersleySampler : PixelSampler, ILaneSampled
{
    /// <summary>Xored into the pixel key for the pixel's random shift.</summary>
    private const uint ShiftSalt = 0x68e31da4u;

    private readonly uint _salt;

    /// <summary>Creates a Hammersley sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different shifts.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public HammersleySampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => _salt = PointHash.Salt(seed);

    /// <inheritdoc />
    public override string Name => "hammersley";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        Formula.Shift<ScalarLane, ScalarMath>(PointHash.PixelKeys<ScalarLane, ScalarMath>(x, y, _salt), out ScalarLane shiftX, out ScalarLane shiftY);
        SamplePoint point = Unshifted(index);
        return new SamplePoint(ScalarMath.Shifted(point.X, shiftX).Value, ScalarMath.Shifted(point.Y, shiftY).Value);
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) => user.Run(() => new LaneForm<TL>(this));

    /// <summary>Point <paramref name="index"/> of the unshifted Hammersley set: (index / N, φ₂(index)).</summary>
    /// <param name="index">The sample index.</param>
    internal SamplePoint Unshifted(int index) => Formula.Unshifted(index, SamplesPerPixel);

    /// <summary>The salted seed the pixel keys are made with (the device form's input).</summary>
    internal uint Salt => _salt;

    /// <summary>The Hammersley point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>Point <paramref name="index"/> of <paramref name="count"/> before the pixel's shift: (i/N, the radical inverse of i).</summary>
        /// <param name="index">The sample's index.</param>
        /// <param name="count">N, the samples per pixel.</param>
        /// <returns>The point.</returns>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static SamplePoint Unshifted(int index, int count) =>
            new((double)index / count, LowDiscrepancy.RadicalInverse2((uint)index));

        /// <summary>
        /// The toroidal shift of the pixels whose keys are <paramref name="keys"/>, each coordinate's top 24 bits; a
        /// point is then <see cref="IPointMath{TV}.Shifted"/> by them.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Shift<TV, TM>(TV keys, out TV shiftX, out TV shiftY)
            where TV : struct
            where TM : IPointMath<TV>
        {
            TV h1 = TM.Hash(TM.Xor(keys, TM.BroadcastBits(ShiftSalt)));
            shiftX = TM.Top24(h1);
            shiftY = TM.Top24(TM.Hash(h1));
        }
    }

    /// <summary>The points in lanes: the shift made once per packet, each point shifted in double and rounded to float.</summary>
    private struct LaneForm<TL> : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly uint _salt;
        private readonly double[] _unshifted;
        private TL _shiftX, _shiftY;

        public LaneForm(HammersleySampler sampler)
        {
            _salt = sampler._salt;
            _unshifted = new double[2 * sampler.SamplesPerPixel];
            for (int i = 0; i < sampler.SamplesPerPixel; i++)
            {
                SamplePoint point = sampler.Unshifted(i);
                (_unshifted[2 * i], _unshifted[(2 * i) + 1]) = (point.X, point.Y);
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row) =>
            Formula.Shift<TL, LaneMath<TL>>(PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, _salt), out _shiftX, out _shiftY);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly int Prepare(int start, int end) => end;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy)
        {
            sx = LaneMath<TL>.Shifted(_unshifted[2 * index], _shiftX);
            sy = LaneMath<TL>.Shifted(_unshifted[(2 * index) + 1], _shiftY);
        }
    }
}
