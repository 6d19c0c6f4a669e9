using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Rendering;

/// <summary>
/// Where a render writes its pixels, one row at a time: the 8-bit rows of a picture (<see cref="IPixelRows"/>, each
/// value converted by the lab's rule, <see cref="Rgb24.FromIntensity"/>), or the caller's linear intensities (the
/// values before that rule). Every renderer writes through <see cref="TargetRow"/>, so each has one row writer for
/// both kinds of output.
/// </summary>
internal abstract class PixelTarget
{
    private protected PixelTarget(int width, int height)
    {
        Width = width;
        Height = height;
    }

    /// <summary>The width W in pixels.</summary>
    public int Width { get; }

    /// <summary>The height H in pixels.</summary>
    public int Height { get; }

    /// <summary>An 8-bit picture's rows.</summary>
    public static PixelTarget Of(IPixelRows image) => new EightBitRows(image);

    /// <summary>
    /// The linear intensities of a W×H render at <paramref name="pixels"/>, W per row, from row
    /// <paramref name="firstRow"/> (0, the top, for the whole picture; a band's first row for a band): memory the
    /// caller keeps pinned (and alive) until the render returns.
    /// </summary>
    public static unsafe PixelTarget Linear(Intensity* pixels, int width, int height, int firstRow = 0) => new LinearRows(pixels, width, height, firstRow);

    /// <summary>Row <paramref name="y"/> (0 at the top), for the thread that renders it.</summary>
    public abstract TargetRow Row(int y);

    /// <summary>The 8-bit row <paramref name="y"/> of the picture, or an empty span for linear rows (a device writes the bytes it made).</summary>
    public virtual Span<Rgb24> EightBitRow(int y) => default;

    private sealed class EightBitRows(IPixelRows image) : PixelTarget(image.Width, image.Height)
    {
        public override TargetRow Row(int y) => new(image.GetRowSpan(y));

        public override Span<Rgb24> EightBitRow(int y) => image.GetRowSpan(y);
    }

    private sealed unsafe class LinearRows(Intensity* pixels, int width, int height, int firstRow) : PixelTarget(width, height)
    {
        public override TargetRow Row(int y)
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(y, firstRow);
            ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, Height);
            return new(new Span<Intensity>(pixels + ((long)(y - firstRow) * Width), Width));
        }
    }
}

/// <summary>
/// One row of a <see cref="PixelTarget"/>: its 8-bit pixels, or its linear intensities. A renderer hands each
/// pixel's linear value to <see cref="Set"/> (or a run of equal ones to <see cref="Fill(int, int, Intensity)"/>); the
/// 8-bit row converts it by the lab's rule, the linear row keeps it as it is.
/// </summary>
internal readonly ref struct TargetRow
{
    private readonly Span<Rgb24> _bytes;
    private readonly Span<Intensity> _linear;

    /// <summary>An 8-bit row.</summary>
    public TargetRow(Span<Rgb24> bytes) => _bytes = bytes;

    /// <summary>A linear row.</summary>
    public TargetRow(Span<Intensity> linear) => _linear = linear;

    /// <summary>The row's width in pixels.</summary>
    public int Length => _linear.IsEmpty ? _bytes.Length : _linear.Length;

    /// <summary>Writes pixel <paramref name="x"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void Set(int x, Intensity value)
    {
        if (_linear.IsEmpty)
        {
            _bytes[x] = Rgb24.FromIntensity(value);
        }
        else
        {
            _linear[x] = value;
        }
    }

    /// <summary>Writes <paramref name="count"/> pixels from <paramref name="x"/>, all <paramref name="value"/>.</summary>
    public void Fill(int x, int count, Intensity value)
    {
        if (_linear.IsEmpty)
        {
            _bytes.Slice(x, count).Fill(Rgb24.FromIntensity(value));
        }
        else
        {
            _linear.Slice(x, count).Fill(value);
        }
    }

    /// <summary>
    /// Writes <paramref name="count"/> pixels from <paramref name="x"/>, all <paramref name="value"/>, whose 8-bit
    /// form <paramref name="level"/> the caller already has (<c>Rgb24.FromIntensity(value)</c>).
    /// </summary>
    public void Fill(int x, int count, Intensity value, Rgb24 level)
    {
        if (_linear.IsEmpty)
        {
            _bytes.Slice(x, count).Fill(level);
        }
        else
        {
            _linear.Slice(x, count).Fill(value);
        }
    }

    /// <summary>
    /// The lane form: writes pixels <paramref name="x"/> … <paramref name="x"/> + <paramref name="count"/> − 1, one
    /// per lane from lane 0, each lane's value <c>scale/256 · (red, green, blue)</c> (the packet kernel's sums with
    /// scale 256/n). The 8-bit row takes the levels <see cref="EightBit"/> writes; the linear row takes
    /// <c>(scale · I)/256</c> with the product in float, whose 8-bit level is that same level.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public void WriteLanes<TL>(TL red, TL green, TL blue, TL scale, int x, int count)
        where TL : struct, ILanes<TL>
    {
        if (_linear.IsEmpty)
        {
            EightBit.WriteLanes(red, green, blue, scale, _bytes.Slice(x, count));
        }
        else
        {
            WriteLinearLanes(red, green, blue, scale, _linear.Slice(x, count));
        }
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void WriteLinearLanes<TL>(TL red, TL green, TL blue, TL scale, Span<Intensity> pixels)
        where TL : struct, ILanes<TL>
    {
        // The 8-bit rule's product, 256 · I in float, kept: divided by 256 (exactly) it is the linear value whose
        // level is the byte the 8-bit row would hold.
        Span<float> values = stackalloc float[3 * TL.Count];
        (red * scale).Store(values);
        (green * scale).Store(values[TL.Count..]);
        (blue * scale).Store(values[(2 * TL.Count)..]);
        for (int lane = 0; lane < pixels.Length; lane++)
        {
            pixels[lane] = new Intensity(values[lane] / 256.0, values[TL.Count + lane] / 256.0, values[(2 * TL.Count) + lane] / 256.0);
        }
    }
}
