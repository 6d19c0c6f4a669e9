using ILGPU;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Sampling;

namespace RayLab.Gpu;

/// <summary>Which built-in point sampler a <see cref="PointFrame"/> runs.</summary>
internal enum DeviceSampler
{
    /// <summary><see cref="RegularSampler"/>.</summary>
    Regular,

    /// <summary><see cref="JitteredSampler"/>.</summary>
    Jittered,

    /// <summary><see cref="RandomSampler"/>.</summary>
    Random,

    /// <summary><see cref="HammersleySampler"/>.</summary>
    Hammersley,

    /// <summary><see cref="NRooksSampler"/>.</summary>
    NRooks,

    /// <summary><see cref="MultiJitteredSampler"/>.</summary>
    MultiJittered,

    /// <summary><see cref="CorrelatedMultiJitteredSampler"/>.</summary>
    CorrelatedMultiJittered,

    /// <summary><see cref="SobolSampler"/>.</summary>
    Sobol,

    /// <summary><see cref="Pmj02Sampler"/> and <see cref="Pmj02BNSampler"/> (their sets in the table, <see cref="PointFrame.Scramble"/> pmj02's shift).</summary>
    Pmj02,

    /// <summary><see cref="ZSobolSampler"/> (its 24 digit permutations in the table).</summary>
    ZSobol,
}

/// <summary>A sphere as the kernel reads it: centre, radius and its flat colour (<see cref="Scene.ColourOf"/>).</summary>
/// <param name="center">The centre.</param>
/// <param name="radius">The radius.</param>
/// <param name="colour">The colour the scene shades it with.</param>
internal readonly struct DeviceSphere(Double3 center, double radius, Intensity colour)
{
    /// <summary>The centre.</summary>
    public readonly Double3 Center = center;

    /// <summary>The radius.</summary>
    public readonly double Radius = radius;

    /// <summary>The colour.</summary>
    public readonly Intensity Colour = colour;
}

/// <summary>What one launch of <see cref="PointKernel"/> renders: the rays, the sampler and which CPU kernel's bytes to give.</summary>
internal struct PointFrame
{
    /// <summary>The camera's rays.</summary>
    public RayBasis Basis;

    /// <summary>The first row rendered (a band of rows starts below 0).</summary>
    public int FirstRow;

    /// <summary>Samples per pixel.</summary>
    public int Samples;

    /// <summary>The sampler.</summary>
    public DeviceSampler Sampler;

    /// <summary>The grid side of the regular and jittered samplers.</summary>
    public int GridSize;

    /// <summary>The salted seed of the hashed samplers.</summary>
    public uint Salt;

    /// <summary>The jitter's scale in float (<see cref="JitteredSampler"/>).</summary>
    public float JitterScale;

    /// <summary>The columns m of <see cref="CorrelatedMultiJitteredSampler"/>'s grid.</summary>
    public int Columns;

    /// <summary>The rows n of <see cref="CorrelatedMultiJitteredSampler"/>'s grid.</summary>
    public int Rows;

    /// <summary>The entries of one pmj02 set in the table (two per point).</summary>
    public int SetLength;

    /// <summary>1: pmj02's digital shift; 0: none (pmj02bn). An int, as <see cref="Lanes"/>.</summary>
    public int Scramble;

    /// <summary>m of <see cref="ZSobolSampler"/>: a pixel's block of 2ᵐ Sobol' indices.</summary>
    public int Log2Block;

    /// <summary><see cref="ZSobolSampler"/>'s salt of the digit permutations.</summary>
    public ulong DigitSalt;

    /// <summary><see cref="ZSobolSampler"/>'s seed of the first coordinate's scramble.</summary>
    public uint XSeed;

    /// <summary><see cref="ZSobolSampler"/>'s seed of the second coordinate's scramble.</summary>
    public uint YSeed;

    /// <summary>
    /// 1: the packet kernels' bytes (points in float, the sum in float, the lanes' 8-bit rule); 0: the scalar double
    /// loop's (<see cref="RenderKernel.Scalar"/>). An int: a kernel parameter holds no bool (not blittable).
    /// </summary>
    public int Lanes;

    /// <summary>The scene's background.</summary>
    public Intensity Background;

    /// <summary>1: the scene's spheres are traced through its hierarchy (<see cref="DeviceScene"/>); 0: every sphere in order.</summary>
    public int Hierarchy;

    /// <summary>The hierarchy's <see cref="SphereHierarchy.Scale"/>.</summary>
    public double HierarchyScale;
}

