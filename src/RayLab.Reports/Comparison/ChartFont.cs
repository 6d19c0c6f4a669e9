using ScottPlot;
using RayLab.Reports.Imaging;

namespace RayLab.Reports.Comparison;

/// <summary>
/// The font RayLab's charts are labelled with: the DejaVu Sans the library embeds, so a chart's text draws on any
/// machine (Skia's Linux library that RayLab ships has no fontconfig and finds no system font).
/// </summary>
public static class ChartFont
{
    /// <summary>Gives a ScottPlot chart the embedded font for every label, title and legend.</summary>
    /// <param name="plot">The chart, before it is saved.</param>
    /// <exception cref="ArgumentNullException"><paramref name="plot"/> is null.</exception>
    public static void Apply(Plot plot)
    {
        ArgumentNullException.ThrowIfNull(plot);
        ChartFonts.Register();
        plot.Font.Set(LabelFont.FamilyName);
    }
}
