using System.Buffers;
using System.Runtime.CompilerServices;

namespace RayLab.Geometry;

/// <summary>
/// A bounding volume hierarchy over a scene's spheres (the lab's reference [5], space subdivision; here the
/// surface-area-heuristic BVH of pbrt-v4 and Embree): axis-aligned boxes, each inner node's two children in one
/// flat array (depth first: the left child follows its parent), leaves of up to <see cref="LeafSize"/> spheres.
/// Built once per scene (binned SAH, 16 bins on the axis of the largest centroid spread; the two halves of a
/// large node in parallel), read by the scalar double path (<see cref="Nearest"/>) and, through float copies of
/// its boxes, by the packet kernel.
/// </summary>
/// <remarks>
/// The hierarchy never changes a picture: <see cref="Nearest"/> returns exactly what testing every sphere in
/// index order returns (<see cref="Scene"/>'s loop), ties included (of two hits at the same t the higher index
/// wins, as in that loop). Boxes are only a filter, widened by a margin far above double's rounding, and a node is
/// skipped for depth only when its entry lies beyond the nearest hit by a relative 10⁻⁶.
/// </remarks>
internal sealed class SphereHierarchy
{
    /// <summary>The most spheres in a leaf.</summary>
    public const int LeafSize = 4;

    /// <summary>The most spheres a hierarchy holds: node and index arrays stay below 2³¹ entries.</summary>
    public const int MaxSpheres = 100_000_000;

    private const int Bins = 16;

    /// <summary>Levels split by the SAH; deeper ones by the median.</summary>
    private const int SahLevels = 40;

    /// <summary>Nodes below this many spheres are built on the calling thread.</summary>
    private const int ParallelGrain = 20_000;

    /// <summary>The relative widening of every box for the double test (double's rounding is ~10⁻¹⁶).</summary>
    private const double Margin = 1e-7;

    /// <summary>The relative depth slack before a node is skipped as lying behind the nearest hit.</summary>
    private const double DepthSlack = 1e-6;

    private readonly HierarchyNode[] _nodes;
    private readonly int[] _order;

    private SphereHierarchy(HierarchyNode[] nodes, int[] order, int depth, double scale)
    {
        _nodes = nodes;
        _order = order;
        Depth = depth;
        Scale = scale;
    }

    /// <summary>The nodes, depth first; node 0 is the root.</summary>
    public ReadOnlySpan<HierarchyNode> Nodes => _nodes;

    /// <summary>The sphere indices (into the scene's spheres) in leaf order; a leaf holds <c>Order[Start..Start+Count]</c>.</summary>
    public ReadOnlySpan<int> Order => _order;

    /// <summary>The number of levels (a traversal stack of this many entries suffices).</summary>
    public int Depth { get; }

    /// <summary>The largest absolute coordinate of the root box: the size of the scene for rounding margins.</summary>
    public double Scale { get; }

    /// <summary>Builds the hierarchy over the spheres of radius &gt; 0 (a sphere of radius 0 is never hit).</summary>
    /// <param name="spheres">The scene's spheres.</param>
    /// <returns>The hierarchy, or null when no sphere can be hit.</returns>
    /// <exception cref="ArgumentException">More than <see cref="MaxSpheres"/> spheres.</exception>
    public static SphereHierarchy? Build(IReadOnlyList<Sphere> spheres)
    {
        ArgumentNullException.ThrowIfNull(spheres);
        if (spheres.Count > MaxSpheres)
        {
            throw new ArgumentException($"The scene has {spheres.Count} spheres; the hierarchy holds at most {MaxSpheres}.", nameof(spheres));
        }

        var order = new List<int>(spheres.Count);
        for (int k = 0; k < spheres.Count; k++)
        {
            if (spheres[k].Radius > 0)
            {
                order.Add(k);
            }
        }

        if (order.Count == 0)
        {
            return null;
        }

        int n = order.Count;
        var items = new Item[n];
        for (int i = 0; i < n; i++)
        {
            Sphere sphere = spheres[order[i]];
            (Double3 lo, Double3 hi) = sphere.Box;
            items[i] = new Item(order[i], lo, hi, sphere.Center);
        }

        // A binary tree with leaves of ≥ 1 sphere has at most 2n − 1 nodes; each subtree gets exactly the
        // slots it uses (2·count − 1 at most, reserved up front), so parallel halves never share a slot.
        var nodes = new HierarchyNode[(2 * n) - 1];
        int used = BuildNode(items, nodes, 0, 0, n, 0, out int depth);
        Array.Resize(ref nodes, used);
        int[] sorted = new int[n];
        for (int i = 0; i < n; i++)
        {
            sorted[i] = items[i].Index;
        }

        HierarchyNode root = nodes[0];
        double scale = Math.Max(MaxAbs(root.Lo), MaxAbs(root.Hi));
        return new SphereHierarchy(nodes, sorted, depth, scale);
    }

