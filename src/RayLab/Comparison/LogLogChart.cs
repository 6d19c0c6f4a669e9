using System.Globalization;
using System.Security;
using System.Text;

namespace RayLab.Comparison;

/// <summary>
/// A line chart with logarithmic axes, written as SVG by hand (no charting library restores here): labelled
/// decades with faint lines at 2…9, one polyline with point markers per series, one colour per series and a
/// legend. Points with a coordinate that is not a positive finite number cannot be placed and are left out.
/// </summary>
public static class LogLogChart
{
    /// <summary>The SVG's size in pixels.</summary>
    public const int Width = 780, Height = 480;

    private const double Left = 80, Top = 40, Right = Width - 220, Bottom = Height - 60;

    // Tableau 10 and two more: distinguishable, and readable on white.
    private static readonly string[] Palette =
    [
        "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948",
        "#b07aa1", "#ff9da7", "#9c755f", "#7f7f7f", "#17becf", "#1b1b1b",
    ];

    /// <summary>One line on the chart.</summary>
    /// <param name="Name">The legend entry.</param>
    /// <param name="Points">The points, joined in this order.</param>
    public sealed record Series(string Name, IReadOnlyList<(double X, double Y)> Points);

    /// <summary>Draws the chart.</summary>
    /// <param name="title">The title above the plot.</param>
    /// <param name="xLabel">The horizontal axis's label.</param>
    /// <param name="yLabel">The vertical axis's label.</param>
    /// <param name="series">The lines, coloured in order.</param>
    /// <returns>A standalone SVG document.</returns>
    public static string ToSvg(string title, string xLabel, string yLabel, IReadOnlyList<Series> series)
    {
        ArgumentNullException.ThrowIfNull(series);
        (double X, double Y)[] all = [.. series.SelectMany(s => s.Points).Where(Drawable)];
        (int xLo, int xHi) = Decades(all.Select(p => p.X));
        (int yLo, int yHi) = Decades(all.Select(p => p.Y));
        double Px(double x) => Left + ((Math.Log10(x) - xLo) / (xHi - xLo) * (Right - Left));
        double Py(double y) => Bottom - ((Math.Log10(y) - yLo) / (yHi - yLo) * (Bottom - Top));

        var svg = new StringBuilder();
        Append(svg, $"""<svg xmlns="http://www.w3.org/2000/svg" width="{Width}" height="{Height}" viewBox="0 0 {Width} {Height}" font-family="sans-serif" font-size="12">""");
        Append(svg, $"""<rect width="{Width}" height="{Height}" fill="white"/>""");
        Append(svg, $"""<text x="{(Left + Right) / 2:F1}" y="22" text-anchor="middle" font-size="15">{Escape(title)}</text>""");
        for (int k = xLo; k <= xHi; k++)
        {
            GridLines(svg, k, k < xHi, m => Px(m), vertical: true);
            Append(svg, $"""<text class="x-decade" x="{Px(Math.Pow(10, k)):F2}" y="{Bottom + 18:F1}" text-anchor="middle">{Decade(k)}</text>""");
        }

        for (int k = yLo; k <= yHi; k++)
        {
            GridLines(svg, k, k < yHi, m => Py(m), vertical: false);
            Append(svg, $"""<text class="y-decade" x="{Left - 8:F1}" y="{Py(Math.Pow(10, k)):F2}" text-anchor="end" dominant-baseline="middle">{Decade(k)}</text>""");
        }

        Append(svg, $"""<rect x="{Left}" y="{Top}" width="{Right - Left}" height="{Bottom - Top}" fill="none" stroke="black"/>""");
        Append(svg, $"""<text x="{(Left + Right) / 2:F1}" y="{Height - 18}" text-anchor="middle">{Escape(xLabel)}</text>""");
        Append(svg, $"""<text transform="translate(20 {(Top + Bottom) / 2:F1}) rotate(-90)" text-anchor="middle">{Escape(yLabel)}</text>""");

        for (int i = 0; i < series.Count; i++)
        {
            string colour = Palette[i % Palette.Length];
            string dash = i < Palette.Length ? "" : """ stroke-dasharray="6 3" """;
            (double X, double Y)[] points = [.. series[i].Points.Where(Drawable)];
            string coordinates = string.Join(' ', points.Select(p => Invariant($"{Px(p.X):F2},{Py(p.Y):F2}")));
            Append(svg, $"""<polyline class="series" data-series="{Escape(series[i].Name)}" points="{coordinates}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>""");
            foreach ((double x, double y) in points)
            {
                Append(svg, $"""<circle cx="{Px(x):F2}" cy="{Py(y):F2}" r="3" fill="{colour}"/>""");
            }

            double ly = Top + 8 + (i * 18);
            Append(svg, $"""<line x1="{Right + 16}" y1="{ly:F1}" x2="{Right + 40}" y2="{ly:F1}" stroke="{colour}" stroke-width="2"{dash}/>""");
            Append(svg, $"""<text class="legend" x="{Right + 46}" y="{ly:F1}" dominant-baseline="middle">{Escape(series[i].Name)}</text>""");
        }

        svg.Append("</svg>\n");
        return svg.ToString();
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

    private static void GridLines(StringBuilder svg, int k, bool withMinor, Func<double, double> at, bool vertical)
    {
        for (int m = 1; m <= (withMinor ? 9 : 1); m++)
        {
            double p = at(m * Math.Pow(10, k));
            string stroke = m == 1 ? "#c8c8c8" : "#ececec";
            if (vertical)
            {
                Append(svg, $"""<line x1="{p:F2}" y1="{Top}" x2="{p:F2}" y2="{Bottom}" stroke="{stroke}"/>""");
            }
            else
            {
                Append(svg, $"""<line x1="{Left}" y1="{p:F2}" x2="{Right}" y2="{p:F2}" stroke="{stroke}"/>""");
            }
        }
    }

    /// <summary>10^k as a plain number from 0.0001 to 100000, beyond that as 1e<i>k</i>.</summary>
    private static string Decade(int k) => k switch
    {
        < -4 or > 5 => Invariant($"1e{k}"),
        < 0 => "0." + new string('0', -k - 1) + "1",
        _ => "1" + new string('0', k),
    };

    private static string Escape(string text) => SecurityElement.Escape(text);

    private static void Append(StringBuilder svg, FormattableString line) => svg.Append(Invariant(line)).Append('\n');

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
