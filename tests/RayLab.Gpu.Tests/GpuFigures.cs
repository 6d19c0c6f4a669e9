using System.Diagnostics;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Gpu.Tests;

/// <summary>
/// The GPU's figures, on a machine with a CUDA GPU (tools/gpu/measure.sh runs this beside the CUDA anchor): the
/// bench scene at 1080p 16 spp, 1080p 256 spp and 2160p 256 spp, jittered, the kernel alone and the whole device
/// call (uploads, kernel, bytes back), medians of 20 after 2 warm-ups, and the first launch (compiling and loading).
/// Prints figures, with how many bytes differ from the CPU renderer's (expected 0; see docs/gpu.md on contraction); skipped without a GPU.
/// </summary>
public class GpuFigures(ITestOutputHelper output)
{
    [Fact]
    [Trait("Category", "Figures")]
    public void KernelAndWholeRenderTimes()
    {
        Assert.SkipUnless(GpuDevice.IsCudaAvailable(), "no CUDA GPU here");
        string scenePath = Environment.GetEnvironmentVariable("RAYLAB_BENCH_SCENE") ?? Path.Combine(AppContext.BaseDirectory, "scenes", "bench-1080.json");
        PreparedScene prepared = SceneFile.Load(scenePath).Prepare();
        using GpuDevice gpu = GpuDevice.Cuda();
        output.WriteLine($"device: {gpu.Name}");
        var first = Stopwatch.StartNew();
        gpu.Warm();
        output.WriteLine($"first launch (compile + load): {first.Elapsed.TotalMilliseconds:F0} ms");
        foreach ((int width, int height, int samples) in new[] { (1920, 1080, 16), (1920, 1080, 256), (3840, 2160, 256) })
        {
            var sampler = new JitteredSampler(samples, 1);
            var image = new Image(width, height);
            var renderer = new Renderer { Device = gpu };
            var kernel = new List<double>();
            var whole = new List<double>();
            for (int run = 0; run < 22; run++)
            {
                RenderStatistics stats = renderer.Render(prepared.Description.Scene, prepared.Camera, RenderMethod.Sampled(sampler), image);
                Assert.Equal(gpu.Name, stats.Device);
                if (run >= 2)
                {
                    kernel.Add(gpu.LastKernelTime.TotalMilliseconds);
                    whole.Add(stats.RenderTime.TotalMilliseconds);
                }
            }

            var cpu = new Image(width, height);
            RenderStatistics cpuStats = new Renderer().Render(prepared.Description.Scene, prepared.Camera, RenderMethod.Sampled(sampler), cpu);
            int differing = image.PixelBytes.ToArray().Zip(cpu.PixelBytes.ToArray()).Count(p => p.First != p.Second);
            output.WriteLine($"{width}x{height} {samples} spp: kernel {Median(kernel):F3} ms, whole device call {Median(whole):F3} ms (median of 20); "
                + $"CPU {cpuStats.RenderTime.TotalMilliseconds:F1} ms ({cpuStats.Kernel}, {Environment.ProcessorCount} threads); bytes differing from the CPU's: {differing}");
        }
    }

    [Fact]
    [Trait("Category", "Figures")]
    public void FieldAndAdaptiveTimes()
    {
        // The sphere field through its hierarchy (jittered 16 spp) and adaptive at max depth 3, plain and guarded, on the
        // bench scene and the field, 1080p: the kernel alone and the whole device call, medians of 5 after a warm-up,
        // the CPU's time once, and the bytes and rays per pixel that differ from the CPU renderer's.
        Assert.SkipUnless(GpuDevice.IsCudaAvailable(), "no CUDA GPU here");
        PreparedScene bench = SceneFile.Load(Environment.GetEnvironmentVariable("RAYLAB_BENCH_SCENE") ?? Path.Combine(AppContext.BaseDirectory, "scenes", "bench-1080.json")).Prepare();
        PreparedScene field = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "sphere-field.json")).Prepare();
        using GpuDevice gpu = GpuDevice.Cuda();
        gpu.Warm();
        var work = new (string Name, PreparedScene Scene, RenderMethod Method)[]
        {
            ("field jittered 16 spp", field, RenderMethod.Sampled(new JitteredSampler(16, 1))),
            ("bench adaptive d3", bench, RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.1))),
            ("bench adaptive d3 guard", bench, RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.1, guard: true))),
            ("field adaptive d3", field, RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.1))),
            ("field adaptive d3 guard", field, RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.1, guard: true))),
        };
        foreach ((string name, PreparedScene prepared, RenderMethod method) in work)
        {
            var image = new Image(1920, 1080);
            float[] rays = new float[1920 * 1080];
            var renderer = new Renderer { Device = gpu };
            var kernel = new List<double>();
            var whole = new List<double>();
            for (int run = 0; run < 6; run++)
            {
                RenderStatistics stats = renderer.Render(prepared.Description.Scene, prepared.Camera, method, image, rays);
                Assert.Equal(gpu.Name, stats.Device);
                if (run >= 1)
                {
                    kernel.Add(gpu.LastKernelTime.TotalMilliseconds);
                    whole.Add(stats.RenderTime.TotalMilliseconds);
                }
            }

            var cpu = new Image(1920, 1080);
            float[] cpuRays = new float[1920 * 1080];
            RenderStatistics cpuStats = new Renderer().Render(prepared.Description.Scene, prepared.Camera, method, cpu, cpuRays);
            int differing = image.PixelBytes.ToArray().Zip(cpu.PixelBytes.ToArray()).Count(p => p.First != p.Second);
            int raysDiffering = rays.Zip(cpuRays).Count(p => p.First != p.Second);
            output.WriteLine($"{name} 1920x1080: kernel {Median(kernel):F3} ms, whole device call {Median(whole):F3} ms (median of 5), host pixels {gpu.LastHostPixels}; "
                + $"CPU {cpuStats.RenderTime.TotalMilliseconds:F1} ms ({Environment.ProcessorCount} threads); bytes differing from the CPU's: {differing}, rays per pixel differing: {raysDiffering}");
        }
    }

    private static double Median(List<double> values)
    {
        values.Sort();
        return values[values.Count / 2];
    }
}
