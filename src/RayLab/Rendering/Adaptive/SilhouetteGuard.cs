using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Sampling;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The guard of <see cref="AdaptiveSampler.Guard"/> (our own method, after Whitted 1980): whether a sphere's
/// silhouette may pass through a square of the adaptive lattice, although the square's traced points agree.
/// </summary>
/// <remarks>
/// <para>The ray through the square's centre passes at distance <c>p = |f − (f·d / d·d) d|</c> from a sphere's
/// centre (f = o − C: the ray–sphere test's stable discriminant is <c>r² − p²</c>). Every other ray of the square
/// differs from it by a window offset w with <c>|w| ≤ δ = ½ √((|a|·Δα)² + (|b|·Δβ)²)</c>, the square's half-diagonal on
/// the window (a ⊥ b). Orthographic: the rays are parallel and their origins differ by w, so their distances differ by at most
/// δ. Perspective: their directions d + w turn by an angle θ with <c>sin θ ≤ δ / |d|</c> about the eye, and the
/// distance <c>|f| sin∠(f, d)</c> changes by at most <c>|f| θ = |f| asin(δ / |d|)</c>. Calling that bound m, some ray of the square may hit
/// the sphere and another miss it only if <c>|p − r| ≤ m</c>: the square is refined then. The test is exact
/// geometry plus a margin of 10⁻⁹ (|f| + r) for rounding, so it never misses a silhouette that crosses the square
/// (off-axis windows included: a and b are the window's own edges), and it is nearly free where every sphere is
/// farther than m from the square's rays: a square of 1/32 pixel is refined only within about 1/32 pixel of a
/// silhouette. A sphere cut by the near or far plane (or around the eye) has a silhouette where the plane cuts
/// it too; there the square is refined whenever <c>p − m ≤ r</c>. Spheres hidden behind others are tested as
/// well: that costs rays, never accuracy.</para>
/// </remarks>
internal sealed class SilhouetteGuard
{
    private readonly ImagePlane _plane;
    private readonly (Double3 Center, double Radius, bool Clipped)[] _spheres;
    private readonly long _size;
    private readonly double _stepWidth, _stepHeight;

    /// <summary>The guard for <paramref name="scene"/> seen on <paramref name="plane"/>, with <paramref name="size"/> lattice steps per pixel.</summary>
    public SilhouetteGuard(Scene scene, ImagePlane plane, long size)
    {
        _plane = plane;
        _size = size;
        _stepWidth = plane.A.Length / (plane.Width * (double)size);
        _stepHeight = plane.B.Length / (plane.Height * (double)size);
        var spheres = new List<(Double3, double, bool)>();
        foreach (Sphere sphere in scene.Spheres)
        {
            if (sphere.Radius == 0)
            {
                continue;
            }

            SphereVisibility visibility = plane.Visibility(sphere.Center, sphere.Radius);
            if (visibility != SphereVisibility.Hidden)
            {
                spheres.Add((sphere.Center, sphere.Radius, visibility == SphereVisibility.Clipped));
            }
        }

        _spheres = [.. spheres];
    }

    /// <summary>True when some sphere's silhouette may pass through the square of <paramref name="size"/> lattice steps at (x0, y0).</summary>
    public bool MayCross(long x0, long y0, long size)
    {
        double half = size * 0.5;
        Ray ray = _plane.GetRay(_plane.LatticeAlpha(x0 + half, _size), _plane.LatticeBeta(y0 + half, _size));
        double delta = half * Math.Sqrt((_stepWidth * _stepWidth) + (_stepHeight * _stepHeight));
        Double3 d = ray.Direction;
        double dd = Double3.Dot(d, d);
        (double spread, double turn) = _plane.SquareSpread(delta, dd);
        foreach ((Double3 center, double radius, bool clipped) in _spheres)
        {
            Double3 f = ray.Origin - center;
            Double3 perp = f - ((Double3.Dot(f, d) / dd) * d);
            double p = perp.Length, reach = f.Length;
            double margin = spread + (reach * turn) + (1e-9 * (reach + radius));
            if (clipped ? p - margin <= radius : Math.Abs(p - radius) <= margin)
            {
                return true;
            }
        }

        return false;
    }
}
