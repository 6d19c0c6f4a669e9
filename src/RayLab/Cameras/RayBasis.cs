using System.Runtime.CompilerServices;

namespace RayLab.Cameras;

/// <summary>
/// What a primary ray of an <see cref="ImagePlane"/> is made from, in double: the eye e, the lab's a, b, c, the
/// orthographic direction, the image size and the visible range of t. An unmanaged value, so the ray formula that
/// the CPU renderers run (<see cref="IProjection.GetRay"/>) runs unchanged in a device kernel that takes it by value.
/// </summary>
internal readonly struct RayBasis
{
    /// <summary>The eye e.</summary>
    public readonly Double3 Eye;

    /// <summary>The lab's a: the window's width along u.</summary>
    public readonly Double3 A;

    /// <summary>The lab's b: the window's height along v.</summary>
    public readonly Double3 B;

    /// <summary>The lab's c: from e to the window's bottom-left corner.</summary>
    public readonly Double3 C;

    /// <summary>The orthographic rays' direction −w (unused by the perspective projection).</summary>
    public readonly Double3 ParallelDirection;

    /// <summary>The image width W in pixels.</summary>
    public readonly int Width;

    /// <summary>The image height H in pixels.</summary>
    public readonly int Height;

    /// <summary>The smallest visible t (the near plane).</summary>
    public readonly double TMin;

    /// <summary>The largest visible t (the far plane).</summary>
    public readonly double TMax;

    /// <summary>1 for the orthographic projection, 0 for the perspective one (a kernel parameter holds no bool: not blittable).</summary>
    private readonly int _orthographic;

    /// <summary>The basis of a plane's rays (<see cref="ImagePlane.Basis"/>).</summary>
    /// <param name="eye">e.</param>
    /// <param name="a">a.</param>
    /// <param name="b">b.</param>
    /// <param name="c">c.</param>
    /// <param name="parallelDirection">The orthographic direction.</param>
    /// <param name="width">W.</param>
    /// <param name="height">H.</param>
    /// <param name="tMin">The smallest visible t.</param>
    /// <param name="tMax">The largest visible t.</param>
    /// <param name="orthographic">True for the orthographic projection.</param>
    public RayBasis(Double3 eye, Double3 a, Double3 b, Double3 c, Double3 parallelDirection, int width, int height, double tMin, double tMax, bool orthographic)
    {
        Eye = eye;
        A = a;
        B = b;
        C = c;
        ParallelDirection = parallelDirection;
        Width = width;
        Height = height;
        TMin = tMin;
        TMax = tMax;
        _orthographic = orthographic ? 1 : 0;
    }

    /// <summary>True for the orthographic projection, false for the perspective one.</summary>
    public bool IsOrthographic => _orthographic != 0;

    /// <summary>The ray through window point (α, β): <see cref="ImagePlane.GetRay"/>'s formula, by the projection's own <c>GetRay</c>.</summary>
    /// <param name="alpha">α, 0 at the window's left edge, 1 at its right.</param>
    /// <param name="beta">β, 0 at the window's bottom edge, 1 at its top.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Ray GetRay(double alpha, double beta) =>
        IsOrthographic ? OrthographicProjection.GetRay(this, alpha, beta) : PerspectiveProjection.GetRay(this, alpha, beta);

    /// <summary>
    /// The ray through point (<paramref name="sx"/>, <paramref name="sy"/>) of pixel (<paramref name="x"/>,
    /// <paramref name="row"/>): <see cref="ImagePlane.GetPixelRay"/>, with the projection chosen by the basis.
    /// </summary>
    /// <param name="x">The pixel's column.</param>
    /// <param name="row">The pixel's row, 0 the top.</param>
    /// <param name="sx">The point's offset in the pixel, 0..1 left to right.</param>
    /// <param name="sy">The point's offset in the pixel, 0..1 top to bottom.</param>
    /// <returns>The ray, in double.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Ray GetPixelRay(int x, int row, double sx, double sy)
    {
        double alpha = WindowMapping.Alpha(x + sx, Width);
        double beta = WindowMapping.Beta(row + sy, Height);
        return IsOrthographic
            ? OrthographicProjection.GetRay(this, alpha, beta)
            : PerspectiveProjection.GetRay(this, alpha, beta);
    }
}
