using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using RayLab.Sampling;

namespace RayLab.Simd;

/// <summary>
/// One of Kensler's permutations (<see cref="Permutation.PermutationElement"/>) per lane: the lane's pattern
/// number and the values derived from it that every element of that permutation needs, made once per packet.
/// </summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal struct LanePermutation<TL>
    where TL : struct, ILanes<TL>
{
    private TL _p, _p16, _p8, _p23, _multiplier, _rotation;

    /// <summary>Sets the lanes' pattern numbers.</summary>
    /// <param name="patterns">Each lane's pattern number p.</param>
    /// <param name="length">The permutations' common length l.</param>
    /// <param name="scratch">Room for <see cref="ILanes{TSelf}.Count"/> values.</param>
    public void Set(TL patterns, in LaneLength<TL> length, Span<uint> scratch)
    {
        _p = patterns;
        _p16 = TL.ShiftRightBits(_p, 16);
        _p8 = TL.ShiftRightBits(_p, 8);
        _p23 = TL.ShiftRightBits(_p, 23);

        // The listing multiplies by 1 | (p ≫ 27) and then by Kensler.PermuteMultiplier3; products modulo 2³² associate, so one
        // multiplier per lane does both.
        _multiplier = TL.MultiplyBits(TL.ShiftRightBits(_p, 27) | TL.BroadcastBits(1), TL.BroadcastBits(Kensler.PermuteMultiplier3));

        // The final rotation (v + p) mod l, with v < l, is v + (p mod l) less l if that reaches l: p mod l is
        // made here once per pixel, a mask when l is a power of two, else Lemire's multiply-only remainder.
        if (length.IsPowerOfTwo)
        {
            _rotation = _p & length.Last;
        }
        else
        {
            _p.Store(MemoryMarshal.Cast<uint, float>(scratch));
            for (int lane = 0; lane < scratch.Length; lane++)
            {
                scratch[lane] = length.Remainder(scratch[lane]);
            }

            _rotation = TL.Load(MemoryMarshal.Cast<uint, float>(scratch));
        }
    }

    /// <summary>
    /// Element <paramref name="i"/> of each lane's permutation, bit for bit the scalar one. With l a power of two
    /// one round always lands below l and this is inlined; otherwise it calls <see cref="Walk"/>.
    /// </summary>
    /// <param name="i">Each lane's position, 0 ≤ i &lt; l.</param>
    /// <param name="length">The lengths l (all lanes equal, l ≤ 2³⁰).</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly TL Element(TL i, in LaneLength<TL> length)
    {
        if (length.IsPowerOfTwo)
        {
            // w = l − 1: the rotation wraps with the mask.
            TL w = length.Mask;
            return TL.AddBits(Round(i, w), _rotation) & w;
        }

        return Walk(i, length);
    }

    /// <summary>
    /// <see cref="Element"/> of two permutations at once. Each round is a chain of dependent multiplies, so its
    /// latency, not its instruction count, sets the time; two independent chains side by side overlap. With both
    /// lengths powers of two (one round each) the two chains are written out here; otherwise each is an
    /// <see cref="Element"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static (TL A, TL B) Pair(in LanePermutation<TL> a, TL ia, in LaneLength<TL> la, in LanePermutation<TL> b, TL ib, in LaneLength<TL> lb)
    {
        if (la.IsPowerOfTwo && lb.IsPowerOfTwo)
        {
            TL wa = la.Mask, wb = lb.Mask;
            TL va = a.Round(ia, wa);
            TL vb = b.Round(ib, wb);
            return (TL.AddBits(va, a._rotation) & wa, TL.AddBits(vb, b._rotation) & wb);
        }

        return Apart(a, ia, la, b, ib, lb);
    }

    /// <summary><see cref="Pair"/> when a length is not a power of two: two <see cref="Element"/>s, in a call of its own (inlined, the JIT's inlining budget runs out).</summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static (TL A, TL B) Apart(in LanePermutation<TL> a, TL ia, in LaneLength<TL> la, in LanePermutation<TL> b, TL ib, in LaneLength<TL> lb) =>
        (a.Element(ia, la), b.Element(ib, lb));

    /// <summary>
    /// Kensler's cycle walking for a length that is not a power of two: a loop that runs until every lane has left
    /// the range [l, w], lanes that are done kept as they are.
    /// </summary>
    /// <remarks>A call of its own: inlined into a sampler's stage beside the power-of-two rounds it would use up the JIT's inlining budget.</remarks>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private readonly TL Walk(TL i, in LaneLength<TL> length)
    {
        TL w = length.Mask, last = length.Last;
        TL v = i;
        TL pending = TL.BroadcastBits(uint.MaxValue);
        do
        {
            TL next = Round(v, w);
            v = TL.Select(pending, next, v);
            pending = TL.LessThanBits(last, v);
        }
        while (TL.MaskBits(pending) != 0);

        TL rotated = TL.AddBits(v, _rotation);
        return TL.Select(TL.LessThanBits(last, rotated), TL.SubtractBits(rotated, length.Length), rotated);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private readonly TL Round(TL v, TL w)
    {
        v = TL.Xor(v, _p);
        v = TL.MultiplyBits(v, TL.BroadcastBits(Kensler.PermuteMultiplier1));
        v = TL.Xor(v, _p16);
        v = TL.Xor(v, TL.ShiftRightBits(v & w, 4));
        v = TL.Xor(v, _p8);
        v = TL.MultiplyBits(v, TL.BroadcastBits(Kensler.PermuteMultiplier2));
        v = TL.Xor(v, _p23);
        v = TL.Xor(v, TL.ShiftRightBits(v & w, 1));
        v = TL.MultiplyBits(v, _multiplier);
        v = TL.Xor(v, TL.ShiftRightBits(v & w, 11));
        v = TL.MultiplyBits(v, TL.BroadcastBits(Kensler.PermuteMultiplier4));
        v = TL.Xor(v, TL.ShiftRightBits(v & w, 2));
        v = TL.MultiplyBits(v, TL.BroadcastBits(Kensler.PermuteMultiplier5));
        v = TL.Xor(v, TL.ShiftRightBits(v & w, 2));
        v = TL.MultiplyBits(v, TL.BroadcastBits(Kensler.PermuteMultiplier6));
        v &= w;
        return TL.Xor(v, TL.ShiftRightBits(v, 5));
    }
}

/// <summary>A permutation length l in every lane, with l − 1 and Kensler's mask w (the next power of two ≥ l, less one).</summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal readonly struct LaneLength<TL>
    where TL : struct, ILanes<TL>
{
    private readonly uint _length;
    private readonly ulong _remainderMultiplier;

    /// <summary>Broadcasts <paramref name="length"/> (1 … 2³⁰) and the values derived from it.</summary>
    /// <param name="length">The permutation length.</param>
    public LaneLength(int length)
    {
        _length = (uint)length;
        _remainderMultiplier = unchecked((ulong.MaxValue / _length) + 1);
        IsPowerOfTwo = int.IsPow2(length);
        Length = TL.BroadcastBits((uint)length);
        Last = TL.BroadcastBits((uint)length - 1);
        Mask = TL.BroadcastBits(Permutation.Mask((uint)length));
    }

    /// <summary>True when l is a power of two (p mod l is p and (l − 1)).</summary>
    public bool IsPowerOfTwo { get; }

    /// <summary>l.</summary>
    public TL Length { get; }

    /// <summary>l − 1.</summary>
    public TL Last { get; }

    /// <summary>w.</summary>
    public TL Mask { get; }

    /// <summary>
    /// <paramref name="p"/> mod l without a division (Lemire, Kaser and Kurz, "Faster remainder by direct
    /// computation", 2019: exact for every 32-bit p and l).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public uint Remainder(uint p) => (uint)Math.BigMul(unchecked(_remainderMultiplier * p), _length, out _);
}

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
internal readonly struct CellFormula : IDoubleFormula
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
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> bHigh, Vector128<double> c, Vector128<double> bLow) =>
        Cell(a, ((bHigh * 256.0) + bLow) * _scale, c);

    /// <summary>The formula with the jitter <paramref name="jitter"/> already scaled.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Cell(Vector128<double> a, Vector128<double> jitter, Vector128<double> c)
    {
        Vector128<double> inner = _innerByMultiply ? (a + jitter) * _inner : (a + jitter) / Vector128.Create(_inner);
        return _outerIsOne ? c + inner : _outerByMultiply ? (c + inner) * _outer : (c + inner) / Vector128.Create(_outer);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector256<double> Apply(Vector256<double> a, Vector256<double> bHigh, Vector256<double> c, Vector256<double> bLow) =>
        Cell(a, ((bHigh * 256.0) + bLow) * _scale, c);

    /// <summary>The formula with the jitter <paramref name="jitter"/> already scaled.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector256<double> Cell(Vector256<double> a, Vector256<double> jitter, Vector256<double> c)
    {
        Vector256<double> inner = _innerByMultiply ? (a + jitter) * _inner : (a + jitter) / Vector256.Create(_inner);
        return _outerIsOne ? c + inner : _outerByMultiply ? (c + inner) * _outer : (c + inner) / Vector256.Create(_outer);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector512<double> Apply(Vector512<double> a, Vector512<double> bHigh, Vector512<double> c, Vector512<double> bLow) =>
        Cell(a, ((bHigh * 256.0) + bLow) * _scale, c);

    /// <summary>The formula with the jitter <paramref name="jitter"/> already scaled.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector512<double> Cell(Vector512<double> a, Vector512<double> jitter, Vector512<double> c)
    {
        Vector512<double> inner = _innerByMultiply ? (a + jitter) * _inner : (a + jitter) / Vector512.Create(_inner);
        return _outerIsOne ? c + inner : _outerByMultiply ? (c + inner) * _outer : (c + inner) / Vector512.Create(_outer);
    }
}

/// <summary>
/// <see cref="CellFormula"/> for <see cref="ILanes{TSelf}.InDoubleFromBits"/>: the jitter's whole 32-bit hash comes as
/// one exact double b, and j = b · scale (the same double as (bHi·256 + bLo) · scale).
/// </summary>
/// <param name="cell">The formula.</param>
internal readonly struct WholeHashCellFormula(CellFormula cell) : IDoubleFormula
{
    private readonly CellFormula _cell = cell;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d) => _cell.Cell(a, b * _cell.Scale, c);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector256<double> Apply(Vector256<double> a, Vector256<double> b, Vector256<double> c, Vector256<double> d) => _cell.Cell(a, b * _cell.Scale, c);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector512<double> Apply(Vector512<double> a, Vector512<double> b, Vector512<double> c, Vector512<double> d) => _cell.Cell(a, b * _cell.Scale, c);
}

