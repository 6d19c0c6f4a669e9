using System.Globalization;
using System.Xml.Linq;
using RayLab.Comparison;

namespace RayLab.Tests.Comparison;

public class LogLogChartTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public void TheSvgParsesWithLabelledDecadesAndALegend()
    {
        XDocument doc = XDocument.Parse(LogLogChart.ToSvg("error & time", "time (ms)", "RMSE (levels)",
        [
            new("jittered", [(1, 100), (10, 10), (100, 1)]),
            new("random <1>", [(2, 50), (20, 20)]),
        ]));

        Assert.Equal(Svg + "svg", doc.Root!.Name);
        Assert.Equal(["1", "10", "100"], Texts(doc, "x-decade"));
        Assert.Equal(["1", "10", "100"], Texts(doc, "y-decade"));
        Assert.Equal(["jittered", "random <1>"], Texts(doc, "legend"));
        Assert.Contains(doc.Descendants(Svg + "text"), t => t.Value == "error & time");
    }

    [Fact]
    public void OnePolylinePerSeriesWithItsOwnColourAndEveryPointOnItsDecade()
    {
        XDocument doc = XDocument.Parse(LogLogChart.ToSvg("t", "x", "y",
        [
            new("a", [(0.01, 1000), (0.1, 100), (1, 10)]),
            new("b", [(0.01, 10), (1, 1000)]),
            new("c", [(0.1, 10)]),
        ]));

        XElement[] lines = [.. doc.Descendants(Svg + "polyline")];
        Assert.Equal(["a", "b", "c"], lines.Select(l => (string)l.Attribute("data-series")!));
        Assert.Equal(3, lines.Select(l => (string)l.Attribute("stroke")!).Distinct().Count());

        // Decades 0.01…1 across and 10…1000 up: each point sits where its decade's label is.
        Assert.Equal(["0.01", "0.1", "1"], Texts(doc, "x-decade"));
        Assert.Equal(["10", "100", "1000"], Texts(doc, "y-decade"));
        double X(string label) => Coordinate(doc, "x-decade", label, "x");
        double Y(string label) => Coordinate(doc, "y-decade", label, "y");
        Assert.Equal([(X("0.01"), Y("1000")), (X("0.1"), Y("100")), (X("1"), Y("10"))], Points(lines[0]));
        Assert.Equal([(X("0.01"), Y("10")), (X("1"), Y("1000"))], Points(lines[1]));
        Assert.Equal([(X("0.1"), Y("10"))], Points(lines[2]));

        // Log axes: equal ratios are equal distances, and larger values are higher up (smaller y).
        Assert.Equal(X("0.1") - X("0.01"), X("1") - X("0.1"), 6);
        Assert.True(Y("1000") < Y("100"));
    }

    [Fact]
    public void PointsBetweenDecadesAreOnTheLogScaleAndUndrawablePointsAreLeftOut()
    {
        XDocument doc = XDocument.Parse(LogLogChart.ToSvg("t", "x", "y",
            [new("s", [(1, 1), (Math.Sqrt(10), 0), (Math.Sqrt(10), Math.Sqrt(10)), (double.NaN, 5), (10, 10)])]));

        (double X, double Y)[] points = Points(Assert.Single(doc.Descendants(Svg + "polyline")));
        Assert.Equal(3, points.Length);
        // √10 is half a decade: exactly midway between 1 and 10 on both axes.
        Assert.Equal((points[0].X + points[2].X) / 2, points[1].X, 1);
        Assert.Equal((points[0].Y + points[2].Y) / 2, points[1].Y, 1);
        Assert.Equal(3, doc.Descendants(Svg + "circle").Count());
    }

    [Fact]
    public void DecadesBeyondTheUsualRangeUseExponentsAndAnEmptyChartStillDraws()
    {
        XDocument wide = XDocument.Parse(LogLogChart.ToSvg("t", "x", "y", [new("s", [(1e-6, 1e6), (2e-5, 3e7)])]));
        Assert.Equal(["1e-6", "1e-5", "0.0001"], Texts(wide, "x-decade"));
        Assert.Equal(["1e6", "1e7", "1e8"], Texts(wide, "y-decade"));

        XDocument empty = XDocument.Parse(LogLogChart.ToSvg("t", "x", "y", [new("nothing", [])]));
        Assert.Equal(["1", "10"], Texts(empty, "x-decade"));
        Assert.Equal("", (string)Assert.Single(empty.Descendants(Svg + "polyline")).Attribute("points")!);
    }

    private static string[] Texts(XDocument doc, string cls) =>
        [.. doc.Descendants(Svg + "text").Where(t => (string?)t.Attribute("class") == cls).Select(t => t.Value)];

    private static double Coordinate(XDocument doc, string cls, string label, string attribute) =>
        double.Parse((string)doc.Descendants(Svg + "text")
            .Single(t => (string?)t.Attribute("class") == cls && t.Value == label).Attribute(attribute)!, CultureInfo.InvariantCulture);

    private static (double X, double Y)[] Points(XElement polyline) =>
        [.. ((string)polyline.Attribute("points")!).Split(' ', StringSplitOptions.RemoveEmptyEntries).Select(p =>
        {
            string[] xy = p.Split(',');
            return (double.Parse(xy[0], CultureInfo.InvariantCulture), double.Parse(xy[1], CultureInfo.InvariantCulture));
        })];
}
