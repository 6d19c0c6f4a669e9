using System.Numerics;

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
public sealed class ZSobolSampler : PixelSampler
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
    /// <see cref="SobolIndex"/> of samples 0 … <paramref name="indices"/>.Length − 1 of pixel (x, y), the same values
    /// with the permutations shared: a digit's permutation is recomputed only when the digits above it change, which
    /// <paramref name="digits"/> remembers from one call to the next (neighbouring pixels share their upper digits).
    /// </summary>
    internal void FillIndices(int x, int y, Span<uint> indices, DigitCache digits)
    {
        int m = Log2Block;
        ulong pixel = Morton(x, y) << m;
        int low = m & 1;
        for (int s = 0; s < indices.Length; s++)
        {
            ulong code = pixel | (uint)s;
            ulong result = 0;
            int level = 0;
            for (int shift = 30 + m; shift >= low; shift -= 2, level++)
            {
                ulong higher = code >> (shift + 2);
                if (digits.Higher[level] != higher)
                {
                    digits.Higher[level] = higher;
                    digits.Permutation[level] = Permutations[PermutationOf(higher)];
                }

                result |= (ulong)((digits.Permutation[level] >> (2 * ((int)(code >> shift) & 3))) & 3) << shift;
            }

            if (low == 1)
            {
                result |= (code & 1) ^ FlipBit(code >> 1);
            }

            indices[s] = (uint)result;
        }
    }

    private int PermuteDigit(int digit, ulong higher) => (Permutations[PermutationOf(higher)] >> (2 * digit)) & 3;

    /// <summary>Which of the 24 permutations the digits <paramref name="higher"/> above a digit pick.</summary>
    private int PermutationOf(ulong higher) => (int)(((Mix(higher ^ DigitSalt) >> 40) * 24) >> 24);

    /// <summary>The last binary digit's flip (odd m), from the digits above it.</summary>
    private ulong FlipBit(ulong higher) => Mix(higher ^ DigitSalt ^ 0x9e3779b97f4a7c15ul) >> 63;

    /// <summary>A 64-bit mixer (the splitmix64 finalizer).</summary>
    private static ulong Mix(ulong z)
    {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ul;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebul;
        return z ^ (z >> 31);
    }

    /// <summary>The Morton code of (x, y): x's bits at the even positions, y's at the odd ones.</summary>
    internal static ulong Morton(int x, int y) => Spread((uint)x) | (Spread((uint)y) << 1);

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

    /// <summary>Per level of digits: the digits above it last seen (none yet: all ones) and the permutation they picked.</summary>
    internal sealed class DigitCache
    {
        public ulong[] Higher { get; } = [.. Enumerable.Repeat(ulong.MaxValue, 64)];

        public byte[] Permutation { get; } = new byte[64];
    }
}
