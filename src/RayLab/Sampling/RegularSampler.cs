using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The lab's regular sampling: an n×n grid, one sample at the centre of each cell, the same pattern in every
/// pixel. Cheap, but it still aliases. One sample is the pixel centre.
/// </summary>
public sealed class RegularSampler : GridSampler, ILaneSampled
{
    /// <summary>Creates an n×n regular sampler.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <exception cref="ArgumentException">Not a positive perfect square.</exception>
    public RegularSampler(int samplesPerPixel) : base(samplesPerPixel, 0) { }

    /// <inheritdoc />
    public override string Name => "regular";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        return Formula.Point(index, GridSize);
    }

    /// <inheritdoc />
    /// <summary>The regular grid's point formula, once, for the CPU and the device.</summary>
    internal readonly struct Formula
    {
        /// <summary>Sample <paramref name="index"/> of an n×n grid: the centre of its cell, row by row.</summary>
        /// <param name="index">The sample's index, 0 ≤ index &lt; n².</param>
        /// <param name="n">The grid's side.</param>
        /// <returns>The point in the pixel.</returns>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static SamplePoint Point(int index, int n) => new(((index % n) + 0.5) / n, ((index / n) + 0.5) / n);
    }

    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) => user.Run(() => new LaneForm<TL>(this));

    /// <summary>The points in lanes: <see cref="GetSample"/>'s (the same in every pixel) in float, from a table made once.</summary>
    private readonly struct LaneForm<TL>(RegularSampler sampler) : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly (float X, float Y)[] _points = Points(sampler);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row)
        {
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public int Prepare(int start, int end) => end;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Sample(int index, out TL sx, out TL sy)
        {
            (float x, float y) = _points[index];
            sx = TL.Broadcast(x);
            sy = TL.Broadcast(y);
        }

        private static (float X, float Y)[] Points(RegularSampler sampler)
        {
            var points = new (float, float)[sampler.SamplesPerPixel];
            for (int i = 0; i < points.Length; i++)
            {
                SamplePoint p = sampler.GetSample(0, 0, i);
                points[i] = ((float)p.X, (float)p.Y);
            }

            return points;
        }
    }
}
