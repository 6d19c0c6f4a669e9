using RayLab.Sampling;

namespace RayLab.Reports.Patterns;

/// <summary>
/// A sampler's Fourier power spectrum, averaged over many pixels (realisations), with Ulichney's radial mean and
/// anisotropy: what the points of one pixel look like in frequency.
/// </summary>
/// <remarks>
/// The periodogram of N points xⱼ at integer frequency f = (u, v) is P(f) = |Σⱼ exp(−2πi f·xⱼ)|² / N (the points
/// treated as a tile of the periodic plane, as pbrt-v4's <c>pspec</c> and the <c>psa</c> tool do; Schlömer and
/// Deussen, "Accurate spectral analysis of two-dimensional point sets", JGT 2011). Uniform random points give
/// P ≈ 1 at every f ≠ 0 (white noise); a blue-noise or stratified set is low near f = 0. The radial mean P̄(r)
/// averages P over the ring of frequencies with round(|f|) = r, and the anisotropy is the ring's variance over
/// P̄(r)², shown in decibels, 10·log₁₀ (Ulichney, "Digital Halftoning", MIT Press 1987, §8). A periodogram's spread
/// is about its mean, so a direction-free pattern averaged over R realisations scores about 10·log₁₀(1/R)
/// (−30 dB at R = 1024); directional structure, such as a grid's, lifts rings far above that. A ring whose mean is 0
/// (a grid's empty rings) has no power to be anisotropic and scores −∞.
/// </remarks>
public sealed class PowerSpectrum
{
    private PowerSpectrum(int samples, int realisations, int maxFrequency, double[] power, double[] radialMean, double[] anisotropy)
    {
        SamplesPerPixel = samples;
        Realisations = realisations;
        MaxFrequency = maxFrequency;
        _power = power;
        RadialMean = radialMean;
        AnisotropyDecibels = anisotropy;
    }

    private readonly double[] _power;

    /// <summary>Points per realisation, N.</summary>
    public int SamplesPerPixel { get; }

    /// <summary>How many pixels the spectrum is averaged over.</summary>
    public int Realisations { get; }

    /// <summary>K: the spectrum covers frequencies −K ≤ u, v ≤ K (cycles per pixel).</summary>
    public int MaxFrequency { get; }

    /// <summary>The mean power at (u, v), −K ≤ u, v ≤ K; the power at (0, 0) is N.</summary>
    /// <param name="u">Horizontal frequency.</param>
    /// <param name="v">Vertical frequency.</param>
    public double Power(int u, int v)
    {
        int side = (2 * MaxFrequency) + 1;
        return _power[((v + MaxFrequency) * side) + u + MaxFrequency];
    }

    /// <summary>P̄(r) for r = 0 … K (entry 0 is the DC term, N).</summary>
    public IReadOnlyList<double> RadialMean { get; }

    /// <summary>Ulichney's anisotropy of ring r in dB, for r = 0 … K (entry 0 is 0: a ring of one frequency; −∞ where the ring's mean is 0).</summary>
    public IReadOnlyList<double> AnisotropyDecibels { get; }

