using System.Buffers;
using System.Globalization;
using SkiaSharp;

namespace RayLab.Reports.Imaging;

/// <summary>
/// Draws a per-pixel quantity — the primary rays an adaptive render spent on each pixel — as a false-colour
/// picture with a legend: a colour bar on the right, titled with the unit and labelled with its scale. The
/// legend's text is drawn by SkiaSharp in the embedded DejaVu Sans (<see cref="LabelFont"/>).
/// </summary>
public static class HeatMap
{
    /// <summary>The width of the colour bar strip to the right of the data, in pixels.</summary>
    internal const int LegendWidth = 84;

    /// <summary>The least height of a heat map: a shorter image is padded below so the colour bar stays legible.</summary>
    internal const int MinHeight = 120;
    private const int Gap = 6, BarWidth = 12, Top = 28, BottomMargin = 8;
    private const float TextSize = 12;

    // Viridis, sampled at five stops: dark blue (few rays) to yellow (many).
    private static readonly (double R, double G, double B)[] Ramp =
    [
        (0.267, 0.005, 0.329), (0.229, 0.322, 0.546), (0.128, 0.567, 0.551), (0.369, 0.789, 0.383), (0.993, 0.906, 0.144),
    ];

    /// <summary>Draws <paramref name="values"/> (W·H, row 0 first) with a colour bar from their minimum to their maximum.</summary>
    /// <param name="values">One value per pixel.</param>
    /// <param name="width">Width W of the data.</param>
    /// <param name="height">Height H of the data.</param>
    /// <returns>An image W + legend wide and at least H high.</returns>
    /// <exception cref="ArgumentException">The span's length is not W·H, or a value is not finite.</exception>
    public static Image Render(ReadOnlySpan<float> values, int width, int height) => Render(values, width, height, "rays/px");

    /// <summary>Draws <paramref name="values"/> (W·H, row 0 first) with a colour bar titled <paramref name="title"/>.</summary>
    /// <param name="values">One value per pixel.</param>
    /// <param name="width">Width W of the data.</param>
    /// <param name="height">Height H of the data.</param>
    /// <param name="title">The colour bar's title, the values' unit (shrunk to fit the legend's width; empty for none).</param>
    /// <returns>An image W + legend wide and at least H high.</returns>
    /// <exception cref="ArgumentException">The span's length is not W·H, or a value is not finite.</exception>
    public static Image Render(ReadOnlySpan<float> values, int width, int height, string title)
    {
        Image.CheckSize(width, height);
        (int imageWidth, int imageHeight) = SizeFor(width, height);
        var image = new Image(imageWidth, imageHeight);
        Render(values, width, height, title, image);
        return image;
    }

    /// <summary>
    /// <see cref="Render(ReadOnlySpan{float}, int, int, string)"/> into <paramref name="image"/>, every pixel of which is
    /// written: for a caller that draws many maps of one size into one image (<see cref="SizeFor"/>).
    /// </summary>
    internal static void Render(ReadOnlySpan<float> values, int width, int height, string title, Image image)
    {
        ArgumentNullException.ThrowIfNull(title);
        ArgumentNullException.ThrowIfNull(image);
        Image.CheckSize(width, height);
        if (values.Length != (long)width * height)
        {
            throw new ArgumentException($"Expected {width}×{height} values, got {values.Length}.", nameof(values));
        }

        CheckCanvas(image, width, height);
        float min = float.PositiveInfinity, max = float.NegativeInfinity;
        foreach (float v in values)
        {
            if (!float.IsFinite(v))
            {
                throw new ArgumentException("Every value must be finite.", nameof(values));
            }

            min = Math.Min(min, v);
            max = Math.Max(max, v);
        }

        PadBelow(image, height);
        Paint(values, width, height, min, max, image);
        DrawLegend(image, width, min, max, title, ColorAt, value => value >= 100 || value == Math.Floor(value) ? "0" : "0.#");
    }

    /// <summary>Throws unless <paramref name="image"/> is <see cref="SizeFor"/> a W×H map.</summary>
    internal static void CheckCanvas(Image image, int width, int height)
    {
        if ((image.Width, image.Height) != SizeFor(width, height))
        {
            throw new ArgumentException($"A {width}×{height} map is drawn into a {SizeFor(width, height)} image, not {image.Width}×{image.Height}.", nameof(image));
        }
    }

    /// <summary>
    /// Fills white the rows below a map <paramref name="height"/> rows high (a short map's padding): the data's rows are
    /// painted and the legend drawn over its strip, so these are the only pixels left to write.
    /// </summary>
    internal static void PadBelow(Image image, int height)
    {
        for (int y = height; y < image.Height; y++)
        {
            image.GetRowSpan(y).Fill(new Rgb24(255, 255, 255));
        }
    }

