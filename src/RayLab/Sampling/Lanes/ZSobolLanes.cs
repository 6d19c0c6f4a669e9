using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Simd;

namespace RayLab.Sampling.Lanes;

/// <summary>
/// <see cref="ZSobolSampler"/> in lanes: each lane's Sobol' indices come from <see cref="ZSobolSampler.FillIndices"/>
/// (the digit permutations, shared between neighbouring pixels), and the two Owen-scrambled coordinates are
/// <see cref="SobolLanes{TL}"/>' last stage with the image's seeds in every lane.
/// </summary>
internal struct ZSobolLanes<TL> : ILaneSampler<TL>, IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly ZSobolSampler _sampler;
    private readonly ZSobolSampler.DigitCache _digits = new();
    private readonly uint[] _pixel;
    private readonly float[] _indices;
    private readonly TL _xSeed, _ySeed;

    /// <summary>Lanes for <paramref name="sampler"/>'s points.</summary>
    public ZSobolLanes(ZSobolSampler sampler)
    {
        _sampler = sampler;
        _pixel = new uint[1 << sampler.Log2Block];
        _indices = new float[sampler.SamplesPerPixel * TL.Count];
        _xSeed = TL.BroadcastBits(sampler.XSeed);
        _ySeed = TL.BroadcastBits(sampler.YSeed);
    }

    /// <inheritdoc />
    public readonly void BeginPacket(int x0, int row)
    {
        int count = TL.Count;
        Span<uint> indices = MemoryMarshal.Cast<float, uint>(_indices.AsSpan());
        for (int lane = 0; lane < count; lane++)
        {
            _sampler.FillIndices(x0 + lane, row, _pixel, _digits);
            for (int index = 0, slot = lane; index < _sampler.SamplesPerPixel; index++, slot += count)
            {
                indices[slot] = _pixel[index];
            }
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
    public readonly void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy)
    {
        // NUS(R(i)) = R(LK(i + seed)); NUS(D₁(i)) = R(LK(R(D₁(i)) + seed)), as in SobolLanes.
        sx = TL.ToUnit(SobolLanes<TL>.Reverse(SobolLanes<TL>.LaineKarras(TL.AddBits(a, _xSeed))));
        sy = TL.ToUnit(SobolLanes<TL>.Reverse(SobolLanes<TL>.LaineKarras(TL.AddBits(SobolLanes<TL>.SupersetXor(a), _ySeed))));
    }
}
