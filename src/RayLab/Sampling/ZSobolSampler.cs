using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
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
    /// are permuted again.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal uint Prefix(ulong pixel, DigitCache digits)
    {
        int m = Log2Block;
        ulong diff = pixel ^ digits.LastPixel;
        ulong prefix = digits.LastPrefix;
        int top = diff == 0 ? -1 : 63 - BitOperations.LeadingZeroCount(diff);
        for (int shift = m; shift <= Math.Min(top, 30 + m); shift += 2)
        {
            prefix = (prefix & ~(3ul << shift)) | ((ulong)PermuteDigit((int)(pixel >> shift) & 3, pixel >> (shift + 2)) << shift);
        }

        digits.LastPixel = pixel;
        digits.LastPrefix = prefix;
        return (uint)prefix;
    }

    /// <summary>
    /// The packed permutation (four 2-bit images) that each of <paramref name="higher"/>'s digit prefixes picks, into
    /// <paramref name="permutations"/>: <see cref="PermutationOf"/> and the table in one pass, the mixer in
    /// <see cref="Vector{T}"/> lanes of 64 bits (emulated where the hardware lacks 64-bit multiplies). Overwrites
    /// <paramref name="higher"/> with the permutations' numbers.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void PermutationsOf(Span<ulong> higher, Span<uint> permutations)
    {
        int j = 0;
        if (Vector.IsHardwareAccelerated)
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

        for (j = 0; j < higher.Length; j++)
        {
            permutations[j] = Permutations[(int)higher[j]];
        }
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
    }

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new LaneForm<TL>(this));

    /// <summary>
    /// The points in lanes. At the start of a packet the digit permutations it needs are hashed together
    /// in 64-bit vector lanes (<see cref="PermutationsOf"/>): those of the sample levels, per lane, and, for a
    /// packet that starts at a multiple of its width, those of the pixels' low levels, one per pair, quad, … of lanes (the
    /// higher levels are the same for the whole packet and come from <see cref="Prefix"/>, recomputed only
    /// from the highest bit that changed since the last packet). The Sobol' indices of all samples are then assembled in
    /// <typeparamref name="TL"/> lanes: a sample's digit at each level is its permutation's 2-bit image, one shift and
    /// mask for all lanes. The two Owen-scrambled coordinates are <see cref="SobolSampler"/>'s coordinates (<c>SobolSampler.Coordinates</c>) with the
    /// image's seeds in every lane.
    /// </summary>
    /// <remarks>
    /// The packet's index work is compiled fully optimised at its first call (as <see cref="PointBlock"/>'s stages are):
    /// left to tiered compilation, its lane operations run as calls until the background compile lands, which on a
    /// loaded machine can be after the warm-up render.
    /// </remarks>
    private struct LaneForm<TL> : ILaneSampler<TL>, IStagedPoints<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private readonly ZSobolSampler _sampler;
        private readonly DigitCache _digits = new();

        /// <summary>Each lane's pixel digits (the bits from m up), as bits.</summary>
        private readonly float[] _prefixes;

        /// <summary>Each lane's Morton code.</summary>
        private readonly ulong[] _codes;

        /// <summary>
        /// The digit prefixes to hash: the sample levels' groups from the top, lane by lane; then one row of lanes for the
        /// low levels of the pixels' own digits (level by level, one per 2ᵏ⁺¹ lanes); then the flips' groups, lane by lane.
        /// </summary>
        private readonly ulong[] _higher;

        /// <summary>The packed permutations (then the flip bits) of <see cref="_higher"/>, as bits.</summary>
        private readonly float[] _permutations;

        /// <summary>The Sobol' indices, sample by sample, lane by lane, as bits.</summary>
        private readonly float[] _indices;

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
            _higher = new ulong[(_groups + 1 + flips) * TL.Count];
            _permutations = new float[(_groups + 1 + flips) * TL.Count];
            _indices = new float[sampler.SamplesPerPixel * TL.Count];
            _xSeed = TL.BroadcastBits(sampler.XSeed);
            _ySeed = TL.BroadcastBits(sampler.YSeed);
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        public readonly void BeginPacket(int x0, int row)
        {
            int count = TL.Count, m = _sampler.Log2Block;
            Span<uint> prefixes = MemoryMarshal.Cast<float, uint>(_prefixes.AsSpan());
            Span<ulong> codes = _codes.AsSpan(), higher = _higher.AsSpan();
            for (int lane = 0; lane < count; lane++)
            {
                codes[lane] = Morton(x0 + lane, row);
            }

            bool aligned = (x0 & (count - 1)) == 0;
            int levels = BitOperations.Log2((uint)count), sampleGroups = _groups * count;
            HashInputs(codes, higher, m, aligned);

            Span<uint> permutations = MemoryMarshal.Cast<float, uint>(_permutations.AsSpan());
            int permuted = sampleGroups + (aligned ? count - 1 : 0);
            _sampler.PermutationsOf(higher[..permuted], permutations);
            _sampler.FlipBits(higher[(sampleGroups + count)..], permutations[(sampleGroups + count)..]);
            if (aligned)
            {
                ulong low = ((1ul << (2 * levels)) - 1) << m;
                ulong shared = _sampler.Prefix(codes[0] << m, _digits) & ~low;
                for (int lane = 0; lane < count; lane++)
                {
                    ulong prefix = shared;
                    for (int k = 0, first = sampleGroups; k < levels; first += count >> (k + 1), k++)
                    {
                        uint permutation = permutations[first + (lane >> (k + 1))];
                        int digit = (int)(codes[lane] >> (2 * k)) & 3;
                        prefix |= (ulong)((permutation >> (2 * digit)) & 3u) << (m + (2 * k));
                    }

                    prefixes[lane] = (uint)prefix;
                }
            }
            else
            {
                for (int lane = 0; lane < count; lane++)
                {
                    prefixes[lane] = _sampler.Prefix(codes[lane] << m, _digits);
                }
            }

            Assemble(m);
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

        /// <summary>Every sample's Sobol' index from the prefixes, the permutations and the flips, all lanes at once.</summary>
        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        private readonly void Assemble(int m)
        {
            int count = TL.Count;
            TL prefix = TL.Load(_prefixes);
            ReadOnlySpan<float> permutations = _permutations;
            Span<float> indices = _indices;
            int flips = (_groups + 1) * count;
            for (int index = 0; index < _sampler.SamplesPerPixel; index++)
            {
                TL value = prefix;
                for (int shift = m - 2, first = 0, groups = 1; shift >= (m & 1); shift -= 2, first += groups, groups *= 4)
                {
                    TL permutation = TL.Load(permutations.Slice((first + (index >> (shift + 2))) * count, count));
                    int digit = (index >> shift) & 3;
                    value = PlaceDigit<TL, LaneMath<TL>>(value, permutation, digit, shift);
                }

                if ((m & 1) == 1)
                {
                    TL flip = TL.Load(permutations.Slice(flips + ((index >> 1) * count), count));
                    value = PlaceFlip<TL, LaneMath<TL>>(value, flip, index);
                }

                value.Store(indices.Slice(index * count, count));
            }
        }

        /// <inheritdoc />
        public int Prepare(int start, int end) => PointBlock.Fill<TL, LaneForm<TL>>(ref this, _block, start, end);

        /// <inheritdoc />
        public static bool HasMiddle => false;

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void First(int index, out TL a, out TL b, out TL c)
        {
            a = TL.Load(_indices.AsSpan(index * TL.Count, TL.Count));
            b = default;
            c = default;
        }

        /// <inheritdoc />
        public readonly void Middle(int index, ref TL a, ref TL b, ref TL c)
        {
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy) =>
            SobolSampler.Coordinates<TL, LaneMath<TL>>(a, _xSeed, _ySeed, out sx, out sy);
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
