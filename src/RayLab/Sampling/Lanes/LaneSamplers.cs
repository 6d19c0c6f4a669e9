using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling.Lanes;

/// <summary>
/// Where the samples of a packet's pixels go, lane by lane: sample <c>index</c> of pixels
/// <c>x0 … x0 + Count − 1</c> of one row. The same points as the scalar <see cref="IPixelSampler"/>, up to
/// float rounding.
/// </summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal interface ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{
    /// <summary>Moves to the packet whose first pixel is (<paramref name="x0"/>, <paramref name="row"/>).</summary>
    void BeginPacket(int x0, int row);

    /// <summary>
    /// Makes samples <paramref name="start"/> … (at most) <paramref name="end"/> − 1 of the packet ready for
    /// <see cref="Sample"/> and returns the index after the last one made ready (more than <paramref name="start"/>).
    /// The kernel asks from 0 (after <see cref="BeginPacket"/>) and then from each returned index until it reaches
    /// the sample count; a sampler that makes its points one at a time returns <paramref name="end"/>.
    /// </summary>
    int Prepare(int start, int end);

    /// <summary>Sample <paramref name="index"/> of every lane's pixel, as offsets in [0, 1)² inside the pixel; <paramref name="index"/> must be in the range <see cref="Prepare"/> made ready last.</summary>
    void Sample(int index, out TL sx, out TL sy);
}

/// <summary>
/// A sampler with a lane form: the packet kernel asks it for the form at a register width instead of knowing its
/// type. Every built-in sampler implements it (a test holds that); a sampler that does not, such as a student's own
/// <see cref="IPixelSampler"/>, takes the buffered path (<see cref="BufferedLanes{TL}"/>).
/// </summary>
internal interface ILaneSampled
{
    /// <summary>Hands <paramref name="user"/> this sampler's lane form at width <typeparamref name="TL"/>.</summary>
    /// <typeparam name="TL">The lane type.</typeparam>
    /// <typeparam name="TU">What uses the lane form.</typeparam>
    /// <typeparam name="TResult">What the user returns.</typeparam>
    TResult WithLanes<TL, TU, TResult>(ref TU user)
        where TL : struct, ILanes<TL>
        where TU : struct, ILaneSamplerUser<TL, TResult>;
}

/// <summary>Something that runs on a lane sampler: given a way to make one (one per thread), its result.</summary>
/// <typeparam name="TL">The lane type.</typeparam>
/// <typeparam name="TResult">The result.</typeparam>
internal interface ILaneSamplerUser<TL, TResult>
    where TL : struct, ILanes<TL>
{
    /// <summary>Runs on the lane sampler that <paramref name="create"/> makes.</summary>
    /// <typeparam name="TS">The lane sampler.</typeparam>
    TResult Run<TS>(Func<TS> create)
        where TS : struct, ILaneSampler<TL>;
}

/// <summary><see cref="CounterHash"/> in lanes: one pixel per lane.</summary>
internal static class LaneHash
{
    /// <summary><see cref="CounterHash.PixelKey"/> of pixels x0 … x0 + Count − 1 of a row; <paramref name="salt"/> is the hashed, salted seed.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL PixelKeys<TL>(int x0, int row, uint salt)
        where TL : struct, ILanes<TL> =>
        TL.Hash(TL.Xor(TL.BroadcastBits(((uint)row << 16) ^ salt), TL.SequenceBits((uint)x0)));

    /// <summary><see cref="CounterHash.SampleHash"/> of sample <paramref name="index"/> in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL SampleHash<TL>(TL keys, int index)
        where TL : struct, ILanes<TL> =>
        TL.Hash(TL.Xor(keys, TL.BroadcastBits((uint)index * CounterHash.Golden)));
}

