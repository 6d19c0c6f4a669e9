using RayLab.Geometry;
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
internal interface IProjection : ILaneRays
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

    /// <summary>The direction every ray shares: −w for parallel rays, else zero.</summary>
    /// <param name="w">Camera backward.</param>
    static abstract Double3 ParallelDirection(Double3 w);

    /// <summary>Where the ray through α = β = 0 starts, relative to e: c for rays from the window, else zero (every ray starts at e).</summary>
    /// <param name="c">The lab's c.</param>
    static abstract Double3 OriginShift(Double3 c);

    /// <summary>The largest |o − C| over the window, given a sphere's o − C at α = β = 0 (the ray origins move by α a + β b when they start on the window).</summary>
    /// <param name="offset">o − C at α = β = 0.</param>
    /// <param name="a">The lab's a.</param>
    /// <param name="b">The lab's b.</param>
    static abstract double LargestOffset(Double3 offset, Double3 a, Double3 b);

    /// <summary>A bound on how far the ray origins lie from the one at α = β = 0: |a| + |b| + |c| for rays from the window, else 0.</summary>
    /// <param name="a">The lab's a.</param>
    /// <param name="b">The lab's b.</param>
    /// <param name="c">The lab's c.</param>
    static abstract double OriginReach(Double3 a, Double3 b, Double3 c);

    /// <summary>How large the ray origins are near a sphere whose largest |o − C| is <paramref name="largest"/>, where float rounds them; 0 when every ray starts at e.</summary>
    /// <param name="largest">The sphere's largest |o − C|.</param>
    static abstract double OriginRoundingSize(double largest);

    /// <summary>How large the ray directions are where float rounds them, |c| + |a| + |b|; 0 for one shared direction.</summary>
    /// <param name="a">The lab's a.</param>
    /// <param name="b">The lab's b.</param>
    /// <param name="c">The lab's c.</param>
    static abstract double DirectionRoundingSize(Double3 a, Double3 b, Double3 c);

    /// <summary>
    /// A bound on how much the float rounding of a ray moves the stable discriminant Δ of a sphere with o − C =
    /// <paramref name="offset"/> at α = β = 0 and largest |o − C| = <paramref name="largest"/> (twice the first-order
    /// terms): a direction off by δ turns the ray by δ/s about e; an origin off by δ moves it by δ.
    /// </summary>
    /// <param name="plane">The image plane.</param>
    /// <param name="offset">o − C at α = β = 0.</param>
    /// <param name="largest">The largest |o − C| over the window.</param>
    /// <param name="epsilon">Float's unit roundoff, doubled (2⁻²³).</param>
    static abstract double RayRoundingBound(ImagePlane plane, Double3 offset, double largest, double epsilon);

    /// <summary>
    /// How far the rays of a square of the window may pass from the square's central ray, at a distance
    /// <c>reach</c> from its origin: <c>Constant + reach · PerReach</c>. Parallel rays shift by the square's
    /// half-diagonal δ; rays from e turn by at most asin(δ/|d|).
    /// </summary>
    /// <param name="delta">The square's half-diagonal δ on the window.</param>
    /// <param name="directionLengthSquared">d·d of the central ray.</param>
    static abstract (double Constant, double PerReach) SquareSpread(double delta, double directionLengthSquared);

    /// <summary>False when a sphere (camera coordinates) lies wholly outside the rays through the window, so that no visible ray can reach it.</summary>
    /// <param name="plane">The image plane.</param>
    /// <param name="centre">The centre in camera coordinates.</param>
    /// <param name="radius">The radius.</param>
    static abstract bool MayBeInView(ImagePlane plane, Double3 centre, double radius);

    /// <summary>True when a sphere at <paramref name="depth"/> along the gaze lies far enough in front of the eye for its outline to be an ellipse (depth − r above 10⁻⁴ r); always for parallel rays.</summary>
    /// <param name="depth">The centre's depth along the gaze.</param>
    /// <param name="radius">The radius.</param>
    static abstract bool IsAheadOfEye(double depth, double radius);

    /// <summary>Window units per world unit at <paramref name="depth"/> along the gaze: s/depth from e, 1 for parallel rays.</summary>
    /// <param name="distance">The plane distance s.</param>
    /// <param name="depth">The depth along the gaze.</param>
    static abstract double WindowScale(double distance, double depth);

    /// <summary>The four side half-spaces of the rays through [α0, α1] × [β0, β1] (see <see cref="ImagePlane.Frustum"/>); returns the central ray's direction.</summary>
    /// <param name="plane">The image plane.</param>
    /// <param name="alpha0">The left α.</param>
    /// <param name="alpha1">The right α.</param>
    /// <param name="beta0">The bottom β.</param>
    /// <param name="beta1">The top β.</param>
    /// <param name="planes">Receives the four planes.</param>
    static abstract Double3 Frustum(ImagePlane plane, double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes);

    /// <summary>The ray through window point (α, β), in double.</summary>
    /// <param name="basis">The image plane's e, a, b, c and −w (<see cref="ImagePlane.Basis"/>).</param>
    /// <param name="alpha">α, left to right.</param>
    /// <param name="beta">β, bottom to top.</param>
    static abstract Ray GetRay(in RayBasis basis, double alpha, double beta);

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
