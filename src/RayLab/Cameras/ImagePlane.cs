using System.Runtime.CompilerServices;
using RayLab.Geometry;

namespace RayLab.Cameras;

/// <summary>
/// A camera's view of a W×H image, checked and precomputed by <see cref="Camera.GetImagePlane"/>: the lab's
/// frame u, v, w, the window (u0, v0, u1, v1), the vectors a, b, c of section 3.2, and the camera's projection
/// both ways — a pixel sample to a ray (<see cref="GetPixelRay"/>) and a world point to pixel coordinates
/// (<see cref="ToPixel"/>).
/// </summary>
/// <remarks>
/// Pixel to window: a sample at (sx, sy) ∈ [0, 1)² inside pixel (x, row) has
/// <c>α = (x + sx)/W</c> and <c>β = 1 − (row + sy)/H</c>; row 0 is the top row and the pixel centre is
/// sx = sy = 0.5. Each α is computed from the integer pixel index, never by accumulating steps. Window to ray is
/// the projection's: each camera's plane is an <c>ImagePlane&lt;TProjection&gt;</c> whose projection type
/// (<see cref="OrthoCamera"/>: orthographic, <see cref="PerspectiveCamera"/>: perspective) holds the formulas.
/// </remarks>
public abstract class ImagePlane
{
    private protected ImagePlane(int width, int height, Double3 eye, Double3 u, Double3 v, Double3 w, Window window,
        double distance, bool orthographic, Double3 corner, double depthPerT, double near, double far, Double3 parallelDirection, Double3 originShift)
    {
        Width = width;
        Height = height;
        Eye = eye;
        U = u;
        V = v;
        W = w;
        Window = window;
        Distance = distance;
        IsOrthographic = orthographic;
        A = window.Width * u;
        B = window.Height * v;
        C = corner;
        // A hit is visible when its depth along the gaze lies in [near, far]; every ray of this plane has the
        // same depth per unit of t.
        DepthPerT = depthPerT;
        TMin = near / depthPerT;
        TMax = far / depthPerT;
        PixelWidth = window.Width / width;
        PixelHeight = window.Height / height;
        NearDepth = near;
        FarDepth = far;
        ParallelDirection = parallelDirection;
        OriginShift = originShift;
        FixedPoint = eye + originShift;
        Basis = new RayBasis(eye, A, B, C, parallelDirection, width, height, TMin, TMax, orthographic);
    }

    /// <summary>The relative margin of <see cref="Visibility"/>: a sphere within 10⁻⁹ of a plane's depth counts as cut by it.</summary>
    private const double PlaneMargin = 1e-9;

    /// <summary>The image width W in pixels.</summary>
    public int Width { get; }

    /// <summary>The image height H in pixels.</summary>
    public int Height { get; }

    /// <summary>The eye e (the camera's Position).</summary>
    public Double3 Eye { get; }

    /// <summary>Camera right, u (image right).</summary>
    public Double3 U { get; }

    /// <summary>Camera up, v (image up).</summary>
    public Double3 V { get; }

    /// <summary>Camera backward, w = −gaze/|gaze|.</summary>
    public Double3 W { get; }

    /// <summary>The window corners u0, v0, u1, v1.</summary>
    public Window Window { get; }

    /// <summary>The plane distance s (perspective).</summary>
    public double Distance { get; }

    /// <summary>True when rays are parallel (orthographic camera).</summary>
    public bool IsOrthographic { get; }

    /// <summary>The lab's a = (u1 − u0) u: the window's horizontal edge.</summary>
    public Double3 A { get; }

    /// <summary>The lab's b = (v1 − v0) v: the window's vertical edge.</summary>
    public Double3 B { get; }

    /// <summary>
    /// The lab's c = u0 u + v0 v − s w: the window's lower-left corner relative to e (orthographic: without the
    /// −s w term, since the rays start on the plane through e).
    /// </summary>
    public Double3 C { get; }

    /// <summary>The smallest visible ray parameter: the near plane's depth in units of t.</summary>
    public double TMin { get; }