/// <summary>
/// <see cref="WholeHashCellFormula"/> when d₁ and d₂ are both powers of two (1 included): <c>(c + (a + b·scale)·(1/d₁))·(1/d₂)</c>
/// with no branch. Multiplying by 1 and adding a c of 0 are exact, so this is the same double as
/// <see cref="CellFormula"/>'s for every such pair.
/// </summary>
internal readonly struct PowerOfTwoCellFormula : IDoubleFormula
{
    private readonly double _scale, _inner, _outer;

    /// <summary>The formula with jitter scale <paramref name="scale"/> and divisors d₁ = <paramref name="inner"/>, d₂ = <paramref name="outer"/>.</summary>
    /// <param name="scale">The jitter's scale.</param>
    /// <param name="inner">d₁, a power of two.</param>
    /// <param name="outer">d₂, a power of two.</param>
    public PowerOfTwoCellFormula(double scale, int inner, int outer)
    {
        if (!int.IsPow2(inner) || !int.IsPow2(outer))
        {
            throw new ArgumentException($"The divisors {inner} and {outer} must be powers of two.", nameof(inner));
        }

        _scale = scale;
        _inner = 1.0 / inner;
        _outer = 1.0 / outer;
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d) =>
        (c + ((a + (b * _scale)) * _inner)) * _outer;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector256<double> Apply(Vector256<double> a, Vector256<double> b, Vector256<double> c, Vector256<double> d) =>
        (c + ((a + (b * _scale)) * _inner)) * _outer;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Vector512<double> Apply(Vector512<double> a, Vector512<double> b, Vector512<double> c, Vector512<double> d) =>
        (c + ((a + (b * _scale)) * _inner)) * _outer;
}

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

