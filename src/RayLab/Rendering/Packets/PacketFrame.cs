using RayLab.Cameras;
using RayLab.Geometry;

namespace RayLab.Rendering.Packets;

/// <summary>
/// One frame's constants for the packet kernel, in float: the window vectors a, b, c, and per sphere its
/// offset from the eye, r², colour and the error bound that decides when a float answer is certain.
/// <see cref="TryCreate"/> says whether float is good enough for the frame at all.
/// </summary>
/// <remarks>
/// <para>
/// The kernel relies on the scene's flat shading (<see cref="Scene"/>): a sample's value is the
/// <see cref="Scene.ColourOf"/> of the sphere it hits, so each sphere's colour is one constant here and the
/// background another, both taken from <see cref="Scene.ColourOf"/>.
/// </para>
/// <para>
/// The kernel tests each ray in float with the stable discriminant <c>Δ = r² − |f|²</c>,
/// <c>f = (o − C) − ((o − C)·d / d·d) d</c> (Ray Tracing Gems, ch. 7). Its rounding error is below
/// <see cref="FloatRounding.DiscriminantError"/>, so where
/// |Δ| exceeds that bound the float answer — hit or miss — is the exact one; only where it does not (rays
/// within float resolution of a silhouette) is the sample traced again in double (Shewchuk's adaptive
/// predicates: fast float with an error bound, exact fallback only where the bound is crossed).
/// </para>
/// <para>
/// Nearer-sphere decisions are certain when the spheres are apart by more than the two entry points' error;
/// spheres closer than that (or overlapping) turn on a per-lane check of |t₁ − t₂| as well.
/// </para>
/// <para>
/// The frame is refused (the caller uses the double-precision scalar path) when a sphere reaches past the
/// near or far plane or surrounds the eye (the kernel takes the near root and no clipping), or when float
/// cannot resolve the pixels: the rounding of a ray's direction (perspective) or origin (orthographic)
/// would move it by more than 1/50 of a pixel (at 1920×1080 it moves it by about 1/3000).
/// </para>
/// </remarks>
internal sealed class PacketFrame
{
    /// <summary>The most (in pixels) that float rounding may move a ray's direction or origin: 1/50 pixel.</summary>
    private const double Resolution = 0.02;

    private PacketFrame(ImagePlane plane, Scene scene, int[] kept, bool withHierarchy)
    {
        Plane = plane;
        Scene = scene;
        Width = plane.Width;
        Height = plane.Height;
        A = plane.A;
        B = plane.B;
        C = plane.C;
        Direction = plane.ParallelDirection;
        Background = Vector(scene.ColourOf(-1));
        Sphere[] spheres = [.. kept.Select(index => scene.Spheres[index])];
        Spheres = new SphereConstants[spheres.Length];
        var depthBounds = new DepthBound[spheres.Length];
        double[] reach = new double[spheres.Length];
        var position = new Dictionary<int, int>(kept.Length);
        for (int k = 0; k < spheres.Length; k++)
        {
            Sphere sphere = spheres[k];
            (Double3 offset, double largest) = plane.SphereOffset(sphere.Center);
            double bound = FloatRounding.DiscriminantError(sphere.Radius, largest);
            Spheres[k] = new SphereConstants(offset, (float)(sphere.Radius * sphere.Radius), (float)(1 / bound), Vector(scene.ColourOf(kept[k])));
            depthBounds[k] = DepthBound.Of(bound, sphere.Radius, largest);
            reach[k] = 3e-3 * (sphere.Radius + largest);
            position[kept[k]] = k;
        }

        SphereHierarchy? hierarchy = scene.Hierarchy;
        double largestReach = reach.Length == 0 ? 0 : reach.Max();
        CheckDepthOrder = hierarchy is null ? AnyCloseAll(spheres, reach) : AnyCloseNear(scene, hierarchy, kept, reach, largestReach);
        if (CheckDepthOrder)
        {
            DepthTolerance = (float)(2 * largestReach);
        }

        if (hierarchy is not null && withHierarchy)
        {
            double largestRadius = spheres.Length == 0 ? 0 : spheres.Max(sphere => sphere.Radius);
            Hierarchy = PacketHierarchy.Create(hierarchy, plane, index => (Spheres[position[index]], depthBounds[position[index]]), largestRadius);
        }
    }

    /// <summary>True when two spheres are closer than 2 × (reach₁ + reach₂): every pair tested.</summary>
    private static bool AnyCloseAll(Sphere[] spheres, double[] reach)
    {
        for (int j = 0; j < spheres.Length; j++)
        {
            for (int k = j + 1; k < spheres.Length; k++)
            {
                if (Close(spheres[j], spheres[k], reach[j], reach[k]))
                {
                    return true;
                }
            }
        }

        return false;
    }

    /// <summary>The same answer as <see cref="AnyCloseAll"/>, each sphere tested only against those the hierarchy finds near it.</summary>
    private static bool AnyCloseNear(Scene scene, SphereHierarchy hierarchy, int[] kept, double[] reach, double largestReach)
    {
        var position = new int[scene.Spheres.Count];
        for (int k = 0; k < kept.Length; k++)
        {
            position[kept[k]] = k;
        }

        bool found = false;
        for (int j = 0; j < kept.Length && !found; j++)
        {
            Sphere sphere = scene.Spheres[kept[j]];
            double r = sphere.Radius + (2 * (reach[j] + largestReach));
            Double3 extent = new(r, r, r);
            int self = kept[j];
            double reachJ = reach[j];
            hierarchy.VisitOverlapping(sphere.Center - extent, sphere.Center + extent, other =>
            {
                if (other != self && Close(sphere, scene.Spheres[other], reachJ, reach[position[other]]))
                {
                    found = true;
                }

                return !found;
            });
        }

        return found;
    }

