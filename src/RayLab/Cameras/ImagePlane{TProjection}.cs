using RayLab.Geometry;

namespace RayLab.Cameras;

/// <summary>An <see cref="ImagePlane"/> whose rays and pixel coordinates come from <typeparamref name="TProjection"/>.</summary>
/// <typeparam name="TProjection">The camera's projection.</typeparam>
internal sealed class ImagePlane<TProjection> : ImagePlane
    where TProjection : struct, IProjection
{
    /// <summary>The plane of a camera with frame u, v, w at <paramref name="eye"/>, seeing <paramref name="window"/>.</summary>
    public ImagePlane(int width, int height, Double3 eye, Double3 u, Double3 v, Double3 w, Window window, double distance, double near, double far)
        : base(width, height, eye, u, v, w, window, distance, TProjection.IsOrthographic,
            TProjection.WindowCorner(u, v, w, window, distance), TProjection.DepthPerT(distance), near, far,
            TProjection.ParallelDirection(w), TProjection.OriginShift(TProjection.WindowCorner(u, v, w, window, distance)))
    {
        OriginReach = TProjection.OriginReach(A, B, C);
        DirectionRoundingSize = TProjection.DirectionRoundingSize(A, B, C);
    }

    /// <inheritdoc />
    internal override double OriginReach { get; }

    /// <inheritdoc />
    internal override double DirectionRoundingSize { get; }

    /// <inheritdoc />
    internal override double LargestOffset(Double3 offset) => TProjection.LargestOffset(offset, A, B);

    /// <inheritdoc />
    internal override double OriginRoundingSize(double largest) => TProjection.OriginRoundingSize(largest);

    /// <inheritdoc />
    internal override double RayRoundingBound(Double3 offset, double largest, double epsilon) => TProjection.RayRoundingBound(this, offset, largest, epsilon);

    /// <inheritdoc />
    internal override (double Constant, double PerReach) SquareSpread(double delta, double directionLengthSquared) => TProjection.SquareSpread(delta, directionLengthSquared);

    /// <inheritdoc />
    internal override bool MayBeInView(Double3 centre, double radius) => TProjection.MayBeInView(this, centre, radius);

    /// <inheritdoc />
    internal override bool IsAheadOfEye(double depth, double radius) => TProjection.IsAheadOfEye(depth, radius);

    /// <inheritdoc />
    internal override double WindowScale(double depth) => TProjection.WindowScale(Distance, depth);

    /// <inheritdoc />
    internal override TResult Dispatch<TAction, TResult>(ref TAction action) => action.Run(this);

    /// <inheritdoc />
    private protected override Double3 SideFrustum(double alpha0, double alpha1, double beta0, double beta1, Span<Plane> planes) =>
        TProjection.Frustum(this, alpha0, alpha1, beta0, beta1, planes);

    /// <inheritdoc />
    public override Ray GetRay(double alpha, double beta) => TProjection.GetRay(in Basis, alpha, beta);

    /// <inheritdoc />
    internal override (double X, double Y, double Z) ToPixelHomogeneous(Double3 v, double w4) => TProjection.ToPixel(this, v, w4);
}
