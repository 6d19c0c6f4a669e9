using System.Globalization;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace RayLab;

/// <summary>
/// A point or direction in 3-D with <see cref="double"/> components: the lab's point/vector type from lab I.
/// </summary>
/// <remarks>
/// <see cref="Vector3"/> converts to it implicitly, so the API accepts System.Numerics vectors; RayLab keeps
/// doubles internally because a float cannot hold, for example, an eye 0.01 above a sphere of radius 10⁶.
/// </remarks>
/// <param name="X">The x component.</param>
/// <param name="Y">The y component.</param>
/// <param name="Z">The z component.</param>
public readonly record struct Double3(double X, double Y, double Z)
{
    /// <summary>The zero vector.</summary>
    public static Double3 Zero => default;

    /// <summary>The unit vector along y.</summary>
    public static Double3 UnitY => new(0, 1, 0);

    /// <summary>The Euclidean length.</summary>
    public double Length => Math.Sqrt(LengthSquared);

    /// <summary>The squared Euclidean length.</summary>
    public double LengthSquared
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get => (X * X) + (Y * Y) + (Z * Z);
    }

    /// <summary>True when every component is finite (not NaN, not ±∞).</summary>
    public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y) && double.IsFinite(Z);

    /// <summary>Converts a System.Numerics vector.</summary>
    public static implicit operator Double3(Vector3 v) => new(v.X, v.Y, v.Z);

    /// <summary>Component-wise sum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Double3 operator +(Double3 a, Double3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    /// <summary>Component-wise difference.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Double3 operator -(Double3 a, Double3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    /// <summary>Negation.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Double3 operator -(Double3 a) => new(-a.X, -a.Y, -a.Z);

    /// <summary>Scales by a scalar.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Double3 operator *(Double3 a, double s) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Scales by a scalar (scalar on the left).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Double3 operator *(double s, Double3 a) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Divides by a scalar.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Double3 operator /(Double3 a, double s) => new(a.X / s, a.Y / s, a.Z / s);

    /// <summary>The dot product.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Dot(Double3 a, Double3 b) => (a.X * b.X) + (a.Y * b.Y) + (a.Z * b.Z);

    /// <summary>The cross product a × b (right-handed).</summary>
    public static Double3 Cross(Double3 a, Double3 b) =>
        new((a.Y * b.Z) - (a.Z * b.Y), (a.Z * b.X) - (a.X * b.Z), (a.X * b.Y) - (a.Y * b.X));

    /// <summary>The vector scaled to length 1.</summary>
    /// <exception cref="ArgumentException">The vector has zero or non-finite length.</exception>
    public static Double3 Normalize(Double3 a)
    {
        double length = a.Length;
        if (!(length > 0) || !double.IsFinite(length))
        {
            throw new ArgumentException($"Cannot normalize {a}: its length is {length}.", nameof(a));
        }

        return a / length;
    }

    /// <summary>The smaller of each component: a box's low corner.</summary>
    internal static Double3 Min(Double3 a, Double3 b) => new(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z));

    /// <summary>The larger of each component: a box's high corner.</summary>
    internal static Double3 Max(Double3 a, Double3 b) => new(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));

    /// <summary>Converts to a single-precision System.Numerics vector (rounding each component).</summary>
    public Vector3 ToVector3() => new((float)X, (float)Y, (float)Z);

    /// <summary>Formats as <c>(X, Y, Z)</c> with invariant-culture numbers.</summary>
    public override string ToString() => string.Create(CultureInfo.InvariantCulture, $"({X:R}, {Y:R}, {Z:R})");
}
