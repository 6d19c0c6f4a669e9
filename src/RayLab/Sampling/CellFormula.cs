using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The cell formula of the jittered family, in double as the scalar samplers write it:
/// <c>(c + ((a + j) / d₁)) / d₂</c> with the jitter <c>j = (bHi·256 + bLo) · scale</c> from a 32-bit hash split in two
/// exact floats (its top 24 bits and its low 8). With scale 2⁻³² and bLo = 0, j is <see cref="CounterHash.ToUnit"/>;
/// with Kensler's 1/(2³² + 512) it is his <c>randfloat</c>.
/// </summary>
/// <remarks>
/// A division by a power of two is a multiplication by its reciprocal, exactly (no result here is subnormal), so
/// those divisors (every count a sampler gets at 4, 16, 64, 256 spp) cost a multiply, not a divide; a divisor of 1
/// costs nothing.
/// </remarks>
internal readonly partial struct CellFormula : IDoubleFormula
{
    /// <summary>The scale that makes the jitter <see cref="CounterHash.ToUnit"/> of the hash.</summary>
    public const double UnitScale = LowDiscrepancy.TwoToMinus32;

    private readonly double _scale, _inner, _outer;
    private readonly bool _innerByMultiply, _outerByMultiply, _outerIsOne;

    /// <summary>The jitter's scale.</summary>
    public double Scale => _scale;

    /// <summary>The formula with jitter scale <paramref name="scale"/> and divisors d₁ = <paramref name="inner"/>, d₂ = <paramref name="outer"/>.</summary>
    /// <param name="scale">The jitter's scale.</param>
    /// <param name="inner">d₁, a whole number ≥ 1.</param>
    /// <param name="outer">d₂, a whole number ≥ 1.</param>
    public CellFormula(double scale, int inner, int outer)
    {
        _scale = scale;
        _innerByMultiply = int.IsPow2(inner);
        _outerByMultiply = int.IsPow2(outer);
        _outerIsOne = outer == 1;
        _inner = _innerByMultiply ? 1.0 / inner : inner;
        _outer = _outerByMultiply ? 1.0 / outer : outer;
    }

    /// <inheritdoc />
    [EveryWidth]
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> bHigh, Vector128<double> c, Vector128<double> bLow) =>
        Cell(a, ((bHigh * 256.0) + bLow) * _scale, c);

    /// <summary>The formula with the jitter <paramref name="jitter"/> already scaled.</summary>
    [EveryWidth]
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Cell(Vector128<double> a, Vector128<double> jitter, Vector128<double> c)
    {
        Vector128<double> inner = _innerByMultiply ? (a + jitter) * _inner : (a + jitter) / Vector128.Create(_inner);
        return _outerIsOne ? c + inner : _outerByMultiply ? (c + inner) * _outer : (c + inner) / Vector128.Create(_outer);
    }
}

/// <summary>
/// <see cref="CellFormula"/> for <see cref="ILanes{TSelf}.InDoubleFromBits"/>: the jitter's whole 32-bit hash comes as
/// one exact double b, and j = b · scale (the same double as (bHi·256 + bLo) · scale).
/// </summary>
/// <param name="cell">The formula.</param>
internal readonly partial struct WholeHashCellFormula(CellFormula cell) : IDoubleFormula
{
    private readonly CellFormula _cell = cell;

    /// <inheritdoc />
    [EveryWidth]
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d) => _cell.Cell(a, b * _cell.Scale, c);
}

/// <summary>
/// <see cref="WholeHashCellFormula"/> when d₁ and d₂ are both powers of two (1 included): <c>(c + (a + b·scale)·(1/d₁))·(1/d₂)</c>
/// with no branch. Multiplying by 1 and adding a c of 0 are exact, so this is the same double as
/// <see cref="CellFormula"/>'s for every such pair.
/// </summary>
internal readonly partial struct PowerOfTwoCellFormula : IDoubleFormula
{
    private readonly double _scale, _inner, _outer;

    /// <summary>The formula with jitter scale <paramref name="scale"/> and divisors d₁ = <paramref name="inner"/>, d₂ = <paramref name="outer"/>.</summary>
    /// <param name="scale">The jitter's scale.</param>
    /// <param name="inner">d₁, a power of two (the caller checks: <see cref="WholeCell.IsPowerOfTwo"/>; no throw, so a device kernel can make it).</param>
    /// <param name="outer">d₂, a power of two.</param>
    public PowerOfTwoCellFormula(double scale, int inner, int outer)
    {
        _scale = scale;
        _inner = 1.0 / inner;
        _outer = 1.0 / outer;
    }

    /// <inheritdoc />
    [EveryWidth]
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d) =>
        (c + ((a + (b * _scale)) * _inner)) * _outer;
}
