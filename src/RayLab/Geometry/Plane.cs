namespace RayLab.Geometry;

/// <summary>A half-space n·x + d ≥ 0 (relative to the frame's fixed point).</summary>
/// <param name="Normal">n, pointing inside.</param>
/// <param name="Offset">d.</param>
internal readonly record struct Plane(Double3 Normal, double Offset)
{
    /// <summary>The half-space n·x + d ≥ 0 with n = ±<paramref name="normal"/> pointing along <paramref name="inward"/>, through <paramref name="point"/>.</summary>
    public static Plane Side(Double3 normal, Double3 inward, Double3 point)
    {
        Double3 n = Double3.Dot(normal, inward) >= 0 ? normal : -normal;
        return new Plane(n, -Double3.Dot(n, point));
    }
}
