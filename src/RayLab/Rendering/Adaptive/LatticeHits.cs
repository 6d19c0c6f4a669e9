using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Rendering.Packets;
using RayLab.Simd;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// What a point of the adaptive lattice hits, as an index (0: the background, k + 1: sphere k of the scene), traced
/// one point at a time in double (<see cref="TraceScalar"/>) or a row of points at a time in SIMD float with an
/// error bound (<see cref="TraceRow{TL, TP}"/>), the two giving the same index for every point.
/// </summary>
/// <remarks>
/// <para>Lattice point (lx, ly), with <c>S = 2^(MaxDepth+1)</c> steps per pixel, is the window point
/// <c>α = lx / (W·S)</c>, <c>β = 1 − ly / (H·S)</c> (<see cref="ImagePlane.GetRay"/>).</para>
/// <para>The SIMD path tests each sphere with the packet kernel's stable discriminant
/// <c>Δ = r² − |f⊥|²</c> (see <see cref="PacketFrame"/>), in float, and keeps the answer only where |Δ| exceeds a
/// bound that covers both the float arithmetic (<see cref="FloatRounding.DiscriminantError"/>) and
/// the float rounding of the ray itself, which the point kernel does not need to cover (its samples are
/// random) but the lattice does, since the double path is its reference to the byte. A ray whose direction
/// (perspective) is off by δ turns by at most <c>δ/s</c> about the eye, moving its distance from the centre by at
/// most <c>L δ / s</c> and Δ by at most <c>3 L² δ / s</c>; one whose origin (orthographic) is off by δ moves
/// Δ by at most <c>3 L δ</c>. With δ ≤ 8 ε (|c| + |a| + |b|) (resp. |e + c − C| + |a| + |b| + L), twice those
/// terms are added. Lanes within the bound, and lanes with two hits closer along the ray than their error bounds
/// (<see cref="LaneSphere.Test{TL}"/>, with this bound), are traced again in double.</para>
/// <para>In a scene with a hierarchy a row's packets traverse the lattice's copy of it
/// (<see cref="PacketHierarchy.Nearest{TL, TP}"/>) instead of testing every sphere: a sphere it skips is one the
/// ray misses or one behind the nearest hit, so the answers and the retraced lanes' indices are the same.</para>
/// </remarks>
internal sealed class LatticeHits
{
    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly double _latticeWidth, _latticeHeight;
    private readonly HitSphere[] _spheres;

    private LatticeHits(Scene scene, ImagePlane plane, long size, PacketFrame frame)
    {
        _scene = scene;
        _plane = plane;
        _latticeWidth = plane.Width * (double)size;
        _latticeHeight = plane.Height * (double)size;
        A = plane.A;
        B = plane.B;
        C = plane.C;
        Direction = plane.ParallelDirection;
        CheckDepthOrder = frame.CheckDepthOrder;
        var spheres = new List<HitSphere>();
        for (int k = 0; k < scene.Spheres.Count; k++)
        {
            Sphere sphere = scene.Spheres[k];
            if (sphere.Radius == 0)
            {
                continue;
            }

            (Double3 offset, double largest) = plane.SphereOffset(sphere.Center);
            double r2 = sphere.Radius * sphere.Radius;
            double arithmetic = FloatRounding.DiscriminantError(sphere.Radius, largest);
            double ray = plane.RayRoundingBound(offset, largest, FloatRounding.MachineEpsilon);
            spheres.Add(new HitSphere(offset, (float)r2, (float)(1 / (arithmetic + ray)), k + 1, DepthBound.Of(arithmetic + ray, sphere.Radius, largest)));
        }

        _spheres = [.. spheres];
        if (scene.Hierarchy is { } hierarchy)
        {
            // The lattice's own copy of the hierarchy: its bounds cover the ray's rounding too, and each sphere
            // carries its index + 1 as the integer bits of the red lane (the kernel only selects it, bit for bit).
            var position = new int[scene.Spheres.Count];
            double largestRadius = 0;
            for (int i = 0; i < spheres.Count; i++)
            {
                int index = (int)spheres[i].Id - 1;
                position[index] = i;
                largestRadius = Math.Max(largestRadius, scene.Spheres[index].Radius);
            }

            Hierarchy = PacketHierarchy.Create(hierarchy, plane, index => spheres[position[index]].ToConstants(), largestRadius);
        }
    }

