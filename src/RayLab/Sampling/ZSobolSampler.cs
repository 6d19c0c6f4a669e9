using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// Owen-scrambled Sobol' samples handed to pixels in a scrambled Morton (Z) order, as in Ahmed and Wonka,
/// "Screen-space blue-noise diffusion of Monte Carlo sampling error via hierarchical ordering of pixels" (SIGGRAPH
/// Asia 2020). Pixel (x, y) with 2ᵐ samples takes the block of 2ᵐ consecutive indices of one Sobol' sequence at its
/// Morton code, after each base-4 digit of (Morton code, sample index) has been permuted by one of the 24
/// permutations of four, chosen by a hash of the digits above it. A pixel's samples therefore form a (0, m, 2)-net,
/// and the four pixels of every 2 × 2 block (the 16 of every 4 × 4, …) together form a larger net: neighbours'
/// samples avoid each other, so their errors are negatively correlated and the error image is blue noise.
/// </summary>
/// <remarks>
/// One sequence for the whole image: the Owen scramble's seeds and the digit permutations come from the seed alone.
/// The sample count is rounded up to a power of two for the block size (a count between two powers takes the first
/// samples of its block). The Sobol' index keeps the low 32 bits, so blocks repeat after 2³²⁻ᵐ pixels (a 1920 × 1080
/// image at 16 samples uses 2²⁶ indices). Coordinates keep the top 24 bits, like the other samplers.
/// </remarks>
public sealed class ZSobolSampler : PixelSampler, ILaneSampled
{
    /// <summary>The 24 permutations of (0, 1, 2, 3) in lexicographic order, each packed as four 2-bit images.</summary>
    private static readonly byte[] Permutations = BuildPermutations();

