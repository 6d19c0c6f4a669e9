using System.Runtime.CompilerServices;
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
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Ray GetRay(ImagePlane plane, double alpha, double beta) =>
        new(plane.Eye, plane.C + (alpha * plane.A) + (beta * plane.B));

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
