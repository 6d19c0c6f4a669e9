using System.Globalization;
using System.Net;
using System.Text;
using RayLab.Metrics;

namespace RayLab.Reports.Comparison;

/// <summary>
/// The speed-against-error report (<c>raylab compare</c>, <see cref="CompareRunner.Run"/>): the table (Markdown and CSV) with
/// RMSE and mean FLIP, each sampler's fitted convergence slopes, the time each needs to reach "maximum error ≤ 1 level",
/// a common RMSE and a common mean FLIP, where the two measures rank the samplers differently, four log-log charts
/// (each measure against time and against rays) and an <c>index.html</c> that shows them with every image, its error
/// image and its FLIP map.
/// </summary>
/// <param name="heading">One line saying what was compared (scene, size, camera, seed, threads, repeats).</param>
/// <param name="command">The command line that reproduces the run, or empty when there is none (a run through <see cref="CompareRunner"/>).</param>
/// <param name="results">The measurements, in the order the settings were rendered.</param>
/// <param name="notes">Remarks on the plan (budgets a grid sampler ran at a different count).</param>
public sealed class CompareReport(string heading, string command, IReadOnlyList<CompareResult> results, IReadOnlyList<string> notes)
{
    private const string Definition =
        "Error: per channel of every pixel, the image's 8-bit level minus the exact image's level (both by the lab's rule "
        + "int(256·I)), in levels; RMSE and mean absolute error over all pixels and channels, max = the largest, "
        + "\"> 1 level\" = the fraction of pixels with some channel off by 2 or more. FLIP: the mean of the image's "
        + "LDR-FLIP map against the exact image (Andersson et al. 2020; 0 = indistinguishable, 1 = the largest "
        + "difference; 0.7 m from a 0.7 m wide display of 3840 pixels), the error a viewer sees. Time: median render time "
        + "(the render loop only). Rays: primary rays traced per pixel. Kernel: the render loop that ran, scalar (one ray at a time, "
        + "in double precision, as every pixel method of your own runs) or a SIMD packet of 4, 8 or 16 rays (vector128, vector256, "
        + "vector512). Rays/ms: the primary rays of one render divided by its time. The scalar and packet kernels differ in speed per "
        + "ray, so compare rays/ms within one kernel: a method on the scalar kernel is not slow because a packet kernel traces more "
        + "rays per millisecond. Where the error sits: low-pass σ=1 and σ=2 = the RMSE of "
        + "the signed error after a Gaussian blur of 1 and 2 pixels (what a viewer a step back sees; fine-grained error cancels, "
        + "patches survive); low share = the part of the error's power at frequencies up to 1/8 cycle per pixel (periods of 8 "
        + "pixels or more; white noise: 0.049), from its radially averaged power spectrum.";

    /// <summary>The results, grouped into the chart's lines in the order they first appear.</summary>
    public IReadOnlyList<IGrouping<string, CompareResult>> Series { get; } = [.. results.GroupBy(r => r.Case.Series)];

    /// <summary>The charts' file stems, RMSE's then FLIP's, each against time and against rays (each written as .png and .svg).</summary>
    public static IReadOnlyList<string> ChartStems { get; } = ["error-vs-time", "error-vs-rays", "flip-vs-time", "flip-vs-rays"];

    /// <summary>
    /// Where the run's time went, shown on <c>index.html</c> (<see cref="WriteTo"/> adds its charts and tables to it
    /// before it writes the page); null for a report without it.
    /// </summary>
    public CompareClock? Clock { get; init; }

    /// <summary>The stage that draws and writes the charts.</summary>
    internal const string ChartsStage = "charts";

    /// <summary>The stage that writes results.csv and results.md.</summary>
    internal const string TablesStage = "tables";

    /// <summary>Writes results.csv, results.md, the <see cref="ChartStems"/> charts (each .png and .svg) and index.html into <paramref name="folder"/>.</summary>
    /// <param name="folder">An existing folder (the images are already in its <c>images/</c>, <c>errors/</c> and <c>flip/</c>).</param>
    public void WriteTo(string folder)
    {
        CompareClock clock = Clock ?? new CompareClock();
        clock.Time(TablesStage, () =>
        {
            File.WriteAllText(Path.Combine(folder, "results.csv"), Csv());
            File.WriteAllText(Path.Combine(folder, "results.md"), Markdown());
        });
        clock.Time(ChartsStage, () => WriteCharts(folder));
        File.WriteAllText(Path.Combine(folder, "index.html"), Html());
    }

