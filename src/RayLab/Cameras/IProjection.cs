using RayLab.Simd;

namespace RayLab.Cameras;

/// <summary>
/// A camera's projection as a type (<see cref="OrthographicProjection"/>, <see cref="PerspectiveProjection"/>):
/// the one place that turns a window point (α, β) into a ray — one at a time in double, or a packet of lanes in
/// float — and a point in camera coordinates into pixel coordinates. Its members are static, so code generic
/// over the projection is compiled once per camera kind, with no branch and no virtual call per ray.
/// </summary>
/// <remarks>
/// The window point is the lab's <c>p = e + c + α a + β b</c> (section 3.2). A perspective ray goes from e
/// through p; an orthographic ray starts at p (on the plane through e) and goes along the gaze −w.
/// </remarks>
internal interface IProjection
{
    /// <summary>True for parallel rays.</summary>
    static abstract bool IsOrthographic { get; }

    /// <summary>
    /// The lab's c relative to e, the window's lower-left corner: <c>u0 u + v0 v − s w</c> for the perspective
    /// camera, <c>u0 u + v0 v</c> for the orthographic one (its window lies on the plane through e).
    /// </summary>
    /// <param name="u">Camera right.</param>
    /// <param name="v">Camera up.</param>
    /// <param name="w">Camera backward.</param>
    /// <param name="window">The window corners u0, v0, u1, v1.</param>
    /// <param name="distance">The plane distance s.</param>
    static abstract Double3 WindowCorner(Double3 u, Double3 v, Double3 w, Window window, double distance);

    /// <summary>The depth along the gaze per unit of the ray parameter t: s for the perspective ray p − e, 1 along −w.</summary>
    /// <param name="distance">The plane distance s.</param>
    static abstract double DepthPerT(double distance);

    /// <summary>The ray through window point (α, β), in double.</summary>
    /// <param name="plane">The image plane (e, w and the lab's a, b, c).</param>
    /// <param name="alpha">α, left to right.</param>
    /// <param name="beta">β, bottom to top.</param>
    static abstract Ray GetRay(ImagePlane plane, double alpha, double beta);

    /// <summary>
    /// A packet's rays through the window points (α, β) of its lanes, in float: the direction d, and the
    /// origin's offset o from the fixed point that the packet kernel's sphere offsets are taken from
    /// (<see cref="AddOrigin{TL}"/>).
    /// </summary>
    /// <param name="window">The lab's a, b, c and the orthographic direction, broadcast.</param>
    /// <param name="alpha">α per lane.</param>
    /// <param name="beta">β per lane.</param>
    /// <param name="origin">The origin's offset per lane (zero for the perspective camera).</param>
    /// <param name="direction">The direction per lane.</param>
    static abstract void GetRays<TL>(in LaneWindow<TL> window, TL alpha, TL beta, out Lanes3<TL> origin, out Lanes3<TL> direction)
        where TL : struct, ILanes<TL>;

    /// <summary>
    /// One component of a sphere's offset for this packet's rays: the frame's offset plus the ray origin's
    /// (orthographic), or the frame's offset alone (perspective: every ray starts at e).
    /// </summary>
    /// <param name="offset">The frame's offset, broadcast.</param>
    /// <param name="origin">The ray origin's offset from <see cref="GetRays{TL}"/>.</param>
    static abstract TL AddOrigin<TL>(TL offset, TL origin)
        where TL : struct, ILanes<TL>;

    /// <summary>
    /// The homogeneous pixel coordinates (Xh, Yh, Zh) of (<paramref name="v"/>, <paramref name="w4"/>) in camera
    /// coordinates (a point for w4 = 1, a direction for w4 = 0): the 3×4 matrix that maps a point to pixel
    /// coordinates (X, Y) = (Xh/Zh, Yh/Zh), X = α W to the right and Y = (1 − β) H down.
    /// </summary>
    /// <param name="plane">The image plane.</param>
    /// <param name="v">(du, dv, dw) in camera coordinates.</param>
    /// <param name="w4">The homogeneous weight.</param>
    static abstract (double X, double Y, double Z) ToPixel(ImagePlane plane, Double3 v, double w4);
}
