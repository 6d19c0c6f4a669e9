using System.Runtime.CompilerServices;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Simd;

namespace RayLab.Rendering.Packets;

/// <summary>
/// The scene's <see cref="SphereHierarchy"/> for one frame of the packet kernel: each box in float, as offsets
/// from the eye (the sphere offsets' fixed point), widened by 10⁻⁴ of its distance, and the spheres' constants
/// in leaf order. A packet's rays traverse it together (<see cref="Nearest{TL, TP}"/>): a node is entered when
/// any lane's ray enters its box before that lane's nearest hit so far.
/// </summary>
/// <remarks>
/// <para>The traversal gives the kernel's answer for the spheres it tests; the spheres it skips cannot change
/// the exact answer, so the float answers it calls certain are the double ones, as without it:</para>
/// <para>- a box a lane's float ray misses is missed by the double ray: the widening (10⁻⁴ of the distance) is
/// far above float's rounding of the ray and of the box (a few 10⁻⁶);</para>
/// <para>- a box entered only beyond 1.01 × the nearest float hit (plus 1 % of the largest radius) lies behind
/// the true nearest hit: a float hit is off by at most 3·10⁻³ (r + |o − C|) (<see cref="PacketFrame"/>'s
/// depth reach).</para>
/// <para>A lane's two hits within the depth tolerance are marked uncertain whichever was found first (the
/// order of the tests is the tree's, not the scene's).</para>
/// </remarks>
internal sealed class PacketHierarchy
{
    /// <summary>The widening of each box, relative to its distance from the eye.</summary>
    private const double Widening = 1e-4;

    private PacketHierarchy(PacketNode[] nodes, SphereConstants[] spheres, DepthBound[] depthBounds, int depth, float radiusSlack, ImagePlane frame)
    {
        Nodes = nodes;
        Spheres = spheres;
        DepthBounds = depthBounds;
        Depth = depth;
        RadiusSlack = radiusSlack;
        _frame = frame;
    }

    private readonly ImagePlane _frame;

    /// <summary>The nodes in the hierarchy's order.</summary>
    public PacketNode[] Nodes { get; }

    /// <summary>The spheres' constants in leaf order.</summary>
    public SphereConstants[] Spheres { get; }

    /// <summary>The spheres' depth error constants in leaf order (<see cref="LaneSphere.Test{TL}"/>).</summary>
    public DepthBound[] DepthBounds { get; }

    /// <summary>The hierarchy's depth (the traversal stack's size).</summary>
    public int Depth { get; }

    /// <summary>1 % of the largest radius (world units): the depth culling's absolute slack.</summary>
    public float RadiusSlack { get; }

    /// <summary>The frame's copy of <paramref name="hierarchy"/>.</summary>
    /// <param name="hierarchy">The scene's hierarchy.</param>
    /// <param name="frame">The frame's rays.</param>
    /// <param name="constantsOf">A sphere's kernel constants and depth error constants, by its index in the scene.</param>
    /// <param name="largestRadius">The largest radius in the scene.</param>
    public static PacketHierarchy Create(SphereHierarchy hierarchy, ImagePlane frame, Func<int, (SphereConstants Constants, DepthBound Bound)> constantsOf, double largestRadius)
    {
        Double3 fixedPoint = frame.FixedPoint;
        double window = frame.OriginReach;
        ReadOnlySpan<HierarchyNode> nodes = hierarchy.Nodes;
        var packetNodes = new PacketNode[nodes.Length];
        for (int i = 0; i < nodes.Length; i++)
        {
            HierarchyNode node = nodes[i];
            Double3 centre = 0.5 * (node.Lo + node.Hi);
            double reach = (fixedPoint - centre).Length + (0.5 * (node.Hi - node.Lo).Length) + window;
            double pad = Widening * reach;
            Double3 widen = new(pad, pad, pad);
            packetNodes[i] = new PacketNode(fixedPoint - (node.Lo - widen), fixedPoint - (node.Hi + widen), node.Start, node.Count, node.Axis);
        }

        ReadOnlySpan<int> order = hierarchy.Order;
        var spheres = new SphereConstants[order.Length];
        var bounds = new DepthBound[order.Length];
        for (int i = 0; i < order.Length; i++)
        {
            (spheres[i], bounds[i]) = constantsOf(order[i]);
        }

        return new PacketHierarchy(packetNodes, spheres, bounds, hierarchy.Depth, (float)(0.01 * largestRadius), frame);
    }

