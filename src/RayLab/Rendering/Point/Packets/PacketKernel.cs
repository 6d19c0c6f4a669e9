using System.Numerics;
using System.Runtime.CompilerServices;
using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Rendering.Point.Packets;

/// <summary>
/// The packet tracer: the renderer's loop with one SIMD lane per pixel (16 pixels per packet with AVX-512,
/// 8 with AVX2, 4 with SSE or NEON). For each sample index it makes the packet's rays, tests every sphere in
/// float and keeps the nearest hit's colour per lane; lanes whose float answer is not certain (see
/// <see cref="PacketFrame"/>) are traced again in double. The work per ray is the scalar path's
/// (<see cref="Scene.Trace"/>), so a student can read that one and trust this one; like it, the kernel relies on
/// the scene's flat shading and takes each sphere's colour from <see cref="Scene.ColourOf"/>.
/// </summary>
internal static partial class PacketKernel
{
    /// <summary>Renders one row of the image into <paramref name="pixels"/> (8-bit or linear); returns the samples traced again in double.</summary>
    /// <remarks>
    /// Compiled fully optimised at once: a render is often the process's only call, and the first tier's
    /// unoptimised SIMD code would run most of it. Each packet is summed in float first; only a packet with an
    /// uncertain lane (about 1 in 70 on the two-sphere scene at 1080p, 16 spp) is summed again with those
    /// samples traced in double, so the bytes are those of tracing the uncertain samples in double.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public static int RenderRow<TL, TS, TP>(PacketFrame frame, ref TS sampler, int samplesPerPixel, int row, TargetRow pixels)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, ILaneRays
    {
        if (frame.Hierarchy is not null)
        {
            return RenderRowThroughHierarchy<TL, TS, TP>(frame, ref sampler, samplesPerPixel, row, pixels);
        }

        int lanes = TL.Count;
        int retraced = 0;
        TL scale = TL.Broadcast(256f / samplesPerPixel);
        for (int x0 = 0; x0 < frame.Width; x0 += lanes)
        {
            sampler.BeginPacket(x0, row);
            LaneColour<TL> sum = SumPacket<TL, TS, TP, FloatOnly>(frame, ref sampler, samplesPerPixel, x0, row);
            if (sum.Unsure != 0)
            {
                (sum, int again) = SumPacketCarefully<TL, TS, TP>(frame, ref sampler, samplesPerPixel, x0, row);
                retraced += again;
            }

            // The lab's 8-bit rule of each pixel's mean, sum/n, as sum · (256/n).
            pixels.WriteLanes(sum.R, sum.G, sum.B, scale, x0, Math.Min(lanes, frame.Width - x0));
        }

        return retraced;
    }

