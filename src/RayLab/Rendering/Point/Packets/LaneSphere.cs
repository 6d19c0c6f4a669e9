using System.Runtime.CompilerServices;

namespace RayLab.Rendering.Point.Packets;

/// <summary>
/// One sphere against a packet of rays in float: the stable discriminant <c>Δ = r² − |f⊥|²</c>, <c>f⊥ = f − (f·d / d·d) d</c>
/// with <c>f = o − C</c> (Ray Tracing Gems, ch. 7), and the near root. The packet kernel and the adaptive lattice both
/// test spheres with it, so their float answers and error bounds (<see cref="PacketFrame"/>) are the same arithmetic.
/// </summary>
internal static class LaneSphere
{
    /// <summary>The near root, negated (−t; NaN where the ray misses), and Δ in <paramref name="disc"/>.</summary>
    /// <param name="fx">o − C, x, per lane.</param>
    /// <param name="fy">o − C, y.</param>
    /// <param name="fz">o − C, z.</param>
    /// <param name="dx">The direction d, x.</param>
    /// <param name="dy">d, y.</param>
    /// <param name="dz">d, z.</param>
    /// <param name="dd">d·d.</param>
    /// <param name="rdd">1 / d·d.</param>
    /// <param name="radiusSquared">r², broadcast.</param>
    /// <param name="disc">Δ per lane.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL NegatedNearRoot<TL>(TL fx, TL fy, TL fz, TL dx, TL dy, TL dz, TL dd, TL rdd, TL radiusSquared, out TL disc)
        where TL : struct, ILanes<TL>
    {
        TL half = TL.MultiplyAdd(fx, dx, TL.MultiplyAdd(fy, dy, fz * dz));   // (o − C)·d
        TL along = half * rdd;
        TL px = TL.NegatedMultiplyAdd(dx, along, fx);                       // (o − C) minus its projection on d
        TL py = TL.NegatedMultiplyAdd(dy, along, fy);
        TL pz = TL.NegatedMultiplyAdd(dz, along, fz);
        disc = radiusSquared - TL.MultiplyAdd(px, px, TL.MultiplyAdd(py, py, pz * pz));
        return (half + TL.Sqrt(disc * dd)) * rdd;                           // −(near root); NaN when Δ < 0
    }
}
