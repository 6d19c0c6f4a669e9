using RayLab.Geometry;

namespace RayLab.Simd;

/// <summary>
/// One frame's rays as the packet code needs them, in double: the camera's image plane implements it, and every quantity here that depends on the projection is the projection's.
/// </summary>
internal interface IRayFrame
{
    /// <summary>The image width W in pixels.</summary>
    int Width { get; }

    /// <summary>The image height H in pixels.</summary>
    int Height { get; }

    /// <summary>The lab's a: the window's horizontal edge.</summary>
    Double3 A { get; }

    /// <summary>The lab's b: the window's vertical edge.</summary>
    Double3 B { get; }

    /// <summary>The lab's c: the window's lower-left corner relative to the eye.</summary>
    Double3 C { get; }

    /// <summary>The direction every ray shares (−w for parallel rays), else zero.</summary>
    Double3 ParallelDirection { get; }

    /// <summary>The point the sphere offsets are taken from: where the ray through α = β = 0 starts.</summary>
    Double3 FixedPoint { get; }

    /// <summary>A bound on how far the rays' origins lie from <see cref="FixedPoint"/> (0 when every ray starts there).</summary>
    double OriginReach { get; }

    /// <summary>How large the rays' directions are where float rounds them (0 when the direction is one constant).</summary>
    double DirectionRoundingSize { get; }

    /// <summary>The smallest visible ray parameter.</summary>
    double TMin { get; }

    /// <summary>The largest visible ray parameter.</summary>
    double TMax { get; }

    /// <summary>A sphere's offset o − C for the ray through α = β = 0, and the largest |o − C| over the window.</summary>
    /// <param name="centre">The sphere's centre C.</param>
    (Double3 Offset, double Largest) SphereOffset(Double3 centre);

    /// <summary>Whether a sphere lies wholly between the near and far planes, is cut by one, or is never visible.</summary>
    /// <param name="centre">The centre.</param>
    /// <param name="radius">The radius.</param>
    SphereVisibility Visibility(Double3 centre, double radius);

    /// <summary>How large the rays' origins are near a sphere whose largest offset is <paramref name="largest"/>, where float rounds them (0 when every ray starts at the fixed point).</summary>
    /// <param name="largest">The sphere's largest |o − C|.</param>
    double OriginRoundingSize(double largest);

    /// <summary>The ray through the sample (sx, sy) of pixel (x, row).</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="row">The pixel row, 0 at the top.</param>
    /// <param name="sx">Offset inside the pixel, left to right.</param>
    /// <param name="sy">Offset inside the pixel, top to bottom.</param>
    Ray GetPixelRay(int x, int row, double sx, double sy);

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
    Double3 Frustum(double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes);
}
