using RayLab.Geometry;

namespace RayLab;

/// <summary>
/// What the camera looks at: spheres, a background intensity and the ambient intensity (the lab's only light).
/// </summary>
/// <remarks>
/// The scene is flat-shaded: ambient light only, so every point of a sphere shows one colour, the sphere's
/// colour × ambient, and a sample's value depends only on which sphere it hits (or none).
/// <see cref="ColourOf"/> is the one place that shades; <see cref="Trace"/> and every renderer take their colours
/// from it. The renderers rely on this contract: the packet kernel carries each sphere's colour as a constant
/// per sphere, the adaptive renderer stores what a pixel corner hit as an index into these colours, and the exact
/// renderer integrates regions of one colour bounded by the spheres' outlines. A shading model that varies across
/// a sphere breaks all three, and the flat-shading tests fail.
/// </remarks>
public sealed class Scene
{
    private readonly Sphere[] _spheres;
    private readonly Intensity[] _colours;

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
        _colours = [.. _spheres.Select(sphere => sphere.Color * ambient)];
    }

    /// <summary>The spheres.</summary>
    public IReadOnlyList<Sphere> Spheres => _spheres;

    /// <summary>The intensity of a sample that hits nothing.</summary>
    public Intensity Background { get; }

    /// <summary>The ambient intensity <c>I_a</c>.</summary>
    public Intensity Ambient { get; }

    /// <summary>
    /// The colour a sample shows when it hits sphere <paramref name="sphere"/> (its colour × ambient), or
    /// nothing (index −1: the background): the scene's whole shading.
    /// </summary>
    /// <param name="sphere">The index of the sphere hit in <see cref="Spheres"/>, or −1 for none.</param>
    /// <returns>The sample's value.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="sphere"/> is below −1 or not below the sphere count.</exception>
    public Intensity ColourOf(int sphere)
    {
        if (sphere < 0)
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(sphere, -1);
            return Background;
        }

        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(sphere, _colours.Length);
        return _colours[sphere];
    }

    /// <summary>
    /// The value of one sample: the <see cref="ColourOf"/> the nearest sphere hit with parameter in
    /// [<paramref name="tMin"/>, <paramref name="tMax"/>], else of none (the background).
    /// </summary>
    /// <param name="ray">The primary ray.</param>
    /// <param name="tMin">The smallest visible parameter (the near plane).</param>
    /// <param name="tMax">The largest visible parameter (the far plane).</param>
    public Intensity Trace(in Ray ray, double tMin, double tMax) => ColourOf(Nearest(ray, tMin, tMax));

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
