namespace RayLab.Reports.Patterns;

/// <summary>The closed forms the test functions' exact integrals need (.NET has no error function).</summary>
internal static class SpecialFunctions
{
    /// <summary>
    /// erf(x) by its Maclaurin series (Abramowitz and Stegun 7.1.5) for |x| ≤ 3, and by the continued fraction of
    /// erfc (A&amp;S 7.1.14, evaluated backwards) beyond: about 1e-14 absolute error throughout.
    /// </summary>
    public static double Erf(double x)
    {
        if (x < 0)
        {
            return -Erf(-x);
        }

        if (x <= 3)
        {
            double term = x, sum = x, x2 = x * x;
            for (int n = 1; n < 200 && Math.Abs(term) > 1e-17 * Math.Abs(sum); n++)
            {
                term *= -x2 / n;
                sum += term / ((2 * n) + 1);
            }

            return 2 / Math.Sqrt(Math.PI) * sum;
        }

        // erfc(x) = exp(−x²)/√π · 1/(x + 1/2/(x + 1/(x + 3/2/(x + 2/(x + …))))).
        double f = x;
        for (int k = 60; k >= 1; k--)
        {
            f = x + (k / 2.0 / f);
        }

        return 1 - (Math.Exp(-x * x) / Math.Sqrt(Math.PI) / f);
    }

    /// <summary>
    /// ∫∫ x·y over the part of [0, 1]² where (x − px)·nx + (y − py)·ny &lt; 0: the square clipped by the half plane
    /// (Sutherland–Hodgman), then Green's theorem edge by edge: ∫∫ x y dA = ∮ x² y / 2 dy, exact for polygons.
    /// </summary>
    public static double BilinearOverClippedSquare(double px, double py, double nx, double ny)
    {
        (double X, double Y)[] square = [(0, 0), (1, 0), (1, 1), (0, 1)];
        var polygon = new List<(double X, double Y)>(5);
        for (int i = 0; i < 4; i++)
        {
            (double X, double Y) a = square[i], b = square[(i + 1) % 4];
            double da = ((a.X - px) * nx) + ((a.Y - py) * ny), db = ((b.X - px) * nx) + ((b.Y - py) * ny);
            if (da < 0)
            {
                polygon.Add(a);
            }

            if ((da < 0) != (db < 0))
            {
                double t = da / (da - db);
                polygon.Add((a.X + (t * (b.X - a.X)), a.Y + (t * (b.Y - a.Y))));
            }
        }

        double sum = 0;
        for (int i = 0; i < polygon.Count; i++)
        {
            (double x0, double y0) = polygon[i];
            (double x1, double y1) = polygon[(i + 1) % polygon.Count];
            // On the edge x = x0 + t dx, y = y0 + t dy: ∫ x² y dy / 2 = dy/2 ∫₀¹ (x0 + t dx)² (y0 + t dy) dt.
            double dx = x1 - x0, dy = y1 - y0;
            double integral = (x0 * x0 * y0) + (((2 * x0 * dx * y0) + (x0 * x0 * dy)) / 2)
                + (((dx * dx * y0) + (2 * x0 * dx * dy)) / 3) + (dx * dx * dy / 4);
            sum += dy / 2 * integral;
        }

        return sum;
    }
}