/// <summary>
/// <see cref="NRooksSampler"/> in lanes: both of a pixel's permutations (column and row) walk in SIMD and the
/// jitter is the counter hash in SIMD. Each point is the scalar sampler's float: with a power-of-two count the cell
/// formula's double value is exact and one float rounding gives it; otherwise it runs in double.
/// </summary>
internal struct NRooksLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly uint _salt;
    private readonly LaneLength<TL> _length;
    private readonly CellFormula _cell;
    private readonly bool _exactInFloat;
    private readonly TL _inverseCount;
    private readonly uint[] _scratch = new uint[TL.Count];
    private LanePermutation<TL> _columns, _rows;
    private TL _keys;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public NRooksLanes(NRooksSampler sampler)
    {
        int count = sampler.SamplesPerPixel;
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _length = new LaneLength<TL>(count);
        _cell = new CellFormula(CellFormula.UnitScale, count, 1);
        _exactInFloat = int.IsPow2(count);
        _inverseCount = TL.Broadcast(1f / count);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row)
    {
        _keys = LaneHash.PixelKeys<TL>(x0, row, _salt);
        _columns.Set(TL.MultiplyBits(_keys, TL.BroadcastBits(NRooksSampler.ColumnSalt)), _length, _scratch);
        _rows.Set(TL.MultiplyBits(_keys, TL.BroadcastBits(NRooksSampler.RowSalt)), _length, _scratch);
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, NRooksLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => false;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        TL i = TL.BroadcastBits((uint)index);
        (a, b) = LanePermutation<TL>.Pair(_columns, i, _length, _rows, i, _length);
        c = default;
    }

    /// <inheritdoc />
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        TL column = TL.BitsToFloat(a), row = TL.BitsToFloat(b);
        TL h1 = LaneHash.SampleHash(_keys, index);
        TL h2 = TL.Hash(h1);
        if (_exactInFloat)
        {
            // (column + u)/N with N = 2ᵏ: column + u rounded once (u·2²⁴ is exact), then an exact scaling.
            TL unit = TL.Broadcast(1f / 16777216f);
            sx = TL.MultiplyAdd(TL.Top24(h1), unit, column) * _inverseCount;
            sy = TL.MultiplyAdd(TL.Top24(h2), unit, row) * _inverseCount;
        }
        else
        {
            sx = TL.InDouble(_cell, column, TL.Top24(h1), default, default);
            sy = TL.InDouble(_cell, row, TL.Top24(h2), default, default);
        }
    }
}