    /// <summary>
    /// The index of the nearest sphere hit with parameter in [<paramref name="tMin"/>, <paramref name="tMax"/>],
    /// or −1: the same answer as testing every sphere in index order.
    /// </summary>
    /// <param name="spheres">The scene's spheres (the list the hierarchy was built over).</param>
    /// <param name="ray">The ray.</param>
    /// <param name="tMin">The smallest visible parameter.</param>
    /// <param name="tMax">The largest visible parameter.</param>
    /// <remarks>The traversal stack is not cleared (<see cref="SkipLocalsInitAttribute"/>): an entry is pushed before it is read.</remarks>
    [SkipLocalsInit]
    public int Nearest(Sphere[] spheres, in Ray ray, double tMin, double tMax)
    {
        var stack = new SpanStack(stackalloc int[Depth + 1]);
        return Traversal.Nearest(new Tree(this, spheres), ref stack, ray, tMin, tMax);
    }

    /// <summary>
    /// The traversal, once, static and generic over where the tree and its stack live: <see cref="Nearest"/> runs it on
    /// the managed arrays with a stack on the CPU's stack, the device kernel of <c>RayLab.Gpu</c> on the same nodes and
    /// order uploaded to the device, with a fixed-size stack in its local memory. Unmanaged values only, no recursion.
    /// </summary>
    internal static class Traversal
    {
        /// <summary>
        /// The index of the nearest sphere of <paramref name="tree"/> hit with parameter in [<paramref name="tMin"/>,
        /// <paramref name="tMax"/>], or −1: the same answer as testing every sphere in index order.
        /// </summary>
        /// <param name="tree">The hierarchy's nodes, order and spheres.</param>
        /// <param name="stack">At least <see cref="Depth"/> + 1 entries.</param>
        /// <param name="ray">The ray.</param>
        /// <param name="tMin">The smallest visible parameter.</param>
        /// <param name="tMax">The largest visible parameter.</param>
        /// <typeparam name="TTree">The tree's storage.</typeparam>
        /// <typeparam name="TStack">The stack's storage.</typeparam>
        // Long: one traversal loop, whose stack, nearest index and best t a split would pass by reference at every node.
        public static int Nearest<TTree, TStack>(in TTree tree, ref TStack stack, in Ray ray, double tMin, double tMax)
            where TTree : struct, IHierarchyView
            where TStack : struct, ITraversalStack, allows ref struct
        {
            Double3 o = ray.Origin, d = ray.Direction;
            double a = Double3.Dot(d, d);
            if (!(a > 0) || !double.IsFinite(a))
            {
                return -1; // Sphere.TryIntersect refuses such a direction for every sphere
            }

            double largest = MaxAbs(d);
            double tiny = largest * 1e-20;
            if (!(tiny > 0) || !o.IsFinite)
            {
                return NearestOfAll(tree, ray, tMin, tMax);
            }

            // A zero component would make 0·∞; a tiny one moves the box test's ray by 10⁻²⁰ of its length.
            Double3 inverse = new(1 / Safe(d.X, tiny), 1 / Safe(d.Y, tiny), 1 / Safe(d.Z, tiny));
            double margin = Margin * (MaxAbs(o) + tree.Scale);
            double lower = tMin * (1 - DepthSlack);
            int nearest = -1;
            double best = tMax;
            // Copies of the views (not of what they view), which the loop keeps in registers.
            TTree view = tree;
            TStack entries = stack;
            int top = 0;
            entries[top++] = 0;
            while (top > 0)
            {
                int self = entries[--top];
                HierarchyNode node = view.Node(self);
                if (!Enters(node, o, inverse, margin, lower, best * (1 + DepthSlack)))
                {
                    continue;
                }

                if (node.Count > 0)
                {
                    for (int i = node.Start; i < node.Start + node.Count; i++)
                    {
                        int index = view.Order(i);
                        if (view.TryIntersect(index, ray, tMin, best, out double t) && (t < best || index > nearest))
                        {
                            best = t;
                            nearest = index;
                        }
                    }

                    continue;
                }

                // Inner node: the left child follows it, the right one is at Start. The near one goes on top.
                bool rightFirst = Component(d, node.Axis) < 0;
                if (rightFirst)
                {
                    entries[top++] = self + 1;
                    entries[top++] = node.Start;
                }
                else
                {
                    entries[top++] = node.Start;
                    entries[top++] = self + 1;
                }
            }

            return nearest;
        }

