using System.Globalization;

namespace RayLab;

/// <summary>
/// The window on the projection plane, in the plane's (u, v) coordinates: the lab's corners
/// (u0, v0) — lower left — and (u1, v1) — upper right (section 3.2). A window with u0 ≠ −u1 or
/// v0 ≠ −v1 is an off-axis projection.
/// </summary>
/// <param name="U0">The left edge, u0.</param>
/// <param name="V0">The bottom edge, v0.</param>
/// <param name="U1">The right edge, u1 (&gt; u0).</param>
/// <param name="V1">The top edge, v1 (&gt; v0).</param>
public readonly record struct Window(double U0, double V0, double U1, double V1)
{
    /// <summary>The width u1 − u0.</summary>
    public double Width => U1 - U0;

    /// <summary>The height v1 − v0.</summary>
    public double Height => V1 - V0;

    /// <summary>A window centred on the axis: (−width/2, −height/2) to (width/2, height/2).</summary>
    /// <param name="width">The width, &gt; 0.</param>
    /// <param name="height">The height, &gt; 0.</param>
    public static Window Centered(double width, double height) => new(-width / 2, -height / 2, width / 2, height / 2);

    /// <summary>Throws unless every corner is finite, u1 &gt; u0, v1 &gt; v0, and the width and height are finite.</summary>
    /// <param name="paramName">The parameter to name in the exception.</param>
    /// <exception cref="ArgumentException">The window is empty, inverted or not finite (its corners or its size).</exception>
    public void Validate(string paramName)
    {
        if (!double.IsFinite(U0) || !double.IsFinite(V0) || !double.IsFinite(U1) || !double.IsFinite(V1))
        {
            throw new ArgumentException($"The window corners must be finite, got {this}.", paramName);
        }

        if (!(U1 > U0) || !(V1 > V0))
        {
            throw new ArgumentException($"The window needs u1 > u0 and v1 > v0, got {this}.", paramName);
        }

        if (!double.IsFinite(Width) || !double.IsFinite(Height))
        {
            throw new ArgumentException($"The window's width u1 − u0 and height v1 − v0 must be finite, got {this}.", paramName);
        }
    }

    /// <summary>Formats as <c>[u0, v0, u1, v1]</c>.</summary>
    public override string ToString() => string.Create(CultureInfo.InvariantCulture, $"[{U0:G6}, {V0:G6}, {U1:G6}, {V1:G6}]");
}