/// <summary>
/// <see cref="MultiJitteredSampler"/> in lanes: the n column and n row permutations of each pixel get their
/// pattern numbers once per packet and their elements walk in SIMD. Each point is the scalar sampler's float: with
/// n a power of two the formula's double value is exact and one float rounding gives it; otherwise it runs in double.
/// </summary>
internal struct MultiJitteredLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();

    private readonly uint _salt;
    private readonly int _n;
    private readonly LaneLength<TL> _length;
    private readonly CellFormula _cell;
    private readonly bool _exactInFloat;
    private readonly TL _inverseCount;
    private readonly uint[] _scratch = new uint[TL.Count];
    private readonly LanePermutation<TL>[] _columns, _rows;
    private readonly (int Column, int Row)[] _cells;
    private TL _keys;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public MultiJitteredLanes(MultiJitteredSampler sampler)
    {
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _n = sampler.GridSize;
        _length = new LaneLength<TL>(_n);
        _cell = new CellFormula(CellFormula.UnitScale, _n, _n);
        _exactInFloat = int.IsPow2(_n);
        _inverseCount = TL.Broadcast(1f / (_n * _n));
        _columns = new LanePermutation<TL>[_n];
        _rows = new LanePermutation<TL>[_n];

        // Sample i's coarse cell (i mod n, i div n), looked up rather than divided for in the hot loop.
        _cells = new (int, int)[_n * _n];
        for (int i = 0; i < _cells.Length; i++)
        {
            _cells[i] = (i % _n, i / _n);
        }
    }

    /// <inheritdoc />
    public void BeginPacket(int x0, int row)
    {
        _keys = LaneHash.PixelKeys<TL>(x0, row, _salt);
        TL columnKeys = TL.Xor(_keys, TL.BroadcastBits(MultiJitteredSampler.ColumnSalt)), rowKeys = TL.Xor(_keys, TL.BroadcastBits(MultiJitteredSampler.RowSalt));
        for (int k = 0; k < _n; k++)
        {
            _columns[k].Set(LaneHash.SampleHash(columnKeys, k), _length, _scratch);
            _rows[k].Set(LaneHash.SampleHash(rowKeys, k), _length, _scratch);
        }
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, MultiJitteredLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => false;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        (int column, int row) = _cells[index];
        (a, b) = LanePermutation<TL>.Pair(
            _columns[column], TL.BroadcastBits((uint)row), _length, _rows[row], TL.BroadcastBits((uint)column), _length);
        c = default;
    }

    /// <inheritdoc />
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        (int column, int row) = _cells[index];
        TL subColumn = TL.BitsToFloat(a), subRow = TL.BitsToFloat(b);
        TL h1 = LaneHash.SampleHash(_keys, index);
        TL h2 = TL.Hash(h1);
        if (_exactInFloat)
        {
            // (column + (sub + u)/n)/n = (column·n + sub + u)/n² with n = 2ᵏ: one rounding of the sum, an exact scaling.
            TL unit = TL.Broadcast(1f / 16777216f);
            sx = TL.MultiplyAdd(TL.Top24(h1), unit, TL.Broadcast(column * _n) + subColumn) * _inverseCount;
            sy = TL.MultiplyAdd(TL.Top24(h2), unit, TL.Broadcast(row * _n) + subRow) * _inverseCount;
        }
        else
        {
            sx = TL.InDouble(_cell, subColumn, TL.Top24(h1), TL.Broadcast(column), default);
            sy = TL.InDouble(_cell, subRow, TL.Top24(h2), TL.Broadcast(row), default);
        }
    }
}