    /// <summary>The scene's hierarchy with this lattice's bounds, when the scene uses one: rows then traverse it instead of testing every sphere.</summary>
    public PacketHierarchy? Hierarchy { get; }

    /// <summary>The lab's a, b, c in float.</summary>
    public Float3 A { get; }

    /// <summary>The lab's b.</summary>
    public Float3 B { get; }

    /// <summary>The lab's c.</summary>
    public Float3 C { get; }

    /// <summary>Orthographic: the common direction −w.</summary>
    public Float3 Direction { get; }

    /// <summary>True when two spheres are close enough that float could order their hits wrongly.</summary>
    public bool CheckDepthOrder { get; }

    /// <summary>The SIMD tracer for this frame, or null when float cannot serve it (see <see cref="PacketFrame.TryCreate"/>).</summary>
    public static LatticeHits? TryCreate(Scene scene, ImagePlane plane, long size, PacketFrame? frame) =>
        frame is null ? null : new LatticeHits(scene, plane, size, frame);

    /// <summary>The index of what lattice point (lx, ly) hits, traced in double: the reference.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int TraceScalar(Scene scene, ImagePlane plane, double latticeWidth, double latticeHeight, long lx, long ly)
    {
        Ray ray = plane.GetRay(WindowMapping.Alpha(lx, latticeWidth), WindowMapping.Beta(ly, latticeHeight));
        return plane.Nearest(scene, ray) + 1;
    }

    /// <summary>
    /// Fills <paramref name="ids"/> with the indices hit by lattice points (<paramref name="lxStart"/> + k·<paramref name="lxStep"/>,
    /// <paramref name="ly"/>), k = 0 … ids.Length − 1, compiled for the plane's projection; returns how many were traced again in double.
    /// </summary>
    public int TraceRow<TL>(long ly, long lxStart, long lxStep, Span<int> ids, int first = 0, int countFrom = 0, int countTo = int.MaxValue)
        where TL : struct, ILanes<TL>
    {
        var line = new LineTrace<TL>(this, ly, lxStart, lxStep, ids, first, countFrom, countTo);
        return _plane.Dispatch<LineTrace<TL>, int>(ref line);
    }

