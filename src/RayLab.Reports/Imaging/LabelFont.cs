using SkiaSharp;

namespace RayLab.Reports.Imaging;

/// <summary>
/// The typeface every label RayLab draws is set in (heat-map legends, compare charts): DejaVu Sans, embedded in the
/// library (Imaging/Fonts, Bitstream Vera licence). Skia's Linux library is the one without fontconfig, so the
/// machine's fonts are never asked for: text looks the same, and draws, on every machine, with or without fonts.
/// </summary>
internal static class LabelFont
{
    /// <summary>The family name charts ask for.</summary>
    public const string FamilyName = "DejaVu Sans";

    private const string ResourceName = "RayLab.Reports.Imaging.Fonts.DejaVuSans.ttf";

    private static readonly Lazy<SKTypeface> Face = new(Load, LazyThreadSafetyMode.ExecutionAndPublication);

    /// <summary>The embedded typeface, loaded once and shared (never dispose it).</summary>
    public static SKTypeface Typeface => Face.Value;

    /// <summary>A font of the embedded typeface at <paramref name="size"/> pixels, antialiased (the caller disposes it).</summary>
    /// <param name="size">The em size in pixels.</param>
    public static SKFont Create(float size) => new(Typeface, size) { Edging = SKFontEdging.Antialias, Subpixel = true };

    private static SKTypeface Load()
    {
        using Stream stream = typeof(LabelFont).Assembly.GetManifestResourceStream(ResourceName)
            ?? throw new InvalidOperationException($"The embedded font {ResourceName} is missing from {typeof(LabelFont).Assembly.GetName().Name}.");
        using SKData data = SKData.Create(stream);
        return SKTypeface.FromData(data) ?? throw new InvalidOperationException($"SkiaSharp could not read the embedded font {ResourceName}.");
    }
}
