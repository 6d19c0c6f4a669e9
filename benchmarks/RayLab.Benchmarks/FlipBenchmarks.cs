using BenchmarkDotNet.Attributes;
using RayLab.Metrics;

namespace RayLab.Benchmarks;

/// <summary>
/// LDR-FLIP (<see cref="Flip.Compute(Image, Image, FlipOptions?)"/>) on a 1920×1080 pair at the paper's 67 pixels per degree, on 1 and 2
/// threads, on the <see cref="BenchPair"/>. The target: ≤ 50 ms on 2 threads.
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
        _reference = BenchPair.Reference();
        _test = BenchPair.Test();
        _options = new FlipOptions { MaxDegreeOfParallelism = Threads };
    }

    [Benchmark]
    public double Compute() => Flip.Compute(_reference, _test, _options).Mean;
}
