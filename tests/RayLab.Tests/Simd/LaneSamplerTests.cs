using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Tests.Simd;

/// <summary>
/// The lane samplers of cmj, multijittered, nrooks, hammersley, sobol, pmj02, pmj02bn and zsobol against the scalar samplers: every lane's
/// point must be the float of <see cref="IPixelSampler.GetSample"/>'s, bit for bit, for packets of 4, 8 and 16
/// pixels (each width runs everywhere, emulated where the hardware lacks it).
/// </summary>
public class LaneSamplerTests
{
    private static readonly uint[] Seeds = [0, 1, 0xdeadbeefu, uint.MaxValue];

    /// <summary>Squares and not, powers of two and not.</summary>
    private static readonly int[] Counts = [1, 2, 3, 5, 7, 12, 16, 17, 32, 60, 64, 100, 256];

    private static readonly int[] Squares = [1, 4, 9, 16, 25, 36, 64, 100, 256];

    /// <summary>Packets (first pixel, row): the last, partial packet of rows 37, 83 and 1921 pixels wide among them.</summary>
    private static IEnumerable<(int X0, int Row)> Packets(int lanes)
    {
        yield return (0, 0);
        yield return (37 - (37 % lanes), 5);
        yield return (83 - (83 % lanes), 60);
        yield return (1921 - (1921 % lanes), 1079);
    }

