namespace RayLab.Sampling;

/// <summary>A sample position inside a pixel: (0, 0) is the pixel's top-left corner, (0.5, 0.5) its centre.</summary>
/// <param name="X">Offset to the right, in [0, 1).</param>
/// <param name="Y">Offset downward, in [0, 1).</param>
public readonly record struct SamplePoint(double X, double Y);
