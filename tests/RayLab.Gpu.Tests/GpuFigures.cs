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

    private static double Median(List<double> values)
    {
        values.Sort();
        return values[values.Count / 2];
    }
}
