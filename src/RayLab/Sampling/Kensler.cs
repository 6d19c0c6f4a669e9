namespace RayLab.Sampling;

/// <summary>
/// The constants of Andrew Kensler's hashes ("Correlated Multi-Jittered Sampling", Pixar Technical Memo 13-01,
/// 2013), written once: the scalar samplers (<see cref="Permutation"/>, <see cref="CorrelatedMultiJitteredSampler"/>)
/// and their SIMD lanes both read them from here, so the two cannot drift apart.
/// </summary>
internal static class Kensler
{
    /// <summary><c>permute</c>'s first odd multiplier (after the xor with the pattern number).</summary>
    public const uint PermuteMultiplier1 = 0xe170893du;

    /// <summary><c>permute</c>'s second odd multiplier.</summary>
    public const uint PermuteMultiplier2 = 0x0929eb3fu;

    /// <summary><c>permute</c>'s third odd multiplier, applied after the pattern's own factor 1 | (p ≫ 27).</summary>
    public const uint PermuteMultiplier3 = 0x6935fa69u;

    /// <summary><c>permute</c>'s fourth odd multiplier.</summary>
    public const uint PermuteMultiplier4 = 0x74dcb303u;

    /// <summary><c>permute</c>'s fifth odd multiplier.</summary>
    public const uint PermuteMultiplier5 = 0x9e501cc3u;

    /// <summary><c>permute</c>'s last odd multiplier.</summary>
    public const uint PermuteMultiplier6 = 0xc860a3dfu;

    /// <summary><c>cmj</c>: the pattern number's salt for the permutation of the sample index.</summary>
    public const uint IndexSalt = 0x51633e2du;

    /// <summary><c>cmj</c>: the salt for the permutation of the columns (shared by the whole pattern).</summary>
    public const uint ColumnSalt = 0x68bc21ebu;

    /// <summary><c>cmj</c>: the salt for the permutation of the rows (shared by the whole pattern).</summary>
    public const uint RowSalt = 0x02e5be93u;

    /// <summary><c>cmj</c>: the salt for the jitter in x.</summary>
    public const uint JitterXSalt = 0x967a889bu;

    /// <summary><c>cmj</c>: the salt for the jitter in y.</summary>
    public const uint JitterYSalt = 0x368cc8b7u;

    /// <summary><c>randfloat</c>'s first multiplier.</summary>
    public const uint RandFloatMultiplier1 = 0xb36534e5u;

    /// <summary><c>randfloat</c>'s second multiplier.</summary>
    public const uint RandFloatMultiplier2 = 0x93fc4795u;

    /// <summary><c>randfloat</c>'s xor constant.</summary>
    public const uint RandFloatXor = 0xdf6e307fu;

    /// <summary><c>randfloat</c>'s scale 1 / (2³² + 512): the hash's 32 bits map into [0, 1) without reaching 1 in float.</summary>
    public const double RandFloatScale = 1.0 / 4294967808.0;
}
