namespace RayLab.Simd;

/// <summary>
/// How a packet's rays are made from their window points, as a type: the camera's projection implements it
/// (<c>RayLab.Cameras.IProjection</c>), so packet code generic over it is compiled once per camera kind, with no
/// branch per ray, and never names a camera.
/// </summary>
internal interface ILaneRays
{
    /// <summary>
    /// A packet's rays through the window points (α, β) of its lanes, in float: the direction d, and the
    /// origin's offset o from the fixed point that the frame's sphere offsets are taken from
    /// (<see cref="AddOrigin{TL}"/>).
    /// </summary>
    /// <param name="window">The lab's a, b, c and the parallel direction, broadcast.</param>
    /// <param name="alpha">α per lane.</param>
    /// <param name="beta">β per lane.</param>
    /// <param name="origin">The origin's offset per lane (zero when every ray starts at the eye).</param>
    /// <param name="direction">The direction per lane.</param>
    static abstract void GetRays<TL>(in LaneWindow<TL> window, TL alpha, TL beta, out Lanes3<TL> origin, out Lanes3<TL> direction)
        where TL : struct, ILanes<TL>;

    /// <summary>
    /// One component of a sphere's offset for this packet's rays: the frame's offset plus the ray origin's
    /// (rays from the window's points), or the frame's offset alone (every ray starts at the eye).
    /// </summary>
    /// <param name="offset">The frame's offset, broadcast.</param>
    /// <param name="origin">The ray origin's offset from <see cref="GetRays{TL}"/>.</param>
    static abstract TL AddOrigin<TL>(TL offset, TL origin)
        where TL : struct, ILanes<TL>;
}
