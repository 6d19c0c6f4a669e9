using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling.Lanes;

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
