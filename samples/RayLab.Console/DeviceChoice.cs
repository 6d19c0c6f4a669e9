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
    /// <summary>The device names the console accepts.</summary>
    public static IReadOnlyList<string> Names { get; } = ["cpu", "gpu", "auto"];

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
            case "gpu":
                throw new UsageException(NativeHasNoGpu);
            default:
                return RenderDevice.Cpu;
#endif
        }
    }
}
