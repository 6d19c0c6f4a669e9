
namespace RayLab.Cameras;

/// <summary>An <see cref="ImagePlane"/> whose rays and pixel coordinates come from <typeparamref name="TProjection"/>.</summary>
/// <typeparam name="TProjection">The camera's projection.</typeparam>
internal sealed class ImagePlane<TProjection> : ImagePlane
    where TProjection : struct, IProjection
{
    /// <summary>The plane of a camera with frame u, v, w at <paramref name="eye"/>, seeing <paramref name="window"/>.</summary>
    public ImagePlane(int width, int height, Double3 eye, Double3 u, Double3 v, Double3 w, Window window, double distance, double near, double far)
        : base(width, height, eye, u, v, w, window, distance, TProjection.IsOrthographic,
            TProjection.WindowCorner(u, v, w, window, distance), TProjection.DepthPerT(distance), near, far)
    {
    }

    /// <inheritdoc />
    public override Ray GetRay(double alpha, double beta) => TProjection.GetRay(this, alpha, beta);

    /// <inheritdoc />
    internal override (double X, double Y, double Z) ToPixelHomogeneous(Double3 v, double w4) => TProjection.ToPixel(this, v, w4);
}