/// <summary>
/// The device kernel: one thread a pixel, each pixel the mean of its samples, only its three bytes written. Every
/// formula in it is the CPU's own (the samplers' <c>Formula</c> structs over <see cref="IPointMath{TV}"/>,
/// <see cref="RayBasis.GetPixelRay"/>, <see cref="SphereHit.TryIntersect"/>, the 8-bit rules), so the bytes are the
/// CPU renderer's: with <see cref="PointFrame.Lanes"/> those of every packet width (the points in the lanes' float, the
/// hit decided in double, as the packet kernels decide every uncertain one), without it those of the scalar loop.
/// </summary>
internal static class PointKernel
{
    /// <summary>Renders pixel <paramref name="index"/> of the band (row by row) into <paramref name="rgb"/>, 3 bytes a pixel.</summary>
    /// <param name="index">The pixel's index in the band.</param>
    /// <param name="frame">The launch's settings.</param>
    /// <param name="spheres">The scene's spheres, in the scene's order.</param>
    /// <param name="table">The sampler's table (pmj02's sets one after another, zsobol's permutations), or one unused entry.</param>
    /// <param name="rgb">The band's bytes, R G B per pixel, row by row.</param>
    /// <param name="nodes">The scene's hierarchy's nodes (<see cref="SphereHierarchy.Nodes"/>), or one unused entry.</param>
    /// <param name="order">The hierarchy's sphere order (<see cref="SphereHierarchy.Order"/>), or one unused entry.</param>
    public static void Render(Index1D index, PointFrame frame, ArrayView<DeviceSphere> spheres, ArrayView<uint> table, ArrayView<byte> rgb, ArrayView<HierarchyNode> nodes, ArrayView<int> order)
    {
        var scene = new DeviceScene(spheres, nodes, order, frame.HierarchyScale, frame.Hierarchy, frame.Background, frame.Hierarchy != 0 ? LocalMemory.Allocate1D<int>(DeviceScene.MaxDepth + 1) : default);
        int width = frame.Basis.Width;
        int x = index % width;
        int row = frame.FirstRow + (index / width);
        long at = 3L * index;
        if (frame.Lanes != 0)
        {
            LaneMean(frame, scene, table, x, row, out float r, out float g, out float b);
            float scale = 256f / frame.Samples;
            rgb[at] = EightBit.LaneLevel(r, scale);
            rgb[at + 1] = EightBit.LaneLevel(g, scale);
            rgb[at + 2] = EightBit.LaneLevel(b, scale);
        }
        else
        {
            Intensity mean = ScalarMean(frame, scene, table, x, row);
            rgb[at] = Intensity.ToLevel(mean.R);
            rgb[at + 1] = Intensity.ToLevel(mean.G);
            rgb[at + 2] = Intensity.ToLevel(mean.B);
        }
    }

    /// <summary>The packet kernels' sum of a pixel's samples: points in float, each colour in float, summed in order.</summary>
    private static void LaneMean(in PointFrame frame, in DeviceScene scene, ArrayView<uint> table, int x, int row, out float r, out float g, out float b)
    {
        uint key = PointHash.PixelKeys<ScalarLane, ScalarMath>(x, row, frame.Salt).Bits;
        var pattern = new PixelPattern(frame, key);
        r = g = b = 0f;
        for (int i = 0; i < frame.Samples; i++)
        {
            float sx, sy;
            if (frame.Sampler == DeviceSampler.Regular)
            {
                SamplePoint p = RegularSampler.Formula.Point(i, frame.GridSize);
                (sx, sy) = ((float)p.X, (float)p.Y);
            }
            else
            {
                Point<FloatLane, FloatLaneMath>(frame, pattern, table, key, x, row, i, out FloatLane px, out FloatLane py);
                (sx, sy) = (px.Value, py.Value);
            }

            Intensity colour = scene.Trace(frame.Basis.GetPixelRay(x, row, sx, sy), frame.Basis.TMin, frame.Basis.TMax);
            r += (float)colour.R;
            g += (float)colour.G;
            b += (float)colour.B;
        }
    }

    /// <summary>The scalar loop's mean of a pixel's samples, in double.</summary>
    private static Intensity ScalarMean(in PointFrame frame, in DeviceScene scene, ArrayView<uint> table, int x, int row)
    {
        uint key = PointHash.PixelKeys<ScalarLane, ScalarMath>(x, row, frame.Salt).Bits;
        var pattern = new PixelPattern(frame, key);
        int n = frame.Samples;
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++)
        {
            double sx, sy;
            if (frame.Sampler == DeviceSampler.Regular)
            {
                SamplePoint p = RegularSampler.Formula.Point(i, frame.GridSize);
                (sx, sy) = (p.X, p.Y);
            }
            else
            {
                Point<ScalarLane, ScalarMath>(frame, pattern, table, key, x, row, i, out ScalarLane px, out ScalarLane py);
                (sx, sy) = (px.Value, py.Value);
            }

            Intensity value = scene.Trace(frame.Basis.GetPixelRay(x, row, sx, sy), frame.Basis.TMin, frame.Basis.TMax);
            r += value.R;
            g += value.G;
            b += value.B;
        }

