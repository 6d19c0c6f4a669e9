using System.Numerics;
using BenchmarkDotNet.Attributes;
using RayLab.Metrics;

namespace RayLab.Benchmarks;

/// <summary>
/// Why the error spectrum has a transform of its own (<c>Fourier</c>): one transform of a 1080p picture's row (1 920)
/// or column (1 080), the spectrum's 3 000 transforms a plane: a vector's lanes of them at once (<c>Vector&lt;double&gt;.Count</c>
/// transforms a call), one in its scalar form, and Math.NET Numerics' <c>Fourier.Forward</c> (no scaling), the served
/// library that takes any length.
/// </summary>
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 9)]
public class FourierBenchmarks
{
    private Fourier _fourier = null!;
    private double[] _re = null!, _im = null!, _laneRe = null!, _laneIm = null!;
    private Complex[] _input = null!, _data = null!;

    [Params(1080, 1920)]
    public int Length { get; set; } = 1920;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(Length);
        int lanes = Vector<double>.Count;
        _fourier = new Fourier(Length);
        _re = [.. Enumerable.Range(0, Length * lanes).Select(_ => random.NextDouble() - 0.5)];
        _im = [.. Enumerable.Range(0, Length * lanes).Select(_ => random.NextDouble() - 0.5)];
        _laneRe = new double[_re.Length];
        _laneIm = new double[_im.Length];
        _input = [.. Enumerable.Range(0, Length).Select(k => new Complex(_re[k], _im[k]))];
        _data = new Complex[Length];
    }

    [Benchmark(Baseline = true, Description = "RayLab, a vector's lanes of transforms")]
    public double Lanes()
    {
        _re.CopyTo(_laneRe, 0);
        _im.CopyTo(_laneIm, 0);
        _fourier.Transform(_laneRe, _laneIm);
        return _laneRe[0];
    }

    [Benchmark(Description = "RayLab, one at a time")]
    public double Scalar()
    {
        _input.CopyTo(_data, 0);
        _fourier.Transform(_data);
        return _data[0].Real;
    }

    [Benchmark(Description = "MathNet.Numerics 5.0.0")]
    public double MathNet()
    {
        _input.CopyTo(_data, 0);
        global::MathNet.Numerics.IntegralTransforms.Fourier.Forward(_data, global::MathNet.Numerics.IntegralTransforms.FourierOptions.NoScaling);
        return _data[0].Real;
    }
}
