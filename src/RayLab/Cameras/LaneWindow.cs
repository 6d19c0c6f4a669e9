using RayLab.Rendering.Point.Packets;

namespace RayLab.Cameras;

/// <summary>Three lanes registers: a vector (x, y, z) per lane.</summary>
/// <param name="X">x per lane.</param>
/// <param name="Y">y per lane.</param>
/// <param name="Z">z per lane.</param>
internal readonly record struct Lanes3<TL>(TL X, TL Y, TL Z)
    where TL : struct, ILanes<TL>
{
    /// <summary>Every lane set to <paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/>.</summary>
    public Lanes3(float x, float y, float z) : this(TL.Broadcast(x), TL.Broadcast(y), TL.Broadcast(z)) { }
}

/// <summary>
/// The image plane's window vectors a, b, c (section 3.2) and the orthographic direction −w, broadcast to
/// every lane once per packet, for <see cref="IProjection.GetRays{TL}"/>.
/// </summary>
/// <param name="A">The lab's a.</param>
/// <param name="B">The lab's b.</param>
/// <param name="C">The lab's c.</param>
/// <param name="Direction">−w (orthographic), else zero.</param>
internal readonly record struct LaneWindow<TL>(Lanes3<TL> A, Lanes3<TL> B, Lanes3<TL> C, Lanes3<TL> Direction)
    where TL : struct, ILanes<TL>;
