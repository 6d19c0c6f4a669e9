using System.Runtime.CompilerServices;
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
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Ray GetRay(ImagePlane plane, double alpha, double beta) =>
        new(plane.Eye + (plane.C + (alpha * plane.A) + (beta * plane.B)), -plane.W);

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