/// <summary><see cref="JitteredSampler"/> in lanes: the counter hash runs in SIMD, one lane per pixel.</summary>
/// <remarks>
/// Sample i is ((i mod n) + u)/n across, computed as one multiply-add: u·2²⁴ (the hash's top 24 bits, exact)
/// times 2⁻²⁴/n, plus (i mod n)/n from a table.
/// </remarks>
internal struct JitteredLanes<TL>(JitteredSampler sampler) : ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{
    private readonly uint _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
    private readonly TL _scale = TL.Broadcast(1f / sampler.GridSize / 16777216f);
    private readonly (float Column, float Row)[] _cells = Cells(sampler.GridSize);
    private TL _keys;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row) => _keys = LaneHash.PixelKeys<TL>(x0, row, _salt);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly int Prepare(int start, int end) => end;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy)
    {
        TL h1 = LaneHash.SampleHash(_keys, index);
        TL h2 = TL.Hash(h1);
        (float column, float row) = _cells[index];
        sx = TL.MultiplyAdd(TL.Top24(h1), _scale, TL.Broadcast(column));
        sy = TL.MultiplyAdd(TL.Top24(h2), _scale, TL.Broadcast(row));
    }

    /// <summary>Sample i's cell corner ((i mod n)/n, (i div n)/n), looked up rather than divided for in the hot loop.</summary>
    private static (float Column, float Row)[] Cells(int n)
    {
        var cells = new (float, float)[n * n];
        for (int i = 0; i < cells.Length; i++)
        {
            cells[i] = ((float)(i % n) / n, (float)(i / n) / n);
        }

        return cells;
    }
}

/// <summary><see cref="RandomSampler"/> in lanes: the counter hash runs in SIMD, one lane per pixel.</summary>
internal struct RandomLanes<TL>(RandomSampler sampler) : ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{
    private readonly uint _salt = CounterHash.Hash(sampler.Seed + CounterHash.Golden);
    private TL _keys;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row) => _keys = LaneHash.PixelKeys<TL>(x0, row, _salt);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly int Prepare(int start, int end) => end;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly void Sample(int index, out TL sx, out TL sy)
    {
        TL h1 = LaneHash.SampleHash(_keys, index);
        sx = TL.ToUnit(h1);
        sy = TL.ToUnit(TL.Hash(h1));
    }
}

/// <summary><see cref="RegularSampler"/> in lanes: the same point in every pixel, from a table made once.</summary>
internal readonly struct RegularLanes<TL>(RegularSampler sampler) : ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{
    private readonly (float X, float Y)[] _points = Points(sampler);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void BeginPacket(int x0, int row)
    {
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public int Prepare(int start, int end) => end;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Sample(int index, out TL sx, out TL sy)
    {
        (float x, float y) = _points[index];
        sx = TL.Broadcast(x);
        sy = TL.Broadcast(y);
    }

    /// <summary>The sampler's points (the same for every pixel), so the hot loop makes no call for them.</summary>
    private static (float X, float Y)[] Points(RegularSampler sampler)
    {
        var points = new (float, float)[sampler.SamplesPerPixel];
        for (int i = 0; i < points.Length; i++)
        {
            SamplePoint p = sampler.GetSample(0, 0, i);
            points[i] = ((float)p.X, (float)p.Y);
        }

        return points;
    }
}

/// <summary>
/// Any other <see cref="IPixelSampler"/>: its points for a whole packet are asked for once per packet, one
/// <see cref="IPixelSampler.GetSamples"/> call per pixel (not a call per sample), and kept in a buffer that belongs
/// to one thread.
/// </summary>
internal readonly struct BufferedLanes<TL>(IPixelSampler sampler) : ILaneSampler<TL>
    where TL : struct, ILanes<TL>
{
    private readonly float[] _x = new float[sampler.SamplesPerPixel * TL.Count];
    private readonly float[] _y = new float[sampler.SamplesPerPixel * TL.Count];
    private readonly SamplePoint[] _pixel = new SamplePoint[sampler.SamplesPerPixel];

    public void BeginPacket(int x0, int row)
    {
        int lanes = TL.Count;
        SamplePoint[] pixel = _pixel;
        float[] xs = _x, ys = _y;
        for (int lane = 0; lane < lanes; lane++)
        {
            sampler.GetSamples(x0 + lane, row, pixel);
            for (int index = 0; index < pixel.Length; index++)
            {
                xs[(index * lanes) + lane] = (float)pixel[index].X;
                ys[(index * lanes) + lane] = (float)pixel[index].Y;
            }
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public int Prepare(int start, int end) => end;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Sample(int index, out TL sx, out TL sy)
    {
        sx = TL.Load(_x.AsSpan(index * TL.Count, TL.Count));
        sy = TL.Load(_y.AsSpan(index * TL.Count, TL.Count));
    }
}
