using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Simd;

namespace RayLab.Rendering;

/// <summary>
/// Which loop renders a frame's rays, shared by every renderer that traces packets (point sampling and the
/// adaptive lattice): the one asked for, the widest packet the hardware runs natively for
/// <see cref="RenderKernel.Auto"/> (falling back to narrower ones, down to scalar where there is no SIMD), or
/// scalar when float cannot serve the frame (<see cref="PacketFrame.TryCreate"/>).
/// </summary>
internal static class KernelChoice
{
    /// <summary>The kernel that renders, and the frame's packet constants when it is a packet kernel.</summary>
    /// <param name="requested">The kernel asked for.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <param name="frame">The packet constants, or null for the scalar kernel.</param>
    /// <param name="reason">Why the frame needs the scalar kernel, when float cannot serve it.</param>
    /// <param name="withHierarchy">Whether the frame needs <see cref="PacketFrame.Hierarchy"/> (see <see cref="PacketFrame.TryCreate"/>).</param>
    public static RenderKernel Choose(RenderKernel requested, Scene scene, ImagePlane plane, out PacketFrame? frame, out string? reason, bool withHierarchy = true)
    {
        frame = null;
        reason = null;
        if (requested == RenderKernel.Scalar)
        {
            return RenderKernel.Scalar;
        }

        if (!PacketFrame.TryCreate(scene, plane, out frame, out reason, withHierarchy))
        {
            return RenderKernel.Scalar;
        }

        return requested switch
        {
            RenderKernel.Auto when Lanes512.IsHardwareAccelerated => RenderKernel.Vector512,
            RenderKernel.Auto when Lanes256.IsHardwareAccelerated => RenderKernel.Vector256,
            RenderKernel.Auto when Lanes128.IsHardwareAccelerated => RenderKernel.Vector128,
            RenderKernel.Auto => RenderKernel.Scalar,
            _ => requested,
        };
    }
}
