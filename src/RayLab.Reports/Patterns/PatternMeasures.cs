using RayLab.Sampling;

namespace RayLab.Reports.Patterns;

/// <summary>How many realisations (pixels) each measure of <see cref="PatternMeasures"/> averages over, and the seed.</summary>
/// <param name="DiscrepancyRealisations">Pixels whose L2-star (and star) discrepancy is averaged, ≥ 1.</param>
/// <param name="StarMaxSamples">The star discrepancy is measured for N up to this (it costs O(N² log N)); 0 for none.</param>
/// <param name="IntegrationRealisations">Pixels (each with its own placement of the test function) per RMSE, ≥ 2.</param>
/// <param name="FunctionSeed">The seed that places the test functions; the same for every sampler, so they integrate the same functions.</param>
/// <param name="MaxDegreeOfParallelism">Threads, or −1 for all. The results do not depend on it.</param>
public sealed record PatternMeasureOptions(
    int DiscrepancyRealisations = 16,
    int StarMaxSamples = 256,
    int IntegrationRealisations = 256,
    uint FunctionSeed = 1,
    int MaxDegreeOfParallelism = -1);

/// <summary>One sampler at one sample count: its discrepancies and its integration errors.</summary>
/// <param name="Sampler">The sampler's name.</param>
/// <param name="Samples">N, points per pixel.</param>
/// <param name="L2Star">The mean L2-star discrepancy over the realisations (<see cref="Discrepancy.L2Star"/>).</param>
/// <param name="Star">The mean star discrepancy (<see cref="Discrepancy.Star"/>), or null above <see cref="PatternMeasureOptions.StarMaxSamples"/>.</param>
/// <param name="Rmse">The RMSE of the estimate of each <see cref="Integrand"/>, by its name, over the realisations.</param>
public sealed record PatternMeasure(string Sampler, int Samples, double L2Star, double? Star, IReadOnlyDictionary<string, double> Rmse);

/// <summary>
/// The measures of section "what each sampler's points look like": discrepancy and integration error against the
/// sample count, for any <see cref="IPixelSampler"/> (the built-in ones or a student's own), and the fitted slopes.
/// </summary>
public static class PatternMeasures
{
    /// <summary>
    /// The sample counts the figures use: powers of two and perfect squares from 4 to 1024, ascending; the grid
    /// samplers (<c>regular</c>, <c>jittered</c>, <c>multijittered</c>) take the squares only.
    /// </summary>
    /// <param name="squaresOnly">Only the perfect squares.</param>
    public static IReadOnlyList<int> Counts(bool squaresOnly = false)
    {
        var counts = new SortedSet<int>();
        for (int n = 2; n * n <= 1024; n++)
        {
            counts.Add(n * n);
        }

        if (!squaresOnly)
        {
            for (int p = 4; p <= 1024; p *= 2)
            {
                counts.Add(p);
            }
        }

        return [.. counts];
    }

    /// <summary>Measures the sampler <paramref name="create"/> makes at each count.</summary>
    /// <param name="create">Makes the sampler with N samples per pixel (e.g. <c>n =&gt; new MySampler(n, seed)</c>).</param>
    /// <param name="counts">The sample counts, each ≥ 1.</param>
    /// <param name="options">Realisations and seed; null for the defaults.</param>
    /// <returns>One measure per count, in the order given. The same inputs give the same numbers whatever the threads.</returns>
    /// <exception cref="ArgumentException">A count below 1, or options out of range.</exception>
    public static IReadOnlyList<PatternMeasure> Measure(Func<int, IPixelSampler> create, IReadOnlyList<int> counts, PatternMeasureOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(create);
        ArgumentNullException.ThrowIfNull(counts);
        options ??= new PatternMeasureOptions();
        ArgumentOutOfRangeException.ThrowIfLessThan(options.DiscrepancyRealisations, 1, nameof(options));
        ArgumentOutOfRangeException.ThrowIfLessThan(options.IntegrationRealisations, 2, nameof(options));
        if (counts.Any(c => c < 1))
        {
            throw new ArgumentException("Every sample count must be at least 1.", nameof(counts));
        }

        IPixelSampler[] samplers = Create(create, counts);

        int dr = options.DiscrepancyRealisations, ir = options.IntegrationRealisations;
        IReadOnlyList<Integrand> functions = Integrand.All;
        var l2 = new double[samplers.Length * dr];
        var star = new double[samplers.Length * dr];
        var squaredErrors = new double[samplers.Length * functions.Count * ir];
        var parallel = new ParallelOptions { MaxDegreeOfParallelism = options.MaxDegreeOfParallelism };

        // One work item per (count, realisation); each writes its own slots, which are summed in order afterwards.
        Parallel.For(0, samplers.Length * Math.Max(dr, ir), parallel, item =>
        {
            int s = item / Math.Max(dr, ir), r = item % Math.Max(dr, ir);
            IPixelSampler sampler = samplers[s];
            SamplePoint[] points = PatternPoints.Of(sampler, r % 64, r / 64);
            if (r < dr)
            {
                l2[(s * dr) + r] = Discrepancy.L2Star(points);
                if (sampler.SamplesPerPixel <= options.StarMaxSamples)
                {
                    star[(s * dr) + r] = Discrepancy.Star(points);
                }
            }

            if (r < ir)
            {
                for (int f = 0; f < functions.Count; f++)
                {
                    (Func<double, double, double> function, double exact) = functions[f].Place(r, options.FunctionSeed);
                    double error = Integrand.Estimate(function, points) - exact;
                    squaredErrors[(((s * functions.Count) + f) * ir) + r] = error * error;
                }
            }
        });

        return Summarise(samplers, counts, options, l2, star, squaredErrors);
    }

