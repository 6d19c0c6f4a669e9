using ILGPU;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Rendering.Adaptive;
using RayLab.Sampling;

namespace RayLab.Gpu;

/// <summary>What one launch of <see cref="AdaptiveKernel"/> renders: the rays, the rule, the lattice and the scene's settings.</summary>
internal struct AdaptiveFrame
{
    /// <summary>The camera's rays.</summary>
    public RayBasis Basis;

    /// <summary>The adaptive rule's settings.</summary>
    public AdaptiveRule Rule;

    /// <summary>The first row rendered.</summary>
    public int FirstRow;

    /// <summary>Lattice steps per pixel side, 2^(MaxDepth + 1).</summary>
    public long Size;

    /// <summary>The guard's lattice step on the window, across (<see cref="SilhouetteGuard.StepWidth"/>).</summary>
    public double StepWidth;

    /// <summary>The guard's lattice step on the window, down.</summary>
    public double StepHeight;

    /// <summary>The scene's background.</summary>
    public Intensity Background;

    /// <summary>1: through the scene's hierarchy; 0: every sphere in order.</summary>
    public int Hierarchy;

    /// <summary>The hierarchy's scale.</summary>
    public double HierarchyScale;

    /// <summary>1: write each pixel's rays to the map.</summary>
    public int Map;

    /// <summary>1: every guard test whose low end does not cross counts as uncertain (the tests' check of the host's path).</summary>
    public int ForceUncertain;

    /// <summary>The most uncertain pixels the launch lists (<see cref="AdaptiveKernel.Render"/>'s <c>uncertain</c>).</summary>
    public int UncertainCapacity;
}

/// <summary>A sphere the guard tests (<see cref="SilhouetteGuard.Spheres"/>): centre, radius, whether a near or far plane cuts it.</summary>
/// <param name="center">The centre.</param>
/// <param name="radius">The radius.</param>
/// <param name="clipped">1: cut by the near or far plane.</param>
internal readonly struct GuardSphere(Double3 center, double radius, int clipped)
{
    /// <summary>The centre.</summary>
    public readonly Double3 Center = center;

    /// <summary>The radius.</summary>
    public readonly double Radius = radius;

    /// <summary>1 when a plane cuts it.</summary>
    public readonly int Clipped = clipped;
}

/// <summary>
/// The lab's adaptive rule on the device: one thread a pixel, each running the CPU's own
/// <see cref="AdaptivePixel.Evaluate{TSource, TStack}"/> with its squares on an explicit stack in local memory, over a
/// lattice whose points it traces itself (<see cref="DeviceLattice"/>: the CPU's ray of a lattice point, its nearest
/// hit in double through the hierarchy, the guard's own test), and writing its three bytes (the CPU's 8-bit rule) and
/// the rays charged to it (the heat map).
/// </summary>
internal static class AdaptiveKernel
{
    /// <summary>Renders pixel <paramref name="index"/> of the band (row by row).</summary>
    /// <param name="index">The pixel's index in the band.</param>
    /// <param name="frame">The launch's settings.</param>
    /// <param name="spheres">The scene's spheres.</param>
    /// <param name="nodes">The hierarchy's nodes, or one unused entry.</param>
    /// <param name="order">The hierarchy's sphere order, or one unused entry.</param>
    /// <param name="guard">The spheres the guard tests (none without the guard: one unused entry).</param>
    /// <param name="rgb">The band's bytes, R G B per pixel.</param>
    /// <param name="rays">The band's rays per pixel (with <see cref="AdaptiveFrame.Map"/>), or one unused entry.</param>
    /// <param name="counts">Entry 0 receives the rays the device traced, entry 1 the number of uncertain pixels.</param>
    /// <param name="uncertain">The uncertain pixels' indices, up to <see cref="AdaptiveFrame.UncertainCapacity"/>: the host evaluates them again.</param>
    public static void Render(Index1D index, AdaptiveFrame frame, ArrayView<DeviceSphere> spheres, ArrayView<HierarchyNode> nodes, ArrayView<int> order,
        ArrayView<GuardSphere> guard, ArrayView<byte> rgb, ArrayView<float> rays, ArrayView<long> counts, ArrayView<int> uncertain)
    {
        int width = frame.Basis.Width;
        int x = index % width;
        int row = frame.FirstRow + (index / width);
        var scene = new DeviceScene(spheres, nodes, order, frame.HierarchyScale, frame.Hierarchy, frame.Background, frame.Hierarchy != 0 ? LocalMemory.Allocate1D<int>(DeviceScene.MaxDepth + 1) : default);
        var lattice = new DeviceLattice(frame, scene, guard);
        var squares = new DeviceSquares(LocalMemory.Allocate1D<AdaptiveSquare>(AdaptiveSampler.MaxSupportedDepth + 1));
        Intensity value = AdaptivePixel.Evaluate(frame.Rule, ref lattice, ref squares, x, row, out double samples);
        long at = 3L * index;
        rgb[at] = EightBit.Level(value.R);
        rgb[at + 1] = EightBit.Level(value.G);
        rgb[at + 2] = EightBit.Level(value.B);
        if (frame.Map != 0)
        {
            rays[index] = (float)samples;
        }

        Atomic.Add(ref counts[0], lattice.Traced);
        if (lattice.Uncertain)
        {
            long slot = Atomic.Add(ref counts[1], 1L);
            if (slot < frame.UncertainCapacity)
            {
                uncertain[(int)slot] = index;
            }
        }
    }
}