/// <summary>
/// <see cref="CorrelatedMultiJitteredSampler"/> in lanes: Kensler's three permutations walk in SIMD, his
/// <c>randfloat</c> hash runs in SIMD, and the cell formulas run in double (the jitter is a rounded double, so
/// only double arithmetic gives the scalar sampler's floats).
/// </summary>
internal struct CorrelatedMultiJitteredLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly uint _salt;
    private readonly LaneLength<TL> _all, _columns, _rows;
    private readonly TL _inverseColumns, _columnCount;
    private readonly int _columnShift;
    private readonly WholeHashCellFormula _x, _y;
    private readonly PowerOfTwoCellFormula _xPowerOfTwo, _yPowerOfTwo;
    private readonly bool _powersOfTwo;
    private readonly uint[] _scratch = new uint[TL.Count];
    private readonly int _m, _n;
    private readonly bool _tabled, _wideColumns, _wideRows;
    private TL _columnsLow, _columnsHigh, _rowsLow, _rowsHigh;
    private LanePermutation<TL> _index, _column, _row;
    private TL _jx, _jxMultiplier, _jy, _jyMultiplier;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public CorrelatedMultiJitteredLanes(CorrelatedMultiJitteredSampler sampler)
    {
        int count = sampler.SamplesPerPixel;
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _all = new LaneLength<TL>(count);
        _columns = new LaneLength<TL>(sampler.Columns);
        _rows = new LaneLength<TL>(sampler.Rows);
        _inverseColumns = TL.Broadcast(1f / sampler.Columns);
        _columnCount = TL.BroadcastBits((uint)sampler.Columns);
        _columnShift = BitOperations.Log2((uint)sampler.Columns);
        _x = new WholeHashCellFormula(new CellFormula(Kensler.RandFloatScale, sampler.Rows, sampler.Columns));
        _y = new WholeHashCellFormula(new CellFormula(Kensler.RandFloatScale, count, 1));

        // 4, 16, 64, 256, 1024 … spp: N, m and n all powers of two, the cell formulas without a branch.
        _powersOfTwo = int.IsPow2(count) && int.IsPow2(sampler.Columns) && int.IsPow2(sampler.Rows);
        if (_powersOfTwo)
        {
            _xPowerOfTwo = new PowerOfTwoCellFormula(Kensler.RandFloatScale, sampler.Rows, sampler.Columns);
            _yPowerOfTwo = new PowerOfTwoCellFormula(Kensler.RandFloatScale, count, 1);
        }

        // The column and row permutations have only m and n elements per pixel, where a pixel has N ≈ m·n samples:
        // made once per packet, 4 bits an entry, into one 32-bit word per lane (two past 8 entries), and each
        // sample shifts its entry out (AVX2's per-lane shift): three or so instructions where a walk of Kensler's
        // hash is a chain of five multiplies.
        _m = sampler.Columns;
        _n = sampler.Rows;
        _tabled = Math.Max(_m, _n) <= MaxTable;
        _wideColumns = _m > 8;
        _wideRows = _n > 8;
    }

    /// <summary>The largest permutation kept as a packed table: 16 entries of 4 bits (m and n ≤ 16: every count below 273).</summary>
    private const int MaxTable = 16;

    /// <inheritdoc />
    public void BeginPacket(int x0, int row)
    {
        TL p = LaneHash.PixelKeys<TL>(x0, row, _salt);
        _index.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.IndexSalt)), _all, _scratch);
        _column.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.ColumnSalt)), _columns, _scratch);
        _row.Set(TL.MultiplyBits(p, TL.BroadcastBits(Kensler.RowSalt)), _rows, _scratch);
        if (_tabled)
        {
            (_columnsLow, _columnsHigh) = Tabulate(_column, _columns, _m);
            (_rowsLow, _rowsHigh) = Tabulate(_row, _rows, _n);
        }

        _jx = TL.MultiplyBits(p, TL.BroadcastBits(Kensler.JitterXSalt));
        _jxMultiplier = TL.ShiftRightBits(_jx, 18) | TL.BroadcastBits(1);
        _jy = TL.MultiplyBits(p, TL.BroadcastBits(Kensler.JitterYSalt));
        _jyMultiplier = TL.ShiftRightBits(_jy, 18) | TL.BroadcastBits(1);
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, CorrelatedMultiJitteredLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => true;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        a = _index.Element(TL.BroadcastBits((uint)index), _all);
        b = default;
        c = default;
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
        TL s = a;
        TL quotient, remainder;
        if (_columns.IsPowerOfTwo)
        {
            quotient = TL.ShiftRightBits(s, _columnShift);
            remainder = s & _columns.Last;
        }
        else
        {
            (quotient, remainder) = DivideByColumns(s);
        }

        if (_tabled)
        {
            b = Pick(_columnsLow, _columnsHigh, _wideColumns, remainder);
            c = Pick(_rowsLow, _rowsHigh, _wideRows, quotient);
        }
        else
        {
            (b, c) = LanePermutation<TL>.Pair(_column, remainder, _columns, _row, quotient, _rows);
        }
    }

    /// <summary>
    /// Entries 0 … <paramref name="length"/> − 1 (≤ 16) of each lane's permutation, 4 bits each: entry k in bits
    /// 4(k mod 8) of the low word (k &lt; 8) or the high one.
    /// </summary>
    private static (TL Low, TL High) Tabulate(in LanePermutation<TL> permutation, in LaneLength<TL> lanes, int length)
    {
        TL low = default, high = default;
        for (int k = 0; k < length; k++)
        {
            TL entry = TL.ShiftLeftBits(permutation.Element(TL.BroadcastBits((uint)k), lanes), 4 * (k & 7));
            if (k < 8)
            {
                low |= entry;
            }
            else
            {
                high |= entry;
            }
        }

        return (low, high);
    }

    /// <summary>Each lane's entry <paramref name="index"/> (0 … 15) of its packed table (<see cref="Tabulate"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL Pick(TL low, TL high, bool wide, TL index)
    {
        TL seven = TL.BroadcastBits(7);
        TL word = wide ? TL.Select(TL.LessThanBits(seven, index), high, low) : low;
        return TL.ShiftRightBitsVariable(word, TL.ShiftLeftBits(index & seven, 2)) & TL.BroadcastBits(15);
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        TL s = a;
        TL jx = RandomBits(s, _jx, _jxMultiplier);
        TL jy = RandomBits(s, _jy, _jyMultiplier);
        if (_powersOfTwo)
        {
            sx = TL.InDoubleFromBits(_xPowerOfTwo, c, jx, b);
            sy = TL.InDoubleFromBits(_yPowerOfTwo, s, jy, default);
        }
        else
        {
            (sx, sy) = InGeneral(s, jx, jy, b, c);
        }
    }

    /// <summary>The cell formulas with a divisor that is not a power of two, in a call of its own (the JIT's inlining budget).</summary>
    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private readonly (TL X, TL Y) InGeneral(TL s, TL jx, TL jy, TL column, TL row) =>
        (TL.InDoubleFromBits(_x, row, jx, column), TL.InDoubleFromBits(_y, s, jy, default));

    /// <summary>s div m and s mod m: a float quotient (s &lt; 2²⁴ is exact) truncated, then corrected by one either way.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private readonly (TL Quotient, TL Remainder) DivideByColumns(TL s)
    {
        TL quotient = TL.TruncateToBits(TL.BitsToFloat(s) * _inverseColumns);
        TL remainder = TL.SubtractBits(s, TL.MultiplyBits(quotient, _columnCount));
        TL low = TL.LessThanBits(remainder, default);
        quotient = TL.Select(low, TL.SubtractBits(quotient, TL.BroadcastBits(1)), quotient);
        remainder = TL.Select(low, TL.AddBits(remainder, _columnCount), remainder);
        TL high = TL.LessThanBits(TL.SubtractBits(_columnCount, TL.BroadcastBits(1)), remainder);
        quotient = TL.Select(high, TL.AddBits(quotient, TL.BroadcastBits(1)), quotient);
        remainder = TL.Select(high, TL.SubtractBits(remainder, _columnCount), remainder);
        return (quotient, remainder);
    }

    /// <summary>Kensler's <c>randfloat</c> hash before its scaling (<see cref="CorrelatedMultiJitteredSampler.RandFloat"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL RandomBits(TL i, TL p, TL multiplier)
    {
        i = TL.Xor(i, p);
        i = TL.Xor(i, TL.ShiftRightBits(i, 17));
        i = TL.Xor(i, TL.ShiftRightBits(i, 10));
        i = TL.MultiplyBits(i, TL.BroadcastBits(Kensler.RandFloatMultiplier1));
        i = TL.Xor(i, TL.ShiftRightBits(i, 12));
        i = TL.Xor(i, TL.ShiftRightBits(i, 21));
        i = TL.MultiplyBits(i, TL.BroadcastBits(Kensler.RandFloatMultiplier2));
        i = TL.Xor(i, TL.BroadcastBits(Kensler.RandFloatXor));
        i = TL.Xor(i, TL.ShiftRightBits(i, 17));
        return TL.MultiplyBits(i, multiplier);
    }
}

