#if RAYLAB_GPU
using RayLab.Gpu;
#endif
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// <c>--device</c>: where point-sampled renders run. The JIT build (the .NET tool, <c>dotnet run</c>) carries
/// <c>RayLab.Gpu</c>; the native (AOT) build cannot host ILGPU, which compiles its kernels at run time, so it is built
/// without it and says so.
/// </summary>
internal static class DeviceChoice
{
    /// <summary>The device names the console lists.</summary>
    public static IReadOnlyList<string> Names { get; } = ["cpu", "gpu", "auto"];

    /// <summary>
    /// A name the console accepts without listing it: ILGPU's CPU accelerator, the device kernels' own code on the CPU
    /// (slow; for checking the device path's bytes and reports where no GPU is).
    /// </summary>
    public const string CpuAccelerator = "ilgpu-cpu";

#if RAYLAB_GPU
    private static readonly Lazy<GpuDevice> Accelerator = new(GpuDevice.CpuAccelerator);
#endif

    /// <summary>Checks <c>--device</c>'s value: one of <see cref="Names"/>, <see cref="CpuAccelerator"/> or null.</summary>
    /// <param name="name">The option's value.</param>
    /// <exception cref="UsageException">Any other value.</exception>
    public static void Check(string? name)
    {
        if (name != CpuAccelerator)
        {
            RenderJob.CheckChoice(name, "--device", "device", Names);
        }
    }

    /// <summary>
    /// Compiles and loads <paramref name="device"/>'s kernels now (its first launch's cost) and returns how long that
    /// took; null for the CPU, whose renders need no such step.
    /// </summary>
    /// <param name="device">The device.</param>
    /// <returns>The first launch's time, or null.</returns>
    public static TimeSpan? FirstLaunch(RenderDevice device)
    {
#if RAYLAB_GPU
        if (device is GpuDevice gpu)
        {
            long start = System.Diagnostics.Stopwatch.GetTimestamp();
            gpu.Warm();
            return System.Diagnostics.Stopwatch.GetElapsedTime(start);
        }
#endif
        return null;
    }

    /// <summary>What the native build says for <c>--device gpu</c>.</summary>
    public const string NativeHasNoGpu =
        "--device gpu: the native raylab cannot host the GPU device (ILGPU compiles its kernels at run time); use the JIT build: dotnet run --project samples/RayLab.Console -c Release -- render …, or the framework-dependent tool package RayLab.Tool.any";

    /// <summary>
    /// The device for <paramref name="name"/>: <c>cpu</c> (and null) the CPU; <c>gpu</c> the first CUDA GPU, or a
    /// one-line <see cref="UsageException"/> where there is none; <c>auto</c> the GPU where there is one, else the CPU.
    /// </summary>
    /// <param name="name">The option's value, checked against <see cref="Names"/>.</param>
    /// <returns>The device.</returns>
    /// <exception cref="UsageException">A GPU was asked for and cannot be opened.</exception>
    public static RenderDevice Open(string? name)
    {
        switch (name)
        {
            case null or "cpu":
                return RenderDevice.Cpu;
#if RAYLAB_GPU
            case CpuAccelerator:
                return Accelerator.Value;
            case "gpu":
                try
                {
                    return RenderDevice.Gpu();
                }
                catch (GpuUnavailableException e)
                {
                    throw new UsageException($"--device gpu: {e.Message}");
                }

            default:
                return RenderDevice.Best();
#else
            case "gpu" or CpuAccelerator:
                throw new UsageException(NativeHasNoGpu);
            default:
                return RenderDevice.Cpu;
#endif
        }
    }
}
