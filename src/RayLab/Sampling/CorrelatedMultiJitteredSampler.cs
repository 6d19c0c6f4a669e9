using System.Runtime.CompilerServices;

namespace RayLab.Sampling;

/// <summary>
/// Kensler's correlated multi-jittered sampling ("Correlated Multi-Jittered Sampling", Pixar Technical Memo
/// 13-01, 2013), the stateless form with hash permutations that works for any number of samples: an m × n grid
/// with m = ⌊√N⌋ columns and n = ⌈N / m⌉ rows. When N = m·n (every square, and 2, 3, 6, 12, 20, …) each of the
/// m × n cells holds exactly one sample and so does each of the N fine columns and N fine rows; otherwise each of
/// the N fine rows and at most one of the m·n fine columns holds a sample.
/// </summary>
/// <remarks>
/// The pattern number is the pixel's <see cref="CounterHash.PixelKey"/>; the rest is Kensler's final
/// listing unchanged: the sample index is permuted, one permutation of the columns and one of the rows are
/// shared by the whole pattern (the correlation), and Kensler's <c>randfloat</c> jitters within the fine cell.
/// </remarks>
public sealed class CorrelatedMultiJitteredSampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates a correlated multi-jittered sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public CorrelatedMultiJitteredSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
        Columns = (int)Math.Sqrt(samplesPerPixel);
        Rows = (samplesPerPixel + Columns - 1) / Columns;
    }

    /// <inheritdoc />
    public override string Name => "cmj";

    /// <summary>m = ⌊√N⌋: columns of the coarse grid.</summary>
    public int Columns { get; }

    /// <summary>n = ⌈N / m⌉: rows of the coarse grid; <see cref="Columns"/> · n ≥ N.</summary>
    public int Rows { get; }

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index) =>
        Sample(index, SamplesPerPixel, Columns, Rows, CounterHash.PixelKey(x, y, Seed));

    /// <summary>
    /// Kensler's <c>cmj(s, N, p)</c>: sample <paramref name="index"/> of the pattern <paramref name="p"/> with
    /// <paramref name="count"/> samples on an <paramref name="m"/> × <paramref name="n"/> grid.
    /// </summary>
    /// <param name="index">The sample index, 0 ≤ index &lt; count.</param>
    /// <param name="count">N, the number of samples.</param>
    /// <param name="m">Columns, ⌊√N⌋.</param>
    /// <param name="n">Rows, ⌈N / m⌉.</param>
    /// <param name="p">The pattern number.</param>
    internal static SamplePoint Sample(int index, int count, int m, int n, uint p)
    {
        int s = Permutation.PermutationElement(index, count, p * Kensler.IndexSalt);
        int sx = Permutation.PermutationElement(s % m, m, p * Kensler.ColumnSalt);
        int sy = Permutation.PermutationElement(s / m, n, p * Kensler.RowSalt);
        double jx = RandFloat((uint)s, p * Kensler.JitterXSalt);
        double jy = RandFloat((uint)s, p * Kensler.JitterYSalt);
        return new SamplePoint((sx + ((sy + jx) / n)) / m, (s + jy) / count);
    }

    /// <summary>Kensler's <c>randfloat(i, p)</c>: a hash of (i, p) scaled into [0, 1).</summary>
    /// <param name="i">The (permuted) sample index.</param>
    /// <param name="p">The pattern number.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static double RandFloat(uint i, uint p)
    {
        i ^= p;
        i ^= i >> 17;
        i ^= i >> 10;
        i *= Kensler.RandFloatMultiplier1;
        i ^= i >> 12;
        i ^= i >> 21;
        i *= Kensler.RandFloatMultiplier2;
        i ^= Kensler.RandFloatXor;
        i ^= i >> 17;
        i *= 1u | (p >> 18);
        return i * Kensler.RandFloatScale;
    }

    /// <inheritdoc />
    /// <remarks>Above <see cref="PatternLimits.MaxSamples"/> samples the lanes would not be exact: the buffered lanes then ask <see cref="GetSample"/>.</remarks>
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        SamplesPerPixel <= PatternLimits.MaxSamples
            ? user.Run(() => new CorrelatedMultiJitteredLanes<TL>(this))
            : user.Run(() => new BufferedLanes<TL>(this));
}
