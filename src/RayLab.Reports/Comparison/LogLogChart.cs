using System.Globalization;
using ScottPlot;
using ScottPlot.TickGenerators;

namespace RayLab.Reports.Comparison;

/// <summary>
/// The compare report's line charts with logarithmic axes, drawn by ScottPlot: both axes labelled in decades with
/// faint lines at 2…9, a title, a legend to the right, and each line told apart by its colour (a palette made for
/// many categories) and its marker's shape. Points with a coordinate that is not a positive finite number cannot be
/// placed and are left out. Text is set in the embedded DejaVu Sans, so the charts look the same on every machine.
/// </summary>
public static class LogLogChart
{
    /// <summary>The charts' size in pixels.</summary>
    public const int Width = 900, Height = 540;

    // The markers, in order: filled shapes first, then open ones and strokes; with the palette's 25 colours every
    // line of a chart of up to 25 lines has its own colour and its neighbours in the legend have different shapes.
    private static readonly MarkerShape[] Shapes =
    [
        MarkerShape.FilledCircle, MarkerShape.FilledSquare, MarkerShape.FilledTriangleUp, MarkerShape.FilledDiamond,
        MarkerShape.FilledTriangleDown, MarkerShape.OpenCircle, MarkerShape.OpenSquare, MarkerShape.OpenTriangleUp,
        MarkerShape.OpenDiamond, MarkerShape.Cross, MarkerShape.Eks,
    ];

    /// <summary>One line on the chart.</summary>
    /// <param name="Name">The legend entry.</param>
    /// <param name="Points">The points, joined in this order.</param>
    public sealed record Series(string Name, IReadOnlyList<(double X, double Y)> Points);

    /// <summary>The chart as a ScottPlot <see cref="Plot"/>, to change or save further (the caller disposes it).</summary>
    /// <param name="title">The title above the plot.</param>
    /// <param name="xLabel">The horizontal axis's label.</param>
    /// <param name="yLabel">The vertical axis's label.</param>
    /// <param name="series">The lines, coloured and marked in order.</param>
    /// <returns>The plot.</returns>
    public static Plot Create(string title, string xLabel, string yLabel, IReadOnlyList<Series> series)
    {
        ArgumentNullException.ThrowIfNull(title);
        ArgumentNullException.ThrowIfNull(xLabel);
        ArgumentNullException.ThrowIfNull(yLabel);
        ArgumentNullException.ThrowIfNull(series);
        var plot = new Plot();
        ChartFont.Apply(plot);
        plot.Title(title, size: 17);
        plot.XLabel(xLabel, size: 14);
        plot.YLabel(yLabel, size: 14);

        var palette = new ScottPlot.Palettes.Tsitsulin();
        for (int i = 0; i < series.Count; i++)
        {
            (double X, double Y)[] points = [.. series[i].Points.Where(Drawable)];
            var line = plot.Add.ScatterLine(
                points.Select(p => Math.Log10(p.X)).ToArray(), points.Select(p => Math.Log10(p.Y)).ToArray(), palette.GetColor(i));
            line.LegendText = series[i].Name;
            line.LineWidth = 1.5f;
            line.MarkerShape = Shapes[i % Shapes.Length];
            line.MarkerSize = 8;
        }

        (double X, double Y)[] all = [.. series.SelectMany(s => s.Points).Where(Drawable)];
        (int xLo, int xHi) = Decades(all.Select(p => p.X));
        (int yLo, int yHi) = Decades(all.Select(p => p.Y));
        plot.Axes.Bottom.TickGenerator = DecadeTicks(xLo, xHi);
        plot.Axes.Left.TickGenerator = DecadeTicks(yLo, yHi);
        plot.Axes.SetLimits(xLo, xHi, yLo, yHi);
        plot.Grid.MajorLineColor = Colors.Black.WithAlpha(0.22);
        plot.Grid.MinorLineColor = Colors.Black.WithAlpha(0.07);
        plot.Grid.MinorLineWidth = 1;
        plot.Legend.FontSize = 13;
        plot.ShowLegend(Edge.Right);
        return plot;
    }

    /// <summary>Writes the chart as <paramref name="stem"/>.png and <paramref name="stem"/>.svg.</summary>
    /// <param name="stem">The path without extension.</param>
    /// <param name="title">The title above the plot.</param>
    /// <param name="xLabel">The horizontal axis's label.</param>
    /// <param name="yLabel">The vertical axis's label.</param>
    /// <param name="series">The lines, coloured and marked in order.</param>
    public static void Save(string stem, string title, string xLabel, string yLabel, IReadOnlyList<Series> series)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(stem);
        using Plot plot = Create(title, xLabel, yLabel, series);
        plot.SavePng(stem + ".png", Width, Height);
        plot.SaveSvg(stem + ".svg", Width, Height);
    }

    private static bool Drawable((double X, double Y) p) => p.X > 0 && p.Y > 0 && double.IsFinite(p.X) && double.IsFinite(p.Y);

    /// <summary>The decades that hold every value: ⌊log₁₀ min⌋ to ⌈log₁₀ max⌉, at least one decade wide.</summary>
    private static (int Lo, int Hi) Decades(IEnumerable<double> values)
    {
        double[] logs = [.. values.Select(Math.Log10)];
        if (logs.Length == 0)
        {
            return (0, 1);
        }

        // A tiny tolerance keeps 1000 in the decade of 1000 despite log10 rounding.
        int lo = (int)Math.Floor(logs.Min() + 1e-9), hi = (int)Math.Ceiling(logs.Max() - 1e-9);
        return (lo, Math.Max(hi, lo + 1));
    }

    /// <summary>Major ticks labelled at each decade 10^k (the axis holds log₁₀ of the values), minor ones at 2…9 · 10^k.</summary>
    private static NumericManual DecadeTicks(int lo, int hi)
    {
        var ticks = new NumericManual();
        for (int k = lo; k <= hi; k++)
        {
            ticks.AddMajor(k, Decade(k));
            for (int m = 2; m <= 9 && k < hi; m++)
            {
                ticks.AddMinor(k + Math.Log10(m));
            }
        }

        return ticks;
    }

    /// <summary>10^k as a plain number from 0.0001 to 100000, beyond that as 1e<i>k</i>.</summary>
    internal static string Decade(int k) => k switch
    {
        < -4 or > 5 => string.Create(CultureInfo.InvariantCulture, $"1e{k}"),
        < 0 => "0." + new string('0', -k - 1) + "1",
        _ => "1" + new string('0', k),
    };
}