    /// <summary>The largest visible ray parameter: the far plane's depth in units of t.</summary>
    public double TMax { get; }

    /// <summary>The depth along the gaze per unit of the ray parameter t (s for the perspective camera, 1 for the orthographic).</summary>
    internal double DepthPerT { get; }

    /// <summary>The near plane's depth along the gaze.</summary>
    internal double NearDepth { get; }

    /// <summary>The far plane's depth along the gaze.</summary>
    internal double FarDepth { get; }

    /// <summary>The direction every ray shares: −w (orthographic), else zero.</summary>
    internal Double3 ParallelDirection { get; }

    /// <summary>Where the ray through α = β = 0 starts, relative to e: c (orthographic), else zero.</summary>
    internal Double3 OriginShift { get; }

    /// <summary>Where the ray through α = β = 0 starts: e + <see cref="OriginShift"/>, the point sphere offsets are taken from.</summary>
    internal Double3 FixedPoint { get; }

    /// <summary>A bound on how far the ray origins lie from <see cref="FixedPoint"/>: |a| + |b| + |c| (orthographic), else 0.</summary>
    internal abstract double OriginReach { get; }

    /// <summary>How large the ray directions are where float rounds them: |c| + |a| + |b| (perspective), else 0.</summary>
    internal abstract double DirectionRoundingSize { get; }

    /// <summary>The window's width per pixel, su = (u1 − u0)/W.</summary>
    internal double PixelWidth { get; }

    /// <summary>What the plane's rays are made from, as one unmanaged value (the ray formula's input on every path); a field, passed by reference.</summary>
    internal readonly RayBasis Basis;

    /// <summary>The window's height per pixel, sv = (v1 − v0)/H.</summary>
    internal double PixelHeight { get; }

    /// <summary>α = (x + sx)/W for a sample sx ∈ [0, 1) inside pixel column x.</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="sx">The sample's offset inside the pixel, left to right.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Alpha(int x, double sx) => WindowMapping.Alpha(x + sx, Width);

    /// <summary>β = 1 − (row + sy)/H for a sample sy ∈ [0, 1) inside pixel row <paramref name="row"/> (row 0 on top).</summary>
    /// <param name="row">The pixel row, 0 at the top.</param>
    /// <param name="sy">The sample's offset inside the pixel, top to bottom.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Beta(int row, double sy) => WindowMapping.Beta(row + sy, Height);

    /// <summary>α of a lattice point: X/W with X and W counted in lattice steps of 1/<paramref name="size"/> pixel.</summary>
    /// <param name="x">X, in lattice steps from the image's left edge.</param>
    /// <param name="size">Lattice steps per pixel.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal double LatticeAlpha(double x, long size) => WindowMapping.Alpha(x, Width * (double)size);

    /// <summary>β of a lattice point: 1 − Y/H with Y and H counted in lattice steps of 1/<paramref name="size"/> pixel.</summary>
    /// <param name="y">Y, in lattice steps from the image's top edge.</param>
    /// <param name="size">Lattice steps per pixel.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal double LatticeBeta(double y, long size) => WindowMapping.Beta(y, Height * (double)size);

    /// <summary>
    /// Whether a sphere lies wholly between the near and far planes, is cut by one, or is never visible: its depth
    /// range along the gaze against [near, far], with one relative margin of 10⁻⁹ (a sphere that close to a plane
    /// counts as cut by it) for every renderer.
    /// </summary>
    /// <param name="centre">The centre.</param>
    /// <param name="radius">The radius.</param>
    internal SphereVisibility Visibility(Double3 centre, double radius)
    {
        double depth = Double3.Dot(centre - Eye, -W);
        double near = NearDepth, far = FarDepth;
        if (depth + radius < near * (1 - PlaneMargin) || depth - radius > far * (1 + PlaneMargin))
        {
            return SphereVisibility.Hidden;
        }

        return depth - radius > near * (1 + PlaneMargin) && depth + radius < far * (1 - PlaneMargin)
            ? SphereVisibility.Whole
            : SphereVisibility.Clipped;
    }

