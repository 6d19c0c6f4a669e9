namespace RayLab.Geometry;

/// <summary>
/// The hit point of a ray and a sphere placed on the surface to the last ulp, for code that needs the
/// point itself (a normal, a secondary ray); the renderer only needs the visibility decision and does not pay
/// for this.
/// </summary>
internal static class AccurateHit
{
    /// <summary>
    /// Makes the same hit/miss decision as <see cref="Sphere.TryIntersect"/> (it calls it), then recomputes the
    /// parameter of that root in double-double arithmetic and returns the hit point.
    /// </summary>
    /// <remarks>
    /// <para>Why: <see cref="Sphere.TryIntersect"/> forms <c>f = o − C</c> in double, so with a sphere of radius
    /// 10⁶ and an eye 0.01 above it f is already rounded to ulp(R)/2 ≈ 6·10⁻¹¹, and <c>o + t d</c> from a double
    /// t is only as good as ulp(t·|d|): its points lie hundreds to thousands of ulp(|p|) off the surface (a tiny
    /// sphere 10⁶ radii away: 10⁵ ulp). That is harmless for the hit/miss decision and the render loop does
    /// not pay for anything here.</para>
    /// <para>How: f is kept exactly (TwoSum); <c>d·d</c>, <c>f·d</c>, <c>f·f − R²</c> and the discriminant
    /// are formed in double-double (~106 bits, so <c>(f·d)² − |d|²(f·f − R²)</c> does not cancel); the root
    /// comes from the stable formulas; one Newton step with the residual <c>|f + t d|² − R²</c> in
    /// double-double gives t to ~106 bits; and the point is <c>o + t d</c> formed in double-double and rounded
    /// once per coordinate. Positions and direction are scaled by powers of two first, so nothing overflows or
    /// underflows anywhere <see cref="Sphere.TryIntersect"/> works (|C|, R up to about 10¹⁵⁴).</para>
    /// <para>Guarantee (tested against exact rational arithmetic on the hard cases and on random spheres and
    /// rays from 2⁻³⁰ to 2³⁰): <c>| |p − C| − R | ≤ ulp(|p|) + 2⁻¹⁰⁰·|o − C|²/R</c>, the first term being
    /// what rounding p's coordinates allows and the second the working precision (it matters only for an
    /// origin ~10¹⁰ radii away or more). The decision and the root (near or far) are the ones
    /// <see cref="Sphere.TryIntersect"/> took; <paramref name="t"/> is not clipped again to
    /// [<paramref name="tMin"/>, <paramref name="tMax"/>], so a hit exactly on the boundary may come back an
    /// ulp outside it. When the exact line misses by less than the decision's rounding (a grazing ray counted
    /// as a hit), the point is the line's closest approach to the centre.</para>
    /// </remarks>
    /// <param name="sphere">The sphere.</param>
    /// <param name="ray">The ray; its direction need not be normalised.</param>
    /// <param name="tMin">The smallest accepted parameter.</param>
    /// <param name="tMax">The largest accepted parameter.</param>
    /// <param name="t">The refined parameter of the hit, when there is one.</param>
    /// <param name="point">The hit point <c>o + t d</c>, when there is one.</param>
    /// <returns>True when the ray hits the sphere within the interval (exactly when <see cref="Sphere.TryIntersect"/> says so).</returns>
    public static bool TryIntersectAccurate(this Sphere sphere, in Ray ray, double tMin, double tMax, out double t, out Double3 point)
    {
        ArgumentNullException.ThrowIfNull(sphere);
        point = default;
        if (!sphere.TryIntersect(ray, tMin, tMax, out t))
        {
            return false;
        }

        (double refined, point) = Refine(sphere, ray, t);
        if (double.IsFinite(refined) && point.IsFinite)
        {
            t = refined;
        }
        else
        {
            Double3 o = ray.Origin, d = ray.Direction; // unreachable for finite inputs; kept as a safe fallback
            point = new Double3(Math.FusedMultiplyAdd(t, d.X, o.X), Math.FusedMultiplyAdd(t, d.Y, o.Y), Math.FusedMultiplyAdd(t, d.Z, o.Z));
        }

        return true;
    }

