using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The lab's random sampling (Suffern's <c>rand()</c> in the pixel): uniform, independent points. Any
/// number of samples; points may clump.
/// </summary>
public sealed class RandomSampler : PixelSampler, ILaneSampled
{
    private readonly uint _salt;

    /// <summary>Creates a random sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public RandomSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => _salt = PointHash.Salt(seed);

    /// <inheritdoc />
    public override string Name => "random";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        Formula.Point<ScalarLane, ScalarMath>(PointHash.PixelKeys<ScalarLane, ScalarMath>(x, y, _salt), index, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) => user.Run(() => new LaneForm<TL>(_salt));

    /// <summary>The salted seed the pixel keys are made with (the device form's input).</summary>
    internal uint Salt => _salt;

    /// <summary>The random sampler's point formula, once, for the CPU lanes, the scalar path and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>Sample <paramref name="index"/> of the pixels whose keys are <paramref name="keys"/>: two hashes, each a coordinate.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(TV keys, int index, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV>
        {
            TV h1 = PointHash.SampleHash<TV, TM>(keys, index);
            sx = TM.ToUnit(h1);
            sy = TM.ToUnit(TM.Hash(h1));
        }
    }

    /// <summary>The points in lanes, one pixel per lane.</summary>
    private struct LaneForm<TL>(uint salt) : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private TL _keys;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row) => _keys = PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, salt);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly int Prepare(int start, int end) => end;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => Formula.Point<TL, LaneMath<TL>>(_keys, index, out sx, out sy);
    }
}
