namespace RayLab.Rendering;

/// <summary>The rule every renderer's <c>MaxDegreeOfParallelism</c> follows.</summary>
internal static class ThreadCount
{
    /// <summary>Returns <paramref name="value"/> when it is −1 (as many as the runtime likes) or ≥ 1.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Any other value.</exception>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2208:Instantiate argument exceptions correctly", Justification = "Called from the MaxDegreeOfParallelism setters: the exception names that property.")]
    public static int Check(int value) => value == -1 || value >= 1
        ? value
        : throw new ArgumentOutOfRangeException("MaxDegreeOfParallelism", value, "Use −1 (all cores) or a count ≥ 1.");
}
