using System.Buffers.Binary;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Simd;

namespace RayLab;

/// <summary>
/// The lab's 8-bit rule (section 2.2) for pixel writers: a component I becomes the level
/// <c>int(256 · I)</c>, clamped to 0..255 (the rule gives 256 at I = 1). Every pixel writer uses it: the scalar
/// form (<see cref="Level"/>, through <see cref="Rgb24.FromIntensity"/>; its code is <see cref="Intensity.ToLevel"/>)
/// and, side by side, the lane form the packet kernel writes its pixels with.
/// </summary>
public static class EightBit
{
    /// <summary>The largest level.</summary>
    private const float Top = 255f;

    /// <summary>
    /// The level of one component: <c>int(256 · I)</c> clamped to 0..255, and 0 for NaN (the rule itself is
    /// <see cref="Intensity.ToLevel"/>, beside the value it converts, so that the scene model needs no imaging).
    /// </summary>
    /// <param name="component">A component value.</param>
    /// <returns>The level, 0..255.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static byte Level(double component) => Intensity.ToLevel(component);

    /// <summary>
    /// The lane form: writes one pixel per lane, levels <c>int(scale · I)</c> clamped to 255 with I the lanes of
    /// <paramref name="red"/>, <paramref name="green"/> and <paramref name="blue"/>. With scale 256 it is
    /// <see cref="Level"/> of each lane; the packet kernel passes its sums with scale 256/n, folding the mean of
    /// n samples into the same multiply. The lanes must not be negative or NaN (sums of intensities never are).
    /// </summary>
    /// <param name="red">Red per lane.</param>
    /// <param name="green">Green per lane.</param>
    /// <param name="blue">Blue per lane.</param>
    /// <param name="scale">256, or 256/n for sums of n samples, in every lane.</param>
    /// <param name="pixels">The pixels to write, one per lane from lane 0: at least 1, at most <c>TL.Count</c>.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static void WriteLanes<TL>(TL red, TL green, TL blue, TL scale, Span<Rgb24> pixels)
        where TL : struct, ILanes<TL>
    {
        // Truncated and packed in SIMD as one word per pixel, R G B 0. Each pixel but the last is written as its
        // 4-byte word (the next pixel overwrites the zero): one store per pixel rather than three.
        TL top = TL.Broadcast(Top);
        var buffer = default(WordBuffer);
        Span<uint> words = buffer;
        TL.StoreRgb(TL.Min(red * scale, top), TL.Min(green * scale, top), TL.Min(blue * scale, top), words);
        int last = pixels.Length - 1;
        Span<byte> bytes = MemoryMarshal.AsBytes(pixels);
        for (int lane = 0; lane < last; lane++)
        {
            BinaryPrimitives.WriteUInt32LittleEndian(bytes[(3 * lane)..], words[lane]);
        }

        uint word = words[last];
        pixels[last] = new Rgb24((byte)word, (byte)(word >> 8), (byte)(word >> 16));
    }

    /// <summary>Room for one packed RGB word per lane of the widest packet, on the stack.</summary>
    /// <summary>
    /// The level <see cref="WriteLanes"/> gives one lane, in scalar code (a device kernel's form of it): the sum times
    /// the scale in float, capped at 255 and truncated. Used where lanes are not, so both give one byte.
    /// </summary>
    /// <param name="sum">The pixel's sum of sample values, in float.</param>
    /// <param name="scale">256/n in float.</param>
    /// <returns>The level, 0..255.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static byte LaneLevel(float sum, float scale) => (byte)(int)MathF.Min(sum * scale, Top);

    [InlineArray(16)]
    private struct WordBuffer
    {
        private uint _element;
    }
}
