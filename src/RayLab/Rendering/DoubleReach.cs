using RayLab.Cameras;

namespace RayLab.Rendering;

/// <summary>
/// How far from the camera a scene may reach in double. The ray–sphere test (<see cref="Sphere.TryIntersect"/>)
/// squares the offset from a ray's origin to a sphere's centre and the sphere's radius; from about 1.3e154 on, those
/// squares overflow and every ray would miss the sphere without a word. With every sphere (centre ± radius) within
/// <see cref="Limit"/> of every ray origin on each axis, and the camera's ray directions within its own limit
/// (<c>|d|²</c> finite), every product and sum of the test stays finite.
/// </summary>
internal static class DoubleReach
{
    /// <summary>The farthest a sphere's surface may lie from a ray origin, on one axis.</summary>
    public const double Limit = 5e152;

    /// <summary>Throws <see cref="UnsupportedSceneException"/> for the first sphere that reaches past <see cref="Limit"/> from the plane's ray origins.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The image plane the render traces through.</param>
    public static void Check(Scene scene, ImagePlane plane)
    {
        if (scene.Bounds is not ({ } min, { } max))
        {
            return;
        }

        // Where rays start: the eye, or the window on the image plane (orthographic); its corners bound it.
        Double3 low = new(double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity), high = -low;
        foreach ((double alpha, double beta) in (ReadOnlySpan<(double, double)>)[(0, 0), (1, 0), (0, 1), (1, 1)])
        {
            Double3 o = plane.GetRay(alpha, beta).Origin;
            (low, high) = (Double3.Min(low, o), Double3.Max(high, o));
        }

        if (Within(min, max, low, high))
        {
            return; // the whole scene at once: the common case costs nothing per sphere
        }

        for (int i = 0; i < scene.Spheres.Count; i++)
        {
            Sphere s = scene.Spheres[i];
            if (!Within(s.Box.Lo, s.Box.Hi, low, high))
            {
                throw new UnsupportedSceneException(i, FormattableString.Invariant(
                    $"(centre {s.Center}, radius {s.Radius:G3}) reaches more than {Limit:G1} from where the camera's rays start, on some axis: the ray–sphere test squares that distance, which overflows double, so the sphere would vanish. Bring the camera and the spheres closer together, or scale the scene down."));
            }
        }
    }

    // On each axis, the farthest a point of box [min, max] lies from a point of box [low, high]. (An overflow to
    // infinity compares as out of reach.)
    private static bool Within(Double3 min, Double3 max, Double3 low, Double3 high) =>
        Math.Max(max.X - low.X, high.X - min.X) <= Limit
        && Math.Max(max.Y - low.Y, high.Y - min.Y) <= Limit
        && Math.Max(max.Z - low.Z, high.Z - min.Z) <= Limit;
}
