using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// The arithmetic a sampler's point formula is written in, once, over <typeparamref name="TV"/>: one pixel's number
/// (<see cref="ScalarLane"/>, whose reals are doubles: the scalar <see cref="IPixelSampler.GetSample"/>) or one number
/// per lane (a lane type, whose reals are floats: the packet kernel). The bit operations are the same at every
/// width. Each real-valued operation names the double expression it stands for: the scalar lane evaluates that
/// expression as written, a lane type gives its float as each operation says.
/// </summary>
/// <typeparam name="TV">One pixel's value or one per lane.</typeparam>
internal interface IPointMath<TV>
    where TV : struct
{
    /// <summary>Every lane's bits set to <paramref name="bits"/>.</summary>
    static abstract TV BroadcastBits(uint bits);

    /// <summary>Lane i's bits set to <c>start + i</c> (the scalar lane: <paramref name="start"/>).</summary>
    static abstract TV SequenceBits(uint start);

    /// <summary>Bitwise exclusive or.</summary>
    static abstract TV Xor(TV a, TV b);

    /// <summary>Bitwise and.</summary>
    static abstract TV And(TV a, TV b);

    /// <summary>Bitwise or.</summary>
    static abstract TV Or(TV a, TV b);

    /// <summary>Sum of the bits as 32-bit unsigned integers (wrapping).</summary>
    static abstract TV AddBits(TV a, TV b);

    /// <summary>Product of the bits as 32-bit unsigned integers (the low 32 bits).</summary>
    static abstract TV MultiplyBits(TV a, TV b);

    /// <summary>The bits shifted right by <paramref name="count"/>, zeros shifted in.</summary>
    static abstract TV ShiftRightBits(TV bits, int count);

    /// <summary>The bits shifted left by <paramref name="count"/> (below 32), zeros shifted in.</summary>
    static abstract TV ShiftLeftBits(TV bits, int count);

    /// <summary><see cref="CounterHash.Hash"/> of the bits.</summary>
    static abstract TV Hash(TV bits);

    /// <summary><see cref="LowDiscrepancy.ReverseBits"/> of the bits.</summary>
    static abstract TV ReverseBits(TV bits);

    /// <summary><see cref="CounterHash.ToUnit"/> of the bits: the top 24 bits times 2⁻²⁴, exact at every precision.</summary>
    static abstract TV ToUnit(TV bits);

    /// <summary>The top 24 bits as a real, exactly: <see cref="ToUnit"/> before its scaling.</summary>
    static abstract TV Top24(TV bits);

    /// <summary>
    /// <c>q + top24·2⁻²⁴</c> wrapped into [0, 1) (a sum that reaches 1 loses 1), in double; a lane type rounds the
    /// double to its float.
    /// </summary>
    static abstract TV Shifted(double q, TV top24);

    /// <summary>
    /// <c>(cell + ToUnit(bits)) / n</c>, in double; a lane type gives it as one fused multiply-add in float,
    /// <c>Top24(bits)·scale + corner</c>, with <paramref name="corner"/> = (float)cell / n and
    /// <paramref name="scale"/> = 1f / n / 2²⁴.
    /// </summary>
    static abstract TV InCell(TV bits, int cell, int n, float corner, float scale);

    /// <summary>
    /// <c>(cell + ToUnit(bits)) / n</c> for each lane's own cell (its bits a whole number below 2²⁴), in double; a
    /// lane type gives the float of that double.
    /// </summary>
    static abstract TV InCellExactly(TV cell, TV bits, in CellDivisor n);

    /// <summary>
    /// <c>(cell + (sub + ToUnit(bits)) / n) / n</c>: a cell inside coarse cell <paramref name="cell"/>, each lane's
    /// <paramref name="sub"/> a whole number below 2²⁴, in double; a lane type gives the float of that double.
    /// </summary>
    static abstract TV InSubCell(int cell, TV sub, TV bits, in CellDivisor n);

    /// <summary>
    /// A point's two coordinates <c>(cell + (sub + bits·scale) / d₁) / d₂</c>, x with <paramref name="x"/>'s scale and
    /// divisors and y with <paramref name="y"/>'s, the whole 32 bits of each <c>bits</c> the jitter's hash (Kensler's
    /// <c>randfloat</c> inside a cell), each lane's cells and subs whole numbers below 2²⁴, in double; a lane type gives
    /// the float of that double. Both at once, so the lanes choose their formulas once per point.
    /// </summary>
    static abstract void InWholeCells(TV cellX, TV subX, TV bitsX, in WholeCell x, TV cellY, TV subY, TV bitsY, in WholeCell y, out TV sx, out TV sy);
}

