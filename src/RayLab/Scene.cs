using RayLab.Geometry;

namespace RayLab;

/// <summary>
/// What the camera looks at: spheres, a background intensity and the ambient intensity (the lab's only light).
/// </summary>
public sealed class Scene
{
    private readonly Sphere[] _spheres;

    /// <summary>Creates a scene.</summary>
    /// <param name="spheres">The spheres; none may be null.</param>
    /// <param name="background">The intensity where no sphere is hit.</param>
    /// <param name="ambient">The ambient intensity <c>I_a</c>; a sphere shows as its colour × ambient.</param>
    /// <exception cref="ArgumentNullException"><paramref name="spheres"/> or one of its items is null.</exception>
    public Scene(IEnumerable<Sphere> spheres, Intensity background, Intensity ambient)
    {
        ArgumentNullException.ThrowIfNull(spheres);
        _spheres = spheres.ToArray();
        for (int i = 0; i < _spheres.Length; i++)
        {
            if (_spheres[i] is null)
            {
                throw new ArgumentNullException(nameof(spheres), $"Sphere {i} is null.");
            }
        }

        Background = background;
        Ambient = ambient;
    }

    /// <summary>The spheres.</summary>
    public IReadOnlyList<Sphere> Spheres => _spheres;

    /// <summary>The intensity of a sample that hits nothing.</summary>
    public Intensity Background { get; }

    /// <summary>The ambient intensity <c>I_a</c>.</summary>
    public Intensity Ambient { get; }

    /// <summary>
    /// The value of one sample: the colour × ambient of the nearest sphere hit with parameter in
    /// [<paramref name="tMin"/>, <paramref name="tMax"/>], else the background.
    /// </summary>
    /// <param name="ray">The primary ray.</param>
    /// <param name="tMin">The smallest visible parameter (the near plane).</param>
    /// <param name="tMax">The largest visible parameter (the far plane).</param>
    public Intensity Trace(in Ray ray, double tMin, double tMax)
    {
        int nearest = Nearest(ray, tMin, tMax);
        return nearest < 0 ? Background : _spheres[nearest].Color * Ambient;
    }

    /// <summary>The index of the nearest sphere hit with parameter in [<paramref name="tMin"/>, <paramref name="tMax"/>], or −1.</summary>
    internal int Nearest(in Ray ray, double tMin, double tMax)
    {
        int nearest = -1;
        double best = tMax;
        for (int k = 0; k < _spheres.Length; k++)
        {
            if (_spheres[k].TryIntersect(ray, tMin, best, out double t))
            {
                best = t;
                nearest = k;
            }
        }

        return nearest;
    }
}