    /// <summary>The packet summed again with its uncertain samples traced in double; also how many there were.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static (LaneColour<TL> Sum, int Retraced) SumPacketCarefully<TL, TS, TP>(PacketFrame frame, ref TS sampler, int samplesPerPixel, int x0, int row)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, ILaneRays
    {
        sampler.BeginPacket(x0, row);
        int count = 0;
        LaneColour<TL> sum = SumPacket<TL, TS, TP, RetraceInDouble>(frame, ref sampler, samplesPerPixel, x0, row, ref count);
        return (sum, count);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static LaneColour<TL> SumPacket<TL, TS, TP, TMode>(PacketFrame frame, ref TS sampler, int samplesPerPixel, int x0, int row)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, ILaneRays
        where TMode : struct, IPacketMode
    {
        int ignored = 0;
        return SumPacket<TL, TS, TP, TMode>(frame, ref sampler, samplesPerPixel, x0, row, ref ignored);
    }

    /// <summary>
    /// The sum over a packet's samples of each lane's colour; <see cref="LaneColour{TL}.Unsure"/> has the lanes
    /// that had an uncertain sample (float only) or that were traced again (careful mode).
    /// </summary>
    // Long: the sample and sphere loops keep every lane register live; a call inside them makes the JIT spill them all per sample (see the uncertain lanes below).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static LaneColour<TL> SumPacket<TL, TS, TP, TMode>(PacketFrame frame, ref TS sampler, int samplesPerPixel, int x0, int row, ref int retracedCount)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, ILaneRays
        where TMode : struct, IPacketMode
    {
        TL one = TL.Broadcast(1f);
        TL invWidth = TL.Broadcast(1f / frame.Width), invHeight = TL.Broadcast(1f / frame.Height);
        Float3 a = frame.A, b = frame.B, c = frame.C, direction = frame.Direction, background = frame.Background;
        var window = new LaneWindow<TL>(new(a.X, a.Y, a.Z), new(b.X, b.Y, b.Z), new(c.X, c.Y, c.Z), new(direction.X, direction.Y, direction.Z));
        ReadOnlySpan<SphereConstants> spheres = frame.Spheres;
        bool checkOrder = frame.CheckDepthOrder;
        TL left = WindowMapping.PacketLeft(x0, invWidth);
        TL rowTop = WindowMapping.RowTop<TL>(row, frame.Height);
        (TL backgroundRed, TL backgroundGreen, TL backgroundBlue) = (TL.Broadcast(background.X), TL.Broadcast(background.Y), TL.Broadcast(background.Z));
        TL accumulatedRed = default, accumulatedGreen = default, accumulatedBlue = default;
        uint retraced = 0;
        for (int start = 0, end; start < samplesPerPixel; start = end)
        {
            end = sampler.Prepare(start, samplesPerPixel);
            for (int index = start; index < end; index++)
            {
                sampler.Sample(index, out TL sx, out TL sy);
                TL alpha = WindowMapping.Alpha(sx, invWidth, left);
                TL beta = WindowMapping.Beta(sy, invHeight, rowTop);
                TP.GetRays(window, alpha, beta, out Lanes3<TL> origin, out Lanes3<TL> ray);
                (TL dx, TL dy, TL dz) = (ray.X, ray.Y, ray.Z);
                TL dd = TL.MultiplyAdd(dx, dx, TL.MultiplyAdd(dy, dy, dz * dz));
                TL rdd = one / dd;
                TL nearest = TL.Broadcast(float.NegativeInfinity);  // −t of the nearest hit so far (kept negated: saves a negation per sphere)
                TL red = backgroundRed, green = backgroundGreen, blue = backgroundBlue;
                TL closest = TL.Broadcast(float.PositiveInfinity);   // the smallest |Δ| / bound over the spheres
                TL unsure = default;
                TL depthTolerance = checkOrder ? TL.Broadcast(frame.DepthTolerance) / TL.Sqrt(dd) : default;
                foreach (ref readonly SphereConstants sphere in spheres)
                {
                    TL fx = TP.AddOrigin(TL.Broadcast(sphere.Offset.X), origin.X);
                    TL fy = TP.AddOrigin(TL.Broadcast(sphere.Offset.Y), origin.Y);
                    TL fz = TP.AddOrigin(TL.Broadcast(sphere.Offset.Z), origin.Z);
                    TL negatedT = LaneSphere.NegatedNearRoot(fx, fy, fz, dx, dy, dz, dd, rdd, TL.Broadcast(sphere.RadiusSquared), out TL disc);
                    closest = TL.MinAbs(closest, disc * TL.Broadcast(sphere.InverseBound));
                    if (checkOrder)
                    {
                        unsure |= TL.LessThanOrEqual(TL.Abs(negatedT - nearest), depthTolerance);   // either order: a farther sphere tested later too
                    }

                    LaneSphere.TakeNearer(ref nearest, negatedT, ref red, ref green, ref blue, (TL.Broadcast(sphere.Colour.X), TL.Broadcast(sphere.Colour.Y), TL.Broadcast(sphere.Colour.Z)));   // t < best
                }

                // The colour of the nearest sphere hit in each lane, or the background. Uncertain lanes: the fast
                // pass only notes them (a call here would make the JIT spill every register around it on each
                // sample); the careful pass traces them again in double.
                uint uncertain = LaneSphere.Uncertain(closest, unsure, checkOrder);
                if (TMode.Retraces)
                {
                    if (uncertain != 0)
                    {
                        LaneColour<TL> exact = Retrace<TL, TP>(frame, x0, row, sx, sy, new LaneColour<TL>(red, green, blue, uncertain));
                        (red, green, blue) = (exact.R, exact.G, exact.B);
                        retraced |= exact.Unsure;
                        retracedCount += BitOperations.PopCount(exact.Unsure);
                    }
                }
                else
                {
                    retraced |= uncertain;
                }

                accumulatedRed += red;
                accumulatedGreen += green;
                accumulatedBlue += blue;
            }
        }

        return new LaneColour<TL>(accumulatedRed, accumulatedGreen, accumulatedBlue, retraced);
    }

    /// <summary>The lanes whose float answer is uncertain, traced again in double (<see cref="Scene.Trace"/>).</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static LaneColour<TL> Retrace<TL, TP>(PacketFrame frame, int x0, int row, TL sx, TL sy, LaneColour<TL> colour)
        where TL : struct, ILanes<TL>
        where TP : struct, ILaneRays
    {
        int count = TL.Count;
        Span<float> values = stackalloc float[count * 5];
        sx.Store(values);
        sy.Store(values[count..]);
        colour.R.Store(values[(2 * count)..]);
        colour.G.Store(values[(3 * count)..]);
        colour.B.Store(values[(4 * count)..]);
        uint lanes = colour.Unsure & (uint)((1UL << Math.Min(count, frame.Width - x0)) - 1); // not the lanes past the image
        ImagePlane plane = frame.Plane;
        for (uint rest = lanes; rest != 0; rest &= rest - 1)
        {
            int lane = BitOperations.TrailingZeroCount(rest);

            Ray ray = plane.GetPixelRay(x0 + lane, row, values[lane], values[count + lane]);
            Intensity value = plane.Trace(frame.Scene, ray);
            values[(2 * count) + lane] = (float)value.R;
            values[(3 * count) + lane] = (float)value.G;
            values[(4 * count) + lane] = (float)value.B;
        }

        return new LaneColour<TL>(TL.Load(values[(2 * count)..]), TL.Load(values[(3 * count)..]), TL.Load(values[(4 * count)..]), lanes);
    }
}

/// <summary>One sample's colour in every lane, and the lanes whose float answer was uncertain.</summary>
internal readonly record struct LaneColour<TL>(TL R, TL G, TL B, uint Unsure)
    where TL : struct, ILanes<TL>;

/// <summary>Whether a packet pass traces its uncertain samples again in double (as a type: one compiled loop each).</summary>
internal interface IPacketMode
{
    /// <summary>True: uncertain samples are traced again in double; false: they are only noted.</summary>
    static abstract bool Retraces { get; }
}

/// <summary>The fast pass: float only, uncertain lanes noted.</summary>
internal readonly struct FloatOnly : IPacketMode
{
    public static bool Retraces => false;
}

/// <summary>The careful pass: uncertain samples traced again in double.</summary>
internal readonly struct RetraceInDouble : IPacketMode
{
    public static bool Retraces => true;
}