/// <summary>
/// The scale and divisors of <see cref="IPointMath{TV}.InWholeCells"/>, and the lanes' double formulas of it, made once.
/// </summary>
internal readonly struct WholeCell
{
    /// <summary>The jitter's scale.</summary>
    public readonly double Scale;

    /// <summary>d₁.</summary>
    public readonly int Inner;

    /// <summary>d₂.</summary>
    public readonly int Outer;

    /// <summary>True when d₁ and d₂ are both powers of two: the lanes take <see cref="PowerOfTwo"/>, with no branch.</summary>
    public readonly bool IsPowerOfTwo;

    /// <summary>The formula for the lanes.</summary>
    public readonly WholeHashCellFormula Formula;

    /// <summary>The formula for the lanes when <see cref="IsPowerOfTwo"/> (else unset).</summary>
    public readonly PowerOfTwoCellFormula PowerOfTwo;

    /// <summary>The formula with jitter scale <paramref name="scale"/> and divisors d₁ = <paramref name="inner"/>, d₂ = <paramref name="outer"/>.</summary>
    /// <param name="scale">The jitter's scale.</param>
    /// <param name="inner">d₁, a whole number ≥ 1.</param>
    /// <param name="outer">d₂, a whole number ≥ 1.</param>
    public WholeCell(double scale, int inner, int outer)
    {
        Scale = scale;
        Inner = inner;
        Outer = outer;
        IsPowerOfTwo = int.IsPow2(inner) && int.IsPow2(outer);
        Formula = new WholeHashCellFormula(new CellFormula(scale, inner, outer));
        if (IsPowerOfTwo)
        {
            PowerOfTwo = new PowerOfTwoCellFormula(scale, inner, outer);
        }
    }
}

/// <summary>
/// The divisors of <see cref="IPointMath{TV}.InCellExactly"/> (n) and <see cref="IPointMath{TV}.InSubCell"/> (n and
/// n again), and what the lanes need of them, made once.
/// </summary>
/// <param name="inner">The inner divisor n, ≥ 1.</param>
/// <param name="outer">The outer divisor: 1, or n for a cell inside a cell.</param>
internal readonly struct CellDivisor(int inner, int outer)
{
    /// <summary>The inner divisor.</summary>
    public readonly int Inner = inner;

    /// <summary>The outer divisor.</summary>
    public readonly int Outer = outer;

    /// <summary>True when the inner divisor is a power of two: one float rounding of the sum, then an exact scaling, gives the float.</summary>
    public readonly bool IsPowerOfTwo = int.IsPow2(inner);

    /// <summary>1/(inner·outer) in float (exact when they are powers of two).</summary>
    public readonly float Inverse = 1f / (inner * outer);

    /// <summary>The formula in double, for the lanes when the divisors are not powers of two.</summary>
    public readonly CellFormula Formula = new(CellFormula.UnitScale, inner, outer);
}

/// <summary>One pixel's value for <see cref="IPointMath{TV}"/>: 32 bits or a double, as the formula's step needs.</summary>
/// <param name="bits">The bits.</param>
/// <param name="value">The real.</param>
internal readonly struct ScalarLane(uint bits, double value)
{
    /// <summary>The value as bits.</summary>
    public readonly uint Bits = bits;

    /// <summary>The value as a real.</summary>
    public readonly double Value = value;
}

