using System.Runtime.CompilerServices;
using RayLab.Geometry;
using RayLab.Simd;

namespace RayLab.Cameras;

/// <summary>
/// The perspective camera's projection (section 3.2): the lab's ray <c>e + t (p − e)</c> from the eye e through
/// the window point <c>p = e + c + α a + β b</c>, with <c>c = u0 u + v0 v − s w</c>; and its inverse, a point at
/// depth −dw seen at the window point s·(du, dv)/(−dw). See <see cref="IProjection"/>.
/// </summary>
internal readonly struct PerspectiveProjection : IProjection
{
    /// <inheritdoc />
    public static bool IsOrthographic => false;

    /// <inheritdoc />
    public static Double3 WindowCorner(Double3 u, Double3 v, Double3 w, Window window, double distance) =>
        (window.U0 * u) + (window.V0 * v) - (distance * w);

    /// <inheritdoc />
    public static double DepthPerT(double distance) => distance;

    /// <inheritdoc />
    public static Double3 ParallelDirection(Double3 w) => Double3.Zero;

    /// <inheritdoc />
    public static Double3 OriginShift(Double3 c) => Double3.Zero;

    /// <inheritdoc />
    /// <remarks>Every ray starts at e: o − C is the same over the window.</remarks>
    public static double LargestOffset(Double3 offset, Double3 a, Double3 b) => offset.Length;

    /// <inheritdoc />
    public static double OriginReach(Double3 a, Double3 b, Double3 c) => 0;

    /// <inheritdoc />
    public static double OriginRoundingSize(double largest) => 0;

    /// <inheritdoc />
    public static double DirectionRoundingSize(Double3 a, Double3 b, Double3 c) => c.Length + a.Length + b.Length;

    /// <inheritdoc />
    /// <remarks>A direction off by δ ≤ 8 ε (|c| + |a| + |b|) turns the ray by δ/s about e and moves Δ by at most 3 L² δ / s.</remarks>
    public static double RayRoundingBound(ImagePlane plane, Double3 offset, double largest, double epsilon)
    {
        double rayError = 8 * epsilon * (plane.C.Length + plane.A.Length + plane.B.Length);
        return 2 * 3 * largest * largest * rayError / plane.Distance;
    }

    /// <inheritdoc />
    public static (double Constant, double PerReach) SquareSpread(double delta, double directionLengthSquared) =>
        (0, Math.Asin(SpreadSine(delta, directionLengthSquared)));

    /// <summary>The sine of the largest turn about the eye of a ray δ off a direction of length² <paramref name="directionLengthSquared"/>: min(1, δ / |d|), whose arcsine is <see cref="SquareSpread"/>'s part per reach.</summary>
    /// <param name="delta">The half-diagonal δ.</param>
    /// <param name="directionLengthSquared">|d|².</param>
    public static double SpreadSine(double delta, double directionLengthSquared) => Math.Min(1, delta / Math.Sqrt(directionLengthSquared));

    /// <inheritdoc />
    /// <remarks>Outside when the sphere lies wholly outside one of the four planes through e and the window's edges.</remarks>
    public static bool MayBeInView(ImagePlane plane, Double3 centre, double radius)
    {
        Window win = plane.Window;
        double s = plane.Distance;
        // Inside ⇔ s·du + u0·dw ≥ 0, −s·du − u1·dw ≥ 0, s·dv + v0·dw ≥ 0, −s·dv − v1·dw ≥ 0.
        return !(Outside(new Double3(s, 0, win.U0)) || Outside(new Double3(-s, 0, -win.U1))
            || Outside(new Double3(0, s, win.V0)) || Outside(new Double3(0, -s, -win.V1)));

        bool Outside(Double3 normal) => Double3.Dot(normal, centre) < -radius * normal.Length;
    }

    /// <inheritdoc />
    public static bool IsAheadOfEye(double depth, double radius) => depth - radius > 1e-4 * radius;

    /// <inheritdoc />
    public static double WindowScale(double distance, double depth) => distance / depth;

    /// <inheritdoc />
    /// <remarks>Directions c + α a + β b from e: four planes through e.</remarks>
    public static Double3 Frustum(ImagePlane plane, double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes)
    {
        Double3 a = plane.A, b = plane.B, c = plane.C;
        planes[0] = Plane.Side(Double3.Cross(c + (alpha0 * a), b), a, Double3.Zero);
        planes[1] = Plane.Side(Double3.Cross(c + (alpha1 * a), b), -a, Double3.Zero);
        planes[2] = Plane.Side(Double3.Cross(c + (beta0 * b), a), b, Double3.Zero);
        planes[3] = Plane.Side(Double3.Cross(c + (beta1 * b), a), -b, Double3.Zero);
        return c + (0.5 * (alpha0 + alpha1) * a) + (0.5 * (beta0 + beta1) * b);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Ray GetRay(in RayBasis basis, double alpha, double beta) =>
        new(basis.Eye, basis.C + (alpha * basis.A) + (beta * basis.B));

    /// <inheritdoc />
    /// <remarks>d = c + α a + β b; the origin is e for every lane, which the frame's sphere offsets e − C already hold.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void GetRays<TL>(in LaneWindow<TL> window, TL alpha, TL beta, out Lanes3<TL> origin, out Lanes3<TL> direction)
        where TL : struct, ILanes<TL>
    {
        (Lanes3<TL> a, Lanes3<TL> b, Lanes3<TL> c) = (window.A, window.B, window.C);
        direction = new Lanes3<TL>(
            TL.MultiplyAdd(alpha, a.X, TL.MultiplyAdd(beta, b.X, c.X)),
            TL.MultiplyAdd(alpha, a.Y, TL.MultiplyAdd(beta, b.Y, c.Y)),
            TL.MultiplyAdd(alpha, a.Z, TL.MultiplyAdd(beta, b.Z, c.Z)));
        origin = default;
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL AddOrigin<TL>(TL offset, TL origin)
        where TL : struct, ILanes<TL> => offset;

    /// <inheritdoc />
    /// <remarks>X = (s du/depth − u0)/su and Y = (v1 − s dv/depth)/sv with depth = −dw, su and sv the window units per pixel.</remarks>
    public static (double X, double Y, double Z) ToPixel(ImagePlane plane, Double3 v, double w4)
    {
        Window window = plane.Window;
        double s = plane.Distance;
        return ((v.X + (window.U0 / s * v.Z)) / plane.PixelWidth, (-v.Y - (window.V1 / s * v.Z)) / plane.PixelHeight, -v.Z / s);
    }
}
