using RayLab.Cameras;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The projection of spheres and circles to <see cref="Outline"/>s in pixel coordinates (X = α W to the right,
/// Y = (1 − β) H down), through the camera's own world → pixel map (<see cref="ImagePlane.ToPixel(Double3)"/>).
/// </summary>
/// <remarks>
/// Camera coordinates of a point x are (du, dv, dw) = ((x − e)·u, (x − e)·v, (x − e)·w); its depth along the
/// gaze is −dw. A point projects to the pixel coordinates (X, Y) = (Xh/Zh, Yh/Zh) of the camera's 3×4 matrix M
/// (<see cref="IProjection.ToPixel"/>); a sphere or a circle projects to the conic whose dual is <c>C* = M Q* Mᵀ</c>, where Q*
/// is the dual quadric (a sphere: Σ r² eₖeₖᵀ − b bᵀ over the three axes; a circle of radius ρ: the same over
/// two axes in its plane; b = (centre, 1)). From C* the ellipse's centre and shape follow directly, and this
/// also works for a circle seen edge-on, whose picture is a segment.
/// </remarks>
internal readonly struct OutlineProjection
{
    private readonly ImagePlane _plane;

    public OutlineProjection(ImagePlane plane)
    {
        _plane = plane;
    }

    /// <summary>The camera coordinates (du, dv, dw) of a world point.</summary>
    /// <param name="world">The point.</param>
    public Double3 ToCamera(Double3 world) => _plane.ToCamera(world);

    /// <summary>
    /// How far, in pixels, double rounding alone can move the picture of a sphere: its camera coordinates and the
    /// window's corners are known to about 1e-16 of their size, and a pixel is su world units on the window (for
    /// the perspective camera, su/s of the depth at the sphere's nearest point). A tiny window far from the axis,
    /// or a sphere far away at a high zoom, can make this a sizeable part of a pixel.
    /// </summary>
    /// <param name="centre">The centre in camera coordinates.</param>
    /// <param name="radius">The radius.</param>
    public double RoundingInPixels(Double3 centre, double radius)
    {
        Window win = _plane.Window;
        double corners = Math.Max(Math.Max(Math.Abs(win.U0), Math.Abs(win.U1)), Math.Max(Math.Abs(win.V0), Math.Abs(win.V1)));
        double size = centre.Length + radius;
        size *= _plane.WindowScale(-centre.Z - radius);

        return 1e-15 * (size + corners) / Math.Min(_plane.PixelWidth, _plane.PixelHeight);
    }

    /// <summary>The outline of a sphere: where the rays tangent to it cross the window.</summary>
    /// <param name="centre">The centre in camera coordinates.</param>
    /// <param name="radius">The radius.</param>
    public Outline Sphere(Double3 centre, double radius) =>
        Project(centre, [new Double3(radius, 0, 0), new Double3(0, radius, 0), new Double3(0, 0, radius)]);

    /// <summary>The picture of a circle.</summary>
    /// <param name="centre">The centre in camera coordinates.</param>
    /// <param name="radius">The radius.</param>
    /// <param name="normal">A unit normal of the circle's plane, in camera coordinates.</param>
    public Outline Circle(Double3 centre, double radius, Double3 normal)
    {
        Double3 other = Math.Abs(normal.X) < 0.5 ? new Double3(1, 0, 0) : new Double3(0, 1, 0);
        Double3 t1 = Double3.Normalize(Double3.Cross(normal, other));
        Double3 t2 = Double3.Cross(normal, t1);
        return Project(centre, [radius * t1, radius * t2]);
    }

    private Outline Project(Double3 centre, ReadOnlySpan<Double3> axes)
    {
        // Work relative to the centre's own picture (x0, y0), so that nothing large cancels.
        (double bx, double by, double bz) = _plane.ToPixelHomogeneous(centre, 1);
        double x0 = bx / bz, y0 = by / bz;
        bx -= x0 * bz;
        by -= y0 * bz;
        double cxx = -bx * bx, cxy = -bx * by, cyy = -by * by, cxz = -bx * bz, cyz = -by * bz, czz = -bz * bz;
        foreach (Double3 axis in axes)
        {
            (double ax, double ay, double az) = _plane.ToPixelHomogeneous(axis, 0);
            ax -= x0 * az;
            ay -= y0 * az;
            cxx += ax * ax;
            cxy += ax * ay;
            cyy += ay * ay;
            cxz += ax * az;
            cyz += ay * az;
            czz += az * az;
        }

        // C* = λ [[Σ − c cᵀ, −c], [−cᵀ, −1]] for the ellipse {c + L u : |u| = 1}, Σ = L Lᵀ.
        double lambda = -czz;
        if (!(lambda > 0) || !double.IsFinite(lambda))
        {
            throw new InvalidOperationException($"The picture of the circle or sphere at {centre} is not an ellipse (λ = {lambda}).");
        }

        double pcx = cxz / czz, pcy = cyz / czz;
        return Outline.FromShape(x0 + pcx, y0 + pcy, (cxx / lambda) + (pcx * pcx), (cxy / lambda) + (pcx * pcy), (cyy / lambda) + (pcy * pcy));
    }
}