    /// <summary>
    /// Fills <paramref name="ids"/> with the indices hit by lattice points (<paramref name="lxStart"/> + k·<paramref name="lxStep"/>,
    /// <paramref name="ly"/>), k = <paramref name="first"/> … <paramref name="first"/> + ids.Length − 1, in packets of
    /// k = <paramref name="first"/> + j·lanes on; returns how many with <paramref name="countFrom"/> ≤ k &lt;
    /// <paramref name="countTo"/> were traced again in double (the others are another piece's, which counts them). A
    /// point's float ray depends on k alone; whether it is traced again may depend on the other lanes of its packet
    /// (the hierarchy visits what any lane needs), so a piece of a line traces the same packets as the whole line.
    /// </summary>
    // Long: one packet loop over the row whose lane registers (window, α step, rays, nearest, closest) a split would pass through memory per packet.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public int TraceRow<TL, TP>(long ly, long lxStart, long lxStep, Span<int> ids, int first = 0, int countFrom = 0, int countTo = int.MaxValue)
        where TL : struct, ILanes<TL>
        where TP : struct, ILaneRays
    {
        int lanes = TL.Count;
        Span<float> buffer = stackalloc float[lanes];
        TL one = TL.Broadcast(1f);
        var window = new LaneWindow<TL>(new(A.X, A.Y, A.Z), new(B.X, B.Y, B.Z), new(C.X, C.Y, C.Z), new(Direction.X, Direction.Y, Direction.Z));
        TL beta = TL.Broadcast((float)WindowMapping.Beta(ly, _latticeHeight));
        TL start = TL.Broadcast((float)WindowMapping.Alpha(lxStart, _latticeWidth)), step = TL.Broadcast((float)(lxStep / _latticeWidth));
        ReadOnlySpan<HitSphere> spheres = _spheres;
        PacketHierarchy? hierarchy = Hierarchy;
        var background = new LaneHit<TL>(TL.Broadcast(float.NegativeInfinity), default, default, default, default, default, default);
        bool checkOrder = CheckDepthOrder;
        int retraced = 0;
        for (int k0 = 0; k0 < ids.Length; k0 += lanes)
        {
            TL alpha = TL.MultiplyAdd(TL.Broadcast(first + k0) + TL.Indices, step, start);
            TP.GetRays(window, alpha, beta, out Lanes3<TL> origin, out Lanes3<TL> ray);
            (TL dx, TL dy, TL dz) = (ray.X, ray.Y, ray.Z);
            TL dd = TL.MultiplyAdd(dx, dx, TL.MultiplyAdd(dy, dy, dz * dz));
            TL rdd = one / dd;
            TL inverseLength = TL.Sqrt(rdd);
            TL id, closest, unsure;
            if (hierarchy is not null)
            {
                LaneHit<TL> found = PacketHierarchy.Nearest<TL, TP>(hierarchy, origin, ray, dd, rdd, inverseLength, checkOrder, background);
                (id, closest, unsure) = (found.R, found.Closest, found.Unsure);
            }
            else
            {
                TL nearest = TL.Broadcast(float.NegativeInfinity);
                TL nearestError = default;
                id = default;
                closest = TL.Broadcast(float.PositiveInfinity);
                unsure = default;
                foreach (ref readonly HitSphere sphere in spheres)
                {
                    TL fx = TP.AddOrigin(TL.Broadcast(sphere.Offset.X), origin.X);
                    TL fy = TP.AddOrigin(TL.Broadcast(sphere.Offset.Y), origin.Y);
                    TL fz = TP.AddOrigin(TL.Broadcast(sphere.Offset.Z), origin.Z);
                    TL negatedT = LaneSphere.Test(fx, fy, fz, dx, dy, dz, dd, rdd, inverseLength, TL.Broadcast(sphere.RadiusSquared), TL.Broadcast(sphere.InverseBound), sphere.Bound, checkOrder, nearest, ref nearestError, ref closest, ref unsure);
                    LaneSphere.TakeNearer(ref nearest, negatedT, ref id, TL.BroadcastBits(sphere.Id));
                }
            }

            uint uncertain = LaneSphere.Uncertain(closest, unsure, checkOrder);
            // The indices are integer bits in the lanes: a whole packet is stored straight into the line.
            int count = Math.Min(lanes, ids.Length - k0);
            if (count == lanes)
            {
                id.Store(MemoryMarshal.Cast<int, float>(ids.Slice(k0, lanes)));
            }
            else
            {
                id.Store(buffer);
                MemoryMarshal.Cast<float, int>(buffer)[..count].CopyTo(ids[k0..]);
            }

            for (uint rest = uncertain & (uint)((1UL << count) - 1); rest != 0; rest &= rest - 1)
            {
                int lane = System.Numerics.BitOperations.TrailingZeroCount(rest);
                ids[k0 + lane] = TraceScalar(_scene, _plane, _latticeWidth, _latticeHeight, lxStart + ((first + k0 + (long)lane) * lxStep), ly);
                int k = first + k0 + lane;
                retraced += k >= countFrom && k < countTo ? 1 : 0;
            }
        }

        return retraced;
    }

    /// <summary>One sphere's constants: o − C at α = β = 0, r², 1 / the error bound of Δ, its index + 1 and its depth error constants.</summary>
    /// <remarks>Fields, as <see cref="SphereConstants"/>'s are: the lanes broadcast them straight from memory.</remarks>
    private readonly struct HitSphere(Double3 offset, float radiusSquared, float inverseBound, int id, DepthBound bound)
    {
        public readonly Float3 Offset = offset;

        public readonly float RadiusSquared = radiusSquared;

        public readonly float InverseBound = inverseBound;

        public readonly uint Id = (uint)id;

        public readonly DepthBound Bound = bound;

        /// <summary>The packet kernel's constants with the index + 1 as the bits of the colour's red.</summary>
        public (SphereConstants Constants, DepthBound Bound) ToConstants() =>
            (new SphereConstants(Offset, RadiusSquared, InverseBound, new Float3(BitConverter.UInt32BitsToSingle(Id), 0, 0)), Bound);
    }

    /// <summary>One line of the lattice, traced by the packet loop compiled for the plane's projection.</summary>
    private readonly ref struct LineTrace<TL>(LatticeHits hits, long ly, long lxStart, long lxStep, Span<int> ids, int first, int countFrom, int countTo) : IProjectionAction<int>
        where TL : struct, ILanes<TL>
    {
        private readonly Span<int> _ids = ids;

        public int Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => hits.TraceRow<TL, TP>(ly, lxStart, lxStep, _ids, first, countFrom, countTo);
    }
}
