
namespace RayLab.PrecisionReport;

/// <summary>
/// Exact answers about a ray (as doubles) and a sphere (as doubles), computed in <see cref="Dyadic"/>
/// arithmetic: no rounding, and no reuse of RayLab's formulas. The reference for the hard-case tests and for
/// docs/precision.md.
/// </summary>
public static class ExactSphere
{
    /// <summary>
    /// The exact decision for an origin outside the sphere: the line meets the ball (|f × d|² ≤ r²|d|², with
    /// f = o − C) and the sphere lies ahead (f·d &lt; 0). The margin is (r²|d|² − |f × d|²)/(r²|d|²), about
    /// 2 (r − dist)/r: how far, relatively, the ray passes inside (&gt; 0) or outside (&lt; 0) the silhouette.
    /// </summary>
    /// <param name="ray">The ray.</param>
    /// <param name="sphere">The sphere, radius &gt; 0.</param>
    /// <exception cref="ArgumentException">The origin is not outside the sphere (the decision assumes it is).</exception>
    public static (bool Hit, double Margin) Hit(Ray ray, Sphere sphere)
    {
        ArgumentNullException.ThrowIfNull(sphere);
        Dyadic[] f = Sub(ray.Origin, sphere.Center);
        Dyadic[] d = Vector(ray.Direction);
        Dyadic r = Dyadic.From(sphere.Radius);
        if (Dot(f, f).Sub(r.Mul(r)).Sign <= 0)
        {
            throw new ArgumentException($"The origin {ray.Origin} is not outside the sphere.", nameof(ray));
        }

        Dyadic[] cross =
        [
            f[1].Mul(d[2]).Sub(f[2].Mul(d[1])),
            f[2].Mul(d[0]).Sub(f[0].Mul(d[2])),
            f[0].Mul(d[1]).Sub(f[1].Mul(d[0])),
        ];
        Dyadic rr = r.Mul(r).Mul(Dot(d, d));
        Dyadic diff = rr.Sub(Dot(cross, cross));
        bool ahead = Dot(f, d).Sign < 0;
        return (diff.Sign >= 0 && ahead, diff.ToDouble() / rr.ToDouble());
    }

    /// <summary>The sign of the exact discriminant (f·d)² − |d|²(|f|² − r²), f = o − C.</summary>
    /// <param name="ray">The ray.</param>
    /// <param name="sphere">The sphere.</param>
    public static int DiscriminantSign(Ray ray, Sphere sphere)
    {
        ArgumentNullException.ThrowIfNull(sphere);
        Dyadic[] f = Sub(ray.Origin, sphere.Center);
        Dyadic[] d = Vector(ray.Direction);
        Dyadic r = Dyadic.From(sphere.Radius);
        Dyadic b = Dot(f, d);
        return b.Mul(b).Sub(Dot(d, d).Mul(Dot(f, f).Sub(r.Mul(r)))).Sign;
    }

    /// <summary>
    /// The surface residual |p − C| − R of a point, from the exact value of |p − C|² − R² divided by 2R
    /// (|p − C| + R to first order): correct to a few digits, which is all a residual needs.
    /// </summary>
    /// <param name="p">The point.</param>
    /// <param name="sphere">The sphere, radius &gt; 0.</param>
    public static double Residual(Double3 p, Sphere sphere)
    {
        ArgumentNullException.ThrowIfNull(sphere);
        Dyadic[] f = Sub(p, sphere.Center);
        Dyadic r = Dyadic.From(sphere.Radius);
        return Dot(f, f).Sub(r.Mul(r)).ToDouble() / (2 * sphere.Radius);
    }

    /// <summary>The exact |a|² of a vector of doubles, as a double (for lengths too large to square in double).</summary>
    /// <param name="a">The vector.</param>
    public static double LengthSquared(Double3 a)
    {
        Dyadic[] v = Vector(a);
        return Dot(v, v).ToDouble();
    }

    /// <summary>The unit in the last place of |x|: the gap from |x| to the next larger double.</summary>
    /// <param name="x">The value.</param>
    public static double Ulp(double x) => Math.BitIncrement(Math.Abs(x)) - Math.Abs(x);

    private static Dyadic[] Vector(Double3 a) => [Dyadic.From(a.X), Dyadic.From(a.Y), Dyadic.From(a.Z)];

    private static Dyadic[] Sub(Double3 a, Double3 b) =>
        [Dyadic.From(a.X).Sub(Dyadic.From(b.X)), Dyadic.From(a.Y).Sub(Dyadic.From(b.Y)), Dyadic.From(a.Z).Sub(Dyadic.From(b.Z))];

    private static Dyadic Dot(Dyadic[] a, Dyadic[] b) => a[0].Mul(b[0]).Add(a[1].Mul(b[1])).Add(a[2].Mul(b[2]));
}
