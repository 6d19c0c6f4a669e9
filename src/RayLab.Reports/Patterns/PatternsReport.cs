using System.Globalization;
using System.Net;
using System.Text;
using RayLab.Rendering.Inspection;
using RayLab.Sampling;
using RayLab.Scenes;
using ScottPlot;

namespace RayLab.Reports.Patterns;

/// <summary>
/// The sampling-patterns report (<c>raylab patterns</c>): the lab's sampling figures (Rys. 12, 13 a–c, the adaptive
/// diagram) and, per sampler, what its points look like: a pixel, a 4×4 block, the power spectrum, the radial mean and
/// anisotropy, the discrepancy and the integration error against N with fitted slopes. Writes PNG and SVG figures,
/// <c>patterns.csv</c>, <c>spectra.csv</c> and <c>index.html</c> into a folder; the same seed writes the same files.
/// </summary>
public static class PatternsReport
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>Draws and measures every figure of <paramref name="request"/> into <paramref name="folder"/>, <c>index.html</c> last.</summary>
    /// <param name="request">What to draw and measure.</param>
    /// <param name="folder">An existing folder the files are written into.</param>
    /// <param name="log">Where the summary (the fitted slopes) is written.</param>
    /// <param name="cancellation">Cancels between figures.</param>
    /// <exception cref="ArgumentException">The request names no sampler, or the folder does not exist.</exception>
    public static void Write(PatternsRequest request, string folder, TextWriter log, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(request);
        ArgumentNullException.ThrowIfNull(log);
        ArgumentException.ThrowIfNullOrWhiteSpace(folder);
        if (request.Samplers.Count == 0)
        {
            throw new ArgumentException("No sampler to draw.", nameof(request));
        }

        if (!Directory.Exists(folder))
        {
            throw new ArgumentException($"The folder '{folder}' does not exist.", nameof(folder));
        }

        var html = new List<(string Heading, string[] Figures, string Text)>();
        string csv = Build(request, folder, html, log, out string slopeTable, cancellation);
        File.WriteAllText(Path.Combine(folder, "patterns.csv"), csv);
        cancellation.ThrowIfCancellationRequested();
        File.WriteAllText(Path.Combine(folder, "index.html"), Html(request, html, slopeTable));
    }

    private static string Build(PatternsRequest r, string dir, List<(string, string[], string)> html, TextWriter stdout, out string slopeTable, CancellationToken cancel)
    {
        // The lab's figures and every other sampler, one pixel each; the adaptive diagram on the lab's scene; spectra;
        // discrepancy and integration error against N.
        PixelFigures(r, dir, html, cancel);
        cancel.ThrowIfCancellationRequested();
        AdaptiveFigure(dir, html);
        List<(string Name, PowerSpectrum Spectrum)> spectra = SpectrumFigures(r, dir, html, cancel);
        List<(PatternSampler Sampler, int[] Counts, IReadOnlyList<PatternMeasure> Values)> measures = DiscrepancyFigures(r, dir, html, cancel);
        slopeTable = IntegrationFigures(r, dir, html, stdout, measures);
        File.WriteAllText(Path.Combine(dir, "spectra.csv"), SpectrumCsv(spectra));
        return MeasureCsv(measures);
    }

    private static void PixelFigures(PatternsRequest r, string dir, List<(string, string[], string)> html, CancellationToken cancel)
    {
        IReadOnlyList<PatternSampler> samplers = r.Samplers;
        int n = r.Samples, side = (int)Math.Round(Math.Sqrt(n));
        bool square = side * side == n;
        var pixelFigures = new List<string>();
        foreach (PatternSampler s in samplers)
        {
            cancel.ThrowIfCancellationRequested();
            IPixelSampler sampler = s.Create(n, r.Seed);
            SamplePoint[] points = PatternPoints.Of(sampler, 0, 0);
            string lab = s.Name switch { "regular" => " (Rys. 12)", "random" => " (Rys. 13a)", "jittered" => " (Rys. 13b)", _ => "" };
            bool rooks = s.Name is "nrooks" or "cmj" or "multijittered";
            PatternFigures.Save(PatternFigures.Pixel($"{s.Name}, {n} points{lab}{(rooks ? ": one per row and column" : "")}", points, rooks: rooks && n <= 64), dir, $"pixel-{s.Name}", 480, 500);
            pixelFigures.Add($"pixel-{s.Name}");
            if (s.Name == "jittered" && square)
            {
                PatternFigures.Save(PatternFigures.Pixel($"jittered, {n} points, with its {side}×{side} strata (Rys. 13c)", points, strata: side), dir, "pixel-jittered-strata", 480, 500);
                pixelFigures.Add("pixel-jittered-strata");
            }
        }

        html.Add(("One pixel", [.. pixelFigures],
            $"The points each sampler puts in pixel (0, 0), {n} of them, seed {r.Seed}; y grows downward as pixel rows do. "
            + "regular is the lab's Rys. 12 (an n×n grid of cell centres), random Rys. 13a, jittered Rys. 13b (one random point in each cell) "
            + "and, with its cells drawn, Rys. 13c. nrooks, cmj and multijittered draw the N rows and N columns: each holds exactly one point "
            + "(the n-rooks property, so a vertical or horizontal edge is sampled at N different offsets). hammersley, sobol, pmj02, "
            + "pmj02bn and zsobol are low-discrepancy sets: no cells, yet no clumps and no large holes (the last four, at a power of two, "
            + "one point in every elementary interval: 1 × N, 2 × N/2, …, N × 1 boxes)."));

        var blockFigures = new List<string>();
        foreach (PatternSampler s in samplers)
        {
            PatternFigures.Save(PatternFigures.Block($"{s.Name}, {n} points in each of 4×4 pixels", s.Create(n, r.Seed)), dir, $"block-{s.Name}", 480, 500);
            blockFigures.Add($"block-{s.Name}");
        }

        html.Add(("A 4×4 block of pixels", [.. blockFigures],
            "The same samplers over 16 neighbouring pixels. regular puts the same grid in every pixel: its points line up across the "
            + "whole image, which is the aliasing the lab warns about (a pattern finer than the grid turns into a false coarse one, and an "
            + "edge nearly parallel to the grid makes stair steps). The others draw new points in every pixel from a hash of (pixel, sample, "
            + "seed), so their errors do not line up from pixel to pixel. zsobol's pixels share one Sobol' sequence in a scrambled Z order: "
            + "each 2×2 group of pixels together holds a net of four times the points, so neighbours' points avoid each other."));
    }

    private static List<(string Name, PowerSpectrum Spectrum)> SpectrumFigures(PatternsRequest r, string dir, List<(string, string[], string)> html, CancellationToken cancel)
    {
        IReadOnlyList<PatternSampler> samplers = r.Samplers;
        int ns = r.SpectrumSamples, k = 3 * (int)Math.Round(Math.Sqrt(ns));
        var spectra = new List<(string Name, PowerSpectrum Spectrum)>();
        var spectrumFigures = new List<string>();
        foreach (PatternSampler s in samplers)
        {
            cancel.ThrowIfCancellationRequested();
            if (s.SquaresOnly && Math.Sqrt(ns) % 1 != 0)
            {
                continue;
            }

            PowerSpectrum spectrum = PowerSpectrum.Measure(s.Create(ns, r.Seed), r.SpectrumRealisations, k);
            spectra.Add((s.Name, spectrum));
            PatternFigures.Save(PatternFigures.Spectrum($"{s.Name}: power spectrum, N = {ns}, {r.SpectrumRealisations} pixels", spectrum), dir, $"spectrum-{s.Name}", 560, 480);
            spectrumFigures.Add($"spectrum-{s.Name}");
        }

        html.Add(("Power spectra", [.. spectrumFigures],
            $"Each sampler's Fourier power spectrum at integer frequencies (u, v), averaged over {r.SpectrumRealisations} pixels of {ns} points "
            + "(the periodogram |Σ exp(−2πi f·x)|²/N, as pbrt-v4's pspec and the psa tool draw it; Schlömer and Deussen 2011). 1 (the middle "
            + "of the colour scale) is white noise: random is 1 everywhere. A dark disc around the centre means the points cannot clump: "
            + "jittered and the multi-jittered and low-discrepancy sets have little low-frequency power, so smooth features are integrated "
            + "with little noise. regular is all or nothing: a few bright spikes on its grid's frequencies, which is aliasing."));

        double[] rings = [.. Enumerable.Range(0, k + 1).Select(i => (double)i)];
        PatternFigures.Save(PatternFigures.Lines($"Radial mean power spectrum, N = {ns}", "|f| (cycles per pixel)", "mean power (1 = white noise)",
            [.. spectra.Select(s => (s.Name, rings[1..], s.Spectrum.RadialMean.Skip(1).ToArray()))], 1, "white noise"), dir, "radial-mean", 900, 520);
        double floor = 10 * Math.Log10(1.0 / r.SpectrumRealisations);
        PatternFigures.Save(PatternFigures.Lines($"Anisotropy, N = {ns}", "|f| (cycles per pixel)", "anisotropy (dB)",
            [.. spectra.Select(s => (s.Name, rings[1..], s.Spectrum.AnisotropyDecibels.Skip(1).ToArray()))], floor, $"direction-free ({floor:0.0} dB)"), dir, "anisotropy", 900, 520);
        html.Add(("Radial mean and anisotropy", ["radial-mean", "anisotropy"],
            "Ulichney's radial mean (Digital Halftoning, 1987): the spectrum averaged over rings |f| = r. Where a curve stays below 1 at low "
            + "frequencies the sampler is better than random there; the height of its first peak tells how regular it is. The anisotropy "
            + $"is each ring's variance over its mean squared, in dB: about 10·log₁₀(1/{r.SpectrumRealisations}) = {floor:0.0} dB for a pattern with "
            + "no preferred direction (the dashed line); rings far above it have directional structure (regular's grid, the lattice-like "
            + "rows of hammersley). regular has no line where a ring holds no power at all."));
        return spectra;
    }

    private static List<(PatternSampler Sampler, int[] Counts, IReadOnlyList<PatternMeasure> Values)> DiscrepancyFigures(
        PatternsRequest r, string dir, List<(string, string[], string)> html, CancellationToken cancel)
    {
        IReadOnlyList<PatternSampler> samplers = r.Samplers;
        var measures = new List<(PatternSampler Sampler, int[] Counts, IReadOnlyList<PatternMeasure> Values)>();
        PatternMeasureOptions options = r.Measures ?? new PatternMeasureOptions();
        foreach (PatternSampler s in samplers)
        {
            cancel.ThrowIfCancellationRequested();
            int[] counts = [.. PatternMeasures.Counts(s.SquaresOnly)];
            measures.Add((s, counts, PatternMeasures.Measure(c => s.Create(c, r.Seed), counts, options)));
        }

        PatternFigures.Save(PatternFigures.LogLog("L2-star discrepancy (Warnock 1972)", "L2-star discrepancy",
            [.. measures.Select(m => (m.Sampler.Name, m.Counts, m.Values.Select(v => v.L2Star).ToArray()))]), dir, "discrepancy-l2", 900, 560);
        var small = measures.Select(m => (m.Sampler.Name, m.Counts.Where((_, i) => m.Values[i].Star is not null).ToArray(),
            m.Values.Where(v => v.Star is not null).Select(v => v.Star!.Value).ToArray())).ToList();
        PatternFigures.Save(PatternFigures.LogLog($"Star discrepancy (largest box), N ≤ {options.StarMaxSamples}", "star discrepancy D*", small), dir, "discrepancy-star", 900, 560);
        html.Add(("Discrepancy", ["discrepancy-l2", "discrepancy-star"],
            $"How far the fraction of points in a box [0, a)×[0, b) strays from its area. The L2-star discrepancy is the root mean square "
            + $"over all such boxes, by Warnock's closed form (1972), averaged over {options.DiscrepancyRealisations} pixels; random falls as "
            + "N^−½, and so does regular (its rows and columns line up: T² = 1/(18N) + 7/(288N²) for the n×n grid), the stratified "
            + "and low-discrepancy sets about as N^−1 (up to a log); nrooks, stratified along each axis alone, sits between. The star discrepancy is the worst box, found "
            + "exactly (Dobkin, Eppstein and Mitchell 1996) for small N; the Koksma–Hlawka inequality bounds the integration error of a "
            + "function of bounded variation by it."));
        return measures;
    }

    // The RMSE figures and the slopes: written to stdout, and returned as a Markdown table.
    private static string IntegrationFigures(PatternsRequest r, string dir, List<(string, string[], string)> html, TextWriter stdout,
        List<(PatternSampler Sampler, int[] Counts, IReadOnlyList<PatternMeasure> Values)> measures)
    {
        PatternMeasureOptions options = r.Measures ?? new PatternMeasureOptions();
        var slopes = new StringBuilder();
        var rows = new StringBuilder("| sampler | " + string.Join(" | ", Integrand.All.Select(f => f.Description)) + " |\n|---|" + string.Concat(Integrand.All.Select(_ => "---:|")) + "\n");
        var figures = new List<string>();
        foreach (Integrand f in Integrand.All)
        {
            var series = measures.Select(m =>
            {
                double[] e = [.. m.Values.Select(v => v.Rmse[f.Name])];
                double slope = PatternMeasures.Slope(m.Counts, e);
                return ($"{m.Sampler.Name} ({slope.ToString("0.00", Inv)})", m.Counts, e);
            }).ToList();
            PatternFigures.Save(PatternFigures.LogLog($"RMSE integrating the {f.Description}; fitted slopes in brackets", "RMSE", series), dir, $"rmse-{f.Name}", 900, 560);
            figures.Add($"rmse-{f.Name}");
        }

        foreach ((PatternSampler s, int[] counts, IReadOnlyList<PatternMeasure> values) in measures)
        {
            string[] cells = [.. Integrand.All.Select(f => PatternMeasures.Slope(counts, [.. values.Select(v => v.Rmse[f.Name])]).ToString("0.00", Inv))];
            rows.Append($"| {s.Name} | {string.Join(" | ", cells)} |\n");
            slopes.Append(Inv, $"{s.Name,-14} slopes: {string.Join(", ", Integrand.All.Select((f, i) => $"{f.Name} {cells[i]}"))}\n");
        }

        html.Add(("Integration error and its slope", [.. figures],
            $"The RMSE of estimating the integral of three test functions over the pixel by the mean of the points, over "
            + $"{options.IntegrationRealisations} pixels, each with the function placed anew (random centre or direction, the same for every "
            + "sampler), against N; the slope of a least-squares line through ln RMSE against ln N is in brackets. The literature's ranking: "
            + "random −0.5 whatever the function; on an edge (the disc) jittered and the other stratified sets about −0.75 (Mitchell 1996; "
            + "Pilleboue et al. 2015 read it off the spectrum's behaviour near zero frequency); on smooth functions (the Gaussian) about −1 "
            + "for jittered, steeper for the scrambled nets (Owen 1997: −1.5). regular is deterministic: its error is the quadrature "
            + "error of the placed function, and its line is ragged because it depends on how the grid meets the edge. The bilinear step "
            + "is an edge too: its slopes sit with the disc's."));
        stdout.Write(slopes.ToString());
        return rows.ToString();
    }

    private static string MeasureCsv(List<(PatternSampler Sampler, int[] Counts, IReadOnlyList<PatternMeasure> Values)> measures)
    {
        var csv = new StringBuilder("sampler,samples,l2_star,star," + string.Join(',', Integrand.All.Select(f => $"rmse_{f.Name}")) + "\n");
        foreach ((PatternSampler _, int[] _, IReadOnlyList<PatternMeasure> values) in measures)
        {
            foreach (PatternMeasure m in values)
            {
                csv.Append(Inv, $"{m.Sampler},{m.Samples},{m.L2Star:R},{(m.Star is double d ? d.ToString("R", Inv) : "")},");
                csv.Append(string.Join(',', Integrand.All.Select(f => m.Rmse[f.Name].ToString("R", Inv))));
                csv.Append('\n');
            }
        }
        return csv.ToString();
    }

    private static string SpectrumCsv(List<(string Name, PowerSpectrum Spectrum)> spectra)
    {
        var spectrumCsv = new StringBuilder("sampler,samples,realisations,ring,radial_mean,anisotropy_db\n");
        foreach ((string name, PowerSpectrum s) in spectra)
        {
            for (int ring = 1; ring <= s.MaxFrequency; ring++)
            {
                double a = s.AnisotropyDecibels[ring];
                spectrumCsv.Append(Inv, $"{name},{s.SamplesPerPixel},{s.Realisations},{ring},{s.RadialMean[ring]:R},{(double.IsFinite(a) ? a.ToString("R", Inv) : "")}\n");
            }
        }
        return spectrumCsv.ToString();
    }

    private static void AdaptiveFigure(string dir, List<(string, string[], string)> html)
    {
        string scenePath = Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");
        SceneDescription description = SceneFile.Load(scenePath);
        PreparedScene scene = description.Prepare();
        AdaptiveSampler sampler = description.Sampler.IsAdaptive ? description.Sampler.CreateAdaptive() : new AdaptiveSampler();
        const int W = 160, H = 120; // a fifth of the scene's 800×600, so an edge pixel holds a visible arc
        AdaptiveDiagram diagram = AdaptiveDiagram.FindEdgePixel(scene.Scene, scene.Camera, W, H, sampler);

        // The scene inside that pixel, 96×96 rays, as the diagram's background.
        Image zoomed = diagram.TraceInside(scene.Scene, scene.Camera, W, H, 96);
        using var png = new MemoryStream();
        zoomed.Save(png, ImageFormat.Png);
        Plot plot = PatternFigures.Adaptive(diagram, png.ToArray());
        PatternFigures.Save(plot, dir, "adaptive", 760, 760);
        string weights = string.Join(", ", diagram.Points.Select(p => $"{p.Label} {p.Weight.ToString("0.####", Inv)}"));
        html.Add(("The adaptive diagram (section 4.1.4)", ["adaptive"],
            $"One edge pixel, ({diagram.PixelX}, {diagram.PixelY}), of the lab's two-sphere scene at {W}×{H}, with the scene's adaptive settings "
            + $"(depth {sampler.MinDepth}–{sampler.MaxDepth}, contrast {sampler.Contrast.ToString(Inv)}): the squares the lab's recursion made and "
            + $"every point it traced, labelled in trace order as the lab labels them (corners A, B, C, D; centre E; then F, G, H, J, …), "
            + $"each with its weight in the pixel's value under the lab's combination rule ¼ Σ (corner + centre)/2, recursively: {weights}. "
            + $"The pixel's value is Σ weight × value: red {diagram.Value.R.ToString("0.0000", Inv)}, green {diagram.Value.G.ToString("0.0000", Inv)}, "
            + $"against the exact area-weighted colour {diagram.Exact.R.ToString("0.0000", Inv)}, {diagram.Exact.G.ToString("0.0000", Inv)} "
            + "(RenderMethod.Exact). The background is the scene inside the pixel, traced at 96×96."));
    }

    private static string Html(PatternsRequest r, List<(string Heading, string[] Figures, string Text)> sections, string slopeTable)
    {
        var b = new StringBuilder();
        b.Append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>RayLab: sampling patterns</title>\n");
        b.Append("<style>body{font-family:sans-serif;max-width:1400px;margin:auto;padding:1em;line-height:1.45}figure{display:inline-block;margin:.3em}"
            + "img{max-width:100%;border:1px solid #ddd}section{margin-bottom:2.5em}code{background:#f4f4f4;padding:0 .2em}"
            + "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.2em .6em}</style>\n</head>\n<body>\n");
        b.Append("<h1>Sampling patterns: the lab's figures, and what each sampler's points look like</h1>\n");
        b.Append($"<p>Made by <code>{WebUtility.HtmlEncode(r.Command)}</code>. Every figure is also an SVG beside its PNG; "
            + "the numbers are in <a href=\"patterns.csv\">patterns.csv</a> and <a href=\"spectra.csv\">spectra.csv</a>.</p>\n");
        foreach ((string heading, string[] figures, string text) in sections)
        {
            b.Append($"<section>\n<h2>{WebUtility.HtmlEncode(heading)}</h2>\n<p>{WebUtility.HtmlEncode(text)}</p>\n");
            foreach (string f in figures)
            {
                b.Append($"<figure><a href=\"{f}.svg\"><img src=\"{f}.png\" alt=\"{WebUtility.HtmlEncode(f)}\"></a></figure>\n");
            }

            if (heading.StartsWith("Integration", StringComparison.Ordinal))
            {
                b.Append("<table>\n");
                foreach (string line in slopeTable.Split('\n', StringSplitOptions.RemoveEmptyEntries).Where(l => !l.StartsWith("|---", StringComparison.Ordinal)))
                {
                    string[] cells = line.Trim('|').Split('|');
                    b.Append("<tr>" + string.Concat(cells.Select(c => $"<td>{WebUtility.HtmlEncode(c.Trim())}</td>")) + "</tr>\n");
                }

                b.Append("</table>\n");
            }

            b.Append("</section>\n");
        }

        b.Append("</body>\n</html>\n");
        return b.ToString();
    }
}
