using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// A toroidal shift in double, as <see cref="HammersleySampler"/> writes it: <c>q + a·2⁻²⁴</c> wrapped into [0, 1),
/// with <c>a</c> the top 24 bits of the shift's hash.
/// </summary>
/// <param name="q">The unshifted coordinate, in [0, 1).</param>
internal readonly partial struct ShiftFormula(double q) : IDoubleFormula
{
    private readonly double _q = q;

    /// <inheritdoc />
    [EveryWidth]
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d)
    {
        Vector128<double> v = Vector128.Create(_q) + (a * CounterHash.UnitStep);
        return Vector128.ConditionalSelect(Vector128.GreaterThanOrEqual(v, Vector128<double>.One), v - Vector128<double>.One, v);
    }
}