    private static IPixelSampler[] Create(Func<int, IPixelSampler> create, IReadOnlyList<int> counts)
    {
        IPixelSampler[] samplers = [.. counts.Select(create)];
        for (int i = 0; i < samplers.Length; i++)
        {
            if (samplers[i].SamplesPerPixel != counts[i])
            {
                throw new ArgumentException($"Asked for {counts[i]} samples, '{samplers[i].Name}' made {samplers[i].SamplesPerPixel}.", nameof(create));
            }
        }

        return samplers;
    }

    // Each count's means over its realisations, the slots added in order (the same numbers whatever the threads).
    private static PatternMeasure[] Summarise(IPixelSampler[] samplers, IReadOnlyList<int> counts, PatternMeasureOptions options, double[] l2, double[] star, double[] squaredErrors)
    {
        int dr = options.DiscrepancyRealisations, ir = options.IntegrationRealisations;
        IReadOnlyList<Integrand> functions = Integrand.All;
        var result = new PatternMeasure[samplers.Length];
        for (int s = 0; s < samplers.Length; s++)
        {
            var rmse = new Dictionary<string, double>();
            for (int f = 0; f < functions.Count; f++)
            {
                rmse[functions[f].Name] = Math.Sqrt(squaredErrors.AsSpan(((s * functions.Count) + f) * ir, ir).ToArray().Sum() / ir);
            }

            bool hasStar = samplers[s].SamplesPerPixel <= options.StarMaxSamples;
            result[s] = new PatternMeasure(
                samplers[s].Name,
                counts[s],
                l2.AsSpan(s * dr, dr).ToArray().Sum() / dr,
                hasStar ? star.AsSpan(s * dr, dr).ToArray().Sum() / dr : null,
                rmse);
        }

        return result;
    }

    /// <summary>
    /// The convergence slope: least squares of ln(error) against ln(N) over the points with a positive error
    /// (Pilleboue et al. 2015 relate it to the spectrum's behaviour near zero frequency). NaN-free: fewer than two
    /// usable points give 0.
    /// </summary>
    /// <param name="samples">N of each point.</param>
    /// <param name="errors">The error at each N.</param>
    public static double Slope(IReadOnlyList<int> samples, IReadOnlyList<double> errors)
    {
        ArgumentNullException.ThrowIfNull(samples);
        ArgumentNullException.ThrowIfNull(errors);
        if (samples.Count != errors.Count)
        {
            throw new ArgumentException("As many errors as sample counts are needed.", nameof(errors));
        }

        var xs = new List<double>();
        var ys = new List<double>();
        for (int i = 0; i < samples.Count; i++)
        {
            if (errors[i] > 0 && samples[i] > 0)
            {
                xs.Add(Math.Log(samples[i]));
                ys.Add(Math.Log(errors[i]));
            }
        }

        if (xs.Count < 2)
        {
            return 0;
        }

        double mx = xs.Average(), my = ys.Average(), sxy = 0, sxx = 0;
        for (int i = 0; i < xs.Count; i++)
        {
            sxy += (xs[i] - mx) * (ys[i] - my);
            sxx += (xs[i] - mx) * (xs[i] - mx);
        }

        return sxx > 0 ? sxy / sxx : 0;
    }
}
