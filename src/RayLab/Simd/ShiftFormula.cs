using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayLab.Sampling;

namespace RayLab.Simd;

/// <summary>
/// A toroidal shift in double, as <see cref="HammersleySampler"/> writes it: <c>q + a·2⁻²⁴</c> wrapped into [0, 1),
/// with <c>a</c> the top 24 bits of the shift's hash.
/// </summary>
/// <param name="q">The unshifted coordinate, in [0, 1).</param>
internal readonly struct ShiftFormula(double q) : IDoubleFormula
{
    private readonly double _q = q;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d)
    {
        Vector128<double> v = Vector128.Create(_q) + (a * CounterHash.UnitStep);
        return Vector128.ConditionalSelect(Vector128.GreaterThanOrEqual(v, Vector128<double>.One), v - Vector128<double>.One, v);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector256<double> Apply(Vector256<double> a, Vector256<double> b, Vector256<double> c, Vector256<double> d)
    {
        Vector256<double> v = Vector256.Create(_q) + (a * CounterHash.UnitStep);
        return Vector256.ConditionalSelect(Vector256.GreaterThanOrEqual(v, Vector256<double>.One), v - Vector256<double>.One, v);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector512<double> Apply(Vector512<double> a, Vector512<double> b, Vector512<double> c, Vector512<double> d)
    {
        Vector512<double> v = Vector512.Create(_q) + (a * CounterHash.UnitStep);
        return Vector512.ConditionalSelect(Vector512.GreaterThanOrEqual(v, Vector512<double>.One), v - Vector512<double>.One, v);
    }
}