    /// <summary>Measures <paramref name="sampler"/>'s spectrum over the pixels (i mod 64, i div 64), i &lt; <paramref name="realisations"/>.</summary>
    /// <param name="sampler">Any sampler.</param>
    /// <param name="realisations">Pixels to average over, ≥ 1 (Ulichney's measures want ≥ 1000).</param>
    /// <param name="maxFrequency">K ≥ 1; 2√N shows the peak of a well-stratified set.</param>
    /// <param name="maxDegreeOfParallelism">Threads, or −1 for all.</param>
    /// <returns>The spectrum; the same for the same sampler and seed whatever the thread count.</returns>
    /// <exception cref="ArgumentOutOfRangeException">A count below 1.</exception>
    public static PowerSpectrum Measure(IPixelSampler sampler, int realisations, int maxFrequency, int maxDegreeOfParallelism = -1)
    {
        ArgumentNullException.ThrowIfNull(sampler);
        ArgumentOutOfRangeException.ThrowIfLessThan(realisations, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(maxFrequency, 1);
        int k = maxFrequency, side = (2 * k) + 1, n = sampler.SamplesPerPixel;
        // Per realisation the half plane v ≥ 0 is enough (P(−f) = P(f)); each realisation writes its own row of
        // partial sums and they are added in order, so the result does not depend on the threads.
        const int Chunk = 64;
        int chunks = (realisations + Chunk - 1) / Chunk;
        var partial = new double[chunks][];
        Parallel.For(0, chunks, new ParallelOptions { MaxDegreeOfParallelism = maxDegreeOfParallelism }, c =>
            partial[c] = HalfPlaneSum(sampler, c * Chunk, Math.Min(realisations, (c + 1) * Chunk), k));

        var half = new double[side * (k + 1)];
        foreach (double[] p in partial)
        {
            for (int i = 0; i < half.Length; i++)
            {
                half[i] += p[i];
            }
        }

        var power = new double[side * side];
        for (int v = -k; v <= k; v++)
        {
            for (int u = -k; u <= k; u++)
            {
                // P(u, v) = P(−u, −v): the lower half mirrors the upper one.
                double value = v >= 0 ? half[(v * side) + u + k] : half[(-v * side) - u + k];
                power[((v + k) * side) + u + k] = value / realisations;
            }
        }

        (double[] mean, double[] anisotropy) = Radial(power, k);
        return new PowerSpectrum(n, realisations, k, power, mean, anisotropy);
    }

    // Σ over the realisations first … end − 1 of the periodogram at (u, v), −K ≤ u ≤ K, 0 ≤ v ≤ K: row v, column u + K.
    private static double[] HalfPlaneSum(IPixelSampler sampler, int first, int end, int k)
    {
        int side = (2 * k) + 1, n = sampler.SamplesPerPixel;
        var sum = new double[side * (k + 1)];
        var points = new SamplePoint[n];
        var cx = new double[side * n];
        var sx = new double[side * n];
        var cy = new double[(k + 1) * n];
        var sy = new double[(k + 1) * n];
        for (int r = first; r < end; r++)
        {
            PatternPoints.Fill(sampler, r % 64, r / 64, points);
            for (int j = 0; j < n; j++)
            {
                for (int u = -k; u <= k; u++)
                {
                    double phase = -2 * Math.PI * u * points[j].X;
                    cx[((u + k) * n) + j] = Math.Cos(phase);
                    sx[((u + k) * n) + j] = Math.Sin(phase);
                }

                for (int v = 0; v <= k; v++)
                {
                    double phase = -2 * Math.PI * v * points[j].Y;
                    cy[(v * n) + j] = Math.Cos(phase);
                    sy[(v * n) + j] = Math.Sin(phase);
                }
            }

            for (int v = 0; v <= k; v++)
            {
                ReadOnlySpan<double> cyv = cy.AsSpan(v * n, n), syv = sy.AsSpan(v * n, n);
                for (int u = -k; u <= k; u++)
                {
                    ReadOnlySpan<double> cxu = cx.AsSpan((u + k) * n, n), sxu = sx.AsSpan((u + k) * n, n);
                    double a = 0, b = 0;
                    for (int j = 0; j < n; j++)
                    {
                        // exp(iα)·exp(iβ) = (cα cβ − sα sβ) + i (sα cβ + cα sβ)
                        a += (cxu[j] * cyv[j]) - (sxu[j] * syv[j]);
                        b += (sxu[j] * cyv[j]) + (cxu[j] * syv[j]);
                    }

                    sum[(v * side) + u + k] += ((a * a) + (b * b)) / n;
                }
            }
        }

        return sum;
    }

    private static (double[] Mean, double[] Anisotropy) Radial(double[] power, int k)
    {
        int side = (2 * k) + 1;
        var sum = new double[k + 1];
        var count = new int[k + 1];
        for (int v = -k; v <= k; v++)
        {
            for (int u = -k; u <= k; u++)
            {
                int r = (int)Math.Round(Math.Sqrt((u * u) + (v * v)));
                if (r <= k)
                {
                    sum[r] += power[((v + k) * side) + u + k];
                    count[r]++;
                }
            }
        }

        var mean = new double[k + 1];
        for (int r = 0; r <= k; r++)
        {
            mean[r] = sum[r] / count[r];
        }

        var spread = new double[k + 1];
        for (int v = -k; v <= k; v++)
        {
            for (int u = -k; u <= k; u++)
            {
                int r = (int)Math.Round(Math.Sqrt((u * u) + (v * v)));
                if (r <= k)
                {
                    double d = power[((v + k) * side) + u + k] - mean[r];
                    spread[r] += d * d;
                }
            }
        }

        var anisotropy = new double[k + 1];
        for (int r = 1; r <= k; r++)
        {
            double variance = spread[r] / (count[r] - 1);
            double ratio = mean[r] > 0 ? variance / (mean[r] * mean[r]) : 0;
            anisotropy[r] = ratio > 0 ? 10 * Math.Log10(ratio) : double.NegativeInfinity;
        }

        return (mean, anisotropy);
    }
}
