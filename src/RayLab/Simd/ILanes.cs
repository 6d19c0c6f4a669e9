using System.Runtime.Intrinsics;

namespace RayLab.Simd;

/// <summary>
/// A SIMD register of float lanes, one lane per pixel of a packet: the operations the packet kernel needs,
/// behind one interface so that one generic kernel serves every width (<see cref="Lanes512"/>,
/// <see cref="Lanes256"/>, <see cref="Lanes128"/>). The JIT specialises the kernel per struct, so these
/// calls compile to single instructions. (The runtime's <c>Vector512&lt;T&gt;</c> family implements no
/// generic-math interface a kernel could be written against, hence these thin wrappers.)
/// </summary>
/// <remarks>
/// Masks are lanes with all bits set (true) or clear (false), as the comparison operations return them.
/// The hash operations treat the lanes' bits as unsigned 32-bit integers.
/// </remarks>
/// <typeparam name="TSelf">The implementing struct.</typeparam>
internal interface ILanes<TSelf>
    where TSelf : struct, ILanes<TSelf>
{
    /// <summary>Lanes per register.</summary>
    static abstract int Count { get; }

    /// <summary>True when the hardware runs this width natively.</summary>
    static abstract bool IsHardwareAccelerated { get; }

    /// <summary>Every lane set to <paramref name="value"/>.</summary>
    static abstract TSelf Broadcast(float value);

    /// <summary>0, 1, 2, … as floats.</summary>
    static abstract TSelf Indices { get; }

    static abstract TSelf operator +(TSelf a, TSelf b);

    static abstract TSelf operator -(TSelf a, TSelf b);

    static abstract TSelf operator *(TSelf a, TSelf b);

    static abstract TSelf operator /(TSelf a, TSelf b);

    /// <summary>Lane-wise <c>a·b + c</c>, fused (one rounding) where the hardware has FMA.</summary>
    static abstract TSelf MultiplyAdd(TSelf a, TSelf b, TSelf c);

    /// <summary>Lane-wise <c>c − a·b</c>, fused where the hardware has FMA.</summary>
    static abstract TSelf NegatedMultiplyAdd(TSelf a, TSelf b, TSelf c);

    static abstract TSelf Sqrt(TSelf x);

    static abstract TSelf Abs(TSelf x);

    /// <summary>The smaller lane, as the hardware's min instruction gives it (NaN and −0 are not treated specially).</summary>
    static abstract TSelf Min(TSelf a, TSelf b);

    /// <summary>
    /// min(<paramref name="smallest"/>, |<paramref name="x"/>|) per lane, for a non-negative
    /// <paramref name="smallest"/>: one instruction with AVX-512 (<c>vrangeps</c>), else an absolute and a min.
    /// </summary>
    static abstract TSelf MinAbs(TSelf smallest, TSelf x);

    /// <summary>Mask of lanes where <c>a ≤ b</c>.</summary>
    static abstract TSelf LessThanOrEqual(TSelf a, TSelf b);

    /// <summary>Mask of lanes where <c>a &lt; b</c>.</summary>
    static abstract TSelf LessThan(TSelf a, TSelf b);

    /// <summary>
    /// Lanes of <paramref name="whenTrue"/> where the mask is set, else of <paramref name="whenFalse"/>; each mask
    /// lane is all ones or all zeros (a comparison's result), so one blend instruction does it.
    /// </summary>
    static abstract TSelf Select(TSelf mask, TSelf whenTrue, TSelf whenFalse);

    /// <summary>
    /// Lanes of <paramref name="whenTrue"/> where <c>a &lt; b</c>, else of <paramref name="whenFalse"/>: <see cref="Select"/>
    /// of <see cref="LessThan"/> written as one step, so that where <see cref="BlendsByMaskRegister"/> the comparison's
    /// mask register drives a masked blend.
    /// </summary>
    static abstract TSelf SelectWhereLess(TSelf a, TSelf b, TSelf whenTrue, TSelf whenFalse);

    /// <summary>
    /// True where several blends on one comparison are cheapest as <see cref="SelectWhereLess"/> at each use (AVX-512 at
    /// 512 bits: the comparison stays in a mask register, one masked blend per use); false where one
    /// <see cref="LessThan"/> kept in lanes and a <see cref="Select"/> per use are (a mask kept in lanes at 512 bits is
    /// widened and narrowed again at every use; below 512 bits no blend takes a mask register).
    /// </summary>
    static abstract bool BlendsByMaskRegister { get; }

    static abstract TSelf operator &(TSelf a, TSelf b);

    static abstract TSelf operator |(TSelf a, TSelf b);

    /// <summary>Bit i set where lane i of the mask is set.</summary>
    static abstract uint MaskBits(TSelf mask);

    /// <summary>
    /// Bit i set where <c>a ≤ b</c> in lane i: <see cref="MaskBits"/> of <see cref="LessThanOrEqual"/> in one step, so
    /// that with AVX-512 the comparison's mask register is read as it is, not widened into lanes and narrowed back.
    /// </summary>
    static abstract uint LessThanOrEqualBits(TSelf a, TSelf b);

    /// <summary>Reads <see cref="Count"/> floats.</summary>
    static abstract TSelf Load(ReadOnlySpan<float> source);

    /// <summary>Writes <see cref="Count"/> floats.</summary>
    void Store(Span<float> destination);

    /// <summary>
    /// Truncates each lane of <paramref name="red"/>, <paramref name="green"/> and <paramref name="blue"/> (each
    /// in 0..255) to a whole number and stores the three as one little-endian word per lane:
    /// <c>r | g &lt;&lt; 8 | b &lt;&lt; 16</c>, the pixel's RGB24 bytes and a zero.
    /// </summary>
    static abstract void StoreRgb(TSelf red, TSelf green, TSelf blue, Span<uint> destination);

    /// <summary>Every lane's bits set to the unsigned integer <paramref name="bits"/>.</summary>
    static abstract TSelf BroadcastBits(uint bits);

    /// <summary>Lane i's bits set to the unsigned integer <c>start + i</c>.</summary>
    static abstract TSelf SequenceBits(uint start);

    /// <summary>Bitwise exclusive or of the lanes' bits.</summary>
    static abstract TSelf Xor(TSelf a, TSelf b);

    /// <summary><see cref="Sampling.CounterHash.Hash"/> (lowbias32) of each lane's bits.</summary>
    static abstract TSelf Hash(TSelf bits);

    /// <summary><see cref="Sampling.CounterHash.ToUnit"/> of each lane's bits: the top 24 bits as a float in [0, 1).</summary>
    static abstract TSelf ToUnit(TSelf bits);

    /// <summary>The top 24 bits of each lane as a float in [0, 2²⁴), exactly: <see cref="ToUnit"/> before its scaling by 2⁻²⁴.</summary>
    static abstract TSelf Top24(TSelf bits);

    /// <summary>Lane-wise sum of the lanes' bits as 32-bit integers (wrapping).</summary>
    static abstract TSelf AddBits(TSelf a, TSelf b);

    /// <summary>Lane-wise difference of the lanes' bits as 32-bit integers (wrapping).</summary>
    static abstract TSelf SubtractBits(TSelf a, TSelf b);

    /// <summary>Lane-wise product of the lanes' bits as 32-bit integers: the low 32 bits, as C#'s unchecked <c>uint</c> product.</summary>
    static abstract TSelf MultiplyBits(TSelf a, TSelf b);

    /// <summary>Each lane's bits shifted left by <paramref name="count"/> (0 … 31), zeros shifted in.</summary>
    static abstract TSelf ShiftLeftBits(TSelf bits, int count);

    /// <summary>Each lane's bits shifted right by <paramref name="count"/> (0 … 31), zeros shifted in (<c>uint</c>'s <c>&gt;&gt;</c>).</summary>
    static abstract TSelf ShiftRightBits(TSelf bits, int count);

    /// <summary>
    /// Each lane's bits shifted right by that lane's <paramref name="counts"/> (0 … 31), zeros shifted in (AVX2's
    /// <c>vpsrlvd</c>; lane by lane where the hardware lacks it).
    /// </summary>
    static abstract TSelf ShiftRightBitsVariable(TSelf bits, TSelf counts);

    /// <summary>Mask of lanes where <c>a &lt; b</c>, the lanes' bits compared as signed 32-bit integers.</summary>
    static abstract TSelf LessThanBits(TSelf a, TSelf b);

    /// <summary>
    /// Lane i's bits set to <c>table[index i]</c>, each lane's bits a signed 32-bit index: a hardware gather where there
    /// is one (AVX2), else a load per lane. The table must stay where it is (pinned) and hold every index.
    /// </summary>
    static abstract unsafe TSelf GatherBits(uint* table, TSelf indices);

    /// <summary>
    /// Lane i's bits of <paramref name="first"/> set to <c>table[index i]</c> and of <paramref name="second"/> to
    /// <c>table[index i + 1]</c>: one 64-bit gather per pair where there is one (AVX2), half as many loads as two
    /// <see cref="GatherBits"/>, then the pairs split into the two. The table must stay where it is (pinned) and hold
    /// every index and the one after it.
    /// </summary>
    static abstract unsafe void GatherPairs(uint* table, TSelf indices, out TSelf first, out TSelf second);

    /// <summary>Each lane's two 16-bit halves multiplied by the other's halves, the low 16 bits of each product kept (no carry between halves).</summary>
    static abstract TSelf MultiplyHalves(TSelf a, TSelf b);

    /// <summary>Each lane's two 16-bit halves shifted right by <paramref name="count"/> (0 … 15) each, zeros shifted in.</summary>
    static abstract TSelf ShiftRightHalves(TSelf bits, int count);

    /// <summary><see cref="Sampling.LowDiscrepancy.ReverseBits"/> of each lane's bits: a byte shuffle and two nibble lookups where the hardware shuffles bytes.</summary>
    static abstract TSelf ReverseBits(TSelf bits);

    /// <summary>Each lane's bits as a signed 32-bit integer, converted to the nearest float (exact below 2²⁴).</summary>
    static abstract TSelf BitsToFloat(TSelf bits);

    /// <summary>Each lane's float truncated toward zero to a signed 32-bit integer, as bits (lanes must be in int range).</summary>
    static abstract TSelf TruncateToBits(TSelf x);

    /// <summary>
    /// <paramref name="formula"/> evaluated in double precision on the lanes widened to doubles (exactly), each
    /// result rounded to the nearest float: what a scalar <c>(float)</c> of the same double expression gives.
    /// </summary>
    static abstract TSelf InDouble<TF>(in TF formula, TSelf a, TSelf b, TSelf c, TSelf d)
        where TF : struct, IDoubleFormula;

    /// <summary>
    /// <paramref name="formula"/> in double on integer lanes: <paramref name="a"/> and <paramref name="c"/> as signed
    /// 32-bit integers and <paramref name="jitter"/> as an unsigned one, each converted to double exactly (the formula's
    /// b; its d is 0), the results rounded to the nearest float. One conversion per input, where
    /// <see cref="InDouble"/> would take a 32-bit hash as two floats.
    /// </summary>
    static abstract TSelf InDoubleFromBits<TF>(in TF formula, TSelf a, TSelf jitter, TSelf c)
        where TF : struct, IDoubleFormula;
}

/// <summary>
/// A double-precision expression of four lanes for <see cref="ILanes{TSelf}.InDouble"/>, written once per register
/// width. The samplers' points are double expressions; evaluating them in double keeps the lanes' points the
/// exact floats the scalar path's <c>(float)</c> gives.
/// </summary>
internal interface IDoubleFormula
{
    /// <summary>The expression on two double lanes.</summary>
    Vector128<double> Apply(Vector128<double> a, Vector128<double> b, Vector128<double> c, Vector128<double> d);

    /// <summary>The expression on four double lanes.</summary>
    Vector256<double> Apply(Vector256<double> a, Vector256<double> b, Vector256<double> c, Vector256<double> d);

    /// <summary>The expression on eight double lanes.</summary>
    Vector512<double> Apply(Vector512<double> a, Vector512<double> b, Vector512<double> c, Vector512<double> d);
}
