using RayLab.Sampling;

namespace RayLab.Tests.Rendering.Adaptive;

/// <summary>
/// The adaptive renderer works a row at a time in O(W) memory per thread, and a <see cref="Renderer"/> keeps
/// those buffers from one render to the next: what a render leaves in them must never reach the next one.
/// </summary>
public class AdaptiveBufferTests
{
    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15), Intensity.White);

    private static Scene ThreeSpheres() => new(
        [new Sphere(new Double3(0, 0, 0), 1.5, new Intensity(0.3, 0.6, 0.9)), new Sphere(new Double3(-1.5, 1, 1), 0.5, Intensity.White), new Sphere(new Double3(1.5, -1, -1), 0.8, new Intensity(1, 0.5, 0))],
        Intensity.Black, new Intensity(0.8, 0.8, 0.8));

    public static TheoryData<int> Threads => [1, 2];

    [Theory]
    [MemberData(nameof(Threads))]
    public void ARendererReusingItsBuffersGivesEachRenderTheBytesRaysAndHeatMapOfAFreshOne(int threads)
    {
        // One renderer draws, in this order, frames whose sizes, settings and scenes all differ.
        (Scene Scene, int W, int H, AdaptiveSampler Sampler)[] renders =
        [
            (TwoSpheres(), 96, 72, new AdaptiveSampler(0, 3, 0.05)),
            (ThreeSpheres(), 64, 50, new AdaptiveSampler(0, 2, 0.01, quincunx: true)),
            (TwoSpheres(), 120, 40, new AdaptiveSampler(1, 3, 0.05)),
            (ThreeSpheres(), 96, 72, new AdaptiveSampler(0, 3, 0.05, guard: true)),
            (TwoSpheres(), 33, 70, new AdaptiveSampler(2, 2, 0.1)),
            (TwoSpheres(), 96, 72, new AdaptiveSampler(0, 3, 0.05)),
        ];
        var kept = new Renderer { MaxDegreeOfParallelism = threads };
        foreach ((Scene scene, int w, int h, AdaptiveSampler sampler) in renders)
        {
            (byte[] bytes, RenderStatistics stats, float[] heat) = Render(kept, scene, w, h, sampler);
            (byte[] freshBytes, RenderStatistics fresh, float[] freshHeat) = Render(new Renderer { MaxDegreeOfParallelism = threads }, scene, w, h, sampler);
            Assert.Equal(freshBytes, bytes);
            Assert.Equal((fresh.PrimaryRays, fresh.RetracedSamples), (stats.PrimaryRays, stats.RetracedSamples));
            Assert.Equal(freshHeat, heat);
        }
    }

    [Theory]
    [InlineData(3)]
    [InlineData(16)]
    public void RaysAndRetracedPointsDoNotDependOnWhichThreadRendersWhichRow(int threads)
    {
        // On one thread every row's top corner line is the row above's; on more, a thread that starts a range or
        // steals one traces it again. Each line's rays and retraced points count once either way, as do edge points
        // both rows traced.
        foreach (AdaptiveSampler sampler in new[] { new AdaptiveSampler(0, 3, 0.02), new AdaptiveSampler(0, 3, 0.02, guard: true), new AdaptiveSampler(1, 3, 0.05), new AdaptiveSampler(0, 2, 0.02, quincunx: true) })
        {
            (byte[] one, RenderStatistics s1, float[] h1) = Render(new Renderer { MaxDegreeOfParallelism = 1 }, TwoSpheres(), 90, 300, sampler);
            (byte[] many, RenderStatistics sn, float[] hn) = Render(new Renderer { MaxDegreeOfParallelism = threads }, TwoSpheres(), 90, 300, sampler);
            Assert.Equal(one, many);
            Assert.Equal((s1.PrimaryRays, s1.RetracedSamples), (sn.PrimaryRays, sn.RetracedSamples));
            Assert.Equal(h1, hn);
        }
    }

    [Fact]
    public void AFrameAllocatesLessThanAnIntPerPixelOnceTheRendererHasItsBuffers()
    {
        // A tall frame: a buffer of W×H pixel corners (4 bytes each) would be 2.4 MB. On one thread the row loop starts
        // on this thread, so this thread's allocation count sees the render's set-up and the buffers the thread rents.
        const int W = 200, H = 3000;
        var renderer = new Renderer { MaxDegreeOfParallelism = 1 };
        var image = new Image(W, H);
        foreach (AdaptiveSampler sampler in new[] { new AdaptiveSampler(), new AdaptiveSampler(guard: true), new AdaptiveSampler(1, 3, 0.1), new AdaptiveSampler(quincunx: true) })
        {
            renderer.Render(TwoSpheres(), Camera, sampler, image);
            long allocated = Allocations.Of(() => renderer.Render(TwoSpheres(), Camera, sampler, image));
            TestContext.Current.TestOutputHelper?.WriteLine($"{sampler}: {allocated} bytes");
            Assert.InRange(allocated, 1, (long)W * H / 16);
        }
    }

    private static (byte[] Bytes, RenderStatistics Stats, float[] Heat) Render(Renderer renderer, Scene scene, int w, int h, AdaptiveSampler sampler)
    {
        var image = new Image(w, h);
        var heat = new float[w * h];
        RenderStatistics stats = renderer.Render(scene, Camera, sampler, image, heat);
        return (image.PixelBytes.ToArray(), stats, heat);
    }
}