        return new Intensity(r / n, g / n, b / n);
    }

    /// <summary>
    /// Sample <paramref name="i"/> of the pixel whose key is <paramref name="key"/>, by the sampler's own formula: in the
    /// lanes' float (<see cref="FloatLaneMath"/>) or the scalar double (<see cref="ScalarMath"/>). Not the regular
    /// grid, whose point needs no arithmetic of either.
    /// </summary>
    private static void Point<TV, TM>(in PointFrame frame, in PixelPattern pattern, ArrayView<uint> table, uint key, int x, int row, int i, out TV sx, out TV sy)
        where TV : struct
        where TM : IPointMath<TV>
    {
        TV keys = TM.BroadcastBits(key);
        switch (frame.Sampler)
        {
            case DeviceSampler.Jittered:
                JitteredSampler.Formula.Point<TV, TM>(keys, i, JitteredSampler.Formula.CellOf(i, frame.GridSize), frame.GridSize, frame.JitterScale, out sx, out sy);
                break;
            case DeviceSampler.Random:
                RandomSampler.Formula.Point<TV, TM>(keys, i, out sx, out sy);
                break;
            case DeviceSampler.Hammersley:
                HammersleySampler.Formula.Shift<TV, TM>(keys, out TV shiftX, out TV shiftY);
                SamplePoint p = HammersleySampler.Formula.Unshifted(i, frame.Samples);
                (sx, sy) = (TM.Shifted(p.X, shiftX), TM.Shifted(p.Y, shiftY));
                break;
            case DeviceSampler.NRooks:
                NRooksSampler.Formula.Point<TV, TM>(key, i, frame.Samples, pattern.Divisor, out sx, out sy);
                break;
            case DeviceSampler.MultiJittered:
                MultiJitteredSampler.Formula.Point<TV, TM>(key, i, frame.GridSize, pattern.Divisor, out sx, out sy);
                break;
            case DeviceSampler.CorrelatedMultiJittered:
                CorrelatedMultiJitteredSampler.Formula.Point<TV, TM>(key, i, frame.Samples, frame.Columns, frame.Rows, pattern.X, pattern.Y, out sx, out sy);
                break;
            case DeviceSampler.Sobol:
                SobolSampler.Formula.Point<TV, TM>(keys, i, out sx, out sy);
                break;
            case DeviceSampler.ZSobol:
                uint sobolIndex = ZSobolSampler.Formula.SobolIndex(new DevicePermutations(table), frame.Log2Block, frame.DigitSalt, x, row, i);
                ZSobolSampler.Formula.Point<TV, TM>(sobolIndex, frame.XSeed, frame.YSeed, out sx, out sy);
                break;
            default:
                long at = ((long)pattern.Set * frame.SetLength) + (2L * i);
                Pmj02Sampler.Shift<TV, TM>(TM.BroadcastBits(table[at]), TM.BroadcastBits(table[at + 1]), TM.BroadcastBits(pattern.ShiftX), TM.BroadcastBits(pattern.ShiftY), out sx, out sy);
                break;
        }
    }
}

/// <summary>What a pixel's samples share, made once per pixel: the divisors and cell formulas of its sampler, pmj02's set and shift.</summary>
internal readonly struct PixelPattern
{
    /// <summary>The n-rooks and multi-jittered divisors.</summary>
    public readonly CellDivisor Divisor;

    /// <summary>cmj's cell formula across.</summary>
    public readonly WholeCell X;

    /// <summary>cmj's cell formula down.</summary>
    public readonly WholeCell Y;

    /// <summary>The pmj02 set the pixel reads.</summary>
    public readonly int Set;

    /// <summary>pmj02's digital shift across (0 for pmj02bn).</summary>
    public readonly uint ShiftX;

    /// <summary>pmj02's digital shift down (0 for pmj02bn).</summary>
    public readonly uint ShiftY;

    /// <summary>The pattern of the pixel whose key is <paramref name="key"/> under <paramref name="frame"/>'s sampler.</summary>
    /// <param name="frame">The launch's settings.</param>
    /// <param name="key">The pixel's key.</param>
    public PixelPattern(in PointFrame frame, uint key)
    {
        if (frame.Sampler == DeviceSampler.NRooks)
        {
            Divisor = new CellDivisor(frame.Samples, 1);
        }
        else if (frame.Sampler == DeviceSampler.MultiJittered)
        {
            Divisor = new CellDivisor(frame.GridSize, frame.GridSize);
        }
        else if (frame.Sampler == DeviceSampler.CorrelatedMultiJittered)
        {
            X = CorrelatedMultiJitteredSampler.XCell(frame.Columns, frame.Rows);
            Y = CorrelatedMultiJitteredSampler.YCell(frame.Samples);
        }
        else if (frame.Sampler == DeviceSampler.Pmj02)
        {
            (Set, ShiftX, ShiftY) = Pmj02Tables.Pixel(key, frame.Scramble != 0);
        }
    }
}