    private void WriteCharts(string folder)
    {
        Chart(Path.Combine(folder, ChartStems[0]), "RMSE against time", r => r.Time.TotalMilliseconds, "median render time (ms)", Rmse);
        Chart(Path.Combine(folder, ChartStems[1]), "RMSE against rays", r => r.RaysPerPixel, "primary rays per pixel", Rmse);
        Chart(Path.Combine(folder, ChartStems[2]), "FLIP against time", r => r.Time.TotalMilliseconds, "median render time (ms)", MeanFlip);
        Chart(Path.Combine(folder, ChartStems[3]), "FLIP against rays", r => r.RaysPerPixel, "primary rays per pixel", MeanFlip);
        foreach (IGrouping<int, CompareResult> g in SpectrumGroups())
        {
            LogLogChart.Save(
                Path.Combine(folder, SpectrumStem(g.Key)), Invariant($"Error spectrum at {g.Key} spp"), "frequency (cycles per pixel)", "power (levels²)",
                [.. g.Select(r => new LogLogChart.Series(r.Case.Series, [.. r.Placement!.Spectrum.RadialMean
                    .Select((p, ring) => (X: ErrorSpectrum.Frequency(ring), Y: p))
                    .Where(point => point.X > 0 && point.Y > 0 && !double.IsNaN(point.Y))]))]);
        }
    }

    /// <summary>The page's table of where the time went: each stage's wall time, its share of the run so far and its calls.</summary>
    private string TimeTable()
    {
        if (Clock is null)
        {
            return "";
        }

        IReadOnlyList<CompareStage> stages = Clock.Stages;
        TimeSpan total = Clock.Elapsed;
        TimeSpan rest = total - stages.Aggregate(TimeSpan.Zero, (sum, s) => sum + s.Time);
        var html = new StringBuilder("<h2>Where the time went</h2>\n<p>Wall time of each stage of this run, measured as it ran (each stage on every core it uses, one after another); "
            + "the share is of the run until this page was written.</p>\n<table>\n<tr><th>stage</th><th>time (s)</th><th>share</th><th>calls</th></tr>\n");
        foreach (CompareStage stage in stages)
        {
            html.Append(Invariant($"<tr><td>{WebUtility.HtmlEncode(stage.Name)}</td><td>{stage.Time.TotalSeconds:F2}</td><td>{100 * stage.Time / total:F1}%</td><td>{stage.Calls}</td></tr>\n"));
        }

        return html.Append(Invariant($"<tr><td>the rest (scene, folders, progress display)</td><td>{rest.TotalSeconds:F2}</td><td>{100 * rest / total:F1}%</td><td></td></tr>\n"))
            .Append(Invariant($"<tr><th>total</th><th>{total.TotalSeconds:F2}</th><th>100%</th><th></th></tr>\n</table>\n")).ToString();
    }

    private sealed record Measure(string Name, string Axis, Func<double, string> Format, Func<CompareResult, double?> Of);

    private static readonly Measure Rmse = new("RMSE", "RMSE (8-bit levels)", e => e.ToString("F3", CultureInfo.InvariantCulture), r => r.Error.Rmse);

    private static readonly Measure MeanFlip = new("mean FLIP", "mean FLIP", e => FlipText(e), r => r.MeanFlip);

    /// <summary>The results as CSV, one row per setting, numbers in invariant culture.</summary>
    public string Csv()
    {
        var csv = new StringBuilder("series,sampler,setting,budget,samples_per_pixel,max_depth,contrast,rays,rays_per_pixel,median_ms,rmse,mean_abs,max,over_one_level,mean_flip,kernel,image,error_image,flip_map,lowpass_1,lowpass_2,low_frequency_share\n");
        foreach (CompareResult r in results)
        {
            CompareCase c = r.Case;
            csv.Append(Invariant($"{c.Series},{c.Sampler},{c.Setting},{c.Budget},{c.SamplesPerPixel},{c.MaxDepth},{c.Contrast:G6},"))
               .Append(Invariant($"{r.Rays},{r.RaysPerPixel:G9},{r.Time.TotalMilliseconds:G9},{r.Error.Rmse:G9},{r.Error.MeanAbsolute:G9},{r.Error.Max},{r.Error.FractionOverOneLevel:G9},{r.MeanFlip:G9},{r.Kernel},"))
               .Append($"images/{c.FileStem}.png,errors/{c.FileStem}.png,{(r.MeanFlip is null ? "" : $"flip/{c.FileStem}.png")},")
               .Append(Invariant($"{r.Placement?.LowPass1:G9},{r.Placement?.LowPass2:G9},{r.Placement?.Spectrum.LowFrequencyShare:G9}\n"));
        }

        return csv.ToString();
    }

