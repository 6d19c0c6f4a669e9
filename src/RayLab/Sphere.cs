namespace RayLab;

/// <summary>A sphere with a flat colour (the lab's sphere from lab I, plus the colour this lab shows it in).</summary>
public sealed class Sphere
{
    /// <summary>Creates a sphere.</summary>
    /// <param name="center">The centre; every component finite.</param>
    /// <param name="radius">The radius, ≥ 0 and finite. A sphere of radius 0 is allowed and is never hit.</param>
    /// <param name="color">The sphere's colour; on screen it is multiplied by the scene's ambient intensity.</param>
    /// <exception cref="ArgumentException">The centre is not finite, or the radius is negative or not finite.</exception>
    public Sphere(Double3 center, double radius, Intensity color)
    {
        if (!center.IsFinite)
        {
            throw new ArgumentException($"The centre must be finite, got {center}.", nameof(center));
        }

        if (!(radius >= 0) || !double.IsFinite(radius))
        {
            throw new ArgumentException($"The radius must be a finite number ≥ 0, got {radius}.", nameof(radius));
        }

        Center = center;
        Radius = radius;
        Color = color;
    }

    /// <summary>The centre.</summary>
    public Double3 Center { get; }

    /// <summary>The radius (≥ 0).</summary>
    public double Radius { get; }

    /// <summary>The flat colour.</summary>
    public Intensity Color { get; }

    /// <summary>The box that holds the sphere: centre ± radius on each axis.</summary>
    internal (Double3 Lo, Double3 Hi) Box => (Center - new Double3(Radius, Radius, Radius), Center + new Double3(Radius, Radius, Radius));

    /// <summary>
    /// Finds the nearest intersection with parameter in the closed interval [<paramref name="tMin"/>,
    /// <paramref name="tMax"/>].
    /// </summary>
    /// <remarks>
    /// Numerically stable (Ray Tracing Gems, ch. 7): the discriminant is formed as
    /// <c>r² − |f − (f·d/d·d) d|²</c> with <c>f = o − C</c>, which does not cancel for small or distant
    /// spheres, and the roots as <c>q = −(b + sign(b)·√Δ)</c>, <c>t₀ = q/a</c>, <c>t₁ = c/q</c>, which avoid
    /// subtracting nearly equal numbers. A tangent ray (discriminant exactly 0) counts as a hit.
    /// If the near root lies before <paramref name="tMin"/> (the near plane cuts the sphere, or the
    /// origin is inside), the far root is tried.
    /// </remarks>
    /// <param name="ray">The ray; its direction need not be normalised.</param>
    /// <param name="tMin">The smallest accepted parameter.</param>
    /// <param name="tMax">The largest accepted parameter.</param>
    /// <param name="t">The parameter of the hit, when there is one.</param>
    /// <returns>True when the ray hits the sphere within the interval.</returns>
    public bool TryIntersect(in Ray ray, double tMin, double tMax, out double t)
    {
        t = double.PositiveInfinity;
        double r = Radius;
        if (r == 0)
        {
            return false;
        }

        Double3 d = ray.Direction;
        Double3 f = ray.Origin - Center;
        double a = Double3.Dot(d, d);
        if (!(a > 0) || !double.IsFinite(a))
        {
            return false; // zero, NaN or infinite direction: no meaningful hit
        }

        double b = Double3.Dot(f, d);               // half of the textbook b
        Double3 perp = f - ((b / a) * d);          // f minus its projection on d
        double disc = (r * r) - perp.LengthSquared; // (b² − ac)/a, without cancellation
        if (!(disc >= 0))
        {
            return false;
        }

        double c = f.LengthSquared - (r * r);
        double sqrtTerm = Math.Sqrt(a) * Math.Sqrt(disc); // not √(a·disc): that product overflows for |d|, r ~ 1e100
        double q = -(b + (b >= 0 ? sqrtTerm : -sqrtTerm));
        double t0, t1;
        if (q == 0)
        {
            t0 = t1 = 0; // b = 0 and Δ = 0 only when c = 0: origin on the surface, tangent
        }
        else
        {
            t0 = q / a;
            t1 = c / q;
            if (t0 > t1)
            {
                (t0, t1) = (t1, t0);
            }
        }

        if (t0 >= tMin && t0 <= tMax)
        {
            t = t0;
            return true;
        }

        if (t1 >= tMin && t1 <= tMax)
        {
            t = t1;
            return true;
        }

        return false;
    }
}