/// <summary><see cref="IPointMath{TV}"/> on one pixel, in <c>uint</c> and <c>double</c>: the scalar samplers' points.</summary>
internal readonly struct ScalarMath : IPointMath<ScalarLane>
{
    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane BroadcastBits(uint bits) => new(bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane SequenceBits(uint start) => new(start, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane Xor(ScalarLane a, ScalarLane b) => new(a.Bits ^ b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane And(ScalarLane a, ScalarLane b) => new(a.Bits & b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane Or(ScalarLane a, ScalarLane b) => new(a.Bits | b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane AddBits(ScalarLane a, ScalarLane b) => new(a.Bits + b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane MultiplyBits(ScalarLane a, ScalarLane b) => new(a.Bits * b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane ShiftRightBits(ScalarLane bits, int count) => new(bits.Bits >> count, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane ShiftLeftBits(ScalarLane bits, int count) => new(bits.Bits << count, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane Hash(ScalarLane bits) => new(CounterHash.Hash(bits.Bits), 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane ReverseBits(ScalarLane bits) => new(LowDiscrepancy.ReverseBits(bits.Bits), 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane ToUnit(ScalarLane bits) => new(0, CounterHash.ToUnit(bits.Bits));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane Top24(ScalarLane bits) => new(0, bits.Bits >> 8);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane Shifted(double q, ScalarLane top24)
    {
        double v = q + (top24.Value * CounterHash.UnitStep);
        return new(0, v >= 1.0 ? v - 1.0 : v);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane InCell(ScalarLane bits, int cell, int n, float corner, float scale) =>
        new(0, (cell + CounterHash.ToUnit(bits.Bits)) / n);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane InCellExactly(ScalarLane cell, ScalarLane bits, in CellDivisor n) =>
        new(0, ((int)cell.Bits + CounterHash.ToUnit(bits.Bits)) / n.Inner);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static ScalarLane InSubCell(int cell, ScalarLane sub, ScalarLane bits, in CellDivisor n) =>
        new(0, (cell + (((int)sub.Bits + CounterHash.ToUnit(bits.Bits)) / n.Inner)) / n.Outer);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void InWholeCells(ScalarLane cellX, ScalarLane subX, ScalarLane bitsX, in WholeCell x, ScalarLane cellY, ScalarLane subY, ScalarLane bitsY, in WholeCell y, out ScalarLane sx, out ScalarLane sy)
    {
        sx = InWholeCell(cellX, subX, bitsX, x);
        sy = InWholeCell(cellY, subY, bitsY, y);
    }

    private static ScalarLane InWholeCell(ScalarLane cell, ScalarLane sub, ScalarLane bits, in WholeCell formula) =>
        new(0, ((int)cell.Bits + (((int)sub.Bits + (bits.Bits * formula.Scale)) / formula.Inner)) / formula.Outer);
}

/// <summary><see cref="IPointMath{TV}"/> in the lanes of <typeparamref name="TL"/>, one pixel per lane, reals in float.</summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal readonly struct LaneMath<TL> : IPointMath<TL>
    where TL : struct, ILanes<TL>
{
    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL BroadcastBits(uint bits) => TL.BroadcastBits(bits);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL SequenceBits(uint start) => TL.SequenceBits(start);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Xor(TL a, TL b) => TL.Xor(a, b);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL And(TL a, TL b) => a & b;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Or(TL a, TL b) => a | b;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL AddBits(TL a, TL b) => TL.AddBits(a, b);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL MultiplyBits(TL a, TL b) => TL.MultiplyBits(a, b);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL ShiftRightBits(TL bits, int count) => TL.ShiftRightBits(bits, count);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL ShiftLeftBits(TL bits, int count) => TL.ShiftLeftBits(bits, count);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Hash(TL bits) => TL.Hash(bits);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL ReverseBits(TL bits) => TL.ReverseBits(bits);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL ToUnit(TL bits) => TL.ToUnit(bits);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Top24(TL bits) => TL.Top24(bits);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Shifted(double q, TL top24) => TL.InDouble(new ShiftFormula(q), top24, default, default, default);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL InCell(TL bits, int cell, int n, float corner, float scale) =>
        TL.MultiplyAdd(TL.Top24(bits), TL.Broadcast(scale), TL.Broadcast(corner));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL InCellExactly(TL cell, TL bits, in CellDivisor n)
    {
        TL c = TL.BitsToFloat(cell);
        if (n.IsPowerOfTwo)
        {
            // (c + u)/N with N = 2ᵏ: c + u rounded once (u·2²⁴ is exact), then an exact scaling.
            return TL.MultiplyAdd(TL.Top24(bits), TL.Broadcast(1f / 16777216f), c) * TL.Broadcast(n.Inverse);
        }

        return TL.InDouble(n.Formula, c, TL.Top24(bits), default, default);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL InSubCell(int cell, TL sub, TL bits, in CellDivisor n)
    {
        TL s = TL.BitsToFloat(sub);
        if (n.IsPowerOfTwo)
        {
            // (cell + (sub + u)/n)/n = (cell·n + sub + u)/n² with n = 2ᵏ: one rounding of the sum, an exact scaling.
            return TL.MultiplyAdd(TL.Top24(bits), TL.Broadcast(1f / 16777216f), TL.Broadcast(cell * n.Inner) + s) * TL.Broadcast(n.Inverse);
        }

        return TL.InDouble(n.Formula, s, TL.Top24(bits), TL.Broadcast(cell), default);
    }

    /// <inheritdoc />
    /// <remarks>
    /// One test per point: where every divisor is a power of two (4, 16, 64 … samples) both formulas are inline; else
    /// one call computes both (a test and a call per coordinate keep more lanes in memory: 7 % of cmj's 16-sample
    /// render).
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void InWholeCells(TL cellX, TL subX, TL bitsX, in WholeCell x, TL cellY, TL subY, TL bitsY, in WholeCell y, out TL sx, out TL sy)
    {
        if (x.IsPowerOfTwo && y.IsPowerOfTwo)
        {
            sx = TL.InDoubleFromBits(x.PowerOfTwo, subX, bitsX, cellX);
            sy = TL.InDoubleFromBits(y.PowerOfTwo, subY, bitsY, cellY);
        }
        else
        {
            (sx, sy) = InWholeCellsDivided(cellX, subX, bitsX, x, cellY, subY, bitsY, y);
        }
    }

    /// <summary><see cref="InWholeCells"/> where a divisor is not a power of two, in a call of its own (the JIT's inlining budget).</summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static (TL X, TL Y) InWholeCellsDivided(TL cellX, TL subX, TL bitsX, in WholeCell x, TL cellY, TL subY, TL bitsY, in WholeCell y) =>
        (InWholeCell(cellX, subX, bitsX, x), InWholeCell(cellY, subY, bitsY, y));

    private static TL InWholeCell(TL cell, TL sub, TL bits, in WholeCell formula) =>
        formula.IsPowerOfTwo ? TL.InDoubleFromBits(formula.PowerOfTwo, sub, bits, cell) : TL.InDoubleFromBits(formula.Formula, sub, bits, cell);
}

/// <summary><see cref="CounterHash"/> in <see cref="IPointMath{TV}"/>: the pixel keys and sample hashes of every sampler.</summary>
internal static class PointHash
{
    /// <summary>
    /// <see cref="CounterHash.PixelKey"/> of pixels x0 … x0 + lanes − 1 of a row; <paramref name="salt"/> is
    /// <see cref="Salt"/> of the seed.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TV PixelKeys<TV, TM>(int x0, int row, uint salt)
        where TV : struct
        where TM : IPointMath<TV> =>
        TM.Hash(TM.Xor(TM.BroadcastBits(((uint)row << 16) ^ salt), TM.SequenceBits((uint)x0)));

    /// <summary><see cref="CounterHash.SampleHash"/> of sample <paramref name="index"/> under each lane's key.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TV SampleHash<TV, TM>(TV keys, int index)
        where TV : struct
        where TM : IPointMath<TV> =>
        TM.Hash(TM.Xor(keys, TM.BroadcastBits((uint)index * CounterHash.Golden)));

    /// <summary>The hashed, salted seed that <see cref="PixelKeys"/> takes.</summary>
    public static uint Salt(uint seed) => CounterHash.Hash(seed + CounterHash.Golden);
}

/// <summary>One pixel's value for <see cref="FloatLaneMath"/>: 32 bits or a float, as the formula's step needs.</summary>
/// <param name="bits">The bits.</param>
/// <param name="value">The real, in float.</param>
internal readonly struct FloatLane(uint bits, float value)
{
    /// <summary>The value as bits.</summary>
    public readonly uint Bits = bits;

    /// <summary>The value as a real.</summary>
    public readonly float Value = value;
}

/// <summary>
/// <see cref="IPointMath{TV}"/> on one pixel with the lanes' float reals, in plain scalar code: what
/// <see cref="LaneMath{TL}"/> gives one lane, for a device kernel (no SIMD there). Every real is the float that the
/// lanes give: the float of <see cref="ScalarMath"/>'s double, except <see cref="InCell"/>, which the lanes give as one
/// fused multiply-add in float; that is formed exactly in double and rounded once (the product of a 24-bit integer
/// and a float is exact in double, and so is its sum with a float corner in [0, 1) for grids up to 64 cells a side),
/// so it is the same float with or without a device's contraction of multiply and add.
/// </summary>
internal readonly struct FloatLaneMath : IPointMath<FloatLane>
{
    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane BroadcastBits(uint bits) => new(bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane SequenceBits(uint start) => new(start, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane Xor(FloatLane a, FloatLane b) => new(a.Bits ^ b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane And(FloatLane a, FloatLane b) => new(a.Bits & b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane Or(FloatLane a, FloatLane b) => new(a.Bits | b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane AddBits(FloatLane a, FloatLane b) => new(a.Bits + b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane MultiplyBits(FloatLane a, FloatLane b) => new(a.Bits * b.Bits, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane ShiftRightBits(FloatLane bits, int count) => new(bits.Bits >> count, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane ShiftLeftBits(FloatLane bits, int count) => new(bits.Bits << count, 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane Hash(FloatLane bits) => new(CounterHash.Hash(bits.Bits), 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane ReverseBits(FloatLane bits) => new(LowDiscrepancy.ReverseBits(bits.Bits), 0);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane ToUnit(FloatLane bits) => Real(ScalarMath.ToUnit(Scalar(bits)));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane Top24(FloatLane bits) => Real(ScalarMath.Top24(Scalar(bits)));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane Shifted(double q, FloatLane top24) => Real(ScalarMath.Shifted(q, new ScalarLane(0, top24.Value)));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane InCell(FloatLane bits, int cell, int n, float corner, float scale) =>
        new(0, (float)(((double)(bits.Bits >> 8) * scale) + corner));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane InCellExactly(FloatLane cell, FloatLane bits, in CellDivisor n) =>
        Real(ScalarMath.InCellExactly(Scalar(cell), Scalar(bits), n));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static FloatLane InSubCell(int cell, FloatLane sub, FloatLane bits, in CellDivisor n) =>
        Real(ScalarMath.InSubCell(cell, Scalar(sub), Scalar(bits), n));

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void InWholeCells(FloatLane cellX, FloatLane subX, FloatLane bitsX, in WholeCell x, FloatLane cellY, FloatLane subY, FloatLane bitsY, in WholeCell y, out FloatLane sx, out FloatLane sy)
    {
        ScalarMath.InWholeCells(Scalar(cellX), Scalar(subX), Scalar(bitsX), x, Scalar(cellY), Scalar(subY), Scalar(bitsY), y, out ScalarLane px, out ScalarLane py);
        sx = Real(px);
        sy = Real(py);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static ScalarLane Scalar(FloatLane lane) => new(lane.Bits, lane.Value);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static FloatLane Real(ScalarLane lane) => new(0, (float)lane.Value);
}
