namespace RayLab.Geometry;

/// <summary>
/// How far float (single precision) arithmetic can stray in the packet kernels' ray–sphere test: the constants
/// behind every "is the float answer certain?" bound, written once.
/// </summary>
internal static class FloatRounding
{
    /// <summary>ε = 2⁻²³, float's machine epsilon: the gap between 1 and the next float, twice float's unit roundoff.</summary>
    public const double MachineEpsilon = 1.0 / (1 << 23);

    /// <summary>
    /// A bound on the float rounding error of the stable discriminant <c>Δ = r² − |f⊥|²</c> (Ray Tracing Gems,
    /// ch. 7) for a sphere of radius r seen from origins at most L from its centre: <c>32 ε (r² + L²)</c>, a generous
    /// multiple of the error analysis. Where |Δ| exceeds it, the float answer (hit or miss) is the exact one.
    /// </summary>
    /// <param name="radius">r, the sphere's radius.</param>
    /// <param name="largestOffset">L, the largest |o − C| over the window.</param>
    /// <returns>The bound, in world units squared.</returns>
    public static double DiscriminantError(double radius, double largestOffset) =>
        32 * MachineEpsilon * ((radius * radius) + (largestOffset * largestOffset));
}
