using System.Globalization;
using System.Text.RegularExpressions;
using RayLab.Reports.Comparison;
using RayLab.Rendering.Inspection;
using RayLab.Sampling;
using ScottPlot;

namespace RayLab.Reports.Patterns;

/// <summary>The figures of <c>raylab patterns</c>, drawn with ScottPlot and saved as PNG and SVG.</summary>
internal static partial class PatternFigures
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>Colours after Tableau's ten, far from all of them.</summary>
    private static readonly Color[] Beyond = [Colors.Black, Colors.Gold, Colors.DarkSlateGray];

    /// <summary>A colour per sampler, stable across figures (Tableau 10, then black, gold and dark slate grey, then Tableau again).</summary>
    public static Color ColourOf(int index) => index is >= 10 and < 13 ? Beyond[index - 10] : new ScottPlot.Palettes.Category10().GetColor(index);

    /// <summary>
    /// One pixel with its points (the lab's Rys. 12 and 13), y downward as in the image; <paramref name="strata"/>
    /// draws an n×n grid of cells, <paramref name="rooks"/> the N rows and N columns.
    /// </summary>
    public static Plot Pixel(string title, SamplePoint[] points, int strata = 0, bool rooks = false)
    {
        var plot = new Plot();
        ChartFont.Apply(plot);
        UnitFrame(plot, 1);
        if (rooks)
        {
            Lines(plot, points.Length, 1, Colors.Orange.WithAlpha(0.6), 1);
        }

        if (strata > 0)
        {
            Lines(plot, strata, 1, Colors.SteelBlue, 1.5f);
        }

        Points(plot, points, 0, 0, Colors.Black, points.Length > 100 ? 4 : 8);
        plot.Title(title);
        return plot;
    }

    /// <summary>A 4×4 block of pixels, each with its own points: correlation between pixels shows.</summary>
    public static Plot Block(string title, IPixelSampler sampler)
    {
        var plot = new Plot();
        ChartFont.Apply(plot);
        UnitFrame(plot, 4);
        Lines(plot, 4, 4, Colors.Gray, 1.5f);
        for (int y = 0; y < 4; y++)
        {
            for (int x = 0; x < 4; x++)
            {
                Points(plot, PatternPoints.Of(sampler, x, y), x, y, Colors.Black, sampler.SamplesPerPixel > 64 ? 2 : 4);
            }
        }

        plot.Title(title);
        return plot;
    }

    /// <summary>The lab's adaptive diagram: squares, labelled points with their weights, value against the exact colour.</summary>
    public static Plot Adaptive(AdaptiveDiagram diagram, byte[] backgroundPng)
    {
        var plot = new Plot();
        ChartFont.Apply(plot);
        var image = new ScottPlot.Image(backgroundPng);
        plot.Add.ImageRect(image, new CoordinateRect(0, 1, 1, 0));
        foreach (AdaptiveSquare square in diagram.Squares)
        {
            var rect = plot.Add.Rectangle(square.X, square.X + square.Size, square.Y + square.Size, square.Y);
            rect.FillStyle.Color = Colors.Transparent;
            rect.LineStyle.Color = Colors.White.WithAlpha(0.9);
            rect.LineStyle.Width = square.Depth == 0 ? 3 : 1.5f;
        }

        foreach (AdaptivePoint p in diagram.Points)
        {
            var marker = plot.Add.Marker(p.X, p.Y);
            marker.MarkerStyle.Size = 9;
            marker.MarkerStyle.FillColor = Colors.White;
            marker.MarkerStyle.OutlineColor = Colors.Black;
            marker.MarkerStyle.OutlineWidth = 1.5f;
            var label = plot.Add.Text($"{p.Label} {Fraction(p.Weight)}", p.X, p.Y);
            label.LabelFontSize = 13;
            label.LabelBold = true;
            label.LabelFontColor = Colors.Black;
            label.LabelBackgroundColor = Colors.White.WithAlpha(0.8);
            label.LabelAlignment = Alignment.UpperLeft;
            label.OffsetX = 5;
            label.OffsetY = 5;
        }

        plot.Axes.SetLimits(-0.04, 1.2, 1.06, -0.04);
        plot.Axes.SquareUnits();
        plot.HideGrid();
        plot.Title(string.Create(Inv, $"Adaptive antialiasing, pixel ({diagram.PixelX}, {diagram.PixelY}): {diagram.Points.Count} rays"));
        plot.XLabel(string.Create(Inv,
            $"lab's rule ({diagram.Value.R:0.000}, {diagram.Value.G:0.000}, {diagram.Value.B:0.000}), exact ({diagram.Exact.R:0.000}, {diagram.Exact.G:0.000}, {diagram.Exact.B:0.000})"));
        plot.YLabel("points in trace order, each with its weight");
        return plot;
    }

    // The combination rule's weights are dyadic: show them as the fractions an instructor writes (13/32).
    private static string Fraction(double weight)
    {
        long denominator = 1;
        while (denominator < (1L << 40) && Math.Abs((weight * denominator) - Math.Round(weight * denominator)) > 1e-9)
        {
            denominator *= 2;
        }

        long numerator = (long)Math.Round(weight * denominator);
        return numerator == 0 ? "0" : denominator == 1 ? numerator.ToString(Inv) : $"{numerator}/{denominator}";
    }

    /// <summary>The mean periodogram of one sampler, log-scaled, DC removed.</summary>
    public static Plot Spectrum(string title, PowerSpectrum spectrum)
    {
        int k = spectrum.MaxFrequency, side = (2 * k) + 1;
        var data = new double[side, side];
        for (int v = -k; v <= k; v++)
        {
            for (int u = -k; u <= k; u++)
            {
                double p = u == 0 && v == 0 ? 1 : spectrum.Power(u, v);
                data[k - v, u + k] = Math.Log10(Math.Clamp(p, 0.01, 100));
            }
        }

        var plot = new Plot();
        ChartFont.Apply(plot);
        var heat = plot.Add.Heatmap(data);
        heat.Colormap = new ScottPlot.Colormaps.Viridis();
        heat.Extent = new CoordinateRect(-k - 0.5, k + 0.5, -k - 0.5, k + 0.5);
        heat.ManualRange = new ScottPlot.Range(-2, 2);
        plot.Axes.SetLimits(-k - 0.5, k + 0.5, -k - 0.5, k + 0.5);
        var bar = plot.Add.ColorBar(heat);
        bar.Label = "log₁₀ power (1 = white noise)";
        plot.Axes.SquareUnits();
        plot.Title(title);
        plot.XLabel("u (cycles per pixel)");
        plot.YLabel("v (cycles per pixel)");
        return plot;
    }

    /// <summary>Lines against a linear x axis (radial mean, anisotropy), one per sampler.</summary>
    public static Plot Lines(string title, string xLabel, string yLabel, IReadOnlyList<(string Name, double[] X, double[] Y)> series, double? reference = null, string? referenceLabel = null)
    {
        var plot = new Plot();
        ChartFont.Apply(plot);
        for (int i = 0; i < series.Count; i++)
        {
            (string name, double[] x, double[] y) = series[i];
            int[] keep = [.. Enumerable.Range(0, x.Length).Where(j => double.IsFinite(y[j]))];
            var line = plot.Add.Scatter(keep.Select(j => x[j]).ToArray(), keep.Select(j => y[j]).ToArray());
            line.LegendText = name;
            line.Color = ColourOf(i);
            line.LineWidth = 2;
            line.MarkerSize = 4;
        }

        if (reference is double r)
        {
            var h = plot.Add.HorizontalLine(r);
            h.LineColor = Colors.Gray;
            h.LinePattern = LinePattern.Dashed;
            h.LegendText = referenceLabel ?? "";
        }

        plot.Title(title);
        plot.XLabel(xLabel);
        plot.YLabel(yLabel);
        plot.ShowLegend(Edge.Right);
        return plot;
    }

    /// <summary>A log-log chart, one line per sampler: log₁₀ values plotted with decade ticks.</summary>
    public static Plot LogLog(string title, string yLabel, IReadOnlyList<(string Name, int[] N, double[] Y)> series)
    {
        var plot = new Plot();
        ChartFont.Apply(plot);
        for (int i = 0; i < series.Count; i++)
        {
            (string name, int[] n, double[] y) = series[i];
            int[] keep = [.. Enumerable.Range(0, n.Length).Where(j => y[j] > 0)];
            var line = plot.Add.Scatter(keep.Select(j => Math.Log10(n[j])).ToArray(), keep.Select(j => Math.Log10(y[j])).ToArray());
            line.LegendText = name;
            line.Color = ColourOf(i);
            line.LineWidth = 2;
            line.MarkerSize = 4;
        }

        foreach (IAxis axis in new IAxis[] { plot.Axes.Bottom, plot.Axes.Left })
        {
            axis.TickGenerator = new ScottPlot.TickGenerators.NumericAutomatic
            {
                MinorTickGenerator = new ScottPlot.TickGenerators.LogMinorTickGenerator(),
                IntegerTicksOnly = true,
                LabelFormatter = v => Math.Pow(10, v).ToString("g4", Inv),
            };
        }

        plot.Title(title);
        plot.XLabel("N, points per pixel");
        plot.YLabel(yLabel);
        plot.ShowLegend(Edge.Right);
        return plot;
    }

    /// <summary>Saves <paramref name="plot"/> as NAME.png and NAME.svg in <paramref name="folder"/>.</summary>
    public static void Save(Plot plot, string folder, string name, int width, int height)
    {
        plot.SavePng(Path.Combine(folder, name + ".png"), width, height);
        // Skia numbers an SVG's clip paths from a counter that lives as long as the process, so a second figure
        // made in the same process gets other ids: renumber them in order of appearance (same seed, same bytes).
        string svg = plot.GetSvgXml(width, height);
        var ids = new Dictionary<string, string>(StringComparer.Ordinal);
        svg = SvgId().Replace(svg, m =>
        {
            string id = m.Groups[1].Value;
            if (!ids.TryGetValue(id, out string? renamed))
            {
                renamed = $"id{ids.Count}";
                ids.Add(id, renamed);
            }

            return m.Value.Replace(id, renamed, StringComparison.Ordinal);
        });
        File.WriteAllText(Path.Combine(folder, name + ".svg"), svg);
    }

    [GeneratedRegex("(?:id=\"|url\\(#|href=\"#)(cl_[0-9a-f]+)")]
    private static partial Regex SvgId();

    private static void UnitFrame(Plot plot, int side)
    {
        plot.Axes.SetLimits(0, side, side, 0); // y downward, as pixel rows and the lab's figures
        plot.Axes.SquareUnits();
        plot.HideGrid();
        var frame = plot.Add.Rectangle(0, side, side, 0);
        frame.FillStyle.Color = Colors.White;
        frame.LineStyle.Color = Colors.Black;
        frame.LineStyle.Width = 2;
    }

    private static void Lines(Plot plot, int cells, int side, Color colour, float width)
    {
        for (int i = 1; i < cells * side; i++)
        {
            double at = (double)i / cells;
            var v = plot.Add.Line(at, 0, at, side);
            v.LineColor = colour;
            v.LineWidth = width;
            var h = plot.Add.Line(0, at, side, at);
            h.LineColor = colour;
            h.LineWidth = width;
        }
    }

    private static void Points(Plot plot, IEnumerable<SamplePoint> points, int dx, int dy, Color colour, float size)
    {
        SamplePoint[] all = [.. points];
        var scatter = plot.Add.ScatterPoints(all.Select(p => dx + p.X).ToArray(), all.Select(p => dy + p.Y).ToArray());
        scatter.Color = colour;
        scatter.MarkerSize = size;
        scatter.MarkerShape = MarkerShape.FilledCircle;
    }
}
