using BenchmarkDotNet.Attributes;
using RayLab.Sampling;

namespace RayLab.Benchmarks;

/// <summary>
/// What one 1920×1080 frame of the benchmark scene allocates, for every renderer (2 threads, auto kernel, one
/// <see cref="Renderer"/> reused across frames as an application would): jittered 16 spp, adaptive at its defaults
/// and with the guard, the exact reference, and a pixel method of one centre ray per pixel.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 7)]
public class RendererMemoryBenchmarks
{
    private readonly Image _image = new(BenchScene.Width, BenchScene.Height);
    private readonly Camera _camera = BenchScene.Camera;
    private readonly Renderer _renderer = new() { MaxDegreeOfParallelism = 2 };
    private RenderMethod _method = null!;

    [Params("jittered-16", "adaptive", "adaptive-guard", "exact", "pixel-method")]
    public string Method { get; set; } = "jittered-16";

    [GlobalSetup]
    public void Setup() => _method = Method switch
    {
        "jittered-16" => RenderMethod.Sampled(new JitteredSampler(16, 1)),
        "adaptive" => RenderMethod.Adaptive(new AdaptiveSampler()),
        "adaptive-guard" => RenderMethod.Adaptive(new AdaptiveSampler(guard: true)),
        "exact" => RenderMethod.Exact,
        _ => RenderMethod.Custom(new CentreMethod()),
    };

    [Benchmark]
    public long Frame() => _renderer.Render(BenchScene.Scene, _camera, _method, _image).PrimaryRays;

    /// <summary>One ray through each pixel's centre: the pixel-method loop's own cost.</summary>
    private sealed class CentreMethod : IPixelMethod<int>
    {
        public string Name => "centre";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch) => pixel.Trace(0.5, 0.5);
    }
}