/// <summary>ZSobol's packed digit permutations in a device buffer (<see cref="IPackedPermutations"/>).</summary>
/// <param name="table">The 24 packed permutations, one a entry.</param>
internal readonly struct DevicePermutations(ArrayView<uint> table) : IPackedPermutations
{
    private readonly ArrayView<uint> _table = table;

    /// <inheritdoc />
    public uint Packed(int number) => _table[number];
}

/// <summary>
/// A scene on the device: its spheres, and its hierarchy's nodes and order when it has one, traced by the CPU's own
/// <see cref="SphereHierarchy.Traversal"/> (or its loop over every sphere) with <see cref="SphereHit.TryIntersect"/>.
/// </summary>
/// <param name="spheres">The spheres, in the scene's order.</param>
/// <param name="nodes">The hierarchy's nodes.</param>
/// <param name="order">The hierarchy's sphere order.</param>
/// <param name="scale">The hierarchy's scale.</param>
/// <param name="hierarchy">1: through the hierarchy; 0: every sphere in order.</param>
/// <param name="background">The background's colour.</param>
/// <param name="stack">The traversal's stack, <see cref="MaxDepth"/> + 1 entries in the thread's local memory (none without the hierarchy).</param>
internal readonly struct DeviceScene(ArrayView<DeviceSphere> spheres, ArrayView<HierarchyNode> nodes, ArrayView<int> order, double scale, int hierarchy, Intensity background, ArrayView<int> stack) : IHierarchyView
{
    /// <summary>The most levels of a hierarchy the device traverses (its stack's entries, less one); a deeper one is traced sphere by sphere.</summary>
    public const int MaxDepth = 63;

    private readonly ArrayView<DeviceSphere> _spheres = spheres;
    private readonly ArrayView<HierarchyNode> _nodes = nodes;
    private readonly ArrayView<int> _order = order;
    private readonly int _hierarchy = hierarchy;
    private readonly Intensity _background = background;
    private readonly ArrayView<int> _stack = stack;

    /// <inheritdoc />
    public double Scale { get; } = scale;

    /// <inheritdoc />
    public int SphereCount => (int)_spheres.Length;

    /// <inheritdoc />
    public HierarchyNode Node(int index) => _nodes[index];

    /// <inheritdoc />
    public int Order(int position) => _order[position];

    /// <inheritdoc />
    public bool TryIntersect(int sphere, in Ray ray, double tMin, double tMax, out double t)
    {
        DeviceSphere s = _spheres[sphere];
        return SphereHit.TryIntersect(s.Center, s.Radius, ray, tMin, tMax, out t);
    }

    /// <summary>The index of the nearest sphere the ray meets in [<paramref name="tMin"/>, <paramref name="tMax"/>], or −1 (the scene's <c>Nearest</c>).</summary>
    /// <param name="ray">The ray.</param>
    /// <param name="tMin">The smallest visible t.</param>
    /// <param name="tMax">The largest visible t.</param>
    public int Nearest(in Ray ray, double tMin, double tMax)
    {
        if (_hierarchy == 0)
        {
            return SphereHierarchy.Traversal.NearestOfAll(this, ray, tMin, tMax);
        }

        var stack = new DeviceStack(_stack);
        return SphereHierarchy.Traversal.Nearest(this, ref stack, ray, tMin, tMax);
    }

    /// <summary>The colour of the nearest sphere the ray meets in the visible range, or the background.</summary>
    /// <param name="ray">The ray.</param>
    /// <param name="tMin">The smallest visible t.</param>
    /// <param name="tMax">The largest visible t.</param>
    public Intensity Trace(in Ray ray, double tMin, double tMax)
    {
        int nearest = Nearest(ray, tMin, tMax);
        return nearest < 0 ? _background : _spheres[nearest].Colour;
    }
}

/// <summary>The hierarchy's traversal stack in the thread's local memory.</summary>
/// <param name="entries">The entries.</param>
internal readonly struct DeviceStack(ArrayView<int> entries) : ITraversalStack
{
    private readonly ArrayView<int> _entries = entries;

    /// <inheritdoc />
    public int this[int index]
    {
        get => _entries[index];
        set => _entries[index] = value;
    }
}