    [Fact]
    public void NRooksLanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new NRooksSampler(n, seed), CheckNRooks<Lanes128>, CheckNRooks<Lanes256>, CheckNRooks<Lanes512>);

    [Fact]
    public void CorrelatedMultiJitteredLanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new CorrelatedMultiJitteredSampler(n, seed), CheckCmj<Lanes128>, CheckCmj<Lanes256>, CheckCmj<Lanes512>);

    [Fact]
    public void MultiJitteredLanesAreTheScalarPoints() => ForEveryWidth(Squares, (n, seed) => new MultiJitteredSampler(n, seed), CheckMultiJittered<Lanes128>, CheckMultiJittered<Lanes256>, CheckMultiJittered<Lanes512>);

    [Fact]
    public void HammersleyLanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new HammersleySampler(n, seed), CheckHammersley<Lanes128>, CheckHammersley<Lanes256>, CheckHammersley<Lanes512>);

    [Fact]
    public void SobolLanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new SobolSampler(n, seed), CheckSobol<Lanes128>, CheckSobol<Lanes256>, CheckSobol<Lanes512>);

    [Fact]
    public void Pmj02LanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new Pmj02Sampler(n, seed), CheckPmj02<Lanes128>, CheckPmj02<Lanes256>, CheckPmj02<Lanes512>);

    [Fact]
    public void Pmj02BNLanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new Pmj02BNSampler(n, seed), CheckPmj02BN<Lanes128>, CheckPmj02BN<Lanes256>, CheckPmj02BN<Lanes512>);

    [Fact]
    public void ZSobolLanesAreTheScalarPoints() => ForEveryWidth(Counts, (n, seed) => new ZSobolSampler(n, seed), CheckZSobol<Lanes128>, CheckZSobol<Lanes256>, CheckZSobol<Lanes512>);

    [Fact]
    public void LargeSampleCountsAreTheScalarPointsToo()
    {
        // Permutation lengths with many rejected rounds and a sample number far past 2⁸ in the float quotient.
        foreach (int n in new[] { 1000, 4097 })
        {
            CheckCmj<Lanes256>(new CorrelatedMultiJitteredSampler(n, 3));
            CheckNRooks<Lanes128>(new NRooksSampler(n, 3));
            CheckSobol<Lanes512>(new SobolSampler(n, 3));
            CheckHammersley<Lanes256>(new HammersleySampler(n, 3));
        }

        CheckMultiJittered<Lanes256>(new MultiJitteredSampler(1024, 3));
    }

    [Theory]
    [InlineData(240)] // m = 15, n = 16: the largest tables, m not a power of two.
    [InlineData(272)] // m = 16, n = 17: one row past the largest table, the permutations walked per sample.
    [InlineData(289)] // m = n = 17.
    public void CmjAtTheEdgeOfItsPerPacketTablesIsTheScalarPoints(int count)
    {
        foreach (uint seed in Seeds)
        {
            CheckCmj<Lanes128>(new CorrelatedMultiJitteredSampler(count, seed));
            CheckCmj<Lanes256>(new CorrelatedMultiJitteredSampler(count, seed));
            CheckCmj<Lanes512>(new CorrelatedMultiJitteredSampler(count, seed));
        }
    }

    [Fact]
    public void EveryBuiltInSamplerHasALaneForm()
    {
        foreach (string name in Samplers.Names)
        {
            IPixelSampler sampler = Samplers.Create(name, 16, 1);
            Assert.True(sampler is ILaneSampled, $"{name} ({sampler.GetType().Name}) has no lane form: the packet kernel would take the buffered path.");
        }
    }

    [Fact]
    public void TheSecondSobolDimensionIsTheReversedSupersetXor()
    {
        var random = new Random(21);
        float[] bits = new float[Lanes256.Count], result = new float[Lanes256.Count];
        for (int round = 0; round < 2000; round++)
        {
            for (int lane = 0; lane < bits.Length; lane++)
            {
                bits[lane] = BitConverter.UInt32BitsToSingle(round < 8 ? (uint)(round * 8 + lane) : (uint)random.NextInt64(0, 1L << 32));
            }

            Lanes256.ReverseBits(SobolSampler.SupersetXor<Lanes256, LaneMath<Lanes256>>(Lanes256.Load(bits))).Store(result);
            for (int lane = 0; lane < bits.Length; lane++)
            {
                Assert.Equal(LowDiscrepancy.SobolDimension1(BitConverter.SingleToUInt32Bits(bits[lane])), BitConverter.SingleToUInt32Bits(result[lane]));
            }
        }
    }

    private static void ForEveryWidth<TS>(int[] counts, Func<int, uint, TS> create, params Action<TS>[] checks)
    {
        foreach (int n in counts)
        {
            foreach (uint seed in Seeds)
            {
                TS sampler = create(n, seed);
                foreach (Action<TS> check in checks)
                {
                    check(sampler);
                }
            }
        }
    }

    private static void CheckNRooks<TL>(NRooksSampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckCmj<TL>(CorrelatedMultiJitteredSampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckMultiJittered<TL>(MultiJitteredSampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckHammersley<TL>(HammersleySampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckSobol<TL>(SobolSampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckPmj02<TL>(Pmj02Sampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckPmj02BN<TL>(Pmj02BNSampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    private static void CheckZSobol<TL>(ZSobolSampler s) where TL : struct, ILanes<TL> => CheckLaneForm<TL>(s);

    /// <summary>The sampler's own lane form, as the packet kernel gets it, against its scalar points.</summary>
    private static void CheckLaneForm<TL>(IPixelSampler sampler)
        where TL : struct, ILanes<TL>
    {
        var check = new LaneFormCheck<TL>(sampler);
        Assert.True(((ILaneSampled)sampler).WithLanes<TL, LaneFormCheck<TL>, bool>(ref check));
    }

    private readonly struct LaneFormCheck<TL>(IPixelSampler sampler) : ILaneSamplerUser<TL, bool>
        where TL : struct, ILanes<TL>
    {
        public bool Run<TS>(Func<TS> create)
            where TS : struct, ILaneSampler<TL>
        {
            Check<TL, TS>(create(), sampler);
            return true;
        }
    }

    private static void Check<TL, TS>(TS lanes, IPixelSampler sampler)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
    {
        int n = TL.Count;
        float[] xs = new float[n], ys = new float[n];
        foreach ((int x0, int row) in Packets(n))
        {
            lanes.BeginPacket(x0, row);
            for (int index = 0, ready = 0; index < sampler.SamplesPerPixel; index++)
            {
                if (index == ready)
                {
                    ready = lanes.Prepare(index, sampler.SamplesPerPixel);
                    Assert.InRange(ready, index + 1, sampler.SamplesPerPixel);
                }

                lanes.Sample(index, out TL sx, out TL sy);
                sx.Store(xs);
                sy.Store(ys);
                for (int lane = 0; lane < n; lane++)
                {
                    SamplePoint p = sampler.GetSample(x0 + lane, row, index);
                    if (BitConverter.SingleToInt32Bits((float)p.X) != BitConverter.SingleToInt32Bits(xs[lane])
                        || BitConverter.SingleToInt32Bits((float)p.Y) != BitConverter.SingleToInt32Bits(ys[lane]))
                    {
                        Assert.Fail($"{sampler.Name} N={sampler.SamplesPerPixel} seed={sampler.Seed} {typeof(TL).Name}: pixel ({x0 + lane}, {row}) sample {index} is ({xs[lane]:R}, {ys[lane]:R}), scalar gives ({(float)p.X:R}, {(float)p.Y:R}).");
                    }
                }
            }
        }
    }

    /// <summary>A sampler as a student would write one: RayLab knows nothing of it, so it takes the buffered path.</summary>
    private sealed class StudentSampler(IPixelSampler inner) : IPixelSampler
    {
        public string Name => "student";

        public int SamplesPerPixel => inner.SamplesPerPixel;

        public uint Seed => inner.Seed;

        public SamplePoint GetSample(int x, int y, int index) => inner.GetSample(x, y, index);
    }

    public static TheoryData<string, int> SamplersAndCounts() => new()
    {
        { "cmj", 12 }, { "cmj", 16 }, { "multijittered", 9 }, { "nrooks", 7 }, { "hammersley", 10 }, { "sobol", 16 }, { "jittered", 4 }, { "random", 3 },
    };

    [Theory]
    [MemberData(nameof(SamplersAndCounts))]
    public void AStudentsSamplerThroughTheBufferedPathGivesTheLaneSamplersBytes(string name, int count)
    {
        var scene = new Scene(
            [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
            new Intensity(0.1, 0.1, 0.15),
            Intensity.White);
        var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };
        IPixelSampler stock = Samplers.Create(name, count, 11);
        foreach (RenderKernel kernel in new[] { RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512 })
        {
            // 83 pixels wide: the last packet is partial for every width.
            Image lanes = new(83, 61), buffered = new(83, 61);
            RenderStatistics stats = new Renderer { Kernel = kernel }.Render(scene, camera, stock, lanes);
            new Renderer { Kernel = kernel }.Render(scene, camera, new StudentSampler(stock), buffered);
            Assert.Equal(kernel, stats.Kernel);
            Assert.True(lanes.PixelBytes.SequenceEqual(buffered.PixelBytes), $"{name} × {kernel}: the lane sampler's image differs from the buffered one.");
        }
    }

    /// <summary>A student's sampler with its own batch call, which the buffered path must use (and count).</summary>
    private sealed class BatchingStudentSampler(IPixelSampler inner) : IPixelSampler
    {
        public int BatchCalls;

        public int SingleCalls;

        public string Name => "student-batch";

        public int SamplesPerPixel => inner.SamplesPerPixel;

        public uint Seed => inner.Seed;

        public SamplePoint GetSample(int x, int y, int index)
        {
            Interlocked.Increment(ref SingleCalls);
            return inner.GetSample(x, y, index);
        }

        public void GetSamples(int x, int y, Span<SamplePoint> points)
        {
            Interlocked.Increment(ref BatchCalls);
            for (int i = 0; i < points.Length; i++)
            {
                points[i] = inner.GetSample(x, y, i);
            }
        }
    }

    [Fact]
    public void TheWorkedExamplesSamplerRendersTheSameBytesOnItsLaneFormAsOnTheBufferedPath()
    {
        // docs/architecture.md, "Adding a sampler": one file, and the packet kernel takes its lane form. With N = 16
        // the lanes' float is the scalar double exactly, so the two paths give the same bytes.
        var scene = new Scene([new Sphere(new Double3(0, 0, 0), 1, new Intensity(0.9, 0.2, 0.2))], new Intensity(0.1, 0.1, 0.15), Intensity.White);
        var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };
        var diagonal = new RayLab.Tests.Sampling.DiagonalSampler(16, 5);
        Image lanes = new(83, 61), buffered = new(83, 61);
        Assert.Equal(RenderKernel.Vector128, new Renderer { Kernel = RenderKernel.Vector128 }.Render(scene, camera, diagonal, lanes).Kernel);
        new Renderer { Kernel = RenderKernel.Vector128 }.Render(scene, camera, new StudentSampler(diagonal), buffered);
        Assert.True(lanes.PixelBytes.SequenceEqual(buffered.PixelBytes), "The worked example's lane form differs from its scalar points.");
    }

    [Fact]
    public void TheBufferedPathAsksForAPixelsSamplesInOneCall()
    {
        var scene = new Scene([new Sphere(new Double3(0, 0, 0), 1, new Intensity(0.9, 0.2, 0.2))], new Intensity(0.1, 0.1, 0.15), Intensity.White);
        var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };
        IPixelSampler stock = Samplers.Create("cmj", 5, 2);
        var student = new BatchingStudentSampler(stock);
        Image viaBatch = new(37, 9), viaLanes = new(37, 9);
        new Renderer { Kernel = RenderKernel.Vector256 }.Render(scene, camera, student, viaBatch);
        new Renderer { Kernel = RenderKernel.Vector256 }.Render(scene, camera, stock, viaLanes);
        Assert.True(viaBatch.PixelBytes.SequenceEqual(viaLanes.PixelBytes));
        Assert.Equal(0, student.SingleCalls);
        Assert.True(student.BatchCalls >= 40 * 9, $"{student.BatchCalls} batch calls for 37 × 9 pixels in packets of 8");
    }
}