    /// <summary>
    /// The leaves whose boxes the rays of a packet may enter, near ones first: the packet's pixels
    /// <paramref name="x0"/> … <paramref name="x0"/> + <paramref name="lanes"/> − 1 of row <paramref name="row"/>,
    /// widened by one pixel on every side (a sample offset anywhere in [−1, 2) stays inside; the kernel checks
    /// [−½, 1½) and traverses from the root for a sample outside it). Tested in double against the float boxes.
    /// </summary>
    /// <param name="x0">The packet's first column.</param>
    /// <param name="lanes">The packet's width (or a span of several packets': see <see cref="FilterLeaves"/>).</param>
    /// <param name="row">The row.</param>
    /// <param name="leaves">Receives the leaves' node indices; as long as <see cref="Nodes"/>.</param>
    /// <returns>The number of leaves.</returns>
    public int CollectLeaves(int x0, int lanes, int row, Span<int> leaves)
    {
        Span<Plane> planes = stackalloc Plane[5];
        int negative = Frustum(x0, lanes, row, planes);
        PacketNode[] nodes = Nodes;
        Span<int> stack = stackalloc int[Depth + 1];
        int top = 0, count = 0;
        stack[top++] = 0;
        while (top > 0)
        {
            int index = stack[--top];
            ref readonly PacketNode node = ref nodes[index];
            if (Outside(node, planes))
            {
                continue;
            }

            if (node.Count > 0)
            {
                leaves[count++] = index;
                continue;
            }

            bool rightFirst = ((negative >> node.Axis) & 1) != 0;
            stack[top++] = rightFirst ? index + 1 : node.Start;
            stack[top++] = rightFirst ? node.Start : index + 1;
        }

        return count;
    }

    /// <summary>
    /// The leaves of <paramref name="span"/> (collected by <see cref="CollectLeaves"/> for pixels that include this
    /// packet's) that the packet's own frustum reaches, in the same order: the same set <see cref="CollectLeaves"/>
    /// gives the packet (a leaf its frustum reaches lies in the wider one too), for a test per leaf instead of a walk.
    /// </summary>
    /// <param name="x0">The packet's first column.</param>
    /// <param name="lanes">The packet's width.</param>
    /// <param name="row">The row.</param>
    /// <param name="span">The leaves of a span of pixels that contains the packet's.</param>
    /// <param name="leaves">Receives the packet's leaves; at least as long as <paramref name="span"/>.</param>
    /// <returns>The number of leaves.</returns>
    public int FilterLeaves(int x0, int lanes, int row, ReadOnlySpan<int> span, Span<int> leaves)
    {
        Span<Plane> planes = stackalloc Plane[5];
        Frustum(x0, lanes, row, planes);
        PacketNode[] nodes = Nodes;
        int count = 0;
        foreach (int index in span)
        {
            if (!Outside(nodes[index], planes))
            {
                leaves[count++] = index;
            }
        }

        return count;
    }

    /// <summary>
    /// The five half-spaces (relative to the fixed point) that bound the rays of pixels <paramref name="x0"/> − 1 …
    /// <paramref name="x0"/> + <paramref name="lanes"/> of rows <paramref name="row"/> − 1 … <paramref name="row"/> + 1;
    /// returns the octant of the frustum's centre direction (bit k: axis k negative), for a near-first walk.
    /// </summary>
    private int Frustum(int x0, int lanes, int row, Span<Plane> planes)
    {
        ImagePlane frame = _frame;
        double alpha0 = (x0 - 1.0) / frame.Width, alpha1 = (x0 + lanes + 1.0) / frame.Width;
        double beta0 = 1 - ((row + 2.0) / frame.Height), beta1 = 1 - ((row - 1.0) / frame.Height);
        Double3 centre = frame.Frustum(alpha0, alpha1, beta0, beta1, planes);
        return (centre.X < 0 ? 1 : 0) | (centre.Y < 0 ? 2 : 0) | (centre.Z < 0 ? 4 : 0);
    }

