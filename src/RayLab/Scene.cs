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
    /// <summary>
    /// From this many spheres on, <see cref="SceneAcceleration.Auto"/> traces through the hierarchy (measured
    /// break-even, docs/performance.md: below it testing every sphere is as fast).
    /// </summary>
    internal const int HierarchyThreshold = 12;

    private readonly Sphere[] _spheres;
    private readonly Intensity[] _colours;
    private readonly Lazy<SphereHierarchy?> _hierarchy;
    private readonly Lazy<(Double3, Double3)?> _bounds;

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
        _hierarchy = new Lazy<SphereHierarchy?>(() => SphereHierarchy.Build(_spheres), LazyThreadSafetyMode.ExecutionAndPublication);
        _bounds = new Lazy<(Double3, Double3)?>(() => BoundsOf(_spheres), LazyThreadSafetyMode.PublicationOnly);
    }

    /// <summary>The box that holds every sphere (centre ± radius on each axis), or null for a scene with none; once per scene.</summary>
    internal (Double3 Min, Double3 Max)? Bounds => _bounds.Value;

    private static (Double3, Double3)? BoundsOf(Sphere[] spheres)
    {
        if (spheres.Length == 0)
        {
            return null;
        }

        (Double3 min, Double3 max) = spheres[0].Box;
        foreach (Sphere s in spheres.AsSpan(1))
        {
            (Double3 lo, Double3 hi) = s.Box;
            (min, max) = (Double3.Min(min, lo), Double3.Max(max, hi));
        }

        return (min, max);
    }

    /// <summary>
    /// Whether rays find their sphere through a bounding volume hierarchy (the lab's reference [5], space
    /// subdivision) or by testing every sphere; <see cref="SceneAcceleration.Auto"/> (the default) uses the
    /// hierarchy from <c>12</c> spheres on. The picture is the same bytes either way; only the time differs.
    /// </summary>
    public SceneAcceleration Acceleration { get; init; }

    /// <summary>True when rays are traced through the hierarchy (see <see cref="Acceleration"/>).</summary>
    internal bool UsesHierarchy => Acceleration switch
    {
        SceneAcceleration.None => false,
        SceneAcceleration.Hierarchy => true,
        _ => _spheres.Length >= HierarchyThreshold,
    };

    /// <summary>The hierarchy when <see cref="UsesHierarchy"/> (built on first use, once per scene), else null.</summary>
    internal SphereHierarchy? Hierarchy => UsesHierarchy ? _hierarchy.Value : null;

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
    /// <remarks>Through the hierarchy when <see cref="UsesHierarchy"/>; the answer is the same either way.</remarks>
    internal int Nearest(in Ray ray, double tMin, double tMax)
    {
        SphereHierarchy? hierarchy = Hierarchy;
        return hierarchy is null
            ? SphereHierarchy.NearestOfAll(_spheres, ray, tMin, tMax)
            : hierarchy.Nearest(_spheres, ray, tMin, tMax);
    }
}
