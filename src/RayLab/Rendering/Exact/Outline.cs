using System.Runtime.CompilerServices;

namespace RayLab.Rendering.Exact;

/// <summary>
/// One border of the exact reference (<see cref="ExactRenderer"/>): an ellipse in pixel coordinates — X to the
/// right, Y down, pixel (x, row) is the square [x, x + 1] × [row, row + 1] — written as
/// <c>X(θ) = Xc + P cos θ + Q sin θ</c>, <c>Y(θ) = Yc + Hy cos θ</c> with Q, Hy ≥ 0.
/// </summary>
/// <remarks>
/// At a height Y inside [Yc − Hy, Yc + Hy], <c>c = cos θ = (Y − Yc)/Hy</c> and the ellipse has two points,
/// the left and right branch <c>X = Xc + P c ∓ Q √(1 − c²)</c>. Q = 0 is a segment (a circle seen edge-on),
/// Hy = 0 a horizontal segment; both are handled by the same formulas.
/// </remarks>
internal readonly struct Outline
{
    private Outline(double xc, double yc, double p, double q, double hy)
    {
        Xc = xc;
        Yc = yc;
        P = p;
        Q = q;
        Hy = hy;
        Hx = Math.Sqrt((p * p) + (q * q));
    }

    /// <summary>The centre's X.</summary>
    public double Xc { get; }

    /// <summary>The centre's Y.</summary>
    public double Yc { get; }

    /// <summary>The cos θ coefficient of X.</summary>
    public double P { get; }

    /// <summary>The sin θ coefficient of X (≥ 0, so branch +1 is the right one).</summary>
    public double Q { get; }

    /// <summary>Half the height (≥ 0).</summary>
    public double Hy { get; }

    /// <summary>Half the width.</summary>
    public double Hx { get; }

    /// <summary>The smallest Y on the ellipse.</summary>
    public double Top => Yc - Hy;

    /// <summary>The largest Y on the ellipse.</summary>
    public double Bottom => Yc + Hy;

    /// <summary>The smallest X on the ellipse.</summary>
    public double Left => Xc - Hx;

    /// <summary>The largest X on the ellipse.</summary>
    public double Right => Xc + Hx;

    /// <summary>
    /// The ellipse {centre + L u : |u| = 1} with L Lᵀ = Σ (its "shape"; for a circle of radius r, Σ = r² I).
    /// </summary>
    /// <param name="xc">Centre X.</param>
    /// <param name="yc">Centre Y.</param>
    /// <param name="sxx">Σ's XX entry.</param>
    /// <param name="sxy">Σ's XY entry.</param>
    /// <param name="syy">Σ's YY entry.</param>
    public static Outline FromShape(double xc, double yc, double sxx, double sxy, double syy)
    {
        // L = [[P, Q], [Hy, 0]] gives L Lᵀ = [[P² + Q², P Hy], [P Hy, Hy²]].
        double hy = Math.Sqrt(Math.Max(syy, 0));
        if (hy == 0)
        {
            return new Outline(xc, yc, Math.Sqrt(Math.Max(sxx, 0)), 0, 0);
        }

        double det = (sxx * syy) - (sxy * sxy);
        return new Outline(xc, yc, sxy / hy, Math.Sqrt(Math.Max(det, 0)) / hy, hy);
    }

    /// <summary>The left and right branch at height <paramref name="y"/> (clamped into the ellipse's height).</summary>
    /// <param name="y">The height; Hy must be &gt; 0.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public (double Left, double Right) At(double y)
    {
        (double c, double s) = CosSin(y);
        double mid = Xc + (P * c);
        return (mid - (Q * s), mid + (Q * s));
    }

    /// <summary>
    /// ∫ X dY of one branch from <paramref name="ya"/> to <paramref name="yb"/> (both inside the ellipse's height,
    /// ya ≤ yb), in closed form: X = Xc + P c ± Q √(1 − c²) with c = (Y − Yc)/Hy, and
    /// ∫ √(1 − c²) dc = (c √(1 − c²) + asin c)/2, evaluated through the angle θ = acos c so that short
    /// intervals lose no digits.
    /// </summary>
    /// <param name="sign">−1 for the left branch, +1 for the right.</param>
    /// <param name="ya">The lower limit.</param>
    /// <param name="yb">The upper limit.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public double Integral(int sign, double ya, double yb)
    {
        (double ca, double sa) = CosSin(ya);
        (double cb, double sb) = CosSin(yb);
        double ua = ya - Yc, ub = yb - Yc;
        // θ falls as Y rises: d = sin(θa − θb) ≥ 0, φ = θa − θb ∈ [0, π].
        double d = Math.Abs((sa * cb) - (ca * sb));
        double phi = Math.Atan2(d, (ca * cb) + (sa * sb));
        double arc = (phi - (((ca * cb) - (sa * sb)) * d)) / 2; // ∫_{ca}^{cb} √(1 − c²) dc
        return (Xc * (yb - ya)) + (P / (2 * Hy) * (ub - ua) * (ub + ua)) + (sign * Q * Hy * arc);
    }

    /// <summary>
    /// Adds the heights strictly inside (<paramref name="y0"/>, <paramref name="y1"/>) where this ellipse changes
    /// the structure of a pixel row: its top and bottom, its leftmost and rightmost points, and every point where
    /// it crosses a pixel column line X = k, 0 ≤ k ≤ <paramref name="width"/>.
    /// </summary>
    /// <param name="y0">The row's top.</param>
    /// <param name="y1">The row's bottom.</param>
    /// <param name="width">The image width W.</param>
    /// <param name="ys">Receives the heights.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void AddBreaks(double y0, double y1, int width, List<double> ys)
    {
        AddInside(Top, y0, y1, ys);
        AddInside(Bottom, y0, y1, ys);
        if (Hy == 0 || Hx == 0)
        {
            return;
        }

        double turn = Hy * P / Hx; // the rightmost point is at Yc + turn, the leftmost at Yc − turn
        AddInside(Yc + turn, y0, y1, ys);
        AddInside(Yc - turn, y0, y1, ys);

        double ya = Math.Max(y0, Top), yb = Math.Min(y1, Bottom);
        (double l0, double r0) = At(ya);
        (double l1, double r1) = At(yb);
        double lo = Math.Min(l0, l1), hi = Math.Max(r0, r1);
        if (Yc + turn >= ya && Yc + turn <= yb)
        {
            hi = Right;
        }

        if (Yc - turn >= ya && Yc - turn <= yb)
        {
            lo = Left;
        }

        double first = Math.Max(Math.Ceiling(lo), 0), last = Math.Min(Math.Floor(hi), width);
        for (double k = first; k <= last; k++)
        {
            double dk = k - Xc, ad = Math.Abs(dk);
            if (ad > Hx)
            {
                continue;
            }

            double root = Math.Sqrt((Hx - ad) * (Hx + ad));
            double scale = Hy / (Hx * Hx);
            AddInside(Yc + (scale * ((P * dk) - (Q * root))), y0, y1, ys);
            AddInside(Yc + (scale * ((P * dk) + (Q * root))), y0, y1, ys);
        }
    }

    /// <summary>The point at parameter θ.</summary>
    /// <param name="theta">θ.</param>
    public (double X, double Y) PointAt(double theta) =>
        (Xc + (P * Math.Cos(theta)) + (Q * Math.Sin(theta)), Yc + (Hy * Math.Cos(theta)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private (double C, double S) CosSin(double y)
    {
        double u = Math.Clamp(y - Yc, -Hy, Hy);
        return (u / Hy, Math.Sqrt((Hy - u) * (Hy + u)) / Hy);
    }

    private static void AddInside(double y, double y0, double y1, List<double> ys)
    {
        if (y > y0 && y < y1)
        {
            ys.Add(y);
        }
    }
}
