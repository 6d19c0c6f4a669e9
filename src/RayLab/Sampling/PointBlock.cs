using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// A lane sampler's point formula cut into stages that <see cref="PointBlock"/> runs one after another over a block
/// of samples, each stage a loop of its own. Three lane values per sample (a, b, c) carry one stage's results to the
/// next; the last stage turns them into the point.
/// </summary>
/// <typeparam name="TL">The lane type.</typeparam>
internal interface IStagedPoints<TL>
    where TL : struct, ILanes<TL>
{
    /// <summary>True when <see cref="Middle"/> does something (else its loop is skipped).</summary>
    static abstract bool HasMiddle { get; }

    /// <summary>The first stage of sample <paramref name="index"/>: sets a, b and c as the next stage needs them.</summary>
    void First(int index, out TL a, out TL b, out TL c);

    /// <summary>The middle stage of sample <paramref name="index"/>, on the first stage's values.</summary>
    void Middle(int index, ref TL a, ref TL b, ref TL c);

    /// <summary>Sample <paramref name="index"/>'s point from the earlier stages' values.</summary>
    void Last(int index, TL a, TL b, TL c, out TL sx, out TL sy);
}

/// <summary>
/// Up to <see cref="Size"/> of a packet's points made ahead of the kernel's samples and kept in a small per-thread
/// buffer (6 KB at 8 lanes). A permutation sampler's point is a chain of dependent multiplies: made one sample at a
/// time from inside the kernel's loop its latency is paid in full, and inlined there it would use up the JIT's
/// inlining budget (the kernel's lane operations would become calls). Here each stage is a loop of its own, small
/// enough to inline whole, whose iterations are independent, so successive samples' chains overlap; the kernel
/// reads two vectors per sample.
/// </summary>
internal static class PointBlock
{
    /// <summary>Points per block; blocks start at multiples of it.</summary>
    public const int Size = 64;

    /// <summary>A buffer for one block of <typeparamref name="TL"/> points and their stages' values.</summary>
    public static float[] Create<TL>()
        where TL : struct, ILanes<TL> => new float[3 * Size * TL.Count];

    /// <summary>
    /// Makes samples <paramref name="start"/> (a multiple of <see cref="Size"/>) up to <paramref name="end"/>, at
    /// most <see cref="Size"/> of them, into <paramref name="block"/>; returns the index after the last one made.
    /// </summary>
    public static int Fill<TL, TS>(ref TS stages, float[] block, int start, int end)
        where TL : struct, ILanes<TL>
        where TS : struct, IStagedPoints<TL>
    {
        int stop = Math.Min(end, start + Size);
        First<TL, TS>(ref stages, block, start, stop);
        if (TS.HasMiddle)
        {
            Middle<TL, TS>(ref stages, block, start, stop);
        }

        Last<TL, TS>(ref stages, block, start, stop);
        return stop;
    }

    /// <summary>Sample <paramref name="index"/>'s lanes from the block <see cref="Fill"/> made last.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Read<TL>(float[] block, int index, out TL sx, out TL sy)
        where TL : struct, ILanes<TL>
    {
        int count = TL.Count;
        ReadOnlySpan<float> source = block.AsSpan((index & (Size - 1)) * 3 * count, 2 * count);
        sx = TL.Load(source);
        sy = TL.Load(source[count..]);
    }

    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static void First<TL, TS>(ref TS stages, float[] block, int start, int stop)
        where TL : struct, ILanes<TL>
        where TS : struct, IStagedPoints<TL>
    {
        int count = TL.Count;
        Span<float> slots = block.AsSpan(0, 3 * count * (stop - start));
        for (int index = start; index < stop; index++)
        {
            stages.First(index, out TL a, out TL b, out TL c);
            a.Store(slots);
            b.Store(slots[count..]);
            c.Store(slots[(2 * count)..]);
            slots = slots[(3 * count)..];
        }
    }

    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static void Middle<TL, TS>(ref TS stages, float[] block, int start, int stop)
        where TL : struct, ILanes<TL>
        where TS : struct, IStagedPoints<TL>
    {
        int count = TL.Count;
        Span<float> slots = block.AsSpan(0, 3 * count * (stop - start));
        for (int index = start; index < stop; index++)
        {
            TL a = TL.Load(slots), b = TL.Load(slots[count..]), c = TL.Load(slots[(2 * count)..]);
            stages.Middle(index, ref a, ref b, ref c);
            a.Store(slots);
            b.Store(slots[count..]);
            c.Store(slots[(2 * count)..]);
            slots = slots[(3 * count)..];
        }
    }

    [MethodImpl(MethodImplOptions.NoInlining | MethodImplOptions.AggressiveOptimization)]
    private static void Last<TL, TS>(ref TS stages, float[] block, int start, int stop)
        where TL : struct, ILanes<TL>
        where TS : struct, IStagedPoints<TL>
    {
        int count = TL.Count;
        Span<float> slots = block.AsSpan(0, 3 * count * (stop - start));
        for (int index = start; index < stop; index++)
        {
            stages.Last(index, TL.Load(slots), TL.Load(slots[count..]), TL.Load(slots[(2 * count)..]), out TL sx, out TL sy);
            sx.Store(slots);
            sy.Store(slots[count..]);
            slots = slots[(3 * count)..];
        }
    }
}