    /// <summary>Creates a ZSobol sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1 (a power of two for the full net property).</param>
    /// <param name="seed">The seed; different seeds give other scrambles and orders.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public ZSobolSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
        Log2Block = BitOperations.Log2(BitOperations.RoundUpToPowerOf2((uint)samplesPerPixel));
        uint key = CounterHash.Hash(seed + CounterHash.Golden);
        DigitSalt = ((ulong)CounterHash.Hash(key ^ 0x85ebca6bu) << 32) | CounterHash.Hash(key ^ 0xc2b2ae35u);
        XSeed = CounterHash.Hash(key ^ 0x27d4eb2fu);
        YSeed = CounterHash.Hash(XSeed);
    }

    /// <inheritdoc />
    public override string Name => "zsobol";

    /// <summary>m: a pixel's block holds 2ᵐ indices, the sample count rounded up to a power of two.</summary>
    internal int Log2Block { get; }

    /// <summary>XORed into the digits above a digit before they are hashed for its permutation.</summary>
    internal ulong DigitSalt { get; }

    /// <summary>The seed of the first coordinate's Owen scramble.</summary>
    internal uint XSeed { get; }

    /// <summary>The seed of the second coordinate's Owen scramble.</summary>
    internal uint YSeed { get; }

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        Formula.Point<ScalarLane, ScalarMath>(SobolIndex(x, y, index), XSeed, YSeed, out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <summary>The 24 packed permutations of four (the device form's table).</summary>
    internal static ReadOnlySpan<byte> PermutationTable => Permutations;

    /// <summary>
    /// The Sobol' index of sample <paramref name="index"/> of pixel (x, y): the digits of (Morton code · 2ᵐ + index),
    /// base 4 from the top (and, for odd m, the last binary digit), each permuted by the digits above it.
    /// </summary>
    /// <param name="x">The pixel column, below 65 536.</param>
    /// <param name="y">The pixel row, below 65 536.</param>
    /// <param name="index">The sample index.</param>
    internal uint SobolIndex(int x, int y, int index) =>
        Formula.SobolIndex(new PackedPermutations(Permutations), Log2Block, DigitSalt, x, y, index);

    /// <summary>The ZSobol point formula, once, for the scalar path and the device (the lanes assemble the same indices a packet at a time).</summary>
    internal readonly struct Formula
    {
        /// <summary>
        /// The Sobol' index of sample <paramref name="index"/> of pixel (x, y) with 2^<paramref name="m"/> indices a
        /// pixel: the digits of (Morton code · 2ᵐ + index), base 4 from the top (and, for odd m, the last binary
        /// digit), each permuted by the digits above it (<paramref name="permutations"/>, <paramref name="digitSalt"/>).
        /// </summary>
        public static uint SobolIndex<TP>(in TP permutations, int m, ulong digitSalt, int x, int y, int index)
            where TP : struct, IPackedPermutations
        {
            ulong code = (Morton(x, y) << m) | (uint)index;
            int low = m & 1;
            var result = new ScalarLane(0, 0);

            // Digits from bit 32 up fall outside the 32-bit index; they only pick the permutations below them.
            for (int shift = 30 + low; shift >= low; shift -= 2)
            {
                var permutation = new ScalarLane(permutations.Packed(PermutationOf(code >> (shift + 2), digitSalt)), 0);
                result = PlaceDigit<ScalarLane, ScalarMath>(result, permutation, (int)(code >> shift) & 3, shift);
            }

            if (low == 1)
            {
                result = PlaceFlip<ScalarLane, ScalarMath>(result, new ScalarLane((uint)FlipBit(code >> 1, digitSalt), 0), index);
            }

            return result.Bits;
        }

        /// <summary>The point of Sobol' index <paramref name="i"/>: both coordinates through their Owen scrambles (<c>SobolSampler.Coordinates</c>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Point<TV, TM>(uint i, uint xSeed, uint ySeed, out TV sx, out TV sy)
            where TV : struct
            where TM : IPointMath<TV> =>
            SobolSampler.Coordinates<TV, TM>(TM.BroadcastBits(i), TM.BroadcastBits(xSeed), TM.BroadcastBits(ySeed), out sx, out sy);
    }

    /// <summary>
    /// The index's digit at <paramref name="shift"/> set into <paramref name="value"/>: the image of
    /// <paramref name="digit"/> under <paramref name="permutation"/> (four packed 2-bit images), in every lane.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TV PlaceDigit<TV, TM>(TV value, TV permutation, int digit, int shift)
        where TV : struct
        where TM : IPointMath<TV> =>
        TM.Or(value, TM.ShiftLeftBits(TM.And(TM.ShiftRightBits(permutation, 2 * digit), TM.BroadcastBits(3u)), shift));

    /// <summary>The last binary digit (odd m) set into <paramref name="value"/>: sample <paramref name="index"/>'s low bit XOR the flip.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TV PlaceFlip<TV, TM>(TV value, TV flip, int index)
        where TV : struct
        where TM : IPointMath<TV> =>
        TM.Or(value, TM.Xor(flip, TM.BroadcastBits((uint)index & 1u)));

    /// <summary>
    /// <see cref="SobolIndex"/> of samples 0 … 2ᵐ − 1 of pixel (x, y) into <paramref name="block"/> (length 2ᵐ), the
    /// same values with the permutations shared. The pixel's own digits are recomputed only from the highest bit in
    /// which its Morton code differs from the last pixel's (<paramref name="digits"/>), and the samples' digits are
    /// expanded level by level, one permutation per group of samples that share the digits above: about 2ᵐ/3
    /// permutations a pixel, against m/2 a sample.
    /// </summary>
    internal void FillIndices(int x, int y, Span<uint> block, DigitCache digits)
    {
        int m = Log2Block;
        ulong pixel = Morton(x, y) << m;
        ulong prefix = Prefix(pixel, digits);

        // block[t] holds the samples whose digits above the current level are t; each level splits every entry in four.
        block[0] = (uint)prefix;
        int count = 1;
        for (int shift = m - 2; shift >= (m & 1); shift -= 2, count *= 4)
        {
            for (int t = count - 1; t >= 0; t--)
            {
                uint start = block[t];
                byte permutation = Permutations[PermutationOf((pixel >> (shift + 2)) | (uint)t, DigitSalt)];
                for (int d = 3; d >= 0; d--)
                {
                    block[(4 * t) + d] = start | (((uint)(permutation >> (2 * d)) & 3u) << shift);
                }
            }
        }

        if ((m & 1) == 1)
        {
            for (int t = count - 1; t >= 0; t--)
            {
                uint start = block[t], flip = (uint)FlipBit((pixel >> 1) | (uint)t, DigitSalt);
                block[(2 * t) + 1] = start | (1u ^ flip);
                block[2 * t] = start | flip;
            }
        }
    }

    /// <summary>
    /// The permuted digits of <paramref name="pixel"/> (a Morton code · 2ᵐ), the bits from m up of every index of its
    /// block; only the digits from the highest bit in which it differs from the last pixel asked (<paramref name="digits"/>)
    /// are permuted again. With <paramref name="skip"/> &gt; 0 the lowest <paramref name="skip"/> digits are left out
    /// (their bits are whatever the cache held: the caller masks them), and the cache remembers that they are stale.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal uint Prefix(ulong pixel, DigitCache digits, int skip = 0)
    {
        int m = Log2Block, from = m + (2 * skip);
        ulong diff = pixel ^ digits.LastPixel;
        ulong prefix = digits.LastPrefix;
        int top = diff == 0 ? -1 : 63 - BitOperations.LeadingZeroCount(diff);

        // Digits below ValidFrom were skipped last time: they are permuted again whatever changed.
        top = Math.Max(top, digits.ValidFrom - 1);
        for (int shift = from; shift <= Math.Min(top, 30 + m); shift += 2)
        {
            prefix = (prefix & ~(3ul << shift)) | ((ulong)PermuteDigit((int)(pixel >> shift) & 3, pixel >> (shift + 2)) << shift);
        }

        digits.LastPixel = pixel;
        digits.LastPrefix = prefix;
        digits.ValidFrom = from;
        return (uint)prefix;
    }

    /// <summary>
    /// The packed permutation (four 2-bit images) that each of <paramref name="higher"/>'s digit prefixes picks, into
    /// <paramref name="permutations"/>: <see cref="PermutationOf"/> and the table in one pass, the mixer in 64-bit
    /// vector lanes (512-bit registers where the hardware has them, else <see cref="Vector{T}"/>; emulated where it
    /// lacks 64-bit multiplies). Overwrites <paramref name="higher"/> with the permutations' numbers.
    /// </summary>
    /// <remarks>The table is read one entry at a time: a gather of 32-bit entries in lanes is slower here.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void PermutationsOf(Span<ulong> higher, Span<uint> permutations)
    {
        int j = 0;
        ref ulong first = ref MemoryMarshal.GetReference(higher);
        if (Vector512.IsHardwareAccelerated)
        {
            var salt = Vector512.Create(DigitSalt);
            for (; j <= higher.Length - Vector512<ulong>.Count; j += Vector512<ulong>.Count)
            {
                Vector512<ulong> z = Vector512.LoadUnsafe(ref first, (nuint)j) ^ salt;
                z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9ul;
                z = (z ^ (z >>> 27)) * 0x94d049bb133111ebul;
                ((((z ^ (z >>> 31)) >>> 40) * 24ul) >>> 24).StoreUnsafe(ref first, (nuint)j);
            }
        }
        else if (Vector.IsHardwareAccelerated)
        {
            var salt = new Vector<ulong>(DigitSalt);
            var twentyFour = new Vector<ulong>(24ul);
            for (; j <= higher.Length - Vector<ulong>.Count; j += Vector<ulong>.Count)
            {
                Span<ulong> slot = higher.Slice(j, Vector<ulong>.Count);
                (((Mix(new Vector<ulong>(slot) ^ salt) >> 40) * twentyFour) >> 24).CopyTo(slot);
            }
        }

        for (; j < higher.Length; j++)
        {
            higher[j] = (ulong)PermutationOf(higher[j], DigitSalt);
        }

        // Every number is below 24 (the mixer's top 24 bits times 24, shifted down by 24): the table needs no bounds check.
        ref byte table = ref MemoryMarshal.GetArrayDataReference(Permutations);
        ref uint target = ref MemoryMarshal.GetReference(permutations[..higher.Length]);
        for (j = 0; j < higher.Length; j++)
        {
            Unsafe.Add(ref target, j) = Unsafe.Add(ref table, (nint)Unsafe.Add(ref first, j));
        }
    }

    /// <summary>
    /// The largest m for which <see cref="Packet512"/> serves a packet: every digit it places (up to bit m + 7) stays
    /// inside the 32-bit index.
    /// </summary>
    internal const int MaxPacket512Block = 24;

    /// <summary>
    /// The table of packed permutations widened to 32 entries of 32 bits, for a two-register permute (entries 24 … 31 are 0).
    /// </summary>
    private static readonly uint[] WidePermutations = [.. Permutations.Select(p => (uint)p), 0, 0, 0, 0, 0, 0, 0, 0];

    /// <summary>
    /// Everything a 16-pixel packet aligned to 16 needs, in 512-bit registers (AVX-512 F and DQ, m ≤
    /// <see cref="MaxPacket512Block"/>): the digit permutations of the sample levels and the flips of an odd m, lane by
    /// lane, into <paramref name="permutations"/> (the lane form's layout), and the pixels' permuted digits (the bits
    /// from m up) as the result. The same hashes and table entries as <see cref="PermutationsOf"/>, <see cref="FlipBits"/>
    /// and <see cref="Prefix"/>: 64-bit mixes of eight lanes at a time, the table read by one permute of 16 lanes, and
    /// each pixel's four low digits permuted in its own lane (no table of group permutations, no gather).
    /// </summary>
    /// <param name="morton">The 16 pixels' Morton codes.</param>
    /// <param name="permutations">Where the lane form reads a sample level's permutations and flips.</param>
    /// <param name="digits">The cache of the last packet's high digits.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal Vector512<uint> Packet512(Vector512<uint> morton, Span<uint> permutations, DigitCache digits)
    {
        int m = Log2Block;
        Vector512<ulong> low = Avx512F.ConvertToVector512UInt64(morton.GetLower()), high = Avx512F.ConvertToVector512UInt64(morton.GetUpper());
        ref uint target = ref MemoryMarshal.GetReference(permutations);
        ref uint wide = ref MemoryMarshal.GetArrayDataReference(WidePermutations);
        Vector512<uint> tableLow = Vector512.LoadUnsafe(ref wide), tableHigh = Vector512.LoadUnsafe(ref wide, 16);
        var salt = Vector512.Create(DigitSalt);

        // Group (level from the top, digits above t) hashes (code · 2ᵐ) >> (shift + 2) | t, as the lanes' index reads it.
        for (int shift = m - 2, groups = 1, first = 0; shift >= (m & 1); shift -= 2, first += groups, groups *= 4)
        {
            Vector512<ulong> aboveLow = (low << (m - shift - 2)) ^ salt, aboveHigh = (high << (m - shift - 2)) ^ salt;
            for (int t = 0; t < groups; t++)
            {
                var digits512 = Vector512.Create((ulong)t);
                Packed512(aboveLow ^ digits512, aboveHigh ^ digits512, tableLow, tableHigh).StoreUnsafe(ref target, (nuint)((first + t) * 16));
            }
        }

        if ((m & 1) == 1)
        {
            // The flips after the groups and one row of lanes: (code · 2ᵐ) >> 1 | t, as FlipBit salts it.
            var flipSalt = Vector512.Create(DigitSalt ^ 0x9e3779b97f4a7c15ul);
            Vector512<ulong> aboveLow = (low << (m - 1)) ^ flipSalt, aboveHigh = (high << (m - 1)) ^ flipSalt;
            int slot = ((((1 << (m - 1)) - 1) / 3) + 1) * 16;
            for (int t = 0; t < 1 << (m - 1); t++, slot += 16)
            {
                var digits512 = Vector512.Create((ulong)t);
                Vector512.Create(
                    Avx512F.ConvertToVector256UInt32(Mix512(aboveLow ^ digits512) >>> 63),
                    Avx512F.ConvertToVector256UInt32(Mix512(aboveHigh ^ digits512) >>> 63)).StoreUnsafe(ref target, (nuint)slot);
            }
        }

        // The pixels' digits from level 4 up are the packet's (the cache); level k below 4 hashes the code above the digit.
        Vector512<uint> prefix = Vector512.Create(Prefix(low.ToScalar() << m, digits, 4) & ~(0xffu << m)), three = Vector512.Create(3u);
        for (int k = 0; k < 4; k++)
        {
            Vector512<uint> permutation = Packed512((low >>> ((2 * k) + 2)) ^ salt, (high >>> ((2 * k) + 2)) ^ salt, tableLow, tableHigh);
            Vector512<uint> digit = (morton >>> (2 * k)) & three;
            prefix |= (Avx512F.ShiftRightLogicalVariable(permutation, digit + digit) & three) << (m + (2 * k));
        }

        return prefix;
    }

    /// <summary>The packed permutations that 16 salted digit prefixes (eight in each argument) pick: <see cref="PermutationOf"/> and the table.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<uint> Packed512(Vector512<ulong> low, Vector512<ulong> high, Vector512<uint> tableLow, Vector512<uint> tableHigh)
    {
        // The mixer's top 24 bits n, then (n · 24) >> 24 = (n · 3) >> 21 in 32-bit lanes.
        Vector512<uint> top = Vector512.Create(Avx512F.ConvertToVector256UInt32(Mix512(low) >>> 40), Avx512F.ConvertToVector256UInt32(Mix512(high) >>> 40));
        return Avx512F.PermuteVar16x32x2(tableLow, (top + (top << 1)) >>> 21, tableHigh);
    }

    /// <summary><see cref="Mix(ulong)"/> in eight 64-bit lanes.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<ulong> Mix512(Vector512<ulong> z)
    {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9ul;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebul;
        return z ^ (z >>> 31);
    }

    /// <summary>The last binary digit's flip (odd m) for each of <paramref name="higher"/>'s prefixes, into <paramref name="flips"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void FlipBits(ReadOnlySpan<ulong> higher, Span<uint> flips)
    {
        for (int j = 0; j < higher.Length; j++)
        {
            flips[j] = (uint)FlipBit(higher[j], DigitSalt);
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int PermuteDigit(int digit, ulong higher) => (Permutations[PermutationOf(higher, DigitSalt)] >> (2 * digit)) & 3;

    /// <summary>Which of the 24 permutations the digits <paramref name="higher"/> above a digit pick under <paramref name="salt"/> (<see cref="DigitSalt"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int PermutationOf(ulong higher, ulong salt) => (int)(((Mix(higher ^ salt) >> 40) * 24) >> 24);

    /// <summary>The last binary digit's flip (odd m), from the digits above it.</summary>
    private static ulong FlipBit(ulong higher, ulong salt) => Mix(higher ^ salt ^ 0x9e3779b97f4a7c15ul) >> 63;

    /// <summary><see cref="Mix(ulong)"/> in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector<ulong> Mix(Vector<ulong> z)
    {
        z = (z ^ (z >> 30)) * new Vector<ulong>(0xbf58476d1ce4e5b9ul);
        z = (z ^ (z >> 27)) * new Vector<ulong>(0x94d049bb133111ebul);
        return z ^ (z >> 31);
    }

    /// <summary>A 64-bit mixer (the splitmix64 finalizer).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static ulong Mix(ulong z)
    {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ul;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebul;
        return z ^ (z >> 31);
    }

    /// <summary>The Morton code of (x, y): x's bits at the even positions, y's at the odd ones.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static ulong Morton(int x, int y) => Spread((uint)x) | (Spread((uint)y) << 1);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static ulong Spread(uint v)
    {
        ulong x = v & 0xffffu;
        x = (x | (x << 8)) & 0x00ff00fful;
        x = (x | (x << 4)) & 0x0f0f0f0ful;
        x = (x | (x << 2)) & 0x33333333ul;
        return (x | (x << 1)) & 0x55555555ul;
    }

    /// <summary><see cref="Spread(uint)"/> in every lane: the low 16 bits moved to the even positions.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static TL Spread<TL>(TL v)
        where TL : struct, ILanes<TL>
    {
        TL x = v & TL.BroadcastBits(0xffffu);
        x = (x | TL.ShiftLeftBits(x, 8)) & TL.BroadcastBits(0x00ff00ffu);
        x = (x | TL.ShiftLeftBits(x, 4)) & TL.BroadcastBits(0x0f0f0f0fu);
        x = (x | TL.ShiftLeftBits(x, 2)) & TL.BroadcastBits(0x33333333u);
        return (x | TL.ShiftLeftBits(x, 1)) & TL.BroadcastBits(0x55555555u);
    }

    private static byte[] BuildPermutations()
    {
        var result = new List<byte>(24);
        for (int a = 0; a < 4; a++)
        {
            for (int b = 0; b < 4; b++)
            {
                for (int c = 0; c < 4; c++)
                {
                    int d = 6 - a - b - c;
                    if (a != b && a != c && b != c && d is >= 0 and < 4 && d != a && d != b && d != c)
                    {
                        result.Add((byte)(a | (b << 2) | (c << 4) | (d << 6)));
                    }
                }
            }
        }

        return [.. result];
    }

    /// <summary>The last pixel <see cref="FillIndices"/> filled: its Morton code · 2ᵐ (none yet: all ones) and its permuted digits.</summary>
    internal sealed class DigitCache
    {
        public ulong LastPixel { get; set; } = ulong.MaxValue;

        public ulong LastPrefix { get; set; }

        /// <summary>The lowest bit from which <see cref="LastPrefix"/>'s digits are those of <see cref="LastPixel"/> (0: all of them).</summary>
        public int ValidFrom { get; set; }
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new LaneForm<TL>(this));

    /// <summary>
    /// The points in lanes. At the start of a packet the lanes' Morton codes are made in
    /// <typeparamref name="TL"/> lanes and the digit permutations the packet needs are hashed together in 64-bit vector
    /// lanes and looked up in the table of packed permutations (<see cref="PermutationsOf"/>): those of the
    /// sample levels, per lane, and, for a packet that starts at a multiple of its width, those of the pixels' low levels,
    /// one per pair, quad, … of lanes, which a gather per level hands to its lanes (the higher levels are the same for
    /// the whole packet and come from <see cref="Prefix"/>, recomputed only from the highest bit that changed since the
    /// last packet). A block of samples' Sobol' indices is then assembled in <typeparamref name="TL"/> lanes (a sample's
    /// digit at each level is its permutation's 2-bit image, one shift and mask for all lanes) and, in the same loop,
    /// scrambled into <see cref="SobolSampler"/>'s two Owen-scrambled coordinates (<c>SobolSampler.Coordinates</c>) with
    /// the image's seeds in every lane.
    /// </summary>
    /// <remarks>
    /// The packet's index work is compiled fully optimised at its first call (as <see cref="PointBlock"/>'s stages are):
    /// left to tiered compilation, its lane operations run as calls until the background compile lands, which on a
    /// loaded machine can be after the warm-up render.
    /// </remarks>
    private struct LaneForm<TL> : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private readonly ZSobolSampler _sampler;
        private readonly DigitCache _digits = new();

        /// <summary>Each lane's pixel digits (the bits from m up), as bits.</summary>
        private readonly float[] _prefixes;

        /// <summary>Each lane's Morton code.</summary>
        private readonly ulong[] _codes;

        /// <summary>Each lane's Morton code, as bits.</summary>
        private readonly float[] _morton;

        /// <summary>True when m is odd: the samples have a last binary digit, with its flips.</summary>
        private readonly bool _flips;

        /// <summary>
        /// The digit prefixes to hash: the sample levels' groups from the top, lane by lane; then one row of lanes for the
        /// low levels of the pixels' own digits (level by level, one per 2ᵏ⁺¹ lanes); then the flips' groups, lane by lane.
        /// </summary>
        private readonly ulong[] _higher;

        /// <summary>The packed permutations (then the flip bits) of <see cref="_higher"/>, as bits.</summary>
        private readonly float[] _permutations;

        private readonly int _groups;
        private readonly TL _xSeed, _ySeed;

        /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
        public LaneForm(ZSobolSampler sampler)
        {
            _sampler = sampler;
            int m = sampler.Log2Block;

            // (4ᴸ − 1) / 3 groups on the L base-4 levels of a sample index, and for odd m 2ᵐ⁻¹ last binary digits.
            _groups = ((1 << (m - (m & 1))) - 1) / 3;
            int flips = (m & 1) == 1 ? 1 << (m - 1) : 0;
            _prefixes = new float[TL.Count];
            _codes = new ulong[TL.Count];
            _morton = new float[TL.Count];
            _flips = flips > 0;
            _higher = new ulong[(_groups + 1 + flips) * TL.Count];
            _permutations = new float[(_groups + 1 + flips) * TL.Count];
            _xSeed = TL.BroadcastBits(sampler.XSeed);
            _ySeed = TL.BroadcastBits(sampler.YSeed);
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        public readonly unsafe void BeginPacket(int x0, int row)
        {
            int count = TL.Count, m = _sampler.Log2Block;
            Span<uint> prefixes = MemoryMarshal.Cast<float, uint>(_prefixes.AsSpan());
            Span<ulong> codes = _codes.AsSpan(), higher = _higher.AsSpan();

            // The lanes' Morton codes (x, y below 2¹⁶: 32 bits), then as 64-bit hash inputs.
            TL morton = Spread(TL.SequenceBits((uint)x0)) | TL.ShiftLeftBits(TL.BroadcastBits((uint)Spread((uint)row)), 1);
            morton.Store(_morton);
            bool aligned = (x0 & (count - 1)) == 0;
            if (typeof(TL) == typeof(Lanes512) && aligned && m <= MaxPacket512Block && Avx512DQ.IsSupported)
            {
                BeginPacket512();
                return;
            }

            ReadOnlySpan<uint> narrow = MemoryMarshal.Cast<float, uint>(_morton.AsSpan(0, count));
            for (int lane = 0; lane < narrow.Length; lane++)
            {
                codes[lane] = narrow[lane];
            }

            int levels = BitOperations.Log2((uint)count), sampleGroups = _groups * count;
            HashInputs(codes, higher, m, aligned);

            Span<uint> permutations = MemoryMarshal.Cast<float, uint>(_permutations.AsSpan());
            int permuted = sampleGroups + (aligned ? count - 1 : 0);
            _sampler.PermutationsOf(higher[..permuted], permutations);
            if (_flips)
            {
                _sampler.FlipBits(higher[(sampleGroups + count)..], permutations[(sampleGroups + count)..]);
            }

            if (aligned)
            {
                // Lane i's digit at pixel level k (below log₂ count) is the image of its own digit under the permutation
                // of its group of 2ᵏ⁺¹ lanes, which HashInputs put at first + (i ≫ (k + 1)): a gather per level.
                ulong low = ((1ul << (2 * levels)) - 1) << m;
                TL prefix = TL.BroadcastBits(_sampler.Prefix(codes[0] << m, _digits, levels) & (uint)~low);
                TL lanes = TL.SequenceBits(0), three = TL.BroadcastBits(3u);
                fixed (float* table = _permutations)
                {
                    for (int k = 0, first = sampleGroups; k < levels; first += count >> (k + 1), k++)
                    {
                        TL permutation = TL.GatherBits((uint*)table + first, TL.ShiftRightBits(lanes, k + 1));
                        TL digit = TL.ShiftRightBits(morton, 2 * k) & three;
                        prefix |= TL.ShiftLeftBits(TL.ShiftRightBitsVariable(permutation, TL.AddBits(digit, digit)) & three, m + (2 * k));
                    }
                }

                prefix.Store(_prefixes);
            }
            else
            {
                for (int lane = 0; lane < count; lane++)
                {
                    prefixes[lane] = _sampler.Prefix(codes[lane] << m, _digits);
                }
            }
        }

        /// <summary>An aligned packet of 16 lanes on AVX-512 (F and DQ): <see cref="Packet512"/> from the Morton codes in <see cref="_morton"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private readonly void BeginPacket512()
        {
            ref uint first = ref Unsafe.As<float, uint>(ref MemoryMarshal.GetArrayDataReference(_morton));
            _sampler.Packet512(Vector512.LoadUnsafe(ref first), MemoryMarshal.Cast<float, uint>(_permutations.AsSpan()), _digits)
                .StoreUnsafe(ref Unsafe.As<float, uint>(ref MemoryMarshal.GetArrayDataReference(_prefixes)));
        }

        /// <summary>
        /// The inputs of every digit permutation the packet needs, into <paramref name="higher"/>: the sample levels'
        /// groups per lane, an aligned packet's shared low pixel levels, and the flips of an odd 2ᵐ.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        private readonly void HashInputs(ReadOnlySpan<ulong> codes, Span<ulong> higher, int m, bool aligned)
        {
            int count = TL.Count;
            int levels = BitOperations.Log2((uint)count), sampleGroups = _groups * count;
            // An aligned packet's pixels share their digits from level log₂(count) up (x's higher bits, y's); a lower
            // level k has one permutation per 2ᵏ⁺¹ lanes, the code above the digit: count − 1 of them in all.
            if (aligned)
            {
                for (int k = 0, slot = sampleGroups; k < levels; k++)
                {
                    for (int lane = 0; lane < count; lane += 2 << k, slot++)
                    {
                        higher[slot] = codes[lane] >> ((2 * k) + 2);
                    }
                }
            }

            // Group (level from the top, digits above t) hashes the pixel's code and t above the level's digit:
            // (code · 2ᵐ) >> (shift + 2) | t, for all lanes at once.
            int width = Vector<ulong>.Count;
            for (int shift = m - 2, groups = 1, first = 0; shift >= (m & 1); shift -= 2, first += groups * count, groups *= 4)
            {
                for (int lane = 0; lane < count; lane += width)
                {
                    Vector<ulong> above = new Vector<ulong>(codes.Slice(lane, width)) << (m - shift - 2);
                    for (int t = 0; t < groups; t++)
                    {
                        (above | new Vector<ulong>((ulong)t)).CopyTo(higher.Slice(first + (t * count) + lane, width));
                    }
                }
            }

            if ((m & 1) == 1)
            {
                for (int lane = 0; lane < count; lane++)
                {
                    ulong above = (codes[lane] << m) >> 1;
                    for (int t = 0, flip = sampleGroups + count; t < 1 << (m - 1); t++)
                    {
                        higher[flip + (t * count) + lane] = above | (uint)t;
                    }
                }
            }
        }

        /// <summary>Sample <paramref name="index"/>'s Sobol' index from the prefixes, the permutations and the flips, all lanes at once.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private readonly TL Index(int index, int m, TL prefix, ReadOnlySpan<float> permutations)
        {
            int count = TL.Count;
            TL value = prefix;
            for (int shift = m - 2, first = 0, groups = 1; shift >= (m & 1); shift -= 2, first += groups, groups *= 4)
            {
                TL permutation = TL.Load(permutations.Slice((first + (index >> (shift + 2))) * count, count));
                value = PlaceDigit<TL, LaneMath<TL>>(value, permutation, (index >> shift) & 3, shift);
            }

            if ((m & 1) == 1)
            {
                TL flip = TL.Load(permutations.Slice(((_groups + 1) * count) + ((index >> 1) * count), count));
                value = PlaceFlip<TL, LaneMath<TL>>(value, flip, index);
            }

            return value;
        }

        /// <inheritdoc />
        public readonly int Prepare(int start, int end)
        {
            int stop = Math.Min(end, start + PointBlock.Size);
            Scramble(start, stop);
            return stop;
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

        /// <summary>
        /// Samples <paramref name="start"/> … <paramref name="stop"/> − 1 into the block (<see cref="PointBlock.Read"/>'s
        /// layout): each sample's Sobol' indices assembled from the packet's prefixes and permutations, then through the
        /// two Owen scrambles, one loop.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
        private readonly void Scramble(int start, int stop)
        {
            int count = TL.Count, m = _sampler.Log2Block;
            ReadOnlySpan<float> permutations = _permutations;
            Span<float> slots = _block.AsSpan(0, 3 * count * (stop - start));
            TL prefix = TL.Load(_prefixes), xSeed = _xSeed, ySeed = _ySeed;
            for (int index = start; index < stop; index++)
            {
                SobolSampler.Coordinates<TL, LaneMath<TL>>(Index(index, m, prefix, permutations), xSeed, ySeed, out TL sx, out TL sy);
                sx.Store(slots);
                sy.Store(slots[count..]);
                slots = slots[(3 * count)..];
            }
        }
    }
}

/// <summary>The 24 packed permutations of four that the ZSobol index formula reads: an array on the CPU, a device buffer in a kernel.</summary>
internal interface IPackedPermutations
{
    /// <summary>Permutation <paramref name="number"/> (0 … 23), its four 2-bit images packed.</summary>
    /// <param name="number">The permutation's number.</param>
    /// <returns>The packed permutation.</returns>
    uint Packed(int number);
}

/// <summary><see cref="IPackedPermutations"/> over the CPU's array.</summary>
/// <param name="table">The packed permutations.</param>
internal readonly struct PackedPermutations(byte[] table) : IPackedPermutations
{
    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public uint Packed(int number) => table[number];
}
