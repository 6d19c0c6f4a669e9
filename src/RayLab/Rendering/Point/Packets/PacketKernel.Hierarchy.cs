using System.Buffers;
using System.Numerics;
using System.Runtime.CompilerServices;
using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Rendering.Point.Packets;

/// <summary>
/// The packet kernel's row for a scene with a hierarchy (<see cref="PacketHierarchy"/>): a loop of its own, so
/// that the loop over every sphere of a small scene keeps its registers (a call in it would make the JIT spill
/// them on every sample).
/// </summary>
internal static partial class PacketKernel
{
    /// <summary>Packets whose leaves one walk of the tree collects (each then filters them by its own frustum).</summary>
    private const int PacketsPerSpan = 4;

    /// <summary>
    /// Renders one row through the hierarchy: per packet the leaves its rays can reach, per sample those leaves'
    /// boxes and spheres in lanes; uncertain lanes are traced again in double at once (traversal costs more than
    /// that call), so a packet is never summed twice. Returns the samples traced again.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static int RenderRowThroughHierarchy<TL, TS, TP>(PacketFrame frame, ref TS sampler, int samplesPerPixel, int row, TargetRow pixels)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, ILaneRays
    {
        PacketHierarchy hierarchy = frame.Hierarchy!;
        int lanes = TL.Count;
        int retraced = 0;
        TL scale = TL.Broadcast(256f / samplesPerPixel);
        int[] leafBuffer = ArrayPool<int>.Shared.Rent(hierarchy.Nodes.Length);
        int[] spanBuffer = ArrayPool<int>.Shared.Rent(hierarchy.Nodes.Length);
        int spanCount = 0;
        for (int x0 = 0; x0 < frame.Width; x0 += lanes)
        {
            sampler.BeginPacket(x0, row);

            // One walk of the tree per span of packets; each packet then keeps the span's leaves its own frustum reaches.
            if (x0 % (lanes * PacketsPerSpan) == 0)
            {
                spanCount = hierarchy.CollectLeaves(x0, lanes * PacketsPerSpan, row, spanBuffer);
            }

            ReadOnlySpan<int> leaves = leafBuffer.AsSpan(0, hierarchy.FilterLeaves(x0, lanes, row, spanBuffer.AsSpan(0, spanCount), leafBuffer));
            LaneColour<TL> sum = SumPacketThroughHierarchy<TL, TS, TP>(frame, hierarchy, ref sampler, samplesPerPixel, x0, row, leaves, ref retraced);
            pixels.WriteLanes(sum.R, sum.G, sum.B, scale, x0, Math.Min(lanes, frame.Width - x0));
        }

        ArrayPool<int>.Shared.Return(spanBuffer);
        ArrayPool<int>.Shared.Return(leafBuffer);
        return retraced;
    }

    /// <summary>The sum over a packet's samples of each lane's colour, uncertain samples traced in double.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static LaneColour<TL> SumPacketThroughHierarchy<TL, TS, TP>(PacketFrame frame, PacketHierarchy hierarchy, ref TS sampler, int samplesPerPixel, int x0, int row, ReadOnlySpan<int> leaves, ref int retracedCount)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, ILaneRays
    {
        TL one = TL.Broadcast(1f);
        TL invWidth = TL.Broadcast(1f / frame.Width), invHeight = TL.Broadcast(1f / frame.Height);
        Float3 a = frame.A, b = frame.B, c = frame.C, direction = frame.Direction, background = frame.Background;
        var window = new LaneWindow<TL>(new(a.X, a.Y, a.Z), new(b.X, b.Y, b.Z), new(c.X, c.Y, c.Z), new(direction.X, direction.Y, direction.Z));
        bool checkOrder = frame.CheckDepthOrder;
        TL minusHalf = TL.Broadcast(-0.5f), oneAndHalf = TL.Broadcast(1.5f);
        TL left = WindowMapping.PacketLeft(x0, invWidth);
        TL rowTop = WindowMapping.RowTop<TL>(row, frame.Height);
        var start = new LaneHit<TL>(TL.Broadcast(float.NegativeInfinity), TL.Broadcast(background.X), TL.Broadcast(background.Y), TL.Broadcast(background.Z), default, default, default);
        TL accumulatedRed = default, accumulatedGreen = default, accumulatedBlue = default;

        // The points come in blocks (ILaneSampler.Prepare): a permutation sampler makes them ahead of the samples.
        for (int first = 0, end; first < samplesPerPixel; first = end)
        {
            end = sampler.Prepare(first, samplesPerPixel);
            for (int index = first; index < end; index++)
            {
                sampler.Sample(index, out TL sx, out TL sy);
                TL alpha = WindowMapping.Alpha(sx, invWidth, left);
                TL beta = WindowMapping.Beta(sy, invHeight, rowTop);
                TP.GetRays(window, alpha, beta, out Lanes3<TL> origin, out Lanes3<TL> ray);
                TL dd = TL.MultiplyAdd(ray.X, ray.X, TL.MultiplyAdd(ray.Y, ray.Y, ray.Z * ray.Z));
                TL rdd = one / dd;
                TL inverseLength = TL.Sqrt(rdd);

                // The packet's leaves hold every box its rays can reach while each sample stays within half a pixel
                // of its pixel (the samplers' [0, 1)); a sample outside that traverses from the root.
                uint stray = TL.MaskBits(TL.LessThan(sx, minusHalf) | TL.LessThan(sy, minusHalf) | TL.LessThan(oneAndHalf, sx) | TL.LessThan(oneAndHalf, sy));
                LaneHit<TL> found = stray == 0
                    ? PacketHierarchy.NearestInLeaves<TL, TP>(hierarchy, leaves, origin, ray, dd, rdd, inverseLength, checkOrder, start)
                    : PacketHierarchy.Nearest<TL, TP>(hierarchy, origin, ray, dd, rdd, inverseLength, checkOrder, start);
                (TL red, TL green, TL blue) = (found.R, found.G, found.B);
                uint uncertain = LaneSphere.Uncertain(found.Closest, found.Unsure, checkOrder);
                if (uncertain != 0)
                {
                    LaneColour<TL> exact = Retrace<TL, TP>(frame, x0, row, sx, sy, new LaneColour<TL>(red, green, blue, uncertain));
                    (red, green, blue) = (exact.R, exact.G, exact.B);
                    retracedCount += BitOperations.PopCount(exact.Unsure);
                }

                accumulatedRed += red;
                accumulatedGreen += green;
                accumulatedBlue += blue;
            }
        }

        return new LaneColour<TL>(accumulatedRed, accumulatedGreen, accumulatedBlue, 0);
    }
}
