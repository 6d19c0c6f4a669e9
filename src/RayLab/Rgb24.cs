using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace RayLab;

/// <summary>One 8-bit-per-channel pixel, laid out R, G, B in 3 bytes (ImageSharp's <c>Rgb24</c> layout).</summary>
/// <param name="R">Red level.</param>
/// <param name="G">Green level.</param>
/// <param name="B">Blue level.</param>
[StructLayout(LayoutKind.Sequential, Pack = 1)]
public readonly record struct Rgb24(byte R, byte G, byte B)
{
    /// <summary>Converts an intensity by the lab's rule <c>int(256·I)</c> clamped to 0..255 (<see cref="EightBit.Level"/>).</summary>
    /// <param name="intensity">The intensity.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Rgb24 FromIntensity(Intensity intensity) =>
        new(EightBit.Level(intensity.R), EightBit.Level(intensity.G), EightBit.Level(intensity.B));

    /// <summary>The levels as ImageSharp's <c>Rgb24</c> writes them, <c>Rgb24(230, 51, 255)</c>, so the two read alike in a message.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => $"Rgb24({R}, {G}, {B})";
}
