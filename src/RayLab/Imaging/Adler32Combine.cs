namespace RayLab.Imaging;

/// <summary>
/// The Adler-32 (RFC 1950, the zlib stream's checksum) of two pieces of data joined, from the Adler-32 of each
/// and the second one's length — what zlib's <c>adler32_combine</c> does, which System.IO.Hashing's
/// <see cref="System.IO.Hashing.Adler32"/> lacks. <see cref="PngEncoder"/> hashes its row bands in parallel with
/// that class and joins the sums with this.
/// </summary>
internal static class Adler32Combine
{
    private const uint Modulus = 65521; // the largest prime below 2^16

    /// <summary>The Adler-32 of A followed by B.</summary>
    /// <param name="first">The Adler-32 of A.</param>
    /// <param name="second">The Adler-32 of B.</param>
    /// <param name="secondLength">The length of B in bytes, ≥ 0.</param>
    /// <returns>The Adler-32 of A followed by B.</returns>
    public static uint Combine(uint first, uint second, long secondLength)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(secondLength);

        // a = 1 + Σ bytes, b = Σ of the running a's (both mod 65521). Joined: a = a1 + a2 − 1, and every one of B's
        // n running a's grows by a1 − 1, so b = b1 + b2 + n·(a1 − 1).
        ulong n = (ulong)(secondLength % Modulus);
        ulong a1 = first & 0xFFFF, b1 = first >> 16, a2 = second & 0xFFFF, b2 = second >> 16;
        ulong a = (a1 + a2 + Modulus - 1) % Modulus;
        ulong b = (b1 + b2 + (n * ((a1 + Modulus - 1) % Modulus))) % Modulus;
        return (uint)((b << 16) | a);
    }
}