    /// <summary>The table, as Markdown.</summary>
    public string Table()
    {
        var md = new StringBuilder("| sampler | setting | rays/px | time (ms) | kernel | rays/ms | RMSE | mean FLIP | low-pass σ=1 | low-pass σ=2 | low share | mean abs. | max | > 1 level |\n|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        foreach (CompareResult r in results)
        {
            md.Append(Invariant($"| {r.Case.Series} | {r.Case.Setting} | {r.RaysPerPixel:F2} | {r.Time.TotalMilliseconds:F1} | {KernelText(r)} | {RateText(r)} | {r.Error.Rmse:F3} | {FlipText(r.MeanFlip)} | {PlacementText(r.Placement)} | {r.Error.MeanAbsolute:F4} | {r.Error.Max} | {100 * r.Error.FractionOverOneLevel:F3}% |\n"));
        }

        return md.ToString();
    }

    /// <summary>results.md: the heading, the table, the slopes, the times to reach an error, and the command.</summary>
    public string Markdown()
    {
        var md = new StringBuilder();
        md.Append($"# raylab compare: {heading}\n\n{Definition}\n\n").Append(Table()).Append('\n');
        TimingNotes(md);

        Slopes(md);
        TimeToOneLevel(md);
        TimesToReach(md);
        Rankings(md);
        WhereTheErrorSits(md);

        if (command.Length > 0)
        {
            md.Append($"\nMade by:\n\n```\n{command}\n```\n");
        }

        return md.ToString();
    }

    /// <summary>The notes, then how the times were taken where a setting was timed once or rendered again.</summary>
    private void TimingNotes(StringBuilder md)
    {
        foreach (string note in notes)
        {
            md.Append($"- {note}\n");
        }

        int once = results.Count(r => r.TimedOnce);
        if (once > 0)
        {
            md.Append(Invariant($"\n{once} of {results.Count} settings took {CompareRunner.LongRender.TotalSeconds:0.##} s or more in their first render, which is their time (no repeats: at that length the timer's error is a part in a million and a preemption about one per cent; load on the machine is not, as it is not for the medians).\n"));
        }

        int retimed = results.Count(r => r.Retimed);
        if (retimed > 0)
        {
            double minimum = CompareRunner.MinimumMeasured.TotalMilliseconds;
            int most = results.Max(r => r.Renders);
            md.Append(Invariant($"\nEach time is the median of its setting's renders. {retimed} of {results.Count} settings whose quick renders disagreed (the renders beside the median more than {CompareRunner.AgreeWithin:P0} apart) were rendered again until they agreed or added up to {minimum:F0} ms (at most {CompareRunner.MaximumRenders} renders; up to {most} here).\n"));
        }
    }

    /// <summary>The convergence-slope section: each line's slopes of ln(error) against ln(rays per pixel).</summary>
    private void Slopes(StringBuilder md)
    {
        md.Append("\n## Convergence slopes\n\n")
          .Append("Least-squares slope of ln(error) against ln(rays per pixel) over each line's settings with error > 0 (rays, "
                  + "not time: rays are exact, times are noisy). Theory for pixels on an edge (Mitchell 1996): random −0.5, "
                  + "jittered −0.75. Once the error is below about a level, quantisation makes the RMSE fall only as the "
                  + "square root of the true error (half the slope); the mean absolute error keeps the true slope. FLIP "
                  + "has no such floor but is not a power of the error either (it saturates on large differences).\n\n")
          .Append("| sampler | slope of RMSE | slope of mean abs. | slope of mean FLIP | settings |\n|---|---:|---:|---:|---:|\n");
        foreach (IGrouping<string, CompareResult> s in Series)
        {
            CompareResult[] measured = [.. s.Where(r => r.Error.Rmse > 0).OrderBy(r => r.RaysPerPixel)];
            CompareResult[] falling = BeforePlateau(measured);
            double[] rays = [.. falling.Select(r => r.RaysPerPixel)];
            string rmse = "n/a", mean = "n/a (rays span less than 2×)", flip = "n/a";
            if (rays.Length > 1 && rays.Max() >= 2 * rays.Min())
            {
                rmse = Format(Slope(falling.Select(r => (r.RaysPerPixel, r.Error.Rmse))));
                mean = Format(Slope(falling.Select(r => (r.RaysPerPixel, r.Error.MeanAbsolute))));
                flip = Format(Slope(falling.Where(r => r.MeanFlip is not null).Select(r => (r.RaysPerPixel, r.MeanFlip!.Value))));
                if (falling.Length < measured.Length)
                {
                    mean += Invariant($" (fitted below {measured[falling.Length].RaysPerPixel:0.##} rays/px, where the error stops falling)");
                }
            }
            else if (falling.Length < measured.Length)
            {
                mean = Invariant($"n/a (the error stops falling at {measured[falling.Length].RaysPerPixel:0.##} rays/px)");
            }

            md.Append(Invariant($"| {s.Key} | {rmse} | {mean} | {flip} | {rays.Length} |\n"));
        }
    }

    /// <summary>The section of each line's fastest setting with every pixel within one level.</summary>
    private void TimeToOneLevel(StringBuilder md)
    {
        md.Append("\n## Time to maximum error ≤ 1 level\n\n")
          .Append("The fastest setting whose every pixel is within one level of the exact image.\n\n")
          .Append("| sampler | time (ms) | setting | rays/px |\n|---|---:|---|---:|\n");
        foreach (IGrouping<string, CompareResult> s in Series)
        {
            md.Append(WithinOneLevel(s) is { } r
                ? Invariant($"| {s.Key} | {r.Time.TotalMilliseconds:F1} | {r.Case.Setting} | {r.RaysPerPixel:F2} |\n")
                : Invariant($"| {s.Key} | not reached | best max {s.Min(r => r.Error.Max)} levels | |\n"));
        }
    }

    /// <summary>For RMSE and mean FLIP: the time each line takes to reach the lowest value every line (and every point sampler) reaches.</summary>
    private void TimesToReach(StringBuilder md)
    {
        foreach (Measure measure in new[] { Rmse, MeanFlip })
        {
            double? everyLine = LowestCommon(Series, measure);
            double? everyPointSampler = LowestCommon([.. Series.Where(s => s.First().Case.SamplesPerPixel is not null)], measure);
            if (everyLine is { } all)
            {
                ReachTable(md, measure, all, $"the lowest {measure.Name} every line reaches");
            }

            if (everyPointSampler is { } point && point < (everyLine ?? double.PositiveInfinity))
            {
                ReachTable(md, measure, point, $"the lowest {measure.Name} every point sampler reaches");
            }
        }
    }

    /// <summary>
    /// A line's results, in order of rays per pixel, up to where its RMSE stops falling: the longest prefix in which
    /// each RMSE is below <see cref="PlateauRatio"/> times the one before. A slope fitted through a plateau (adaptive's
    /// error levels off once its depth stops resolving the edges) would average a falling line with a flat one and
    /// describe neither.
    /// </summary>
    /// <param name="line">One line's results with RMSE &gt; 0, sorted by rays per pixel.</param>
    public static CompareResult[] BeforePlateau(CompareResult[] line)
    {
        ArgumentNullException.ThrowIfNull(line);
        int n = Math.Min(line.Length, 1);
        while (n < line.Length && line[n].Error.Rmse < PlateauRatio * line[n - 1].Error.Rmse)
        {
            n++;
        }

        return line[..n];
    }

    /// <summary>The factor by which a line's RMSE must fall from one setting to the next to count as still falling.</summary>
    public const double PlateauRatio = 0.95;

    /// <summary>The least-squares slope of ln y against ln x over the points with x, y &gt; 0; null with fewer than two distinct x.</summary>
    /// <param name="points">The points.</param>
    public static double? Slope(IEnumerable<(double X, double Y)> points)
    {
        (double X, double Y)[] logs = [.. points.Where(p => p.X > 0 && p.Y > 0).Select(p => (Math.Log(p.X), Math.Log(p.Y)))];
        if (logs.Select(p => p.X).Distinct().Count() < 2)
        {
            return null;
        }

        double mx = logs.Average(p => p.X), my = logs.Average(p => p.Y);
        return logs.Sum(p => (p.X - mx) * (p.Y - my)) / logs.Sum(p => (p.X - mx) * (p.X - mx));
    }

    /// <summary>The fastest result whose maximum error is at most one level, or null.</summary>
    /// <param name="series">One line's results.</param>
    public static CompareResult? WithinOneLevel(IEnumerable<CompareResult> series) =>
        series.Where(r => r.Error.Max <= 1).MinBy(r => r.Time);

    /// <summary>
    /// What a line spends to reach <paramref name="rmse"/>, by <paramref name="cost"/> (time or rays): at the first
    /// setting (in order of rays) at or below it, interpolated on the log-log line from the setting before; null
    /// if no setting reaches it.
    /// </summary>
    /// <param name="series">One line's results.</param>
    /// <param name="rmse">The RMSE to reach.</param>
    /// <param name="cost">What is spent: e.g. the median time in ms, or rays per pixel.</param>
    public static double? CostToReach(IEnumerable<CompareResult> series, double rmse, Func<CompareResult, double> cost) =>
        CostToReach(series, rmse, cost, r => r.Error.Rmse);

    /// <summary>
    /// What a line spends to bring <paramref name="error"/> (e.g. the mean FLIP) down to <paramref name="target"/>, by
    /// <paramref name="cost"/>: as <see cref="CostToReach(IEnumerable{CompareResult}, double, Func{CompareResult, double})"/>
    /// does for the RMSE. Settings whose error is null (not measured) are passed over.
    /// </summary>
    /// <param name="series">One line's results.</param>
    /// <param name="target">The error to reach.</param>
    /// <param name="cost">What is spent: e.g. the median time in ms, or rays per pixel.</param>
    /// <param name="error">The error of a setting, e.g. <c>r =&gt; r.MeanFlip</c>.</param>
    public static double? CostToReach(IEnumerable<CompareResult> series, double target, Func<CompareResult, double> cost, Func<CompareResult, double?> error)
    {
        ArgumentNullException.ThrowIfNull(series);
        ArgumentNullException.ThrowIfNull(cost);
        ArgumentNullException.ThrowIfNull(error);
        (CompareResult R, double E)? previous = null;
        foreach (CompareResult r in series.OrderBy(r => r.Rays))
        {
            if (error(r) is not { } e)
            {
                continue;
            }

            if (e <= target)
            {
                double c = cost(r);
                if (previous is not { } p || e == target || e <= 0)
                {
                    return c;
                }

                double c0 = cost(p.R);
                double f = Math.Log(target / p.E) / Math.Log(e / p.E);
                return Math.Exp(Math.Log(c0) + (f * Math.Log(c / c0)));
            }

            previous = (r, e);
        }

        return null;
    }

    /// <summary>
    /// Kendall's τ-b between two orderings of the same items: 1 when they rank every pair alike, −1 when they
    /// reverse every pair, ties in either counted as neither; null with fewer than two items or when one ordering
    /// ties them all.
    /// </summary>
    /// <param name="pairs">Each item's two values (e.g. its RMSE and its mean FLIP).</param>
    public static double? KendallTau(IReadOnlyList<(double A, double B)> pairs)
    {
        ArgumentNullException.ThrowIfNull(pairs);
        long concordant = 0, discordant = 0, tiedA = 0, tiedB = 0;
        for (int i = 0; i < pairs.Count; i++)
        {
            for (int j = i + 1; j < pairs.Count; j++)
            {
                int a = pairs[i].A.CompareTo(pairs[j].A), b = pairs[i].B.CompareTo(pairs[j].B);
                if (a == 0 && b == 0)
                {
                    continue;
                }

                if (a == 0)
                {
                    tiedA++;
                }
                else if (b == 0)
                {
                    tiedB++;
                }
                else if (a == b)
                {
                    concordant++;
                }
                else
                {
                    discordant++;
                }
            }
        }

        double denominator = Math.Sqrt((double)(concordant + discordant + tiedA) * (concordant + discordant + tiedB));
        return denominator > 0 ? (concordant - discordant) / denominator : null;
    }

    /// <summary>The lowest error every line reaches (the largest of the lines' minima); null if there is none above 0.</summary>
    private static double? LowestCommon(IReadOnlyList<IGrouping<string, CompareResult>> lines, Measure measure)
    {
        double[] minima = [.. lines.Select(s => s.Select(measure.Of).Where(e => e is not null).Select(e => e!.Value).DefaultIfEmpty(double.NaN).Min())];
        double target = minima.Length == 0 || minima.Any(double.IsNaN) ? 0 : minima.Max();
        return target > 0 ? target : null;
    }

    private void ReachTable(StringBuilder md, Measure measure, double target, string why)
    {
        md.Append(Invariant($"\n## Time to {measure.Name} ≤ {measure.Format(target)} ({why})\n\n"))
          .Append("Interpolated on the log-log line between the two settings around it; fastest first.\n\n")
          .Append("| sampler | time (ms) | × the fastest | rays/px |\n|---|---:|---:|---:|\n");
        var reached = Series.Select(s => (Name: s.Key, Ms: CostToReach(s, target, r => r.Time.TotalMilliseconds, measure.Of), Rays: CostToReach(s, target, r => r.RaysPerPixel, measure.Of)))
            .OrderBy(t => t.Ms ?? double.PositiveInfinity).ToList();
        double fastest = reached[0].Ms ?? double.NaN;
        foreach ((string name, double? ms, double? rays) in reached)
        {
            md.Append(ms is { } t
                ? Invariant($"| {name} | {t:F1} | {t / fastest:F2} | {rays:F2} |\n")
                : $"| {name} | not reached | | |\n");
        }
    }

    /// <summary>
    /// Where RMSE and FLIP rank the point samplers alike and where not: at each sample count two or more of them ran
    /// at, the samplers in order of each measure, Kendall's τ between the orders, and the pairs they swap.
    /// </summary>
    private void Rankings(StringBuilder md)
    {
        var budgets = results.Where(r => r.Case.SamplesPerPixel is not null && r.MeanFlip is not null)
            .GroupBy(r => r.Case.SamplesPerPixel!.Value).Where(g => g.Select(r => r.Case.Series).Distinct().Count() > 1).OrderBy(g => g.Key).ToList();
        if (budgets.Count == 0)
        {
            return;
        }

        md.Append("\n## RMSE and FLIP: the same ranking?\n\n")
          .Append("At each sample count, the point samplers from the lowest error to the highest by each measure (ties joined by =), "
                  + "Kendall's τ between the two orders (1: the same order, −1: reversed) and the pairs the two measures order the other way round.\n\n")
          .Append("| spp | by RMSE | by mean FLIP | τ | swapped |\n|---:|---|---|---:|---|\n");
        foreach (IGrouping<int, CompareResult> g in budgets)
        {
            CompareResult[] set = [.. g];
            var swapped = new List<string>();
            for (int i = 0; i < set.Length; i++)
            {
                for (int j = i + 1; j < set.Length; j++)
                {
                    int byRmse = set[i].Error.Rmse.CompareTo(set[j].Error.Rmse), byFlip = set[i].MeanFlip!.Value.CompareTo(set[j].MeanFlip!.Value);
                    if (byRmse != 0 && byFlip != 0 && byRmse != byFlip)
                    {
                        (CompareResult better, CompareResult worse) = byRmse < 0 ? (set[i], set[j]) : (set[j], set[i]);
                        swapped.Add($"{better.Case.Series} < {worse.Case.Series} by RMSE, > by FLIP");
                    }
                }
            }

            double? tau = KendallTau([.. set.Select(r => (r.Error.Rmse, r.MeanFlip!.Value))]);
            md.Append(Invariant($"| {g.Key} | {Order(set, r => r.Error.Rmse)} | {Order(set, r => r.MeanFlip!.Value)} | {Format(tau)} | {(swapped.Count == 0 ? "none" : string.Join("; ", swapped))} |\n"));
        }
    }

    /// <summary>The settings' series from the lowest value to the highest, equal values joined by " = ".</summary>
    private static string Order(IEnumerable<CompareResult> set, Func<CompareResult, double> value)
    {
        var text = new StringBuilder();
        double? last = null;
        foreach (CompareResult r in set.OrderBy(value))
        {
            double v = value(r);
            text.Append(last is null ? "" : v == last ? " = " : " < ").Append(r.Case.Series);
            last = v;
        }

        return text.ToString();
    }

    /// <summary>The spectrum chart's file stem (written as .png and .svg) for <paramref name="samplesPerPixel"/>.</summary>
    /// <param name="samplesPerPixel">The sample count the chart shows.</param>
    public static string SpectrumStem(int samplesPerPixel) => Invariant($"error-spectrum-{samplesPerPixel}spp");

    /// <summary>The point samplers' results with a spectrum, by sample count, where two or more series ran at it.</summary>
    private List<IGrouping<int, CompareResult>> SpectrumGroups() =>
        [.. results.Where(r => r.Case.SamplesPerPixel is not null && r.Placement is not null)
            .GroupBy(r => r.Case.SamplesPerPixel!.Value).Where(g => g.Select(r => r.Case.Series).Distinct().Count() > 1).OrderBy(g => g.Key)];

    private static string PlacementText(ErrorPlacement? p) =>
        p is null ? "– | – | –" : Invariant($"{p.LowPass1:F3} | {p.LowPass2:F3} | {p.Spectrum.LowFrequencyShare:F3}");

    /// <summary>
    /// At each sample count two or more point samplers ran at: which sampler each measure puts first. RMSE counts all
    /// error alike; the low-pass errors and the low share reward error pushed to fine grain.
    /// </summary>
    private void WhereTheErrorSits(StringBuilder md)
    {
        List<IGrouping<int, CompareResult>> groups = SpectrumGroups();
        if (groups.Count == 0)
        {
            return;
        }

        md.Append("\n## Where the error sits\n\n")
          .Append("At each sample count, the point sampler each measure puts first (lowest), and the spread of the low share. "
                  + "RMSE counts every error alike; the low-pass errors keep only what survives a blur of 1 and 2 pixels, and the "
                  + "low share says how much of the error's power is at periods of 8 pixels or more. The charts error-spectrum-*.png "
                  + "show each sampler's spectrum.\n\n")
          .Append("| spp | first by RMSE | first by mean FLIP | first by low-pass σ=1 | first by low-pass σ=2 | lowest low share | low share, range |\n|---:|---|---|---|---|---|---|\n");
        foreach (IGrouping<int, CompareResult> g in groups)
        {
            CompareResult[] set = [.. g];
            string First(Func<CompareResult, double> value) => string.Join(" = ", set.Where(r => value(r) == set.Min(value)).Select(r => r.Case.Series));
            double lowest = set.Min(r => r.Placement!.Spectrum.LowFrequencyShare), highest = set.Max(r => r.Placement!.Spectrum.LowFrequencyShare);
            md.Append(Invariant($"| {g.Key} | {First(r => r.Error.Rmse)} | {(set.All(r => r.MeanFlip is not null) ? First(r => r.MeanFlip!.Value) : "–")} | "))
              .Append(Invariant($"{First(r => r.Placement!.LowPass1)} | {First(r => r.Placement!.LowPass2)} | {First(r => r.Placement!.Spectrum.LowFrequencyShare)} | {lowest:F3}–{highest:F3} |\n"));
        }
    }

    private void Chart(string stem, string title, Func<CompareResult, double> x, string xLabel, Measure measure) => LogLogChart.Save(
        stem, title, xLabel, measure.Axis,
        [.. Series.Select(s => new LogLogChart.Series(s.Key, [.. s.Where(r => measure.Of(r) is not null).Select(r => (x(r), measure.Of(r)!.Value))]))]);

    private string Html()
    {
        static string E(string s) => WebUtility.HtmlEncode(s);
        var html = new StringBuilder();
        html.Append($"<!DOCTYPE html>\n<html lang=\"en\">\n<head><meta charset=\"utf-8\"><title>raylab compare</title>\n")
            .Append("<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}td,th{padding:2px 8px;border-bottom:1px solid #ddd;text-align:right}td:first-child,td:nth-child(2),td:nth-child(5){text-align:left}</style></head>\n<body>\n")
            .Append($"<h1>raylab compare</h1>\n<p>{E(heading)}</p>\n<p>{E(Definition)}</p>\n")
            .Append("<p><a href=\"results.md\">results.md</a> (table, slopes, times to reach an error) · <a href=\"results.csv\">results.csv</a> · <a href=\"images/exact.png\">the exact image</a></p>\n")
            .Append("<p><a href=\"error-vs-time.svg\"><img src=\"error-vs-time.png\" alt=\"RMSE against time, log-log\"></a>")
            .Append("<a href=\"flip-vs-time.svg\"><img src=\"flip-vs-time.png\" alt=\"mean FLIP against time, log-log\"></a></p>\n")
            .Append("<p><a href=\"error-vs-rays.svg\"><img src=\"error-vs-rays.png\" alt=\"RMSE against rays per pixel, log-log\"></a>")
            .Append("<a href=\"flip-vs-rays.svg\"><img src=\"flip-vs-rays.png\" alt=\"mean FLIP against rays per pixel, log-log\"></a></p>\n")
            .Append(string.Concat(SpectrumGroups().Select(g => $"<a href=\"{SpectrumStem(g.Key)}.svg\"><img src=\"{SpectrumStem(g.Key)}.png\" alt=\"error spectrum at {g.Key} spp, log-log\"></a>")) is { Length: > 0 } spectra ? $"<p>{spectra}</p>\n" : "")
            .Append("<p>Each row: the picture, its error image (the largest channel error of each pixel, in levels: what the RMSE adds up) "
                    + "and its FLIP map (what a viewer sees flipping between it and the exact image, in NVIDIA's magma colours: black = no visible difference). Click one for its full size.</p>\n")
            .Append("<table>\n<tr><th>sampler</th><th>setting</th><th>rays/px</th><th>time (ms)</th><th>kernel</th><th>rays/ms</th><th>RMSE</th><th>mean FLIP</th><th>low-pass σ=1</th><th>low-pass σ=2</th><th>low share</th><th>max</th><th>&gt; 1 level</th><th>image</th><th>error</th><th>FLIP map</th></tr>\n");
        foreach (CompareResult r in results)
        {
            string stem = E(r.Case.FileStem);
            html.Append(Invariant($"<tr><td>{E(r.Case.Series)}</td><td>{E(r.Case.Setting)}</td><td>{r.RaysPerPixel:F2}</td><td>{r.Time.TotalMilliseconds:F1}</td><td>{KernelText(r)}</td><td>{RateText(r)}</td><td>{r.Error.Rmse:F3}</td><td>{FlipText(r.MeanFlip)}</td><td>{PlacementText(r.Placement).Replace(" | ", "</td><td>", StringComparison.Ordinal)}</td><td>{r.Error.Max}</td><td>{100 * r.Error.FractionOverOneLevel:F3}%</td>"))
                .Append(Thumbnail($"images/{stem}.png", "image"))
                .Append(Thumbnail($"errors/{stem}.png", "error image"))
                .Append(r.MeanFlip is null ? "<td>not measured</td>" : Thumbnail($"flip/{stem}.png", "FLIP map"))
                .Append("</tr>\n");
        }

        html.Append("</table>\n").Append(TimeTable());
        if (command.Length > 0)
        {
            html.Append($"<p>Made by <code>{E(command)}</code></p>\n");
        }

        html.Append("</body>\n</html>\n");
        return html.ToString();
    }

    /// <summary>A table cell with a small copy of the picture at <paramref name="path"/>, linked to the picture itself.</summary>
    private static string Thumbnail(string path, string alt) =>
        $"<td><a href=\"{path}\"><img src=\"{path}\" alt=\"{alt}\" width=\"{ThumbnailWidth}\" loading=\"lazy\"></a></td>";

    private const int ThumbnailWidth = 200;

    /// <summary>A mean FLIP to three significant digits (0.0493, 0.000512), or n/a.</summary>
    private static string FlipText(double? flip) => flip switch
    {
        null => "n/a",
        0 => "0",
        { } f => f.ToString("F" + Math.Clamp(2 - (int)Math.Floor(Math.Log10(f)), 0, 9).ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture),
    };

    /// <summary>The kernel that rendered a setting, as <c>raylab render --kernel</c> spells it: scalar, vector128, vector256 or vector512.</summary>
    private static string KernelText(CompareResult r) => r.Kernel.ToString().ToLowerInvariant();

    /// <summary>
    /// Primary rays per millisecond of render time (the rays of one render over its median time): a whole number from
    /// 100 up, three significant digits below; n/a for a time of 0.
    /// </summary>
    private static string RateText(CompareResult r)
    {
        double ms = r.Time.TotalMilliseconds;
        if (ms <= 0)
        {
            return "n/a";
        }

        double rate = r.Rays / ms;
        return rate >= 100 ? Invariant($"{rate:F0}") : Invariant($"{rate:G3}");
    }

    private static string Format(double? slope) => slope is { } s ? s.ToString("F2", CultureInfo.InvariantCulture) : "n/a";

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