    /// <summary>A sphere's o − C for the ray through α = β = 0, and the largest |o − C| over the window.</summary>
    /// <param name="centre">The sphere's centre C.</param>
    internal (Double3 Offset, double Largest) SphereOffset(Double3 centre)
    {
        Double3 offset = Eye - centre + OriginShift;
        return (offset, LargestOffset(offset));
    }

    /// <summary>The largest |o − C| over the window, given o − C at α = β = 0.</summary>
    /// <param name="offset">o − C at α = β = 0.</param>
    internal abstract double LargestOffset(Double3 offset);

    /// <summary>How large the ray origins are near a sphere whose largest |o − C| is <paramref name="largest"/>, where float rounds them (orthographic), else 0.</summary>
    /// <param name="largest">The largest |o − C|.</param>
    internal abstract double OriginRoundingSize(double largest);

    /// <summary>A bound on how much the float rounding of a ray moves a sphere's stable discriminant (see <see cref="IProjection.RayRoundingBound"/>).</summary>
    /// <param name="offset">o − C at α = β = 0.</param>
    /// <param name="largest">The largest |o − C|.</param>
    /// <param name="epsilon">Float's unit roundoff, doubled.</param>
    internal abstract double RayRoundingBound(Double3 offset, double largest, double epsilon);

    /// <summary>How far the rays of a window square of half-diagonal δ pass from its central ray: <c>Constant + reach · PerReach</c> (see <see cref="IProjection.SquareSpread"/>).</summary>
    /// <param name="delta">The half-diagonal δ.</param>
    /// <param name="directionLengthSquared">d·d of the central ray.</param>
    internal abstract (double Constant, double PerReach) SquareSpread(double delta, double directionLengthSquared);

    /// <summary>False when a sphere (camera coordinates) lies wholly outside the rays through the window.</summary>
    /// <param name="centre">The centre in camera coordinates.</param>
    /// <param name="radius">The radius.</param>
    internal abstract bool MayBeInView(Double3 centre, double radius);

    /// <summary>True when a sphere at <paramref name="depth"/> lies far enough in front of the eye for its outline to be an ellipse (always, orthographic).</summary>
    /// <param name="depth">The centre's depth along the gaze.</param>
    /// <param name="radius">The radius.</param>
    internal abstract bool IsAheadOfEye(double depth, double radius);

    /// <summary>Window units per world unit at <paramref name="depth"/> along the gaze: s/depth (perspective), 1 (orthographic).</summary>
    /// <param name="depth">The depth.</param>
    internal abstract double WindowScale(double depth);

    /// <summary>
    /// Runs <paramref name="action"/> compiled for this plane's projection: the one place the orthographic or
    /// perspective choice is made, for every renderer.
    /// </summary>
    /// <param name="action">The work, generic over the projection.</param>
    internal abstract TResult Dispatch<TAction, TResult>(ref TAction action)
        where TAction : struct, IProjectionAction<TResult>, allows ref struct;

    /// <summary>The five planes that bound the rays through [α0, α1] × [β0, β1] (see <see cref="Frustum"/>).</summary>
    private protected abstract Double3 SideFrustum(double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes);

    /// <summary>
    /// The five half-spaces, relative to <see cref="FixedPoint"/>, that bound the rays through the window rectangle
    /// [α0, α1] × [β0, β1] (four sides and the plane through the eye, nothing behind it), into
    /// <paramref name="planes"/>; returns the direction of the rectangle's central ray.
    /// </summary>
    /// <param name="alpha0">The left α.</param>
    /// <param name="alpha1">The right α.</param>
    /// <param name="beta0">The bottom β.</param>
    /// <param name="beta1">The top β.</param>
    /// <param name="planes">Receives the five planes.</param>
    internal Double3 Frustum(double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes)
    {
        Double3 centre = SideFrustum(alpha0, alpha1, beta0, beta1, planes);
        planes[4] = new Plane(-W, 0); // nothing behind the eye (or the orthographic window's plane)
        return centre;
    }

