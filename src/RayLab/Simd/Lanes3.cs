namespace RayLab.Simd;

/// <summary>Three lane registers: a vector (x, y, z) per lane, as the packet form of a ray's origin or direction.</summary>
/// <param name="X">x per lane.</param>
/// <param name="Y">y per lane.</param>
/// <param name="Z">z per lane.</param>
internal readonly record struct Lanes3<TL>(TL X, TL Y, TL Z)
    where TL : struct, ILanes<TL>
{
    /// <summary>Every lane set to <paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/>.</summary>
    public Lanes3(float x, float y, float z) : this(TL.Broadcast(x), TL.Broadcast(y), TL.Broadcast(z)) { }
}