    private static bool Close(Sphere a, Sphere b, double reachA, double reachB) =>
        (a.Center - b.Center).Length - a.Radius - b.Radius <= 2 * (reachA + reachB);

    /// <summary>The camera's image plane, in double: the uncertain samples are traced again through it.</summary>
    public ImagePlane Plane { get; }

    public Scene Scene { get; }

    public int Width { get; }

    public int Height { get; }

    /// <summary>The lab's a (window width along u).</summary>
    public Float3 A { get; }

    /// <summary>The lab's b (window height along v).</summary>
    public Float3 B { get; }

    /// <summary>The lab's c (lower-left window corner relative to e).</summary>
    public Float3 C { get; }

    /// <summary>Orthographic: the common direction −w.</summary>
    public Float3 Direction { get; }

    public Float3 Background { get; }

    /// <summary>The spheres the kernel tests (radius 0 left out: never hit).</summary>
    public SphereConstants[] Spheres { get; }

    /// <summary>The scene's hierarchy in float for this frame, when the scene uses one and the frame was made with it; the kernel then traverses it instead of testing <see cref="Spheres"/>.</summary>
    public PacketHierarchy? Hierarchy { get; }

    /// <summary>True when two spheres are close enough that float could order their hits wrongly.</summary>
    public bool CheckDepthOrder { get; }

    /// <summary>With <see cref="CheckDepthOrder"/>: hits closer than this distance (world units) along a ray are uncertain.</summary>
    public float DepthTolerance { get; }

    /// <summary>The frame, when float with the error bounds can render it; else null and why not.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane for the frame.</param>
    /// <param name="frame">The frame constants.</param>
    /// <param name="reason">Why the frame needs the double path.</param>
    /// <param name="withHierarchy">Whether to build <see cref="Hierarchy"/>: false for a caller that traverses its own (the adaptive lattice), which spares each frame the copy.</param>
    public static bool TryCreate(Scene scene, ImagePlane plane, out PacketFrame? frame, out string? reason, bool withHierarchy = true)
    {
        frame = null;
        double pixel = Math.Min(plane.A.Length / plane.Width, plane.B.Length / plane.Height);
        var kept = new List<int>();
        for (int k = 0; k < scene.Spheres.Count; k++)
        {
            Sphere sphere = scene.Spheres[k];
            if (sphere.Radius == 0)
            {
                continue;
            }

            if (plane.Visibility(sphere.Center, sphere.Radius) != SphereVisibility.Whole)
            {
                reason = $"sphere {k} reaches past the near or far plane";
                return false;
            }

            (_, double largest) = plane.SphereOffset(sphere.Center);
            if (!(largest + sphere.Radius < 1e18))
            {
                reason = $"sphere {k} is too far away for float";
                return false;
            }

            if (!(8 * FloatRounding.MachineEpsilon * plane.OriginRoundingSize(largest) <= Resolution * pixel))
            {
                reason = $"float cannot resolve the ray origins a pixel apart near sphere {k}";
                return false;
            }

            kept.Add(k);
        }

        if (!(8 * FloatRounding.MachineEpsilon * plane.DirectionRoundingSize <= Resolution * pixel))
        {
            reason = "float cannot resolve the ray directions a pixel apart (field of view too narrow for the image size)";
            return false;
        }

        reason = null;
        frame = new PacketFrame(plane, scene, [.. kept], withHierarchy);
        return true;
    }

    private static Float3 Vector(Intensity i) => new((float)i.R, (float)i.G, (float)i.B);
}

/// <summary>One sphere's constants for the kernel.</summary>
/// <remarks>
/// Fields, not properties: a property returns its <see cref="Float3"/> as a copy, which the JIT keeps in scalar
/// registers and broadcasts from there (one more vector instruction per value per sphere); a field is read by the
/// broadcast itself.
/// </remarks>
/// <param name="offset">e − C (perspective) or e + c − C (orthographic).</param>
/// <param name="radiusSquared">r².</param>
/// <param name="inverseBound">1 / the error bound of Δ: |Δ|·this ≤ 1 is uncertain in float.</param>
/// <param name="colour">The sphere's <see cref="Scene.ColourOf"/>.</param>
internal readonly struct SphereConstants(Float3 offset, float radiusSquared, float inverseBound, Float3 colour)
{
    /// <summary>e − C (perspective) or e + c − C (orthographic).</summary>
    public readonly Float3 Offset = offset;

    /// <summary>r².</summary>
    public readonly float RadiusSquared = radiusSquared;

    /// <summary>1 / the error bound of Δ: |Δ|·this ≤ 1 is uncertain in float.</summary>
    public readonly float InverseBound = inverseBound;

    /// <summary>The sphere's <see cref="Scene.ColourOf"/>.</summary>
    public readonly Float3 Colour = colour;
}

/// <summary>Three floats: a frame constant the kernel broadcasts into lanes.</summary>
/// <param name="X">x (or red).</param>
/// <param name="Y">y (or green).</param>
/// <param name="Z">z (or blue).</param>
internal readonly record struct Float3(float X, float Y, float Z)
{
    public Float3(Double3 v) : this((float)v.X, (float)v.Y, (float)v.Z) { }

    public static implicit operator Float3(Double3 v) => new(v);
}
