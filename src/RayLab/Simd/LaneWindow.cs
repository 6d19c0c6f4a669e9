namespace RayLab.Simd;

/// <summary>
/// The image plane's window vectors a, b, c (section 3.2) and the orthographic direction −w, broadcast to
/// every lane once per packet, for <see cref="RayLab.Cameras.IProjection.GetRays{TL}"/>.
/// </summary>
/// <param name="A">The lab's a.</param>
/// <param name="B">The lab's b.</param>
/// <param name="C">The lab's c.</param>
/// <param name="Direction">−w (orthographic), else zero.</param>
internal readonly record struct LaneWindow<TL>(Lanes3<TL> A, Lanes3<TL> B, Lanes3<TL> C, Lanes3<TL> Direction)
    where TL : struct, ILanes<TL>;
