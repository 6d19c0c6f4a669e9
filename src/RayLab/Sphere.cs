using RayLab.Geometry;

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
    public bool TryIntersect(in Ray ray, double tMin, double tMax, out double t) =>
        SphereHit.TryIntersect(Center, Radius, ray, tMin, tMax, out t);
}