/// <summary>
/// The adaptive lattice on the device: every point the rule asks for traced by this thread, in double, with the
/// CPU's formulas (<see cref="LatticeHits.TraceScalar"/>'s ray and nearest hit, <see cref="AdaptivePixel.Share"/>,
/// <see cref="SilhouetteGuard.SquareRay"/> and <see cref="SilhouetteGuard.Crosses"/> over every sphere it keeps, the
/// perspective margin's arcsine bracketed by <see cref="AsinBracket"/>, a test the bracket leaves undecided the host's).
/// </summary>
/// <param name="frame">The launch's settings.</param>
/// <param name="scene">The scene.</param>
/// <param name="guard">The guard's spheres.</param>
internal struct DeviceLattice(in AdaptiveFrame frame, in DeviceScene scene, ArrayView<GuardSphere> guard) : ILatticeSource
{
    private readonly RayBasis _basis = frame.Basis;
    private readonly long _size = frame.Size;
    private readonly double _stepWidth = frame.StepWidth, _stepHeight = frame.StepHeight;
    private readonly int _guarded = frame.Rule.Guard ? 1 : 0;
    private readonly int _forceUncertain = frame.ForceUncertain;
    private readonly DeviceScene _scene = scene;
    private readonly ArrayView<GuardSphere> _guard = guard;

    /// <summary>The points traced so far.</summary>
    public long Traced { get; private set; }

    /// <inheritdoc />
    public Intensity At(long lx, long ly, out double weight)
    {
        weight = AdaptivePixel.Share(lx, ly, _size);
        return Trace(lx, ly);
    }

    /// <inheritdoc />
    public Intensity Centre(long lx, long ly) => Trace(lx, ly);

    /// <summary>
    /// True once a guard test here was uncertain: the arcsine of the perspective guard's margin is bracketed on the
    /// device (<see cref="AsinBracket"/>; a GPU's arcsine is not the CPU's), and a test whose answer differs between the
    /// bracket's ends is the host's to decide: the pixel is evaluated again on the CPU.
    /// </summary>
    public bool Uncertain { get; private set; }

