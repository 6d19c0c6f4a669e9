using System.Runtime.CompilerServices;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Tests.Sampling;

/// <summary>
/// docs/architecture.md's worked example "Adding a sampler", compiled: sample i of N on the pixel's diagonal at
/// (i + u)/N, the formula written once and run by both kernels.
/// </summary>
internal sealed class DiagonalSampler : PixelSampler, ILaneSampled
{
    private readonly uint _salt;

    public DiagonalSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => _salt = PointHash.Salt(seed);

    public override string Name => "diagonal";

    public override SamplePoint GetSample(int x, int y, int index)
    {
        ScalarLane p = Point<ScalarLane, ScalarMath>(PointHash.PixelKeys<ScalarLane, ScalarMath>(x, y, _salt), index, SamplesPerPixel);
        return new SamplePoint(p.Value, p.Value);
    }

    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) => user.Run(() => new LaneForm<TL>(this));

    // The formula, once: (i + u)/N, u the sample's hash (IPointMath.InCell).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TV Point<TV, TM>(TV keys, int index, int count)
        where TV : struct
        where TM : IPointMath<TV> =>
        TM.InCell(PointHash.SampleHash<TV, TM>(keys, index), index, count, (float)index / count, 1f / count / 16777216f);

    private struct LaneForm<TL>(DiagonalSampler sampler) : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly uint _salt = sampler._salt;
        private readonly int _count = sampler.SamplesPerPixel;
        private TL _keys;

        public void BeginPacket(int x0, int row) => _keys = PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, _salt);

        public readonly int Prepare(int start, int end) => end;

        public readonly void Sample(int index, out TL sx, out TL sy) => sx = sy = Point<TL, LaneMath<TL>>(_keys, index, _count);
    }
}
