using System.Runtime.Intrinsics;
using BenchmarkDotNet.Attributes;
using RayLab.Cameras;
using RayLab.Rendering;
using RayLab.Rendering.Packets;
using RayLab.Rendering.Point.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Benchmarks;

/// <summary>The ray–sphere test alone: the scalar double test on 4096 rays, and the packet kernel on one 1920-pixel row (16 spp).</summary>
[MemoryDiagnoser]
public class IntersectionBenchmarks
{
    private Ray[] _rays = null!;
    private Sphere _sphere = null!;
    private PacketFrame _frame = null!;
    private readonly Rgb24[] _row = new Rgb24[BenchScene.Width];
    private JitteredSampler _jittered = null!;

    [GlobalSetup]
    public void Setup()
    {
        ImagePlane plane = BenchScene.Camera.GetImagePlane(BenchScene.Width, BenchScene.Height);
        _sphere = BenchScene.Scene.Spheres[0];
        _rays = new Ray[4096];
        for (int i = 0; i < _rays.Length; i++)
        {
            _rays[i] = plane.GetPixelRay(600 + (i % 64), 400 + (i / 64), 0.5, 0.5);
        }

        PacketFrame.TryCreate(BenchScene.Scene, plane, out PacketFrame? frame, out _);
        _frame = frame!;
        _jittered = new JitteredSampler(16, 1);
    }

    [Benchmark(OperationsPerInvoke = 4096)]
    public int ScalarDoublePerRay()
    {
        int hits = 0;
        foreach (Ray ray in _rays)
        {
            hits += _sphere.TryIntersect(ray, 0, double.PositiveInfinity, out _) ? 1 : 0;
        }

        return hits;
    }

    [Benchmark(OperationsPerInvoke = BenchScene.Width * 16)]
    public int Packet512RowPerSample()
    {
        var row = new JitteredRow<Lanes512>(_frame, _row);
        return ((ILaneSampled)_jittered).WithLanes<Lanes512, JitteredRow<Lanes512>, int>(ref row);
    }

    [Benchmark(OperationsPerInvoke = BenchScene.Width * 16)]
    public int Packet256RowPerSample()
    {
        var row = new JitteredRow<Lanes256>(_frame, _row);
        return ((ILaneSampled)_jittered).WithLanes<Lanes256, JitteredRow<Lanes256>, int>(ref row);
    }
}

/// <summary>The packet kernel on one row with the jittered sampler's lane form.</summary>
internal readonly struct JitteredRow<TL>(PacketFrame frame, Rgb24[] row) : ILaneSamplerUser<TL, int>
    where TL : struct, ILanes<TL>
{
    public int Run<TS>(Func<TS> create)
        where TS : struct, ILaneSampler<TL>
    {
        TS sampler = create();
        return PacketKernel.RenderRow<TL, TS, PerspectiveProjection>(frame, ref sampler, 16, 540, new TargetRow(row));
    }
}

/// <summary>Each sampler's point generation alone: 16 samples for each pixel of a 1920-pixel row.</summary>
[MemoryDiagnoser]
public class SamplerBenchmarks
{
    private IPixelSampler _sampler = null!;

    [ParamsSource(nameof(Names))]
    public string Sampler { get; set; } = "jittered";

    public static IEnumerable<string> Names => Samplers.Names;

    [GlobalSetup]
    public void Setup() => _sampler = Samplers.Create(Sampler, 16, 1);

    [Benchmark(OperationsPerInvoke = BenchScene.Width * 16)]
    public double PerSample()
    {
        double sum = 0;
        for (int x = 0; x < BenchScene.Width; x++)
        {
            for (int i = 0; i < 16; i++)
            {
                SamplePoint p = _sampler.GetSample(x, 540, i);
                sum += p.X + p.Y;
            }
        }

        return sum;
    }
}

/// <summary>
/// Each sampler's points as the packet kernel gets them (8 lanes): 16 samples for each pixel of a 1920-pixel row,
/// through the sampler's own lane sampler and through the buffered path a student's sampler takes.
/// </summary>
[MemoryDiagnoser]
public class LaneSamplerBenchmarks
{
    private IPixelSampler _sampler = null!;

    [ParamsSource(nameof(Names))]
    public string Sampler { get; set; } = "jittered";

    public static IEnumerable<string> Names => Samplers.Names;

    [GlobalSetup]
    public void Setup() => _sampler = Samplers.Create(Sampler, 16, 1);

    [Benchmark(OperationsPerInvoke = BenchScene.Width * 16)]
    public float LanesPerSample()
    {
        var row = default(LaneRow);
        return _sampler is ILaneSampled sampled
            ? sampled.WithLanes<Lanes256, LaneRow, float>(ref row)
            : Row(new BufferedLanes<Lanes256>(_sampler));
    }

    [Benchmark(OperationsPerInvoke = BenchScene.Width * 16)]
    public float BufferedPerSample() => Row(new BufferedLanes<Lanes256>(_sampler));

    private static float Row<TS>(TS lanes)
        where TS : struct, ILaneSampler<Lanes256>
    {
        Lanes256 sum = default;
        for (int x0 = 0; x0 < BenchScene.Width; x0 += Lanes256.Count)
        {
            lanes.BeginPacket(x0, 540);
            for (int start = 0, end; start < 16; start = end)
            {
                end = lanes.Prepare(start, 16);
                for (int i = start; i < end; i++)
                {
                    lanes.Sample(i, out Lanes256 sx, out Lanes256 sy);
                    sum += sx + sy;
                }
            }
        }

        return sum.V.ToScalar();
    }

    /// <summary>A row of points from the lane form the sampler hands over.</summary>
    private readonly struct LaneRow : ILaneSamplerUser<Lanes256, float>
    {
        public float Run<TS>(Func<TS> create)
            where TS : struct, ILaneSampler<Lanes256> => Row(create());
    }
}