/// <summary>
/// <see cref="HammersleySampler"/> in lanes: the per-pixel shift is the counter hash in SIMD, made once per packet;
/// each sample adds it to the unshifted point in double and wraps, as the scalar sampler does.
/// </summary>
internal struct HammersleyLanes<TL> : ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{

    private readonly uint _salt;
    private readonly double[] _unshifted;
    private TL _shiftX, _shiftY;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public HammersleyLanes(HammersleySampler sampler)
    {
        _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
        _unshifted = new double[2 * sampler.SamplesPerPixel];
        for (int i = 0; i < sampler.SamplesPerPixel; i++)
        {
            SamplePoint point = sampler.Unshifted(i);
            (_unshifted[2 * i], _unshifted[(2 * i) + 1]) = (point.X, point.Y);
        }
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row)
    {
        TL h1 = TL.Hash(TL.Xor(LaneHash.PixelKeys<TL>(x0, row, _salt), TL.BroadcastBits(HammersleySampler.ShiftSalt)));
        _shiftX = TL.Top24(h1);
        _shiftY = TL.Top24(TL.Hash(h1));
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly int Prepare(int start, int end) => end;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy)
    {
        sx = TL.InDouble(new ShiftFormula(_unshifted[2 * index]), _shiftX, default, default, default);
        sy = TL.InDouble(new ShiftFormula(_unshifted[(2 * index) + 1]), _shiftY, default, default, default);
    }
}

