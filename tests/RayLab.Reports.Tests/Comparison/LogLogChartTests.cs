using System.Xml.Linq;
using RayLab.Reports.Comparison;
using ScottPlot;
using ScottPlot.Plottables;

namespace RayLab.Reports.Tests.Comparison;

public sealed class LogLogChartTests : IDisposable
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void EachSeriesIsALineOfLog10PointsNamedInTheLegend()
    {
        using Plot plot = LogLogChart.Create("error & time", "time (ms)", "RMSE (levels)",
        [
            new("jittered", [(1, 100), (10, 10), (100, 1)]),
            new("random <1>", [(2, 50), (20, 20)]),
        ]);

        Scatter[] lines = [.. plot.GetPlottables().OfType<Scatter>()];
        Assert.Equal(["jittered", "random <1>"], lines.Select(l => l.LegendText));
        Assert.Equal([(0, 2), (1, 1), (2, 0)], Coordinates(lines[0]));
        Assert.Equal([(Math.Log10(2), Math.Log10(50)), (Math.Log10(20), Math.Log10(20))], Coordinates(lines[1]));
        Assert.Equal("error & time", plot.Axes.Title.Label.Text);
    }

    [Fact]
    public void AxesAreLabelledInDecadesWithMinorTicksAtTwoToNine()
    {
        using Plot plot = LogLogChart.Create("t", "x", "y",
        [
            new("a", [(0.01, 1000), (0.1, 100), (1, 10)]),
            new("b", [(0.02, 10), (0.5, 1000)]),
        ]);

        Assert.Equal(["0.01", "0.1", "1"], MajorLabels(plot, plot.Axes.Bottom));
        Assert.Equal(["10", "100", "1000"], MajorLabels(plot, plot.Axes.Left));
        double[] minor = [.. Rendered(plot, plot.Axes.Bottom).Where(t => !t.IsMajor).Select(t => t.Position)];
        Assert.Equal(16, minor.Length); // 2…9 in each of the two decades
        Assert.Contains(minor, p => Math.Abs(p - Math.Log10(0.05)) < 1e-12);
        AxisLimits limits = plot.Axes.GetLimits();
        Assert.Equal((-2, 0, 1, 3), (limits.Left, limits.Right, limits.Bottom, limits.Top));
    }

    [Fact]
    public void UndrawablePointsAreLeftOutAndDecadesBeyondTheUsualRangeUseExponents()
    {
        using Plot plot = LogLogChart.Create("t", "x", "y",
            [new("s", [(1e-6, 1e6), (Math.Sqrt(10), 0), (double.NaN, 5), (-1, 2), (2e-5, 3e7)])]);

        Assert.Equal(2, Coordinates(Assert.Single(plot.GetPlottables().OfType<Scatter>())).Length);
        Assert.Equal(["1e-6", "1e-5", "0.0001"], MajorLabels(plot, plot.Axes.Bottom));
        Assert.Equal(["1e6", "1e7", "1e8"], MajorLabels(plot, plot.Axes.Left));

        using Plot empty = LogLogChart.Create("t", "x", "y", [new("nothing", [])]);
        Assert.Equal(["1", "10"], MajorLabels(empty, empty.Axes.Bottom));
    }

    [Fact]
    public void TwelveLinesEachHaveTheirOwnColourAndNeighboursDifferInShape()
    {
        LogLogChart.Series[] series = [.. Enumerable.Range(0, 12).Select(i => new LogLogChart.Series($"s{i}", [(1, i + 1.0), (10, i + 2.0)]))];
        using Plot plot = LogLogChart.Create("t", "x", "y", series);

        Scatter[] lines = [.. plot.GetPlottables().OfType<Scatter>()];
        Assert.Equal(12, lines.Select(l => l.Color).Distinct().Count());
        Assert.All(lines.Zip(lines.Skip(1)), pair => Assert.NotEqual(pair.First.MarkerShape, pair.Second.MarkerShape));
        Assert.All(lines, l => Assert.NotEqual(MarkerShape.None, l.MarkerShape));
    }

    [Fact]
    public void SaveWritesAPngWithTextAndAnSvgNamingTheTitleAndEverySeries()
    {
        string stem = _dir.File("chart");
        LogLogChart.Save(stem, "RMSE against time", "time (ms)", "RMSE (levels)",
            [new("jittered", [(1, 10), (100, 1)]), new("adaptive c=0.5", [(3, 5), (30, 0.5)])]);

        SkiaDecode.Result png = SkiaDecode.Load(stem + ".png");
        Assert.Equal((LogLogChart.Width, LogLogChart.Height), (png.Width, png.Height));
        // The title's glyphs: dark pixels in the band above the plot, which is otherwise white.
        int dark = 0;
        for (int i = 0; i < png.Width * 30 * 3; i += 3)
        {
            dark += png.Rgb[i] + png.Rgb[i + 1] + png.Rgb[i + 2] < 200 ? 1 : 0;
        }

        Assert.True(dark > 50, $"{dark} dark pixels in the title band");

        string text = string.Concat(XDocument.Load(stem + ".svg").Descendants(Svg + "text").Select(t => t.Value));
        Assert.Contains("RMSE against time", text, StringComparison.Ordinal);
        Assert.Contains("jittered", text, StringComparison.Ordinal);
        Assert.Contains("adaptive c=0.5", text, StringComparison.Ordinal);
    }

    private static (double X, double Y)[] Coordinates(Scatter line) => [.. line.Data.GetScatterPoints().Select(p => (p.X, p.Y))];

    // The ticks are made when the plot is laid out: render it once first.
    private static string[] MajorLabels(Plot plot, IAxis axis) => [.. Rendered(plot, axis).Where(t => t.IsMajor).OrderBy(t => t.Position).Select(t => t.Label)];

    private static Tick[] Rendered(Plot plot, IAxis axis)
    {
        plot.GetImage(LogLogChart.Width, LogLogChart.Height).Dispose();
        return axis.TickGenerator.Ticks;
    }
}
