namespace RayLab.Sampling;

/// <summary>Where the permutation samplers' lanes are exact.</summary>
internal static class PatternLimits
{
    /// <summary>
    /// The most samples per pixel the permutation-based lane samplers take: their lanes hold sample numbers as
    /// exact floats (below 2²⁴) and permutation lengths compared as signed integers (below 2³⁰). More go through
    /// the buffered path.
    /// </summary>
    public const int MaxSamples = 1 << 20;
}
