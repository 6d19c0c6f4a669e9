namespace RayLab.Gpu.Tests;

/// <summary>One ILGPU CPU accelerator for a test class: the kernel is compiled once.</summary>
public sealed class CpuAcceleratorFixture : IDisposable
{
    public GpuDevice Device { get; } = GpuDevice.CpuAccelerator();

    public void Dispose() => Device.Dispose();
}
