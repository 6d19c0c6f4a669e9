using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>
/// Every render method gives the same bytes (and adaptive the same rays and heat map) at 1, 3 and 16 threads, on a
/// scene whose rows cost very different amounts: a field of small spheres receding to the horizon, through the
/// hierarchy. At 16 threads on a small machine most workers start late and find their ranges stolen.
/// </summary>
public class ThreadCountTests
{
    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 1.6, 4), Target = new Double3(0, 0, -6), Fov = 50, NearPlane = 0.1, FarPlane = 1000 };

    private static Scene Field()
    {
        var spheres = new List<Sphere>();
        for (int j = 0; j < 12; j++)
        {
            for (int i = 0; i < 8; i++)
            {
                spheres.Add(new Sphere(new Double3(i - 3.5, 0, -j), 0.35, (i + j) % 2 == 0 ? new Intensity(0.95, 0.95, 0.9) : new Intensity(0.15, 0.3, 0.8)));
            }
        }

        return new Scene(spheres, new Intensity(0.05, 0.05, 0.08), Intensity.White);
    }

    public static TheoryData<string> Methods => ["jittered", "adaptive", "guard", "min-depth", "quincunx", "exact"];

    private static RenderMethod Method(string name) => name switch
    {
        "jittered" => RenderMethod.Sampled(new JitteredSampler(4, 7)),
        "adaptive" => RenderMethod.Adaptive(new AdaptiveSampler()),
        "guard" => RenderMethod.Adaptive(new AdaptiveSampler(guard: true)),
        "min-depth" => RenderMethod.Adaptive(new AdaptiveSampler(1, 3, 0.1)),
        "quincunx" => RenderMethod.Adaptive(new AdaptiveSampler(quincunx: true)),
        _ => RenderMethod.Exact,
    };

    [Theory]
    [MemberData(nameof(Methods))]
    public void EveryMethodGivesTheSameBytesRaysAndHeatMapAtEveryThreadCount(string name)
    {
        const int W = 160, H = 120;
        Scene scene = Field();
        Assert.True(scene.UsesHierarchy);
        bool heat = name != "exact";
        (byte[] Bytes, long Rays, long Retraced, float[]? Heat) Render(int threads)
        {
            var image = new Image(W, H);
            float[]? rays = heat ? new float[W * H] : null;
            RenderStatistics stats = new Renderer { MaxDegreeOfParallelism = threads }.Render(scene, Camera, Method(name), image, rays);
            return (image.PixelBytes.ToArray(), stats.PrimaryRays, stats.RetracedSamples, rays);
        }

        var one = Render(1);
        Assert.Contains(one.Bytes, b => b > 100);
        foreach (int threads in new[] { 3, 16 })
        {
            var many = Render(threads);
            Assert.Equal(one.Bytes, many.Bytes);
            Assert.Equal((one.Rays, one.Retraced), (many.Rays, many.Retraced));
            Assert.Equal(one.Heat, many.Heat);
        }
    }
}
