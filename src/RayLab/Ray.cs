namespace RayLab;

/// <summary>
/// A ray <c>r(t) = Origin + t · Direction</c> (the lab's ray from lab I). The direction need not have
/// length 1: a perspective camera makes the lab's ray <c>e + t (p − e)</c>, whose direction is <c>p − e</c>.
/// </summary>
/// <param name="Origin">Where the ray starts (t = 0).</param>
/// <param name="Direction">The direction; not normalised.</param>
public readonly record struct Ray(Double3 Origin, Double3 Direction)
{
    /// <summary>The point at parameter <paramref name="t"/>.</summary>
    /// <param name="t">The ray parameter.</param>
    public Double3 At(double t) => Origin + (t * Direction);
}
