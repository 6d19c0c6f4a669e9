using System.Runtime.CompilerServices;
using RayLab.Geometry;
using RayLab.Simd;

namespace RayLab.Cameras;

/// <summary>
/// The orthographic camera's projection (section 3.1): the ray from the window point
/// <c>p = e + c + α a + β b</c>, with <c>c = u0 u + v0 v</c> on the plane through e, along the gaze −w; and its
/// inverse, a point seen at the window point (du, dv) whatever its depth. See <see cref="IProjection"/>.
/// </summary>
internal readonly struct OrthographicProjection : IProjection
{
    /// <inheritdoc />
    public static bool IsOrthographic => true;

    /// <inheritdoc />
    public static Double3 WindowCorner(Double3 u, Double3 v, Double3 w, Window window, double distance) =>
        (window.U0 * u) + (window.V0 * v);

    /// <inheritdoc />
    public static double DepthPerT(double distance) => 1;

    /// <inheritdoc />
    public static Double3 ParallelDirection(Double3 w) => -w;

    /// <inheritdoc />
    public static Double3 OriginShift(Double3 c) => c;

    /// <inheritdoc />
    /// <remarks>|o − C| is convex over the window: its largest value is at a corner.</remarks>
    public static double LargestOffset(Double3 offset, Double3 a, Double3 b) =>
        Math.Max(Math.Max(offset.Length, (offset + a).Length), Math.Max((offset + b).Length, (offset + a + b).Length));

    /// <inheritdoc />
    public static double OriginReach(Double3 a, Double3 b, Double3 c) => a.Length + b.Length + c.Length;

    /// <inheritdoc />
    public static double OriginRoundingSize(double largest) => largest;

    /// <inheritdoc />
    public static double DirectionRoundingSize(Double3 a, Double3 b, Double3 c) => 0;

    /// <inheritdoc />
    /// <remarks>An origin off by δ ≤ 8 ε (|e + c − C| + |a| + |b| + L) moves Δ by at most 3 L δ; the direction −w rounded by 8 ε moves it by 3 L² · 8 ε.</remarks>
    public static double RayRoundingBound(ImagePlane plane, Double3 offset, double largest, double epsilon) =>
        2 * ((3 * largest * 8 * epsilon * (offset.Length + plane.A.Length + plane.B.Length + largest)) + (3 * largest * largest * 8 * epsilon));

    /// <inheritdoc />
    public static (double Constant, double PerReach) SquareSpread(double delta, double directionLengthSquared) => (delta, 0);

    /// <inheritdoc />
    /// <remarks>Not culled: every sphere is kept (a sphere outside the window costs time, never accuracy).</remarks>
    public static bool MayBeInView(ImagePlane plane, Double3 centre, double radius) => true;

    /// <inheritdoc />
    public static bool IsAheadOfEye(double depth, double radius) => true;

    /// <inheritdoc />
    public static double WindowScale(double distance, double depth) => 1;

    /// <inheritdoc />
    /// <remarks>Origins α a + β b (from e + c), direction −w: four planes along −w through the window's edges.</remarks>
    public static Double3 Frustum(ImagePlane plane, double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes)
    {
        Double3 a = plane.A, b = plane.B, gaze = -plane.W;
        planes[0] = Plane.Side(Double3.Cross(b, gaze), a, alpha0 * a);
        planes[1] = Plane.Side(Double3.Cross(b, gaze), -a, alpha1 * a);
        planes[2] = Plane.Side(Double3.Cross(a, gaze), b, beta0 * b);
        planes[3] = Plane.Side(Double3.Cross(a, gaze), -b, beta1 * b);
        return gaze;
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Ray GetRay(in RayBasis basis, double alpha, double beta) =>
        new(basis.Eye + (basis.C + (alpha * basis.A) + (beta * basis.B)), basis.ParallelDirection);

    /// <inheritdoc />
    /// <remarks>o = α a + β b relative to e + c, which the frame's sphere offsets e + c − C already hold; d = −w.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void GetRays<TL>(in LaneWindow<TL> window, TL alpha, TL beta, out Lanes3<TL> origin, out Lanes3<TL> direction)
        where TL : struct, ILanes<TL>
    {
        (Lanes3<TL> a, Lanes3<TL> b) = (window.A, window.B);
        direction = window.Direction;
        origin = new Lanes3<TL>(
            TL.MultiplyAdd(alpha, a.X, beta * b.X),
            TL.MultiplyAdd(alpha, a.Y, beta * b.Y),
            TL.MultiplyAdd(alpha, a.Z, beta * b.Z));
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL AddOrigin<TL>(TL offset, TL origin)
        where TL : struct, ILanes<TL> => offset + origin;

    /// <inheritdoc />
    /// <remarks>X = (du − u0)/su and Y = (v1 − dv)/sv, su and sv the window units per pixel: the ray through (X, Y) starts at e + du u + dv v.</remarks>
    public static (double X, double Y, double Z) ToPixel(ImagePlane plane, Double3 v, double w4)
    {
        Window window = plane.Window;
        return ((v.X - (window.U0 * w4)) / plane.PixelWidth, ((window.V1 * w4) - v.Y) / plane.PixelHeight, w4);
    }
}
