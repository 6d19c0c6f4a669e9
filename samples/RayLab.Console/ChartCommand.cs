using System.CommandLine;
using System.Globalization;
using RayLab.Reports.Comparison;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab chart TABLE.csv --out STEM [--title T] [--x-label X] [--y-label Y]</c> (hidden: a helper behind the
/// docs' charts, e.g. tools/sphere-count.sh): draws a CSV table as the library's log-log chart
/// (<see cref="LogLogChart"/>), STEM.png and STEM.svg. The first column is x, every further column one line named
/// by its header; a cell that is not a positive number (empty, or a cut-off such as "&gt; 60 s") is left out.
/// </summary>
public static class ChartCommand
{
    /// <summary>Builds the command.</summary>
    /// <param name="stdout">Where the summary line goes.</param>
    /// <param name="stderr">Where errors go, one line each.</param>
    public static Command Create(TextWriter stdout, TextWriter stderr)
    {
        var table = new Argument<string>("table") { Description = "The CSV: a header row, then x and one value per line in each row." };
        var output = new Option<string>("--out") { Description = "The chart's path without extension: STEM.png and STEM.svg are written.", Required = true, HelpName = "STEM" };
        var title = new Option<string>("--title") { Description = "The chart's title.", DefaultValueFactory = _ => "" };
        var xLabel = new Option<string?>("--x-label") { Description = "The horizontal axis's label. Default: the first column's header." };
        var yLabel = new Option<string>("--y-label") { Description = "The vertical axis's label.", DefaultValueFactory = _ => "" };
        var chart = new Command("chart", "Draw a CSV table as a log-log chart (PNG and SVG).") { table, output, title, xLabel, yLabel };
        chart.Hidden = true;
        chart.SetAction(result =>
        {
            string path = result.GetRequiredValue(table);
            string stem = result.GetRequiredValue(output);
            return CommandExit.Run(
                stderr,
                () =>
                {
                    (string xName, List<LogLogChart.Series> series) = Read(path);
                    LogLogChart.Save(stem, result.GetRequiredValue(title), result.GetValue(xLabel) ?? xName, result.GetRequiredValue(yLabel), series);
                    stdout.WriteLine($"{stem}.png, {stem}.svg: {series.Count} lines, {series.Sum(s => s.Points.Count)} points");
                    return CommandExit.Done;
                },
                cancelled: $"{stem}.png not written",
                tooLarge: $"draw {path}",
                CancellationToken.None);
        });
        return chart;
    }

    /// <summary>The table's x header and one series per further column.</summary>
    private static (string XName, List<LogLogChart.Series> Series) Read(string path)
    {
        string[] lines = [.. File.ReadAllLines(path).Where(line => line.Trim().Length > 0)];
        if (lines.Length == 0)
        {
            throw new FormatException($"{path}: the table is empty (expected a header row)");
        }

        string[] header = lines[0].Split(',');
        var points = header.Skip(1).Select(_ => new List<(double X, double Y)>()).ToArray();
        for (int row = 1; row < lines.Length; row++)
        {
            string[] cells = lines[row].Split(',');
            if (cells.Length != header.Length)
            {
                throw new FormatException($"{path}: line {row + 1}: {cells.Length} cells, the header has {header.Length}");
            }

            if (!double.TryParse(cells[0], NumberStyles.Float, CultureInfo.InvariantCulture, out double x))
            {
                throw new FormatException($"{path}: line {row + 1}: x must be a number, got '{cells[0]}'");
            }

            for (int column = 1; column < cells.Length; column++)
            {
                if (double.TryParse(cells[column], NumberStyles.Float, CultureInfo.InvariantCulture, out double y) && y > 0 && double.IsFinite(y))
                {
                    points[column - 1].Add((x, y));
                }
            }
        }

        return (header[0].Trim(), [.. header.Skip(1).Select((name, i) => new LogLogChart.Series(name.Trim(), points[i]))]);
    }
}