    /// <summary>
    /// The root of |o + t d − C|² = R² nearest to <paramref name="guess"/>: the stable formulas on double-double
    /// coefficients give it to a few ulps, one Newton step with a double-double residual adds the bits below
    /// the last one, and the point o + t d is formed from that double-double t and rounded once.
    /// </summary>
    // Long: one derivation (scale, double-double root, Newton step, rounded point) whose steps read each other's exact intermediates.
    private static (double T, Double3 Point) Refine(Sphere sphere, in Ray ray, double guess)
    {
        // Scale positions by 2^−k and the direction by 2^−m (exact): |f|, R and |d| near 1, so no square overflows.
        // f + t d = 2^k (f' + t 2^(m−k) d'), so the scaled root is t' = t · 2^(m−k).
        Double3 o = ray.Origin, c = sphere.Center, d = ray.Direction;
        int k = Math.ILogB(Max(Max(MaxAbs(o), MaxAbs(c)), sphere.Radius));
        int m = Math.ILogB(MaxAbs(d));
        double r = Math.ScaleB(sphere.Radius, -k);
        Double3 os = Scale(o, -k), ds = Scale(d, -m);
        Double3 cs = Scale(c, -k);
        Span<DoubleDouble> f = [DoubleDouble.TwoDiff(os.X, cs.X), DoubleDouble.TwoDiff(os.Y, cs.Y), DoubleDouble.TwoDiff(os.Z, cs.Z)];
        Span<double> dv = [ds.X, ds.Y, ds.Z];
        Span<double> ov = [os.X, os.Y, os.Z];

        // a t² + 2 b t + c = 0 with a = d·d, b = f·d, c = f·f − r², all to ~106 bits, so b² − ac does not cancel.
        DoubleDouble a = DoubleDouble.TwoProduct(dv[0], dv[0]) + DoubleDouble.TwoProduct(dv[1], dv[1]) + DoubleDouble.TwoProduct(dv[2], dv[2]);
        DoubleDouble b = (f[0] * dv[0]) + (f[1] * dv[1]) + (f[2] * dv[2]);
        DoubleDouble cc = (f[0] * f[0]) + (f[1] * f[1]) + (f[2] * f[2]) - DoubleDouble.TwoProduct(r, r);
        DoubleDouble disc = (b * b) - (a * cc);

        double sqrtDisc = disc.Sign > 0 ? Math.Sqrt(disc.Hi) : 0;
        double q = -(b.Hi + (b.Hi >= 0 ? sqrtDisc : -sqrtDisc));
        double t0, t1;
        if (q == 0)
        {
            t0 = t1 = 0; // b = 0 and Δ = 0: origin on the surface, tangent
        }
        else
        {
            t0 = q / a.Hi;
            t1 = disc.Sign > 0 ? cc.Hi / q : t0; // a double root when the exact line only grazes the sphere
        }

        double scaledGuess = Math.ScaleB(guess, m - k);
        double ts = Math.Abs(t0 - scaledGuess) <= Math.Abs(t1 - scaledGuess) ? t0 : t1;

        // Newton on g(t) = |f + t d|² − r², with f + t d and g in double-double: t' + δ is t' to ~106 bits. A step
        // larger than a few ulps means g' ≈ 0 (a grazing ray), where the point does not depend on t: skip it.
        DoubleDouble g = -DoubleDouble.TwoProduct(r, r);
        double slope = 0;
        for (int i = 0; i < 3; i++)
        {
            DoubleDouble fi = f[i] + DoubleDouble.TwoProduct(ts, dv[i]);
            g += fi * fi;
            slope += 2 * fi.Hi * dv[i];
        }

        double step = -g.Hi / slope;
        if (!(Math.Abs(step) <= Math.ScaleB(Math.Abs(ts), -40)))
        {
            step = 0;
        }

        // p = o + (t' + δ) d' 2^k, each coordinate rounded once.
        Span<double> p = stackalloc double[3];
        for (int i = 0; i < 3; i++)
        {
            DoubleDouble coordinate = new DoubleDouble(ov[i], 0) + DoubleDouble.TwoProduct(ts, dv[i]) + DoubleDouble.TwoProduct(step, dv[i]);
            p[i] = Math.ScaleB(coordinate.Hi, k);
        }

        return (Math.ScaleB(ts + step, k - m), new Double3(p[0], p[1], p[2]));
    }

    private static Double3 Scale(Double3 v, int e) => new(Math.ScaleB(v.X, e), Math.ScaleB(v.Y, e), Math.ScaleB(v.Z, e));

    private static double MaxAbs(Double3 v) => Max(Max(Math.Abs(v.X), Math.Abs(v.Y)), Math.Abs(v.Z));

    private static double Max(double a, double b) => a >= b ? a : b;
}
