using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// <see cref="Pmj02Sampler"/> and <see cref="Pmj02BNSampler"/> in lanes: each lane's pixel reads its own generated
/// set (a gather, one scalar load per lane), then the digital shift and the conversion run in lanes, a block of
/// <see cref="PointBlock.Size"/> samples at a time. The points are <see cref="Pmj02Tables.Point"/>'s, bit for bit.
/// </summary>
internal struct Pmj02Lanes<TL> : ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _block = PointBlock.Create<TL>();
    private readonly uint[][] _sets;
    private readonly uint[][] _laneSets = new uint[TL.Count][];
    private readonly float[] _keys = new float[2 * TL.Count];
    private readonly uint _seed;
    private readonly bool _scramble;

    /// <summary>Lanes for pmj02's points.</summary>
    public Pmj02Lanes(Pmj02Sampler sampler)
        : this(sampler.Sets, sampler.Seed, scramble: true)
    {
    }

    /// <summary>Lanes for pmj02bn's points.</summary>
    public Pmj02Lanes(Pmj02BNSampler sampler)
        : this(sampler.Sets, sampler.Seed, scramble: false)
    {
    }

    private Pmj02Lanes(uint[][] sets, uint seed, bool scramble)
    {
        _sets = sets;
        _seed = seed;
        _scramble = scramble;
    }

    /// <inheritdoc />
    public readonly void BeginPacket(int x0, int row)
    {
        Span<uint> keys = MemoryMarshal.Cast<float, uint>(_keys.AsSpan());
        for (int lane = 0; lane < TL.Count; lane++)
        {
            (int set, uint x, uint y) = Pmj02Tables.Pixel(CounterHash.PixelKey(x0 + lane, row, _seed), _scramble);
            _laneSets[lane] = _sets[set];
            keys[lane] = x;
            keys[TL.Count + lane] = y;
        }
    }

    /// <inheritdoc />
    public readonly int Prepare(int start, int end)
    {
        int count = TL.Count;
        int stop = Math.Min(end, start + PointBlock.Size);
        Span<float> slots = _block.AsSpan(0, 3 * count * (stop - start));
        Span<uint> bits = MemoryMarshal.Cast<float, uint>(slots);
        for (int lane = 0; lane < count; lane++)
        {
            uint[] set = _laneSets[lane];
            for (int index = start, slot = lane; index < stop; index++, slot += 3 * count)
            {
                bits[slot] = set[2 * index];
                bits[slot + count] = set[(2 * index) + 1];
            }
        }

        TL kx = TL.Load(_keys), ky = TL.Load(_keys.AsSpan(count));
        for (int index = start; index < stop; index++)
        {
            TL.ToUnit(TL.Xor(TL.Load(slots), kx)).Store(slots);
            TL.ToUnit(TL.Xor(TL.Load(slots[count..]), ky)).Store(slots[count..]);
            slots = slots[(3 * count)..];
        }

        return stop;
    }

    /// <inheritdoc />
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);
}
