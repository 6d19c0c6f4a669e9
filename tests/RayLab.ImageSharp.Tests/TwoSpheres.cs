using RayLab.Sampling;

namespace RayLab.ImageSharp.Tests;

/// <summary>The lab's two spheres, both cameras, and one of every render method.</summary>
internal static class TwoSpheres
{
    public static Scene Scene { get; } = new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    public static Camera Perspective { get; } = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    public static Camera Orthographic { get; } = new OrthoCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, ViewHeight = 4.2, NearPlane = 0.1, FarPlane = 100 };

    /// <summary>Every render method: each built-in point sampler, adaptive (plain, deeper, guarded), exact, and a student's own sampler and pixel method.</summary>
    public static IEnumerable<string> MethodNames =>
        Samplers.Names.Concat(["adaptive", "adaptive-min1", "adaptive-guard", "exact", "own-sampler", "own-method"]);

    public static RenderMethod Method(string name) => name switch
    {
        "adaptive" => RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.05)),
        "adaptive-min1" => RenderMethod.Adaptive(new AdaptiveSampler(1, 3, 0.05, quincunx: true)),
        "adaptive-guard" => RenderMethod.Adaptive(new AdaptiveSampler(0, 2, 0.05, guard: true)),
        "exact" => RenderMethod.Exact,
        "own-sampler" => RenderMethod.Sampled(new Diagonal()),
        "own-method" => RenderMethod.Custom(new CentreThenCorners()),
        _ => RenderMethod.Sampled(Samplers.Create(name, 4, 7)),
    };

    /// <summary>A student's point sampler: three points on the pixel's diagonal.</summary>
    private sealed class Diagonal : IPixelSampler
    {
        public string Name => "diagonal";

        public int SamplesPerPixel => 3;

        public uint Seed => 0;

        public SamplePoint GetSample(int x, int y, int index) => new((index + 0.5) / 3, (index + 0.5) / 3);
    }

    /// <summary>A student's pixel method: the centre, and the four quarter centres where the centre differs from the pixel to the left.</summary>
    private sealed class CentreThenCorners : IPixelMethod<int>
    {
        public string Name => "centre-then-corners";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch)
        {
            Intensity centre = pixel.Trace(0.5, 0.5);
            if (pixel.PreviousInRow.Length == 0 || pixel.PreviousInRow[^1] == centre)
            {
                return centre;
            }

            return (pixel.Trace(0.25, 0.25) + pixel.Trace(0.75, 0.25) + pixel.Trace(0.25, 0.75) + pixel.Trace(0.75, 0.75)) / 4;
        }
    }
}
