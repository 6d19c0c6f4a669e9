using BenchmarkDotNet.Attributes;
using RayLab.Sampling;

namespace RayLab.Benchmarks;

/// <summary>A full 1920×1080 frame of the two-sphere scene, 16 samples per pixel, per sampler (2 threads, auto kernel).</summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 7)]
public class FrameBenchmarks
{
    private readonly Image _image = new(BenchScene.Width, BenchScene.Height);
    private readonly Camera _camera = BenchScene.Camera;
    private readonly Renderer _renderer = new() { MaxDegreeOfParallelism = 2 };
    private IPixelSampler _sampler = null!;

    [ParamsSource(nameof(Names))]
    public string Sampler { get; set; } = "jittered";

    public static IEnumerable<string> Names => Samplers.Names;

    [GlobalSetup]
    public void Setup() => _sampler = Samplers.Create(Sampler, 16, 1);

    [Benchmark]
    public long Frame() => _renderer.Render(BenchScene.Scene, _camera, _sampler, _image).PrimaryRays;
}

/// <summary>
/// The lab's adaptive sampler on the same frame at its default settings (depth 0–3, contrast 0.1), with and without
/// the quincunx and the silhouette guard: the allocation column shows nothing per pixel or per row (the renderer
/// keeps its per-thread lines from one frame to the next).
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 7)]
public class AdaptiveFrameBenchmarks
{
    private readonly Image _image = new(BenchScene.Width, BenchScene.Height);
    private readonly Camera _camera = BenchScene.Camera;
    private readonly Renderer _renderer = new() { MaxDegreeOfParallelism = 2 };

    [Params(false, true)]
    public bool Quincunx { get; set; }

    [Params(false, true)]
    public bool Guard { get; set; }

    [Benchmark]
    public long Frame() => _renderer.Render(BenchScene.Scene, _camera, new AdaptiveSampler(quincunx: Quincunx, guard: Guard), _image).PrimaryRays;
}

/// <summary>The adaptive sampler with every pixel split to depth 3 (min = max depth 3) at 800×600: 128 rays a pixel, traced in packets.</summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 7)]
public class AdaptiveDepth3Benchmarks
{
    private readonly Image _image = new(800, 600);
    private readonly Camera _camera = BenchScene.Camera;
    private readonly Renderer _renderer = new() { MaxDegreeOfParallelism = 2 };
    private readonly AdaptiveSampler _sampler = new(3, 3, 0.1);

    [Benchmark]
    public long Frame() => _renderer.Render(BenchScene.Scene, _camera, _sampler, _image).PrimaryRays;
}

/// <summary>The jittered 16-spp frame through each render loop: the scalar double path and each SIMD width.</summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 7)]
public class KernelBenchmarks
{
    private readonly Image _image = new(BenchScene.Width, BenchScene.Height);
    private readonly Camera _camera = BenchScene.Camera;
    private readonly IPixelSampler _sampler = new JitteredSampler(16, 1);
    private Renderer _renderer = null!;

    [Params(RenderKernel.Scalar, RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512)]
    public RenderKernel Kernel { get; set; }

    [GlobalSetup]
    public void Setup() => _renderer = new Renderer { MaxDegreeOfParallelism = 2, Kernel = Kernel };

    [Benchmark]
    public long Frame() => _renderer.Render(BenchScene.Scene, _camera, _sampler, _image).PrimaryRays;
}

/// <summary>How the packet kernel scales with the number of spheres (1920×1080, jittered 16 spp, 2 threads).</summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 1, iterationCount: 5)]
public class SphereCountBenchmarks
{
    private readonly Image _image = new(BenchScene.Width, BenchScene.Height);
    private readonly Camera _camera = BenchScene.Camera;
    private readonly Renderer _renderer = new() { MaxDegreeOfParallelism = 2 };
    private readonly IPixelSampler _sampler = new JitteredSampler(16, 1);
    private Scene _scene = null!;

    [Params(2, 8, 32, 128)]
    public int Spheres { get; set; }

    [GlobalSetup]
    public void Setup() => _scene = BenchScene.WithSpheres(Spheres);

    [Benchmark]
    public long Frame() => _renderer.Render(_scene, _camera, _sampler, _image).PrimaryRays;
}
