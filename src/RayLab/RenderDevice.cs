using RayLab.Cameras;
using RayLab.Rendering;
using RayLab.Sampling;

namespace RayLab;

/// <summary>
/// Where a <see cref="Renderer"/> runs its point-sampled renders: <see cref="Cpu"/> (the default, every method), or
/// a device added by another package (<c>RayLab.Gpu</c>: a CUDA GPU through ILGPU), chosen with
/// <see cref="Renderer.Device"/>. A device renders what it can and leaves the rest to the CPU renderers in the same
/// call, with the same bytes; <see cref="RenderStatistics.Device"/> says which ran.
/// </summary>
public abstract class RenderDevice
{
    /// <summary>Only RayLab's own packages add devices.</summary>
    internal RenderDevice()
    {
    }

    /// <summary>The CPU: RayLab's own renderers, every method (the default).</summary>
    public static RenderDevice Cpu { get; } = new CpuDevice();

    /// <summary>The device's name, as reports print it ("cpu", or the GPU's name).</summary>
    public abstract string Name { get; }

    /// <summary>True for <see cref="Cpu"/>.</summary>
    public bool IsCpu => this is CpuDevice;

    /// <inheritdoc />
    public override string ToString() => Name;

    /// <summary>
    /// Renders a point-sampled image on the device, or returns null when it does not take this render (a sampler or
    /// target it has no form for), and the CPU renders it.
    /// </summary>
    internal abstract RenderStatistics? TryRender(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image, RenderOptions options);

    /// <summary>
    /// Renders <paramref name="sampler"/>'s adaptive image on this device, or returns null for the CPU renderer to
    /// render it; <paramref name="raysPerPixel"/>, if given, receives each rendered pixel's rays.
    /// </summary>
    internal virtual RenderStatistics? TryRenderAdaptive(Scene scene, ImagePlane plane, AdaptiveSampler sampler, PixelTarget image, RenderOptions options, float[]? raysPerPixel) => null;

    private sealed class CpuDevice : RenderDevice
    {
        public override string Name => "cpu";

        internal override RenderStatistics? TryRender(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image, RenderOptions options) => null;
    }
}
