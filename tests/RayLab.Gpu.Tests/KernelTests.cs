using ILGPU;
using ILGPU.Backends.EntryPoints;
using ILGPU.Backends.PTX;
using ILGPU.Runtime.Cuda;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Gpu.Tests;

/// <summary>What can be checked of the CUDA path without a GPU: the kernel's PTX, the point formulas' float, the device choice.</summary>
public class KernelTests
{
    [Fact]
    public void TheKernelCompilesToPtxWithNoCallOutsideIt()
    {
        // ILGPU's PTX backend runs without a GPU. A .NET method it has no PTX for (MathF.FusedMultiplyAdd, for one)
        // becomes an external function the CUDA driver cannot link: the kernel must have none.
        string ptx = Ptx();
        Assert.Contains(".entry", ptx, StringComparison.Ordinal);
        Assert.DoesNotContain(".extern .func", ptx, StringComparison.Ordinal);
    }

    [Fact]
    public void AnUnlinkableCallIsSeen()
    {
        // The check above can fail: a kernel calling MathF.FusedMultiplyAdd has an external function.
        Assert.Contains(".extern .func", Ptx(typeof(KernelTests).GetMethod(nameof(FusedKernel), System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Static)!), StringComparison.Ordinal);
    }

    [Fact]
    public void TheAdaptiveKernelCompilesToPtxWithNoCallOutsideIt()
    {
        // The adaptive rule (its explicit stacks in local memory, the guard's asin and square roots) has a PTX form too.
        string ptx = Ptx(typeof(AdaptiveKernel).GetMethod(nameof(AdaptiveKernel.Render)));
        Assert.Contains(".entry", ptx, StringComparison.Ordinal);
        Assert.DoesNotContain(".extern .func", ptx, StringComparison.Ordinal);
    }

    private static void FusedKernel(Index1D index, ArrayView<float> values) => values[index] = MathF.FusedMultiplyAdd(values[index], 2f, 1f);

    internal static string Ptx(System.Reflection.MethodInfo? kernel = null)
    {
        using Context context = Context.Create(builder => builder.Cuda());
        using var backend = new PTXBackend(context, new CudaCapabilityContext(CudaArchitecture.SM_80), CudaArchitecture.SM_80, CudaInstructionSet.ISA_80, null);
        EntryPointDescription entry = EntryPointDescription.FromImplicitlyGroupedKernel(kernel ?? typeof(PointKernel).GetMethod(nameof(PointKernel.Render))!);
        return ((PTXCompiledKernel)backend.Compile(entry, default)).PTXAssembly;
    }

    [Theory]
    [InlineData("jittered", 4)]
    [InlineData("jittered", 9)]
    [InlineData("jittered", 1024)]
    [InlineData("random", 6)]
    [InlineData("hammersley", 6)]
    [InlineData("hammersley", 1024)]
    public void TheDevicePointsAreTheLanesFloats(string sampler, int samples)
    {
        // FloatLaneMath is one lane of LaneMath in plain code: the same float for every point of a row of pixels.
        IPixelSampler points = Samplers.Create(sampler, samples, 11);
        PointFrame frame = GpuDevice.FrameOf(points)!.Value;
        (uint salt, int grid, float scale) = (frame.Salt, frame.GridSize, frame.JitterScale);
        int differing = 0;
        Span<float> lane = stackalloc float[2 * Lanes128.Count];
        for (int x0 = 0; x0 < 64; x0 += Lanes128.Count)
        {
            Lanes128 keys = PointHash.PixelKeys<Lanes128, LaneMath<Lanes128>>(x0, 5, salt);
            for (int i = 0; i < samples; i++)
            {
                Lanes128 lx, ly;
                if (sampler == "jittered")
                {
                    JitteredSampler.Formula.Point<Lanes128, LaneMath<Lanes128>>(keys, i, JitteredSampler.Formula.CellOf(i, grid), grid, scale, out lx, out ly);
                }
                else if (sampler == "random")
                {
                    RandomSampler.Formula.Point<Lanes128, LaneMath<Lanes128>>(keys, i, out lx, out ly);
                }
                else
                {
                    HammersleySampler.Formula.Shift<Lanes128, LaneMath<Lanes128>>(keys, out Lanes128 shiftX, out Lanes128 shiftY);
                    SamplePoint p = HammersleySampler.Formula.Unshifted(i, samples);
                    (lx, ly) = (LaneMath<Lanes128>.Shifted(p.X, shiftX), LaneMath<Lanes128>.Shifted(p.Y, shiftY));
                }

                lx.Store(lane);
                ly.Store(lane[Lanes128.Count..]);
                for (int k = 0; k < Lanes128.Count; k++)
                {
                    FloatLane key = PointHash.PixelKeys<FloatLane, FloatLaneMath>(x0 + k, 5, salt);
                    FloatLane fx, fy;
                    if (sampler == "jittered")
                    {
                        JitteredSampler.Formula.Point<FloatLane, FloatLaneMath>(key, i, JitteredSampler.Formula.CellOf(i, grid), grid, scale, out fx, out fy);
                    }
                    else if (sampler == "random")
                    {
                        RandomSampler.Formula.Point<FloatLane, FloatLaneMath>(key, i, out fx, out fy);
                    }
                    else
                    {
                        HammersleySampler.Formula.Shift<FloatLane, FloatLaneMath>(key, out FloatLane shiftX, out FloatLane shiftY);
                        SamplePoint p = HammersleySampler.Formula.Unshifted(i, samples);
                        (fx, fy) = (FloatLaneMath.Shifted(p.X, shiftX), FloatLaneMath.Shifted(p.Y, shiftY));
                    }

                    differing += fx.Value == lane[k] && fy.Value == lane[Lanes128.Count + k] ? 0 : 1;
                }
            }
        }

        Assert.Equal(0, differing);
    }

    [Fact]
    public void WithoutAGpuTheDeviceSaysSoInOneLineOrFallsBackWhenAsked()
    {
        Assert.SkipWhen(GpuDevice.IsCudaAvailable(), "a CUDA GPU is present");
        var error = Assert.Throws<GpuUnavailableException>(() => RenderDevice.Gpu());
        Assert.DoesNotContain('\n', error.Message);
        Assert.StartsWith("No CUDA GPU", error.Message, StringComparison.Ordinal);
        Assert.Same(RenderDevice.Cpu, RenderDevice.Gpu(fallBackToCpu: true));
        Assert.Same(RenderDevice.Cpu, RenderDevice.Best());
    }
}