        /// <summary>The nearest hit over every sphere of <paramref name="tree"/> in index order (the scene's loop).</summary>
        /// <param name="tree">The spheres.</param>
        /// <param name="ray">The ray.</param>
        /// <param name="tMin">The smallest visible parameter.</param>
        /// <param name="tMax">The largest visible parameter.</param>
        /// <typeparam name="TTree">The spheres' storage.</typeparam>
        public static int NearestOfAll<TTree>(in TTree tree, in Ray ray, double tMin, double tMax)
            where TTree : struct, IHierarchyView
        {
            int nearest = -1;
            double best = tMax;
            TTree view = tree;
            for (int k = 0; k < view.SphereCount; k++)
            {
                if (view.TryIntersect(k, ray, tMin, best, out double t))
                {
                    best = t;
                    nearest = k;
                }
            }

            return nearest;
        }
    }

    /// <summary>The managed tree: this hierarchy's arrays and the scene's spheres.</summary>
    /// <remarks>The arrays themselves, not the hierarchy: the traversal reads them with no indirection through it.</remarks>
    private readonly struct Tree : IHierarchyView
    {
        private readonly HierarchyNode[] _nodes;
        private readonly int[] _order;
        private readonly Sphere[] _spheres;

        /// <summary>The hierarchy's tree over <paramref name="spheres"/>.</summary>
        public Tree(SphereHierarchy hierarchy, Sphere[] spheres)
        {
            _nodes = hierarchy._nodes;
            _order = hierarchy._order;
            _spheres = spheres;
            Scale = hierarchy.Scale;
        }

        /// <summary>The spheres alone, for <see cref="Traversal.NearestOfAll"/> (no nodes).</summary>
        public Tree(Sphere[] spheres)
        {
            _nodes = null!;
            _order = null!;
            _spheres = spheres;
        }

        public double Scale { get; }

        public int SphereCount => _spheres.Length;

        public HierarchyNode Node(int index) => _nodes[index];

        public int Order(int position) => _order[position];

        public bool TryIntersect(int sphere, in Ray ray, double tMin, double tMax, out double t) => _spheres[sphere].TryIntersect(ray, tMin, tMax, out t);
    }

    /// <summary>A traversal stack on the CPU's stack.</summary>
    private ref struct SpanStack(Span<int> entries) : ITraversalStack
    {
        private readonly Span<int> _entries = entries;

        public readonly int this[int index]
        {
            get => _entries[index];
            set => _entries[index] = value;
        }
    }

    /// <summary>
    /// Calls <paramref name="visit"/> with the index of every sphere in a leaf whose box meets the box
    /// [<paramref name="lo"/>, <paramref name="hi"/>] (a superset of the spheres whose boxes meet it), until it returns false.
    /// </summary>
    /// <param name="lo">The query box's lower corner.</param>
    /// <param name="hi">The query box's upper corner.</param>
    /// <param name="visit">Called per candidate; false stops the walk.</param>
    public void VisitOverlapping(Double3 lo, Double3 hi, Func<int, bool> visit)
    {
        ArgumentNullException.ThrowIfNull(visit);
        Span<int> stack = stackalloc int[Depth + 1];
        int top = 0;
        stack[top++] = 0;
        while (top > 0)
        {
            int self = stack[--top];
            ref readonly HierarchyNode node = ref _nodes[self];
            if (node.Lo.X > hi.X || node.Lo.Y > hi.Y || node.Lo.Z > hi.Z || node.Hi.X < lo.X || node.Hi.Y < lo.Y || node.Hi.Z < lo.Z)
            {
                continue;
            }

            if (node.Count == 0)
            {
                stack[top++] = node.Start;
                stack[top++] = self + 1;
                continue;
            }

            for (int i = node.Start; i < node.Start + node.Count; i++)
            {
                if (!visit(_order[i]))
                {
                    return;
                }
            }
        }
    }

