using BenchmarkDotNet.Attributes;
using RayLab.Metrics;
using RayLab.Sampling;

namespace RayLab.Benchmarks;

/// <summary>
/// LDR-FLIP (<see cref="Flip.Compute(Image, Image, FlipOptions?)"/>) on a 1920×1080 pair at the paper's 67 pixels per degree, on 1 and 2
/// threads: the two-sphere bench scene rendered jittered 16 spp (the reference) against regular 1 spp (the test).
/// Issue 30's target: ≤ 50 ms on 2 threads. FLIP's work does not depend on the pictures' content.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 15)]
public class FlipBenchmarks
{
    private Image _reference = null!;
    private Image _test = null!;
    private FlipOptions _options = null!;

    [Params(1, 2)]
    public int Threads { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _reference = PngSizes.Picture();
        _test = new Image(BenchScene.Width, BenchScene.Height);
        new Renderer().Render(BenchScene.Scene, BenchScene.Camera, new RegularSampler(1), _test);
        _options = new FlipOptions { MaxDegreeOfParallelism = Threads };
    }

    [Benchmark]
    public double Compute() => Flip.Compute(_reference, _test, _options).Mean;
}
