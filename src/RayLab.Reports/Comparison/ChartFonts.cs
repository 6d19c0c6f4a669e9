using ScottPlot;
using SkiaSharp;
using RayLab.Reports.Imaging;

namespace RayLab.Reports.Comparison;

/// <summary>
/// Hands ScottPlot the embedded DejaVu Sans (<see cref="LabelFont"/>) when a chart asks for it by name: Skia's
/// Linux library here has no fontconfig, so ScottPlot's own resolver finds no system font to fall back on.
/// </summary>
internal sealed class ChartFonts : IFontResolver
{
    private static readonly Lock Gate = new();
    private static bool _registered;

    /// <summary>Adds the resolver to ScottPlot's list once (the list is global; later calls do nothing).</summary>
    public static void Register()
    {
        lock (Gate)
        {
            if (!_registered)
            {
                Fonts.FontResolvers.Insert(0, new ChartFonts());
                Fonts.Default = LabelFont.FamilyName; // text added after Plot.Font.Set (labels, annotations) too
                _registered = true;
            }
        }
    }

    /// <inheritdoc/>
    public SKTypeface? CreateTypeface(string fontName, FontWeight weight, FontSlant slant, FontSpacing width) =>
        Matches(fontName) ? LabelFont.Typeface : null;

    /// <inheritdoc/>
    public SKTypeface? CreateTypeface(string fontName, bool bold, bool italic) => Matches(fontName) ? LabelFont.Typeface : null;

    private static bool Matches(string fontName) => string.Equals(fontName, LabelFont.FamilyName, StringComparison.OrdinalIgnoreCase);
}