    /// <summary>The nearest hit over every sphere in index order (the scene's loop).</summary>
    internal static int NearestOfAll(Sphere[] spheres, in Ray ray, double tMin, double tMax) =>
        Traversal.NearestOfAll(new Tree(spheres), ray, tMin, tMax);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Enters(in HierarchyNode node, Double3 o, Double3 inverse, double margin, double lower, double upper)
    {
        double near = lower, far = upper;
        Slab(node.Lo.X - margin - o.X, node.Hi.X + margin - o.X, inverse.X, ref near, ref far);
        Slab(node.Lo.Y - margin - o.Y, node.Hi.Y + margin - o.Y, inverse.Y, ref near, ref far);
        Slab(node.Lo.Z - margin - o.Z, node.Hi.Z + margin - o.Z, inverse.Z, ref near, ref far);
        return near <= far;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Slab(double lo, double hi, double inverse, ref double near, ref double far)
    {
        double t0 = lo * inverse, t1 = hi * inverse;
        if (inverse < 0)
        {
            (t0, t1) = (t1, t0);
        }

        near = t0 > near ? t0 : near;
        far = t1 < far ? t1 : far;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Safe(double component, double tiny) =>
        Math.Abs(component) >= tiny ? component : (component >= 0 ? tiny : -tiny);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double Component(Double3 v, int axis) => axis switch { 0 => v.X, 1 => v.Y, _ => v.Z };

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double MaxAbs(Double3 v) => Math.Max(Math.Max(Math.Abs(v.X), Math.Abs(v.Y)), Math.Abs(v.Z));

    /// <summary>Builds the subtree of items[start..start+count] at nodes[slot]; returns the next free slot.</summary>
    /// <remarks>Below <see cref="SahLevels"/> levels the split is the binned SAH's; deeper (a pathological spread of
    /// sizes) it is the median, so the tree is never deeper than <see cref="SahLevels"/> + log₂ n.</remarks>
    private static int BuildNode(Item[] items, HierarchyNode[] nodes, int slot, int start, int count, int level, out int depth)
    {
        (Double3 lo, Double3 hi, Double3 centreLo, Double3 centreHi) = Bounds(items, start, count);
        int axis = 0, leftCount = count / 2;
        bool split = count > LeafSize && (level < SahLevels
            ? TrySplit(items, start, count, lo, hi, centreLo, centreHi, out axis, out leftCount)
            : MedianSplit(items, start, count, centreLo, centreHi, out axis, out leftCount));
        if (!split)
        {
            nodes[slot] = new HierarchyNode(lo, hi, start, count, 0);
            depth = 1;
            return slot + 1;
        }

        int leftSlot = slot + 1;
        int rightSlot = slot + 1 + ((2 * leftCount) - 1); // the left subtree's reserved slots
        int leftDepth = 0, rightDepth = 0, leftEnd = 0, rightEnd = 0;
        if (count >= ParallelGrain)
        {
            Parallel.Invoke(
                () => leftEnd = BuildNode(items, nodes, leftSlot, start, leftCount, level + 1, out leftDepth),
                () => rightEnd = BuildNode(items, nodes, rightSlot, start + leftCount, count - leftCount, level + 1, out rightDepth));
        }
        else
        {
            leftEnd = BuildNode(items, nodes, leftSlot, start, leftCount, level + 1, out leftDepth);
            rightEnd = BuildNode(items, nodes, rightSlot, start + leftCount, count - leftCount, level + 1, out rightDepth);
        }

        // Close the gap the left subtree left unused, so the right child's slot is recorded where it ends up.
        int gap = rightSlot - leftEnd;
        if (gap > 0)
        {
            Array.Copy(nodes, rightSlot, nodes, leftEnd, rightEnd - rightSlot);
            for (int i = leftEnd; i < rightEnd - gap; i++)
            {
                if (nodes[i].Count == 0)
                {
                    nodes[i] = nodes[i] with { Start = nodes[i].Start - gap };
                }
            }
        }

        nodes[slot] = new HierarchyNode(lo, hi, leftEnd, 0, axis);
        depth = 1 + Math.Max(leftDepth, rightDepth);
        return rightEnd - gap;
    }

    private static (Double3 Lo, Double3 Hi, Double3 CentreLo, Double3 CentreHi) Bounds(Item[] items, int start, int count)
    {
        Double3 lo = items[start].Lo, hi = items[start].Hi, cLo = items[start].Centre, cHi = cLo;
        for (int i = start + 1; i < start + count; i++)
        {
            ref readonly Item item = ref items[i];
            lo = Double3.Min(lo, item.Lo);
            hi = Double3.Max(hi, item.Hi);
            cLo = Double3.Min(cLo, item.Centre);
            cHi = Double3.Max(cHi, item.Centre);
        }

        return (lo, hi, cLo, cHi);
    }

    /// <summary>The binned SAH split of items[start..start+count], partitioned in place (stable); false when a leaf is cheaper.</summary>
    private static bool TrySplit(Item[] items, int start, int count, Double3 lo, Double3 hi, Double3 centreLo, Double3 centreHi, out int axis, out int leftCount)
    {
        Double3 spread = centreHi - centreLo;
        axis = WidestAxis(spread);
        double min = Component(centreLo, axis), extent = Component(spread, axis);
        leftCount = count / 2;
        if (!(extent > 0))
        {
            return true; // every centre at one point: split in the middle (a tree, not one huge leaf)
        }

        var bins = new SahBins();
        double scale = Bins / extent;
        bins.Fill(items, start, count, axis, min, scale);
        int bestBin = bins.Cheapest(count, out int bestLeft, out double bestCost);
        if (bestBin < 0)
        {
            return true;
        }

        // A leaf costs N intersections; a split one traversal step (≈ 1/2 an intersection) plus the children.
        double leafCost = count * Area(lo, hi);
        if (count <= 2 * LeafSize && (0.5 * Area(lo, hi)) + bestCost >= leafCost)
        {
            leftCount = 0;
            return false;
        }

        Partition(items, start, count, bestLeft, axis, min, scale, bestBin);
        leftCount = bestLeft;
        return true;
    }

    /// <summary>The axis (0, 1, 2 for x, y, z) along which <paramref name="spread"/> is largest; the first on a tie.</summary>
    private static int WidestAxis(Double3 spread) =>
        spread.X >= spread.Y && spread.X >= spread.Z ? 0 : (spread.Y >= spread.Z ? 1 : 2);

    /// <summary>Moves the items[start..start+count] of the bins up to <paramref name="lastLeftBin"/> (<paramref name="leftCount"/> of them) before the others, each side in its order.</summary>
    private static void Partition(Item[] items, int start, int count, int leftCount, int axis, double min, double scale, int lastLeftBin)
    {
        Item[] right = ArrayPool<Item>.Shared.Rent(count - leftCount);
        int l = start, r = 0;
        for (int i = start; i < start + count; i++)
        {
            if (BinOf(items[i].Centre, axis, min, scale) <= lastLeftBin)
            {
                items[l++] = items[i];
            }
            else
            {
                right[r++] = items[i];
            }
        }

        Array.Copy(right, 0, items, l, r);
        ArrayPool<Item>.Shared.Return(right);
    }

    [InlineArray(Bins)]
    private struct BinCounts
    {
        private int _element;
    }

    [InlineArray(Bins)]
    private struct BinBoxes
    {
        private Double3 _element;
    }

    /// <summary>The SAH's bins along one axis: each bin's item count and the box around its items.</summary>
    private struct SahBins
    {
        private BinCounts _count;
        private BinBoxes _lo, _hi;

        /// <summary>Puts each item of items[start..start+count] into the bin of its centre.</summary>
        public void Fill(Item[] items, int start, int count, int axis, double min, double scale)
        {
            for (int i = start; i < start + count; i++)
            {
                int b = BinOf(items[i].Centre, axis, min, scale);
                if (_count[b]++ == 0)
                {
                    _lo[b] = items[i].Lo;
                    _hi[b] = items[i].Hi;
                }
                else
                {
                    _lo[b] = Double3.Min(_lo[b], items[i].Lo);
                    _hi[b] = Double3.Max(_hi[b], items[i].Hi);
                }
            }
        }

        /// <summary>
        /// The bin after which a split costs least, A_left·N_left + A_right·N_right (relative to the parent's area),
        /// with its left side's item count and the cost; −1 when no split leaves items on both sides.
        /// </summary>
        public readonly int Cheapest(int count, out int bestLeft, out double bestCost)
        {
            Span<double> rightCost = stackalloc double[Bins];
            Double3 accLo = default, accHi = default;
            int accCount = 0;
            for (int b = Bins - 1; b > 0; b--)
            {
                Accumulate(_count[b], _lo[b], _hi[b], ref accLo, ref accHi, ref accCount);
                rightCost[b] = accCount == 0 ? 0 : Area(accLo, accHi) * accCount;
            }

            bestCost = double.PositiveInfinity;
            bestLeft = 0;
            int bestBin = -1;
            accCount = 0;
            for (int b = 0; b < Bins - 1; b++)
            {
                Accumulate(_count[b], _lo[b], _hi[b], ref accLo, ref accHi, ref accCount);
                if (accCount == 0 || accCount == count)
                {
                    continue;
                }

                double cost = (Area(accLo, accHi) * accCount) + rightCost[b + 1];
                if (cost < bestCost)
                {
                    bestCost = cost;
                    bestBin = b;
                    bestLeft = accCount;
                }
            }

            return bestBin;
        }
    }

    /// <summary>Sorts items[start..start+count] by centre along the axis of largest spread and splits it in half.</summary>
    private static bool MedianSplit(Item[] items, int start, int count, Double3 centreLo, Double3 centreHi, out int axis, out int leftCount)
    {
        int a = WidestAxis(centreHi - centreLo);
        Array.Sort(items, start, count, Comparer<Item>.Create((p, q) =>
        {
            int byCentre = Component(p.Centre, a).CompareTo(Component(q.Centre, a));
            return byCentre != 0 ? byCentre : p.Index.CompareTo(q.Index);
        }));
        axis = a;
        leftCount = count / 2;
        return true;
    }

    private static void Accumulate(int count, Double3 lo, Double3 hi, ref Double3 accLo, ref Double3 accHi, ref int accCount)
    {
        if (count == 0)
        {
            return;
        }

        (accLo, accHi) = accCount == 0 ? (lo, hi) : (Double3.Min(accLo, lo), Double3.Max(accHi, hi));
        accCount += count;
    }

    private static int BinOf(Double3 centre, int axis, double min, double scale) =>
        Math.Clamp((int)((Component(centre, axis) - min) * scale), 0, Bins - 1);

    private static double Area(Double3 lo, Double3 hi)
    {
        Double3 e = hi - lo;
        return (e.X * e.Y) + (e.Y * e.Z) + (e.Z * e.X);
    }

    /// <summary>A sphere while building: its index, box and centre.</summary>
    private readonly record struct Item(int Index, Double3 Lo, Double3 Hi, Double3 Centre);
}

/// <summary>
/// One node of a <see cref="SphereHierarchy"/>: its box, and either its spheres (a leaf: <see cref="Count"/> &gt; 0,
/// <c>Order[Start..Start+Count]</c>) or its right child (inner: <see cref="Count"/> = 0, the right child at
/// <see cref="Start"/>, the left one right after this node), split along <see cref="Axis"/>.
/// </summary>
/// <param name="Lo">The box's lower corner.</param>
/// <param name="Hi">The box's upper corner.</param>
/// <param name="Start">A leaf's first position in the order, or an inner node's right child.</param>
/// <param name="Count">A leaf's sphere count; 0 for an inner node.</param>
/// <param name="Axis">The split axis (0 x, 1 y, 2 z) of an inner node.</param>
internal readonly record struct HierarchyNode(Double3 Lo, Double3 Hi, int Start, int Count, int Axis);

/// <summary>A sphere hierarchy's storage, for <see cref="SphereHierarchy.Traversal"/>: its nodes, its leaves' sphere order and the spheres' hit test.</summary>
internal interface IHierarchyView
{
    /// <summary>The largest absolute coordinate of the root box (<see cref="SphereHierarchy.Scale"/>).</summary>
    double Scale { get; }

    /// <summary>The number of spheres.</summary>
    int SphereCount { get; }

    /// <summary>Node <paramref name="index"/>, depth first (<see cref="SphereHierarchy.Nodes"/>).</summary>
    /// <param name="index">The node's index.</param>
    HierarchyNode Node(int index);

    /// <summary>The sphere at <paramref name="position"/> of the leaves' order (<see cref="SphereHierarchy.Order"/>).</summary>
    /// <param name="position">The position.</param>
    int Order(int position);

    /// <summary><see cref="SphereHit.TryIntersect"/> of sphere <paramref name="sphere"/>.</summary>
    /// <param name="sphere">The sphere's index in the scene.</param>
    /// <param name="ray">The ray.</param>
    /// <param name="tMin">The smallest t accepted.</param>
    /// <param name="tMax">The largest t accepted.</param>
    /// <param name="t">The hit's t.</param>
    bool TryIntersect(int sphere, in Ray ray, double tMin, double tMax, out double t);
}

/// <summary>The traversal stack of <see cref="SphereHierarchy.Traversal"/>: node indices.</summary>
internal interface ITraversalStack
{
    /// <summary>Entry <paramref name="index"/>.</summary>
    /// <param name="index">The entry.</param>
    int this[int index] { get; set; }
}
