using RayLab.Cameras;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>
/// Independent truths for the exact reference's tests, none of which uses the renderer's own code: the area of a
/// disc inside a rectangle (integrated along X, the renderer integrates along Y), an adaptive Gauss–Kronrod
/// integral, and the pixel coordinates of a world point straight from the lab's camera formulas.
/// </summary>
internal static class ExactReferenceMath
{
    /// <summary>
    /// The area of the disc (centre (cx, cy), radius r) inside [x0, x1] × [y0, y1]: ∫ |[cy − h, cy + h] ∩ [y0, y1]| dx
    /// with h(x) = √(r² − (x − cx)²), in closed form between the x where the chord's ends meet y0 or y1.
    /// </summary>
    public static double DiscRectangleArea(double cx, double cy, double r, double x0, double y0, double x1, double y1)
    {
        double a = Math.Max(x0, cx - r), b = Math.Min(x1, cx + r);
        if (!(a < b))
        {
            return 0;
        }

        var xs = new List<double> { a, b };
        foreach (double y in new[] { y0, y1 })
        {
            double dy = y - cy;
            if (Math.Abs(dy) < r)
            {
                double w = Math.Sqrt((r * r) - (dy * dy));
                xs.AddRange(new[] { cx - w, cx + w }.Where(x => x > a && x < b));
            }
        }

        xs.Sort();
        double area = 0;
        for (int i = 0; i + 1 < xs.Count; i++)
        {
            double xa = xs[i], xb = xs[i + 1], hm = Half(0.5 * (xa + xb));
            if (Math.Min(cy + hm, y1) <= Math.Max(cy - hm, y0))
            {
                continue; // the chord misses the rectangle on this whole piece
            }

            double arc = Primitive(xb) - Primitive(xa); // ∫ h dx
            double top = cy + hm <= y1 ? (cy * (xb - xa)) + arc : y1 * (xb - xa);
            double bottom = cy - hm >= y0 ? (cy * (xb - xa)) - arc : y0 * (xb - xa);
            area += top - bottom;
        }

        return area;

        // √(r² − u²) as √((r − u)(r + u)) and asin(u/r) as atan2(u, √(r² − u²)): both keep their digits near u = ±r.
        double Half(double x) => Math.Sqrt(Math.Max((r - (x - cx)) * (r + (x - cx)), 0));
        double Primitive(double x) => (((x - cx) * Half(x)) + (r * r * Math.Atan2(x - cx, Half(x)))) / 2;
    }

    /// <summary>∫ f over [a, b] by adaptive Gauss–Kronrod (7/15 points), splitting until |K15 − G7| ≤ tolerance.</summary>
    public static double Integrate(Func<double, double> f, double a, double b, double tolerance, int depth = 50)
    {
        double centre = 0.5 * (a + b), half = 0.5 * (b - a);
        double kronrod = Wk[7] * f(centre), gauss = Wg[3] * f(centre);
        for (int i = 0; i < 7; i++)
        {
            double sum = f(centre - (half * Xk[i])) + f(centre + (half * Xk[i]));
            kronrod += Wk[i] * sum;
            if (i % 2 == 1)
            {
                gauss += Wg[i / 2] * sum;
            }
        }

        kronrod *= half;
        gauss *= half;
        if (Math.Abs(kronrod - gauss) <= tolerance || depth == 0)
        {
            return kronrod;
        }

        return Integrate(f, a, centre, tolerance / 2, depth - 1) + Integrate(f, centre, b, tolerance / 2, depth - 1);
    }

    /// <summary>
    /// Pixel coordinates (X = α W, Y = (1 − β) H) of a world point, from the lab's formulas: the window point
    /// (u, v) = s (d·u, d·v)/depth for the perspective camera and (d·u, d·v) for the orthographic one, d = p − e.
    /// </summary>
    public static (double X, double Y) ToPixel(ImagePlane plane, Double3 point)
    {
        Double3 d = point - plane.Eye;
        double scale = plane.IsOrthographic ? 1 : plane.Distance / -Double3.Dot(d, plane.W);
        double u = scale * Double3.Dot(d, plane.U), v = scale * Double3.Dot(d, plane.V);
        Window w = plane.Window;
        return ((u - w.U0) / w.Width * plane.Width, (w.V1 - v) / w.Height * plane.Height);
    }

    private static readonly double[] Xk =
    [
        0.991455371120812639206854697526329, 0.949107912342758524526189684047851, 0.864864423359769072789712788640926,
        0.741531185599394439863864773280788, 0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
        0.207784955007898467600689403773245,
    ];

    private static readonly double[] Wk =
    [
        0.022935322010529224963732008058970, 0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
        0.140653259715525918745189590510238, 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
        0.204432940075298892414161999234649, 0.209482141084727828012999174891714,
    ];

    // Gauss weights of the nodes Xk[1], Xk[3], Xk[5] and the centre.
    private static readonly double[] Wg =
    [
        0.129484966168869693270611432679082, 0.279705391489276667901467771423780, 0.381830050505118944950369775488975,
        0.417959183673469387755102040816327,
    ];
}
