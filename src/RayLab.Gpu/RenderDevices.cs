namespace RayLab.Gpu;

/// <summary>
/// The GPU on <see cref="RenderDevice"/> itself: with <c>using RayLab.Gpu;</c>, <c>RenderDevice.Gpu()</c> and
/// <c>RenderDevice.Best()</c> choose the device a <see cref="Renderer"/> runs on
/// (<c>new Renderer { Device = RenderDevice.Gpu() }</c>).
/// </summary>
public static class RenderDevices
{
    private static readonly Lock Gate = new();
    private static GpuDevice? _cuda;

    /// <summary>The device members.</summary>
    extension(RenderDevice)
    {
        /// <summary>
        /// The first CUDA GPU, opened once for the process and kept. Where there is none it throws
        /// <see cref="GpuUnavailableException"/> (one line), or, with <paramref name="fallBackToCpu"/>, returns
        /// <see cref="RenderDevice.Cpu"/>.
        /// </summary>
        /// <param name="fallBackToCpu">True: the CPU where no GPU is, rather than an error.</param>
        /// <returns>The GPU, or the CPU when asked to fall back.</returns>
        /// <exception cref="GpuUnavailableException">No CUDA GPU, and no fallback was asked for.</exception>
        public static RenderDevice Gpu(bool fallBackToCpu = false)
        {
            lock (Gate)
            {
                try
                {
                    return _cuda ??= GpuDevice.Cuda();
                }
                catch (GpuUnavailableException) when (fallBackToCpu)
                {
                    return RenderDevice.Cpu;
                }
            }
        }

        /// <summary>The fastest device here: the first CUDA GPU when there is one, else the CPU.</summary>
        /// <returns>The device.</returns>
        public static RenderDevice Best() => RenderDevice.Gpu(fallBackToCpu: true);
    }
}
