using System.Runtime.CompilerServices;

namespace RayLab.Geometry;

/// <summary>
/// The stable ray–sphere hit, once: <see cref="Sphere.TryIntersect"/> is this formula, and so is every other path
/// that traces a sphere in double (the packet kernels' retrace, the device kernel of <c>RayLab.Gpu</c>). Static and
/// on unmanaged values only, so a device compiler takes it as it is.
/// </summary>
internal readonly struct SphereHit
{
    /// <summary>The nearest t in [<paramref name="tMin"/>, <paramref name="tMax"/>] where <paramref name="ray"/> meets the sphere, if any.</summary>
    /// <param name="center">The sphere's centre.</param>
    /// <param name="radius">The sphere's radius (0 is never hit).</param>
    /// <param name="ray">The ray.</param>
    /// <param name="tMin">The smallest t accepted.</param>
    /// <param name="tMax">The largest t accepted.</param>
    /// <param name="t">The hit's t, or +∞ when there is none.</param>
    /// <returns>True when the ray meets the sphere within the range.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool TryIntersect(Double3 center, double radius, in Ray ray, double tMin, double tMax, out double t)
    {
        t = double.PositiveInfinity;
        double r = radius;
        if (r == 0)
        {
            return false;
        }

        Double3 d = ray.Direction;
        Double3 f = ray.Origin - center;
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
