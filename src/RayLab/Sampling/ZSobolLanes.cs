using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// <see cref="ZSobolSampler"/> in lanes. At the start of a packet the digit permutations it needs are hashed together
/// in 64-bit vector lanes (<see cref="ZSobolSampler.PermutationsOf"/>): those of the sample levels, per lane, and, for a
/// packet that starts at a multiple of its width, those of the pixels' low levels, one per pair, quad, … of lanes (the
/// higher levels are the same for the whole packet and come from <see cref="ZSobolSampler.Prefix"/>, recomputed only
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
internal struct ZSobolLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly ZSobolSampler _sampler;
    private readonly ZSobolSampler.DigitCache _digits = new();

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
    public ZSobolLanes(ZSobolSampler sampler)
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
            codes[lane] = ZSobolSampler.Morton(x0 + lane, row);
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
        TL prefix = TL.Load(_prefixes), three = TL.BroadcastBits(3u);
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
                value = value | TL.ShiftLeftBits(TL.ShiftRightBits(permutation, 2 * digit) & three, shift);
            }

            if ((m & 1) == 1)
            {
                TL flip = TL.Load(permutations.Slice(flips + ((index >> 1) * count), count));
                value = value | TL.Xor(flip, TL.BroadcastBits((uint)index & 1u));
            }

            value.Store(indices.Slice(index * count, count));
        }
    }

    /// <inheritdoc />
    public int Prepare(int start, int end) => PointBlock.Fill<TL, ZSobolLanes<TL>>(ref this, _block, start, end);

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
