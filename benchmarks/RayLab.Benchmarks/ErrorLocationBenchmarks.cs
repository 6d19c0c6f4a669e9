using BenchmarkDotNet.Attributes;
using RayLab.Metrics;

namespace RayLab.Benchmarks;

/// <summary>
/// Where in the picture the error lies, per picture of <c>raylab compare</c> at 1920×1080 on 2 threads: the low-pass
/// errors (<see cref="ErrorLocation.LowPassRmse(Image, Image, double, int)"/>, σ = 1 and 2 px) and the error spectrum
/// (<see cref="ErrorLocation.Spectrum(Image, Image, int)"/>), each from its own error planes, on the
/// <see cref="BenchPair"/>.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 15)]
public class ErrorLocationBenchmarks
{
    private Image _reference = null!;
    private Image _test = null!;

    [GlobalSetup]
    public void Setup()
    {
        _reference = BenchPair.Reference();
        _test = BenchPair.Test();
    }

    /// <summary>The low-pass error at σ = 1 px (its planes included).</summary>
    [Benchmark]
    public double LowPassSigma1() => ErrorLocation.LowPassRmse(_test, _reference, 1, 2);

    /// <summary>The low-pass error at σ = 2 px (its planes included).</summary>
    [Benchmark]
    public double LowPassSigma2() => ErrorLocation.LowPassRmse(_test, _reference, 2, 2);

    /// <summary>The error spectrum (its planes included).</summary>
    [Benchmark]
    public double Spectrum() => ErrorLocation.Spectrum(_test, _reference, 2).LowFrequencyShare;
}
