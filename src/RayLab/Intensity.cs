using System.Globalization;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace RayLab;

/// <summary>
/// A light intensity with red, green and blue components: the lab's <c>LightIntensity</c> (section 2.1).
/// Components are non-negative (a negative value becomes 0); the nominal range is 0..1, but larger values
/// may exist before they are written to an image.
/// </summary>
/// <remarks>
/// Only ambient light exists in this lab, so an object's colour on screen is its colour multiplied
/// component-wise by the ambient intensity: <c>color * ambient</c>.
/// </remarks>
public readonly struct Intensity : IEquatable<Intensity>, IAdditionOperators<Intensity, Intensity, Intensity>, IMultiplyOperators<Intensity, double, Intensity>
{
    /// <summary>Black: all components 0.</summary>
    public static Intensity Black => default;

    /// <summary>White: all components 1.</summary>
    public static Intensity White => new(1, 1, 1);

    /// <summary>Creates an intensity from three components; a negative (or NaN) component becomes 0.</summary>
    /// <param name="r">Red.</param>
    /// <param name="g">Green.</param>
    /// <param name="b">Blue.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Intensity(double r, double g, double b)
    {
        R = NonNegative(r);
        G = NonNegative(g);
        B = NonNegative(b);
    }

    /// <summary>Creates an intensity with red and green; blue is 0 (the lab's two-component constructor).</summary>
    /// <param name="r">Red.</param>
    /// <param name="g">Green.</param>
    public Intensity(double r, double g) : this(r, g, 0) { }

    /// <summary>Creates an intensity with red only; green and blue are 0 (the lab's one-component constructor).</summary>
    /// <param name="r">Red.</param>
    public Intensity(double r) : this(r, 0, 0) { }

    /// <summary>Creates black (the lab's constructor with no components).</summary>
    public Intensity() : this(0, 0, 0) { }

    /// <summary>The red component, never negative.</summary>
    public double R { get; }

    /// <summary>The green component, never negative.</summary>
    public double G { get; }

    /// <summary>The blue component, never negative.</summary>
    public double B { get; }

    /// <summary>Component-wise sum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Intensity operator +(Intensity a, Intensity b) => new(a.R + b.R, a.G + b.G, a.B + b.B);

    /// <summary>Component-wise difference; a component that would be negative becomes 0.</summary>
    public static Intensity operator -(Intensity a, Intensity b) => new(a.R - b.R, a.G - b.G, a.B - b.B);

    /// <summary>Scales every component.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Intensity operator *(Intensity a, double s) => new(a.R * s, a.G * s, a.B * s);

    /// <summary>Scales every component (scalar on the left).</summary>
    public static Intensity operator *(double s, Intensity a) => a * s;

    /// <summary>Component-wise product: an object's colour lit by an intensity (colour × ambient).</summary>
    public static Intensity operator *(Intensity a, Intensity b) => new(a.R * b.R, a.G * b.G, a.B * b.B);

    /// <summary>Divides every component by a scalar.</summary>
    /// <exception cref="DivideByZeroException"><paramref name="s"/> is 0.</exception>
    public static Intensity operator /(Intensity a, double s)
    {
        if (s == 0)
        {
            throw new DivideByZeroException("An intensity cannot be divided by zero.");
        }

        return new(a.R / s, a.G / s, a.B / s);
    }

    /// <summary>Equal when all three components are equal.</summary>
    public static bool operator ==(Intensity a, Intensity b) => a.Equals(b);

    /// <summary>Not equal when any component differs.</summary>
    public static bool operator !=(Intensity a, Intensity b) => !a.Equals(b);

    /// <summary>
    /// The lab's conversion of one component to an 8-bit level (section 2.2): <c>level = int(256 · I)</c>,
    /// clamped to 0..255 (the lab's rule gives 256 at I = 1), and 0 for NaN. The one scalar form of the rule:
    /// <see cref="EightBit.Level"/>, which every pixel writer uses, is this.
    /// </summary>
    /// <param name="component">A component value.</param>
    /// <returns>The level, 0..255.</returns>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static byte ToLevel(double component)
    {
        double scaled = component * 256.0;
        // NaN fails both comparisons and lands on 0; +inf lands on 255.
        if (!(scaled > 0))
        {
            return 0;
        }

        return scaled >= 255.0 ? (byte)255 : (byte)scaled;
    }

    /// <inheritdoc />
    public bool Equals(Intensity other) => R.Equals(other.R) && G.Equals(other.G) && B.Equals(other.B);

    /// <inheritdoc />
    public override bool Equals(object? obj) => obj is Intensity other && Equals(other);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(R, G, B);

    /// <summary>Formats as <c>(R, G, B)</c> with invariant-culture numbers.</summary>
    public override string ToString() =>
        string.Create(CultureInfo.InvariantCulture, $"({R:G6}, {G:G6}, {B:G6})");

    // NaN, -0 and negatives all fail 'v > 0' and become +0.
    private static double NonNegative(double v) => v > 0 ? v : 0;
}
