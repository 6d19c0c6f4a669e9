using System.Globalization;
using FsCheck;
using FsCheck.Fluent;
using RayLab.Sampling;

namespace RayLab.Tests.Properties;

/// <summary>
/// A random valid scene for the property tests: spheres, colours, a camera and a sampler, with ordinary values
/// most of the time and extreme ones (tiny, huge, zero, grazing) the rest. "Valid" means every constructor and
/// <see cref="Camera.GetImagePlane"/> accept it.
/// </summary>
public sealed record RandomScene(Scene Scene, Camera Camera, IPixelSampler? Sampler, AdaptiveSampler? Adaptive, int Width, int Height)
{
    /// <summary>The smallest and largest linear value a sample can have: background and colour × ambient, per channel.</summary>
    public (Intensity Low, Intensity High) Range
    {
        get
        {
            Intensity[] values = [Scene.Background, .. Scene.Spheres.Select(s => s.Color * Scene.Ambient)];
            return (new Intensity(values.Min(v => v.R), values.Min(v => v.G), values.Min(v => v.B)),
                    new Intensity(values.Max(v => v.R), values.Max(v => v.G), values.Max(v => v.B)));
        }
    }

    /// <summary>Every generated scene, printed when a property fails.</summary>
    public override string ToString()
    {
        var s = new System.Text.StringBuilder();
        s.Append(CultureInfo.InvariantCulture, $"{Width}×{Height}, {Camera.GetType().Name} at {Camera.Position} → {Camera.Target}, up {Camera.Up}, ");
        s.Append(CultureInfo.InvariantCulture, $"near {Camera.NearPlane:R}, far {Camera.FarPlane:R}, fov {Camera.Fov:R}, window {Camera.Window?.ToString() ?? "none"}; ");
        s.Append(Sampler is { } p ? $"{p.Name} {p.SamplesPerPixel} seed {p.Seed}" : Adaptive!.ToString()).Append("; ");
        s.Append(CultureInfo.InvariantCulture, $"background {Scene.Background}, ambient {Scene.Ambient}; spheres:");
        foreach (Sphere sphere in Scene.Spheres)
        {
            s.Append(CultureInfo.InvariantCulture, $" [{sphere.Center} r {sphere.Radius:R} {sphere.Color}]");
        }

        return s.ToString();
    }

    /// <summary>Point samplers and the adaptive one.</summary>
    public static Gen<RandomScene> Any { get; } = Build(adaptive: true);

    /// <summary>Point samplers only (<c>RenderMethod.Sampled</c>).</summary>
    public static Gen<RandomScene> WithPointSampler { get; } = Build(adaptive: false);

    private static Gen<double> Coordinate { get; } = Gen.Frequency(
        (6, PropertyCheck.Between(-10, 10)),
        (1, PropertyCheck.Signed.SelectMany(m => PropertyCheck.PowerOfTwo(-60, 60), (m, s) => m * s)),
        (1, Gen.Elements(0.0, -0.0, 1e-300, 1e15, -1e15)));

    private static Gen<Double3> Point { get; } = Gen.Three(Coordinate).Select(v => new Double3(v.Item1, v.Item2, v.Item3));

    private static Gen<double> Radius { get; } = Gen.Frequency(
        (1, Gen.Constant(0.0)),
        (6, PropertyCheck.Between(0.01, 5)),
        (1, PropertyCheck.PowerOfTwo(-40, 60)));

    // Up to 2^150 per component, so colour × ambient stays finite (see the property test's remark).
    private static Gen<double> Level { get; } = Gen.Frequency(
        (6, PropertyCheck.Between(0, 1.5)),
        (1, Gen.Constant(0.0)),
        (1, PropertyCheck.PowerOfTwo(-30, 150)));

    private static Gen<Intensity> Colour { get; } = Gen.Three(Level).Select(c => new Intensity(c.Item1, c.Item2, c.Item3));

    private static Gen<Sphere> Spheres { get; } =
        from centre in Point
        from radius in Radius
        from colour in Colour
        select new Sphere(centre, radius, colour);

    private static Gen<Window?> Windows { get; } = Gen.Frequency(
        (3, Gen.Constant<Window?>(null)),
        (1, from u0 in PropertyCheck.Between(-3, 3)
            from v0 in PropertyCheck.Between(-3, 3)
            from w in PropertyCheck.PowerOfTwo(-30, 8)
            from h in PropertyCheck.PowerOfTwo(-30, 8)
            select (Window?)new Window(u0, v0, u0 + w, v0 + h)));

    private static Gen<Camera> Cameras { get; } =
        from perspective in Gen.Elements(true, false)
        from position in Point
        from gaze in Point
        from up in Gen.Frequency((3, Gen.Constant(Double3.UnitY)), (1, Point))
        from near in Gen.Frequency((2, Gen.Elements(0.0, 0.1, 1.0)), (1, PropertyCheck.Between(0, 50)))
        from depth in PropertyCheck.PowerOfTwo(-10, 40)
        from fov in Gen.Frequency((4, PropertyCheck.Between(1, 170)), (1, Gen.Elements(1e-6, 179.999)))
        from size in PropertyCheck.PowerOfTwo(-20, 20)
        from window in Windows
        select perspective
            ? (Camera)new PerspectiveCamera { Position = position, Target = position + gaze, Up = up, NearPlane = near, FarPlane = near + depth, Fov = fov, Distance = size, Window = window }
            : new OrthoCamera { Position = position, Target = position + gaze, Up = up, NearPlane = near, FarPlane = near + depth, ViewHeight = size, Window = window };

    private static Gen<IPixelSampler> PointSamplers { get; } =
        from name in Gen.Elements(Samplers.Names.ToArray())
        from n in Gen.Choose(1, 4)
        from count in Gen.Choose(1, 16)
        from seed in Gen.Choose(0, int.MaxValue)
        select Samplers.Create(name, name is "regular" or "jittered" or "multijittered" ? n * n : count, (uint)seed);

    private static Gen<AdaptiveSampler> AdaptiveSamplers { get; } =
        from max in Gen.Choose(0, 3)
        from min in Gen.Choose(0, max)
        from contrast in Gen.Frequency((1, Gen.Constant(0.0)), (3, PropertyCheck.Between(0, 0.5)))
        select new AdaptiveSampler(min, max, contrast);

    private static Gen<RandomScene> Build(bool adaptive) =>
        from spheres in Gen.Choose(0, 4).SelectMany(n => Gen.ArrayOf(Spheres, n))
        from background in Colour
        from ambient in Colour
        from camera in Cameras
        from useAdaptive in adaptive ? Gen.Frequency((2, Gen.Constant(false)), (1, Gen.Constant(true))) : Gen.Constant(false)
        from point in PointSamplers
        from adaptiveSampler in AdaptiveSamplers
        from width in Gen.Choose(1, 12)
        from height in Gen.Choose(1, 12)
        where IsValid(camera, width, height)
        select new RandomScene(new Scene(spheres, background, ambient), camera, useAdaptive ? null : point, useAdaptive ? adaptiveSampler : null, width, height);

    private static bool IsValid(Camera camera, int width, int height)
    {
        try
        {
            camera.GetImagePlane(width, height);
            return true;
        }
        catch (ArgumentException)
        {
            return false; // position = target, up parallel to the gaze, …: not a valid scene
        }
    }
}
