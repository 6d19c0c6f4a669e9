using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

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

/// <summary><see cref="CounterHash"/> in lanes: one pixel per lane (<see cref="PointHash"/> at a lane type).</summary>
internal static class LaneHash
{
    /// <summary><see cref="CounterHash.PixelKey"/> of pixels x0 … x0 + Count − 1 of a row; <paramref name="salt"/> is the hashed, salted seed.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL PixelKeys<TL>(int x0, int row, uint salt)
        where TL : struct, ILanes<TL> => PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, salt);

    /// <summary><see cref="CounterHash.SampleHash"/> of sample <paramref name="index"/> in every lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL SampleHash<TL>(TL keys, int index)
        where TL : struct, ILanes<TL> => PointHash.SampleHash<TL, LaneMath<TL>>(keys, index);
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