/// <summary>
/// <see cref="SobolSampler"/> in lanes: integer arithmetic only. Each nested uniform scramble reverses its input's
/// bits first and its output's last; the reversals between two scrambles, and the one that ends the second Sobol'
/// dimension, cancel, so only three reversals a sample remain. The second dimension itself is a superset XOR over
/// the index's bits (the Pascal matrix mod 2: C(k, j) is odd exactly when j's bits are a subset of k's), five
/// shift–mask–xor steps.
/// </summary>
internal struct SobolLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();

    private readonly uint _salt;
    private TL _indexSeed, _xSeed, _ySeed;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public SobolLanes(SobolSampler sampler) => _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row)
    {
        _indexSeed = TL.Hash(TL.Xor(LaneHash.PixelKeys<TL>(x0, row, _salt), TL.BroadcastBits(SobolSampler.IndexSalt)));
        _xSeed = TL.Hash(_indexSeed);
        _ySeed = TL.Hash(_xSeed);
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, SobolLanes<TL>>(ref this, _block, start, end);

    /// <inheritdoc />
    public static bool HasMiddle => false;

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void First(int index, out TL a, out TL b, out TL c)
    {
        // i = NUS(index) = R(LK(R(index) + seed)), R the bit reversal, LK the Laine–Karras mix.
        a = Reverse(LaineKarras(TL.AddBits(TL.BroadcastBits(LowDiscrepancy.ReverseBits((uint)index)), _indexSeed)));
        b = default;
        c = default;
    }

    /// <inheritdoc />
    public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
    {
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        TL i = a;

        // NUS(R(i)) = R(LK(i + seed)); NUS(D₁(i)) = R(LK(R(D₁(i)) + seed)) with R(D₁(i)) the superset XOR.
        sx = TL.ToUnit(Reverse(LaineKarras(TL.AddBits(i, _xSeed))));
        sy = TL.ToUnit(Reverse(LaineKarras(TL.AddBits(SupersetXor(i), _ySeed))));
    }

    /// <summary>The middle of <see cref="LowDiscrepancy.NestedUniformScramble"/>, between its two reversals (the seed already added).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL LaineKarras(TL x)
    {
        x = TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras1)));
        x = TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras2)));
        x = TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras3)));
        return TL.Xor(x, TL.MultiplyBits(x, TL.BroadcastBits(LowDiscrepancy.LaineKarras4)));
    }

    /// <summary>Bit j of the result is the XOR of the bits k ⊇ j of <paramref name="x"/>: <see cref="LowDiscrepancy.SobolDimension1"/> before its final reversal.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static TL SupersetXor(TL x)
    {
        x = TL.Xor(x, TL.ShiftRightBits(x, 1) & TL.BroadcastBits(0x55555555u));
        x = TL.Xor(x, TL.ShiftRightBits(x, 2) & TL.BroadcastBits(0x33333333u));
        x = TL.Xor(x, TL.ShiftRightBits(x, 4) & TL.BroadcastBits(0x0f0f0f0fu));
        x = TL.Xor(x, TL.ShiftRightBits(x, 8) & TL.BroadcastBits(0x00ff00ffu));
        return TL.Xor(x, TL.ShiftRightBits(x, 16));
    }

    /// <summary><see cref="LowDiscrepancy.ReverseBits"/> in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static TL Reverse(TL x) => TL.ReverseBits(x);
}

/// <summary>Where the permutation samplers' lanes are exact.</summary>
internal static class PatternLimits
{
    /// <summary>
    /// The most samples per pixel the permutation-based lane samplers take: their lanes hold sample numbers as
    /// exact floats (below 2²⁴) and permutation lengths compared as signed integers (below 2³⁰). More go through
    /// the buffered path.
    /// </summary>
    public const int MaxSamples = 1 << 20;
}