    /// <inheritdoc />
    public bool MayCross(long x0, long y0, long size)
    {
        if (_guarded == 0)
        {
            return false;
        }

        (Double3 origin, Double3 d, double dd, double delta) = SilhouetteGuard.SquareRay(_basis, _size, _stepWidth, _stepHeight, x0, y0, size);
        double spread, turnLow, turnHigh;
        if (_basis.IsOrthographic)
        {
            (spread, turnLow) = OrthographicProjection.SquareSpread(delta, dd);
            turnHigh = turnLow;
        }
        else
        {
            spread = 0;
            AsinBracket.Of(PerspectiveProjection.SpreadSine(delta, dd), out turnLow, out turnHigh);
        }

        for (int i = 0; i < (int)_guard.Length; i++)
        {
            GuardSphere sphere = _guard[i];
            bool low = SilhouetteGuard.Crosses(origin, d, dd, spread, turnLow, sphere.Center, sphere.Radius, sphere.Clipped != 0, 1);
            if (low)
            {
                return true; // a margin no wider than the CPU's already crosses
            }

            if (_forceUncertain != 0 || SilhouetteGuard.Crosses(origin, d, dd, spread, turnHigh, sphere.Center, sphere.Radius, sphere.Clipped != 0, 1))
            {
                Uncertain = true;
                return true;
            }
        }

        return false;
    }

    private Intensity Trace(long lx, long ly)
    {
        Traced++;
        Ray ray = _basis.GetRay(WindowMapping.Alpha(lx, _basis.Width * (double)_size), WindowMapping.Beta(ly, _basis.Height * (double)_size));
        return _scene.Trace(ray, _basis.TMin, _basis.TMax);
    }
}

/// <summary>The adaptive rule's squares in the thread's local memory.</summary>
/// <param name="squares">The squares.</param>
internal readonly struct DeviceSquares(ArrayView<AdaptiveSquare> squares) : ISquareStack
{
    private readonly ArrayView<AdaptiveSquare> _squares = squares;

    /// <inheritdoc />
    public ref AdaptiveSquare this[int index] => ref _squares[index];
}

/// <summary>
/// Bounds on arcsine, for the perspective guard's margin on the device: a GPU has no arcsine of the CPU's, so the
/// kernel takes the guard's answer where it is the same at both ends of a bracket that holds the CPU's
/// <see cref="Math.Asin"/>, and hands the rest to the host.
/// </summary>
internal static class AsinBracket
{
    /// <summary>
    /// lo ≤ Math.Asin(u) ≤ hi for 0 ≤ u ≤ 1: below ½ the Maclaurin series' first six terms (all positive: their sum is a
    /// lower bound) and that sum plus the remainder's bound c₆u¹³/(1 − u²) (the coefficients decrease), each end
    /// widened by 4·10⁻¹⁵ of itself for the rounding here and the CPU's (some 18 units in the last place); from ½ on
    /// [u, π/2] (loose: such a guard test is the host's, and only a square wider than half its distance asks for one).
    /// </summary>
    /// <param name="u">The sine, 0 to 1.</param>
    /// <param name="lo">A lower bound.</param>
    /// <param name="hi">An upper bound.</param>
    public static void Of(double u, out double lo, out double hi)
    {
        if (!(u < 0.5))
        {
            lo = u * (1 - 4e-15);
            hi = 1.5707963267948968;
            return;
        }

        double u2 = u * u;
        // asin u = u (1 + u²/6 + 3u⁴/40 + 5u⁶/112 + 35u⁸/1152 + 63u¹⁰/2816 + …), the next coefficient 231/13312.
        double sum = u * (1 + (u2 * ((1.0 / 6) + (u2 * ((3.0 / 40) + (u2 * ((5.0 / 112) + (u2 * ((35.0 / 1152) + (u2 * (63.0 / 2816)))))))))));
        double u12 = u2 * u2 * u2 * u2 * u2 * u2;
        double rest = 231.0 / 13312 * u12 * u / (1 - u2);
        lo = sum * (1 - 4e-15);
        hi = (sum + rest) * (1 + 4e-15);
    }
}