    /// <summary>True when the node's box lies wholly outside one of the half-spaces.</summary>
    private static bool Outside(in PacketNode node, ReadOnlySpan<Plane> planes)
    {
        // The box relative to the fixed point is [−Lo, −Hi] (the node stores fixed point − corner).
        Double3 lo = new(-(double)node.Lo.X, -(double)node.Lo.Y, -(double)node.Lo.Z);
        Double3 hi = new(-(double)node.Hi.X, -(double)node.Hi.Y, -(double)node.Hi.Z);
        foreach (Plane side in planes)
        {
            Double3 n = side.Normal;
            double farthest = ((n.X >= 0 ? hi.X : lo.X) * n.X) + ((n.Y >= 0 ? hi.Y : lo.Y) * n.Y) + ((n.Z >= 0 ? hi.Z : lo.Z) * n.Z);
            if (farthest + side.Offset < 0)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// The nearest hit per lane among the spheres of the packet's <paramref name="leaves"/> (from
    /// <see cref="CollectLeaves"/>): each leaf's box tested against the lanes first, as in <see cref="Nearest{TL, TP}"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    public static LaneHit<TL> NearestInLeaves<TL, TP>(PacketHierarchy hierarchy, ReadOnlySpan<int> leaves, in Lanes3<TL> origin, in Lanes3<TL> direction, TL dd, TL rdd, TL inverseLength, bool checkOrder, in LaneHit<TL> background)
        where TL : struct, ILanes<TL>
        where TP : struct, ILaneRays
    {
        (TL dx, TL dy, TL dz) = (direction.X, direction.Y, direction.Z);
        TL minusOne = TL.Broadcast(-1f);
        TL tiny = TL.Sqrt(dd) * TL.Broadcast(1e-12f);
        TL nx = minusOne / TL.Select(TL.LessThan(TL.Abs(dx), tiny), tiny, dx);
        TL ny = minusOne / TL.Select(TL.LessThan(TL.Abs(dy), tiny), tiny, dy);
        TL nz = minusOne / TL.Select(TL.LessThan(TL.Abs(dz), tiny), tiny, dz);
        TL slack = TL.Broadcast(hierarchy.RadiusSlack) * TL.Sqrt(rdd);
        var state = new LaneHit<TL>(background.Nearest, background.R, background.G, background.B, TL.Broadcast(float.PositiveInfinity), default, default);
        PacketNode[] nodes = hierarchy.Nodes;
        SphereConstants[] spheres = hierarchy.Spheres;
        DepthBound[] bounds = hierarchy.DepthBounds;
        foreach (int index in leaves)
        {
            ref readonly PacketNode node = ref nodes[index];
            if (Enters<TL, TP>(node, origin, nx, ny, nz, state.Nearest, slack))
            {
                TestLeaf<TL, TP>(spheres, bounds, node, origin, dx, dy, dz, dd, rdd, inverseLength, checkOrder, ref state);
            }
        }

        return state;
    }

    /// <summary>True when any lane's ray enters the node's box before 1.01 × its nearest hit + slack.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Enters<TL, TP>(in PacketNode node, in Lanes3<TL> origin, TL nx, TL ny, TL nz, TL nearest, TL slack)
        where TL : struct, ILanes<TL>
        where TP : struct, ILaneRays
    {
        TL ax = TP.AddOrigin(TL.Broadcast(node.Lo.X), origin.X) * nx, bx = TP.AddOrigin(TL.Broadcast(node.Hi.X), origin.X) * nx;
        TL ay = TP.AddOrigin(TL.Broadcast(node.Lo.Y), origin.Y) * ny, by = TP.AddOrigin(TL.Broadcast(node.Hi.Y), origin.Y) * ny;
        TL az = TP.AddOrigin(TL.Broadcast(node.Lo.Z), origin.Z) * nz, bz = TP.AddOrigin(TL.Broadcast(node.Hi.Z), origin.Z) * nz;
        TL enter = Max(Max(TL.Min(ax, bx), TL.Min(ay, by)), TL.Min(az, bz));
        TL leave = TL.Min(TL.Min(Max(ax, bx), Max(ay, by)), Max(az, bz));
        TL limit = TL.MultiplyAdd(nearest, TL.Broadcast(-1.01f), slack);  // 1.01 × the nearest t + slack (+∞ before a hit)
        TL inside = TL.LessThanOrEqual(enter, leave) & TL.LessThanOrEqual(default, leave) & TL.LessThanOrEqual(enter, limit);
        return TL.MaskBits(inside) != 0;
    }

    /// <summary>The kernel's per-sphere test (<see cref="LaneSphere.Test{TL}"/>) over one leaf's spheres.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void TestLeaf<TL, TP>(SphereConstants[] spheres, DepthBound[] bounds, in PacketNode node, in Lanes3<TL> origin, TL dx, TL dy, TL dz, TL dd, TL rdd, TL inverseLength, bool checkOrder, ref LaneHit<TL> state)
        where TL : struct, ILanes<TL>
        where TP : struct, ILaneRays
    {
        (TL nearest, TL red, TL green, TL blue, TL closest, TL unsure, TL nearestError) = state;
        for (int i = node.Start; i < node.Start + node.Count; i++)
        {
            ref readonly SphereConstants sphere = ref spheres[i];
            TL fx = TP.AddOrigin(TL.Broadcast(sphere.Offset.X), origin.X);
            TL fy = TP.AddOrigin(TL.Broadcast(sphere.Offset.Y), origin.Y);
            TL fz = TP.AddOrigin(TL.Broadcast(sphere.Offset.Z), origin.Z);
            TL negatedT = LaneSphere.Test(fx, fy, fz, dx, dy, dz, dd, rdd, inverseLength, TL.Broadcast(sphere.RadiusSquared), TL.Broadcast(sphere.InverseBound), bounds[i], checkOrder, nearest, ref nearestError, ref closest, ref unsure);
            LaneSphere.TakeNearer(ref nearest, negatedT, ref red, ref green, ref blue, (TL.Broadcast(sphere.Colour.X), TL.Broadcast(sphere.Colour.Y), TL.Broadcast(sphere.Colour.Z)));
        }

        state = new LaneHit<TL>(nearest, red, green, blue, closest, unsure, nearestError);
    }

    /// <summary>
    /// The nearest hit per lane among the spheres whose boxes the packet's rays reach: the kernel's per-sphere
    /// loop (<see cref="LaneSphere.Test{TL}"/>) run over the leaves the packet enters, near child first.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    public static LaneHit<TL> Nearest<TL, TP>(PacketHierarchy hierarchy, in Lanes3<TL> origin, in Lanes3<TL> direction, TL dd, TL rdd, TL inverseLength, bool checkOrder, in LaneHit<TL> background)
        where TL : struct, ILanes<TL>
        where TP : struct, ILaneRays
    {
        (TL dx, TL dy, TL dz) = (direction.X, direction.Y, direction.Z);
        TL zero = default;
        TL minusOne = TL.Broadcast(-1f);
        TL tiny = TL.Sqrt(dd) * TL.Broadcast(1e-12f);   // a zero component would make 0·∞: it moves the box test's ray by 10⁻¹²
        TL nx = minusOne / TL.Select(TL.LessThan(TL.Abs(dx), tiny), tiny, dx);
        TL ny = minusOne / TL.Select(TL.LessThan(TL.Abs(dy), tiny), tiny, dy);
        TL nz = minusOne / TL.Select(TL.LessThan(TL.Abs(dz), tiny), tiny, dz);
        TL slack = TL.Broadcast(hierarchy.RadiusSlack) * TL.Sqrt(rdd);
        var state = new LaneHit<TL>(background.Nearest, background.R, background.G, background.B, TL.Broadcast(float.PositiveInfinity), default, default);
        uint negative = (TL.MaskBits(TL.LessThan(dx, zero)) & 1) | ((TL.MaskBits(TL.LessThan(dy, zero)) & 1) << 1) | ((TL.MaskBits(TL.LessThan(dz, zero)) & 1) << 2);
        PacketNode[] nodes = hierarchy.Nodes;
        SphereConstants[] spheres = hierarchy.Spheres;
        DepthBound[] bounds = hierarchy.DepthBounds;
        Span<int> stack = stackalloc int[hierarchy.Depth + 1];
        int top = 0;
        stack[top++] = 0;
        while (top > 0)
        {
            int index = stack[--top];
            ref readonly PacketNode node = ref nodes[index];
            if (!Enters<TL, TP>(node, origin, nx, ny, nz, state.Nearest, slack))
            {
                continue;
            }

            if (node.Count == 0)
            {
                bool rightFirst = ((negative >> node.Axis) & 1) != 0;
                stack[top++] = rightFirst ? index + 1 : node.Start;
                stack[top++] = rightFirst ? node.Start : index + 1;
                continue;
            }

            TestLeaf<TL, TP>(spheres, bounds, node, origin, dx, dy, dz, dd, rdd, inverseLength, checkOrder, ref state);
        }

        return state;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL Max<TL>(TL a, TL b)
        where TL : struct, ILanes<TL> => TL.Select(TL.LessThan(a, b), b, a);
}

/// <summary>
/// One node of a <see cref="PacketHierarchy"/>: its widened box as offsets from the frame's fixed point
/// (fixed point − corner), and the <see cref="HierarchyNode"/>'s links.
/// </summary>
/// <param name="Lo">Fixed point − the lower corner.</param>
/// <param name="Hi">Fixed point − the upper corner.</param>
/// <param name="Start">A leaf's first sphere, or an inner node's right child.</param>
/// <param name="Count">A leaf's sphere count; 0 for an inner node.</param>
/// <param name="Axis">The split axis.</param>
internal readonly record struct PacketNode(Float3 Lo, Float3 Hi, int Start, int Count, int Axis);


/// <summary>A packet's nearest hits: −t, colour, the smallest |Δ|/bound, the lanes uncertain in depth order and the error bound of each lane's t.</summary>
internal readonly record struct LaneHit<TL>(TL Nearest, TL R, TL G, TL B, TL Closest, TL Unsure, TL NearestError)
    where TL : struct, ILanes<TL>;
