using System.Numerics;

namespace RayLab.PrecisionReport;

/// <summary>
/// Two textbook ray–sphere tests, written once for any IEEE type T (float for a single-precision tracer,
/// double for the plain-double reference): the ray, the sphere and the interval are rounded to T, and every
/// operation is done in T (.NET does not contract them into fused multiply-adds).
/// </summary>
public static class SphereFormulas
{
    /// <summary>The textbook test: a = d·d, b = 2 f·d, c = f·f − r², Δ = b² − 4ac, t = (−b ∓ √Δ)/2a.</summary>
    /// <typeparam name="T">The arithmetic: float or double.</typeparam>
    /// <param name="ray">The ray.</param>
    /// <param name="sphere">The sphere.</param>
    /// <param name="tMin">The smallest accepted parameter.</param>
    /// <param name="tMax">The largest accepted parameter.</param>
    /// <param name="point">The hit point o + t d computed in T, when there is a hit.</param>
    public static bool Naive<T>(Ray ray, Sphere sphere, double tMin, double tMax, out Double3 point)
        where T : IFloatingPointIeee754<T>
    {
        ArgumentNullException.ThrowIfNull(sphere);
        (V<T> o, V<T> d, V<T> c, T r) = Round<T>(ray, sphere);
        T two = T.CreateTruncating(2), four = T.CreateTruncating(4);
        V<T> f = o - c;
        T a = V<T>.Dot(d, d);
        T b = two * V<T>.Dot(f, d);
        T cc = V<T>.Dot(f, f) - (r * r);
        T disc = (b * b) - (four * a * cc);
        point = default;
        if (!(disc >= T.Zero) || !(a > T.Zero))
        {
            return false;
        }

        T s = T.Sqrt(disc);
        return Choose((-b - s) / (two * a), (-b + s) / (two * a), tMin, tMax, o, d, out point);
    }

    /// <summary>
    /// Ray Tracing Gems ch. 7 (the formula <see cref="Sphere.TryIntersect"/> uses), in T:
    /// Δ/a = r² − |f − (f·d/d·d) d|², q = −(b + sign(b)·√a·√(Δ/a)), t₀ = q/a, t₁ = c/q.
    /// </summary>
    /// <typeparam name="T">The arithmetic: float or double.</typeparam>
    /// <param name="ray">The ray.</param>
    /// <param name="sphere">The sphere.</param>
    /// <param name="tMin">The smallest accepted parameter.</param>
    /// <param name="tMax">The largest accepted parameter.</param>
    /// <param name="point">The hit point o + t d computed in T, when there is a hit.</param>
    public static bool Rtg<T>(Ray ray, Sphere sphere, double tMin, double tMax, out Double3 point)
        where T : IFloatingPointIeee754<T>
    {
        ArgumentNullException.ThrowIfNull(sphere);
        (V<T> o, V<T> d, V<T> c, T r) = Round<T>(ray, sphere);
        V<T> f = o - c;
        T a = V<T>.Dot(d, d);
        point = default;
        if (!(a > T.Zero) || !T.IsFinite(a) || r == T.Zero)
        {
            return false;
        }

        T b = V<T>.Dot(f, d);
        V<T> perp = f - ((b / a) * d);
        T disc = (r * r) - V<T>.Dot(perp, perp);
        if (!(disc >= T.Zero))
        {
            return false;
        }

        T cc = V<T>.Dot(f, f) - (r * r);
        T sq = T.Sqrt(a) * T.Sqrt(disc);
        T q = -(b + (b >= T.Zero ? sq : -sq));
        return q == T.Zero
            ? Choose(T.Zero, T.Zero, tMin, tMax, o, d, out point)
            : Choose(q / a, cc / q, tMin, tMax, o, d, out point);
    }

    private static bool Choose<T>(T t0, T t1, double tMin, double tMax, V<T> o, V<T> d, out Double3 point)
        where T : IFloatingPointIeee754<T>
    {
        T lo = T.CreateTruncating(tMin), hi = T.CreateTruncating(tMax);
        if (t0 > t1)
        {
            (t0, t1) = (t1, t0);
        }

        T t = t0 >= lo && t0 <= hi ? t0 : t1 >= lo && t1 <= hi ? t1 : T.NaN;
        V<T> p = o + (t * d);
        point = new Double3(double.CreateTruncating(p.X), double.CreateTruncating(p.Y), double.CreateTruncating(p.Z));
        return !T.IsNaN(t);
    }

    private static (V<T> O, V<T> D, V<T> C, T R) Round<T>(Ray ray, Sphere sphere)
        where T : IFloatingPointIeee754<T> =>
        (V<T>.From(ray.Origin), V<T>.From(ray.Direction), V<T>.From(sphere.Center), T.CreateTruncating(sphere.Radius));

    /// <summary>A vector in T with the few operations the tests need.</summary>
    private readonly record struct V<T>(T X, T Y, T Z)
        where T : IFloatingPointIeee754<T>
    {
        public static V<T> From(Double3 v) => new(T.CreateTruncating(v.X), T.CreateTruncating(v.Y), T.CreateTruncating(v.Z));

        public static V<T> operator -(V<T> a, V<T> b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

        public static V<T> operator +(V<T> a, V<T> b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        public static V<T> operator *(T s, V<T> a) => new(s * a.X, s * a.Y, s * a.Z);

        public static T Dot(V<T> a, V<T> b) => (a.X * b.X) + (a.Y * b.Y) + (a.Z * b.Z);
    }
}
