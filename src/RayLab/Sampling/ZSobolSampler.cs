using System.Numerics;
using System.Runtime.CompilerServices;

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
    public override SamplePoint GetSample(int x, int y, int index) => Point(SobolIndex(x, y, index));

    /// <summary>The point of Sobol' index <paramref name="i"/>: both coordinates through their Owen scrambles.</summary>
    private SamplePoint Point(uint i) => new(
        CounterHash.ToUnit(LowDiscrepancy.NestedUniformScramble(LowDiscrepancy.ReverseBits(i), XSeed)),
        CounterHash.ToUnit(LowDiscrepancy.NestedUniformScramble(LowDiscrepancy.SobolDimension1(i), YSeed)));

    /// <summary>
    /// The Sobol' index of sample <paramref name="index"/> of pixel (x, y): the digits of (Morton code · 2ᵐ + index),
    /// base 4 from the top (and, for odd m, the last binary digit), each permuted by the digits above it.
    /// </summary>
    /// <param name="x">The pixel column, below 65 536.</param>
    /// <param name="y">The pixel row, below 65 536.</param>
    /// <param name="index">The sample index.</param>
    internal uint SobolIndex(int x, int y, int index)
    {
        int m = Log2Block;
        ulong code = (Morton(x, y) << m) | (uint)index;
        int low = m & 1;
        ulong result = 0;
        for (int shift = 30 + m; shift >= low; shift -= 2)
        {
            result |= (ulong)PermuteDigit((int)(code >> shift) & 3, code >> (shift + 2)) << shift;
        }

        if (low == 1)
        {
            result |= (code & 1) ^ FlipBit(code >> 1);
        }

        return (uint)result;
    }

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
                byte permutation = Permutations[PermutationOf((pixel >> (shift + 2)) | (uint)t)];
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
                uint start = block[t], flip = (uint)FlipBit((pixel >> 1) | (uint)t);
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
            higher[j] = (ulong)PermutationOf(higher[j]);
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
            flips[j] = (uint)FlipBit(higher[j]);
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int PermuteDigit(int digit, ulong higher) => (Permutations[PermutationOf(higher)] >> (2 * digit)) & 3;

    /// <summary>Which of the 24 permutations the digits <paramref name="higher"/> above a digit pick.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private int PermutationOf(ulong higher) => (int)(((Mix(higher ^ DigitSalt) >> 40) * 24) >> 24);

    /// <summary>The last binary digit's flip (odd m), from the digits above it.</summary>
    private ulong FlipBit(ulong higher) => Mix(higher ^ DigitSalt ^ 0x9e3779b97f4a7c15ul) >> 63;

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
        user.Run(() => new ZSobolLanes<TL>(this));
}
