using System.Runtime.CompilerServices;
using RayLab.Geometry;
using RayLab.Simd;

namespace RayLab.Rendering.Packets;

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
        where TL : struct, ILanes<TL> =>
        NegatedNearRoot(fx, fy, fz, dx, dy, dz, dd, rdd, radiusSquared, out disc, out _);

    /// <summary>The near root, negated, Δ in <paramref name="disc"/> and √(Δ·d·d) in <paramref name="root"/>.</summary>
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
    /// <param name="root">√(Δ·d·d) per lane (NaN where the ray misses).</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL NegatedNearRoot<TL>(TL fx, TL fy, TL fz, TL dx, TL dy, TL dz, TL dd, TL rdd, TL radiusSquared, out TL disc, out TL root)
        where TL : struct, ILanes<TL>
    {
        TL half = TL.MultiplyAdd(fx, dx, TL.MultiplyAdd(fy, dy, fz * dz));   // (o − C)·d
        TL along = half * rdd;
        TL px = TL.NegatedMultiplyAdd(dx, along, fx);                       // (o − C) minus its projection on d
        TL py = TL.NegatedMultiplyAdd(dy, along, fy);
        TL pz = TL.NegatedMultiplyAdd(dz, along, fz);
        disc = radiusSquared - TL.MultiplyAdd(px, px, TL.MultiplyAdd(py, py, pz * pz));
        root = TL.Sqrt(disc * dd);
        return (half + root) * rdd;                                         // −(near root); NaN when Δ < 0
    }

    /// <summary>
    /// One sphere against a packet of rays: the step the hierarchy's leaves (<see cref="PacketHierarchy"/>) and the
    /// adaptive lattice repeat per sphere. Returns −t (NaN where the ray misses). The sphere is the new nearest hit
    /// where <c>nearest &lt; −t</c>: the caller takes its colour or index there and then keeps −t as the nearest
    /// (<see cref="TakeNearer{TL}(ref TL, TL, ref TL, TL)"/>).
    /// </summary>
    /// <remarks>
    /// <para>Besides the hit, each lane keeps the smallest |Δ| / bound (<paramref name="closest"/>: ≤ 1 means the
    /// float answer may be wrong) and, when <paramref name="checkOrder"/>, whether two hits lie so close along the
    /// ray that float may order them wrongly (<paramref name="unsure"/>). That tolerance is per lane, from the
    /// hits' own error, not one margin for the whole frame: where the lane is certain (|Δ| &gt; B, B the sphere's
    /// bound of Δ's error), the true Δ is positive and √Δ is off by at most B / √Δ_float; the rest of the root is
    /// a few roundings of |o − C| + r. So a hit's t is off by at most <c>K / √(Δ·d·d) + R / |d|</c>, with
    /// <c>K = 2B</c> (twice the bound: also the float rounding of the ray itself) and <c>R = 16 ε (|o − C| + r)</c>
    /// (<see cref="DepthBound"/>), and two hits whose t differ by less than the sum of their bounds are marked.</para>
    /// <para>Near a silhouette (Δ just above B) the bound is the frame-wide √B-sized one the point kernel's
    /// all-sphere loop uses (<see cref="PacketFrame.DepthTolerance"/>); through a sphere's middle it is hundreds of
    /// times smaller, so overlapping spheres send far fewer samples to the double retrace.</para>
    /// </remarks>
    /// <param name="fx">o − C, x, per lane.</param>
    /// <param name="fy">o − C, y.</param>
    /// <param name="fz">o − C, z.</param>
    /// <param name="dx">The direction d, x.</param>
    /// <param name="dy">d, y.</param>
    /// <param name="dz">d, z.</param>
    /// <param name="dd">d·d.</param>
    /// <param name="rdd">1 / d·d.</param>
    /// <param name="inverseLength">1 / |d|.</param>
    /// <param name="radiusSquared">The sphere's r², broadcast (by the caller, from the sphere's own memory: a float
    /// parameter here would be loaded into a scalar register and broadcast from there, one more vector instruction per
    /// sphere).</param>
    /// <param name="inverseBound">1 / the bound of Δ's error, broadcast.</param>
    /// <param name="bound">The sphere's depth error constants.</param>
    /// <param name="checkOrder">Whether hits close in depth are marked (the frame has close spheres).</param>
    /// <param name="nearest">−t of the nearest hit so far (−∞ before one); the caller updates it.</param>
    /// <param name="nearestError">The error bound of that hit's t, updated here.</param>
    /// <param name="closest">The smallest |Δ| / bound so far.</param>
    /// <param name="unsure">The lanes with two hits closer than their error bounds.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Test<TL>(TL fx, TL fy, TL fz, TL dx, TL dy, TL dz, TL dd, TL rdd, TL inverseLength, TL radiusSquared, TL inverseBound, DepthBound bound, bool checkOrder, TL nearest, ref TL nearestError, ref TL closest, ref TL unsure)
        where TL : struct, ILanes<TL>
    {
        TL negatedT = NegatedNearRoot(fx, fy, fz, dx, dy, dz, dd, rdd, radiusSquared, out TL disc, out TL root);
        closest = TL.MinAbs(closest, disc * inverseBound);
        if (checkOrder)
        {
            TL error = TL.MultiplyAdd(TL.Broadcast(bound.Silhouette), TL.Broadcast(1f) / root, TL.Broadcast(bound.Rounding) * inverseLength);
            unsure |= TL.LessThanOrEqual(TL.Abs(negatedT - nearest), error + nearestError);   // either order: a farther sphere tested later too
            nearestError = TL.SelectWhereLess(nearest, negatedT, error, nearestError);        // t < best (false for NaN)
        }

        return negatedT;
    }

    /// <summary>
    /// Where this sphere is the new nearest hit (<c>nearest &lt; −t</c>, false for NaN): <paramref name="red"/>,
    /// <paramref name="green"/> and <paramref name="blue"/> take its colour, then <paramref name="nearest"/> its −t.
    /// One comparison, blended in the way the width does best (<see cref="ILanes{TSelf}.BlendsByMaskRegister"/>).
    /// </summary>
    /// <param name="nearest">−t of the nearest hit so far.</param>
    /// <param name="negatedT">This sphere's −t (<see cref="Test{TL}"/>).</param>
    /// <param name="red">The nearest hit's red so far.</param>
    /// <param name="green">Its green.</param>
    /// <param name="blue">Its blue.</param>
    /// <param name="colour">This sphere's colour, each channel broadcast.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void TakeNearer<TL>(ref TL nearest, TL negatedT, ref TL red, ref TL green, ref TL blue, (TL R, TL G, TL B) colour)
        where TL : struct, ILanes<TL>
    {
        if (TL.BlendsByMaskRegister)
        {
            red = TL.SelectWhereLess(nearest, negatedT, colour.R, red);
            green = TL.SelectWhereLess(nearest, negatedT, colour.G, green);
            blue = TL.SelectWhereLess(nearest, negatedT, colour.B, blue);
            nearest = TL.SelectWhereLess(nearest, negatedT, negatedT, nearest);
        }
        else
        {
            TL hit = TL.LessThan(nearest, negatedT);
            red = TL.Select(hit, colour.R, red);
            green = TL.Select(hit, colour.G, green);
            blue = TL.Select(hit, colour.B, blue);
            nearest = TL.Select(hit, negatedT, nearest);
        }
    }

    /// <summary>As <see cref="TakeNearer{TL}(ref TL, TL, ref TL, ref TL, ref TL, ValueTuple{TL, TL, TL})"/> for one value: <paramref name="id"/> takes <paramref name="sphereId"/>.</summary>
    /// <param name="nearest">−t of the nearest hit so far.</param>
    /// <param name="negatedT">This sphere's −t.</param>
    /// <param name="id">The nearest hit's index so far.</param>
    /// <param name="sphereId">This sphere's index, broadcast.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void TakeNearer<TL>(ref TL nearest, TL negatedT, ref TL id, TL sphereId)
        where TL : struct, ILanes<TL>
    {
        if (TL.BlendsByMaskRegister)
        {
            id = TL.SelectWhereLess(nearest, negatedT, sphereId, id);
            nearest = TL.SelectWhereLess(nearest, negatedT, negatedT, nearest);
        }
        else
        {
            TL hit = TL.LessThan(nearest, negatedT);
            id = TL.Select(hit, sphereId, id);
            nearest = TL.Select(hit, negatedT, nearest);
        }
    }

    /// <summary>
    /// The lanes whose float answer may be wrong, as bits: the smallest |Δ| / bound over the spheres at most 1
    /// (<paramref name="closest"/>), or, where the frame checks the depth order, two hits closer than their error bounds
    /// (<paramref name="unsure"/>). The comparison's bits are read in one step (<see cref="ILanes{TSelf}.LessThanOrEqualBits"/>),
    /// and the depth-order lanes only where they can be set.
    /// </summary>
    /// <param name="closest">The smallest |Δ| / bound per lane (<see cref="Test{TL}"/>).</param>
    /// <param name="unsure">The lanes with two hits closer than their error bounds.</param>
    /// <param name="checkOrder">Whether the frame checks the depth order (else <paramref name="unsure"/> is empty).</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static uint Uncertain<TL>(TL closest, TL unsure, bool checkOrder)
        where TL : struct, ILanes<TL>
    {
        uint uncertain = TL.LessThanOrEqualBits(closest, TL.Broadcast(1f));
        return checkOrder ? uncertain | TL.MaskBits(unsure) : uncertain;
    }
}

/// <summary>
/// A sphere's constants for the per-lane depth tolerance of <see cref="LaneSphere.Test{TL}"/>: a hit's t is off
/// by at most <see cref="Silhouette"/> / √(Δ·d·d) + <see cref="Rounding"/> / |d|.
/// </summary>
/// <param name="Silhouette">2 B, B the bound of Δ's float error (world units²).</param>
/// <param name="Rounding">16 ε (|o − C| + r), the largest |o − C| over the window (world units).</param>
internal readonly record struct DepthBound(float Silhouette, float Rounding)
{
    /// <summary>The constants of a sphere of radius <paramref name="radius"/>, |o − C| ≤ <paramref name="largest"/>, Δ's error ≤ <paramref name="discBound"/>.</summary>
    /// <param name="discBound">B, the bound of Δ's error.</param>
    /// <param name="radius">The sphere's radius.</param>
    /// <param name="largest">The largest |o − C| over the window.</param>
    public static DepthBound Of(double discBound, double radius, double largest) =>
        new((float)(2 * discBound * (1 + 1e-3)), (float)(16 * FloatRounding.MachineEpsilon * (largest + radius)));
}