    /// <summary>The size of a map of W×H values with its legend: W + <see cref="LegendWidth"/> wide, at least <see cref="MinHeight"/> high.</summary>
    internal static (int Width, int Height) SizeFor(int width, int height) => (width + LegendWidth, Math.Max(height, MinHeight));

    /// <summary>
    /// Colours the values into the image's first W columns, in bands of rows in parallel (a 1080p map is 2 million
    /// colours; each pixel's colour depends on its value alone, so the bytes do not depend on the thread count).
    /// </summary>
    private static void Paint(ReadOnlySpan<float> values, int width, int height, float min, float max, Image image)
    {
        const int BandRows = 64;
        float[] copy = ArrayPool<float>.Shared.Rent(values.Length);
        try
        {
            values.CopyTo(copy);
            Parallel.For(0, (height + BandRows - 1) / BandRows, band =>
            {
                for (int y = band * BandRows; y < Math.Min(height, (band + 1) * BandRows); y++)
                {
                    Span<Rgb24> row = image.GetRowSpan(y);
                    ReadOnlySpan<float> source = copy.AsSpan(y * width, width);
                    for (int x = 0; x < width; x++)
                    {
                        row[x] = ColorAt(Normalize(source[x], min, max));
                    }
                }
            });
        }
        finally
        {
            ArrayPool<float>.Shared.Return(copy);
        }
    }

    /// <summary>The colour for t ∈ [0, 1] on the ramp (dark blue at 0, yellow at 1).</summary>
    /// <param name="t">Position on the scale; clamped to [0, 1].</param>
    public static Rgb24 ColorAt(double t)
    {
        t = Math.Clamp(double.IsNaN(t) ? 0 : t, 0, 1) * (Ramp.Length - 1);
        int i = Math.Min((int)t, Ramp.Length - 2);
        double f = t - i;
        (double R, double G, double B) a = Ramp[i], b = Ramp[i + 1];
        return new Rgb24(Level(a.R, b.R, f), Level(a.G, b.G, f), Level(a.B, b.B, f));
    }

    private static double Normalize(float v, float min, float max) => max > min ? (v - min) / (double)(max - min) : 0;

    private static byte Level(double a, double b, double f) => (byte)Math.Round(255 * (a + ((b - a) * f)));

    /// <summary>
    /// Draws the colour bar strip (<see cref="LegendWidth"/> wide, the image's height) at column <paramref name="x0"/>:
    /// the bar runs from <paramref name="min"/> at the bottom to <paramref name="max"/> at the top in the colours of
    /// <paramref name="color"/> (called with 0…1), five labelled ticks, <paramref name="title"/> above.
    /// </summary>
    internal static void DrawLegend(Image image, int x0, float min, float max, string title, Func<double, Rgb24> color, Func<double, string> labelFormat)
    {
        int height = image.Height;
        int bottom = height - BottomMargin;
        using var strip = new SKBitmap(new SKImageInfo(LegendWidth, height, SKColorType.Rgba8888, SKAlphaType.Opaque));
        using (var canvas = new SKCanvas(strip))
        using (SKFont font = LabelFont.Create(TextSize))
        using (var ink = new SKPaint { Color = SKColors.Black, IsAntialias = true })
        using (var tick = new SKPaint { Color = SKColors.Black, IsAntialias = false })
        {
            canvas.Clear(SKColors.White);
            if (title.Length > 0)
            {
                // The unit, shrunk if needed to fit the strip.
                float room = LegendWidth - Gap - 2;
                float width = font.MeasureText(title);
                using SKFont titleFont = LabelFont.Create(width > room ? TextSize * room / width : TextSize);
                canvas.DrawText(title, Gap, Top - 13, SKTextAlign.Left, titleFont, ink);
            }

            const int Ticks = 5;
            for (int k = 0; k < Ticks; k++)
            {
                double f = k / (double)(Ticks - 1);
                int y = bottom - (int)Math.Round(f * (bottom - Top));
                canvas.DrawRect(SKRect.Create(Gap + BarWidth, y, 3, 1), tick);
                double value = min + (f * (max - min));
                string label = value.ToString(labelFormat(value), CultureInfo.InvariantCulture);
                float baseline = Math.Clamp(y + (TextSize * 0.36f), TextSize, height - 1);
                canvas.DrawText(label, Gap + BarWidth + 6, baseline, SKTextAlign.Left, font, ink);
            }
        }

        Image legend = Image.FromSKBitmap(strip);
        for (int y = Top; y <= bottom; y++)
        {
            legend.GetRowSpan(y).Slice(Gap, BarWidth).Fill(color((bottom - y) / (double)(bottom - Top)));
        }

        for (int y = 0; y < height; y++)
        {
            legend.GetRowSpan(y).CopyTo(image.GetRowSpan(y)[x0..]);
        }
    }
}