    /// <summary>
    /// The ray through window point (α, β) ∈ [0, 1]², α left to right and β bottom to top. Perspective: the
    /// lab's <c>e + t (p − e)</c> with <c>p = e + c + α a + β b</c>. Orthographic: from the point
    /// <c>e + c + α a + β b</c> on the plane through e, along the gaze −w.
    /// </summary>
    /// <param name="alpha">α, the horizontal window coordinate.</param>
    /// <param name="beta">β, the vertical window coordinate.</param>
    public abstract Ray GetRay(double alpha, double beta);

    /// <summary>
    /// The ray through the point (<paramref name="x"/>, <paramref name="y"/>) of the image in pixel coordinates:
    /// X to the right, Y down, pixel (x, row) covering [x, x + 1] × [row, row + 1]; the window point is
    /// α = X/W, β = 1 − Y/H.
    /// </summary>
    /// <param name="x">X, in pixels from the image's left edge.</param>
    /// <param name="y">Y, in pixels from the image's top edge.</param>
    public Ray GetRayAt(double x, double y) => GetRay(WindowMapping.Alpha(x, Width), WindowMapping.Beta(y, Height));

    /// <summary>The ray through the sample (sx, sy) of pixel (x, row).</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="row">The pixel row, 0 at the top.</param>
    /// <param name="sx">Offset inside the pixel, 0..1 left to right.</param>
    /// <param name="sy">Offset inside the pixel, 0..1 top to bottom.</param>
    public Ray GetPixelRay(int x, int row, double sx, double sy) => GetRay(Alpha(x, sx), Beta(row, sy));

    /// <summary>
    /// The value of one sample seen through this plane: <paramref name="scene"/>'s <see cref="Scene.Trace"/> of
    /// <paramref name="ray"/> between the near and far planes (<see cref="TMin"/>, <see cref="TMax"/>).
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="ray">A ray of this plane.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal Intensity Trace(Scene scene, in Ray ray) => scene.Trace(ray, TMin, TMax);

    /// <summary>The index of the nearest sphere of <paramref name="scene"/> that <paramref name="ray"/> hits between the near and far planes, or −1.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="ray">A ray of this plane.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal int Nearest(Scene scene, in Ray ray) => scene.Nearest(ray, TMin, TMax);

    /// <summary>
    /// Where a world point is seen: its pixel coordinates (X, Y), X to the right and Y down as in
    /// <see cref="GetRayAt"/>, so that the ray through them passes through the point. For a perspective camera
    /// the point must lie in front of the eye (its depth along the gaze positive).
    /// </summary>
    /// <param name="world">The point.</param>
    /// <returns>X and Y in pixels.</returns>
    public (double X, double Y) ToPixel(Double3 world)
    {
        (double x, double y, double z) = ToPixelHomogeneous(ToCamera(world), 1);
        return (x / z, y / z);
    }

    /// <summary>The camera coordinates (du, dv, dw) = ((x − e)·u, (x − e)·v, (x − e)·w) of a world point x; its depth along the gaze is −dw.</summary>
    /// <param name="world">The point.</param>
    internal Double3 ToCamera(Double3 world)
    {
        Double3 d = world - Eye;
        return new Double3(Double3.Dot(d, U), Double3.Dot(d, V), Double3.Dot(d, W));
    }

    /// <summary>
    /// The projection's 3×4 matrix applied to (<paramref name="v"/>, <paramref name="w4"/>) in camera coordinates
    /// (a point for w4 = 1, a direction for w4 = 0): homogeneous pixel coordinates (Xh, Yh, Zh), the point's
    /// pixel coordinates being (Xh/Zh, Yh/Zh).
    /// </summary>
    /// <param name="v">(du, dv, dw).</param>
    /// <param name="w4">The homogeneous weight.</param>
    internal abstract (double X, double Y, double Z) ToPixelHomogeneous(Double3 v, double w4);
}
