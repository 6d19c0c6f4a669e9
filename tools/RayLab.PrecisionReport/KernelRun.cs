
namespace RayLab.PrecisionReport;

/// <summary>One render of a hard case by RayLab's renderer with one <see cref="Renderer.Kernel"/> setting.</summary>
/// <param name="Asked">The kernel asked for.</param>
/// <param name="Ran">The kernel that ran (scalar when the packet frame refused the scene).</param>
/// <param name="Retraced">Samples the packet kernel found within float's error bound and traced again in double.</param>
/// <param name="ScalarReason">Why the scene took the scalar path, when it did for a packet kernel; else null.</param>
/// <param name="Wrong">Pixels whose colour disagrees with the exact decision.</param>
public sealed record KernelRun(RenderKernel Asked, RenderKernel Ran, long Retraced, string? ScalarReason, int Wrong)
{
    /// <summary>The settings every case is rendered with: what users get, then each loop forced.</summary>
    public static IReadOnlyList<RenderKernel> Kernels { get; } =
        [RenderKernel.Auto, RenderKernel.Scalar, RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512];
}
