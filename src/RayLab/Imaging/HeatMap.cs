using System.Globalization;

namespace RayLab.Imaging;

/// <summary>
/// Draws a per-pixel quantity — the primary rays an adaptive render spent on each pixel — as a false-colour
/// picture with a legend: a colour bar on the right labelled with its numbers. Drawn with RayLab's own image
/// type and a built-in 3×5 pixel font; no imaging library is needed.
/// </summary>
public static class HeatMap
{
    private const int Scale = 2;          // font pixels per glyph pixel
    private const int LegendWidth = 24 + (6 * 4 * Scale);
    private const int MinHeight = 5 * 12 * Scale;

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
    /// <param name="title">The colour bar's title, up to 7 characters of the built-in font (digits, <c>. /</c> and <c>a e l p r s v x y</c>).</param>
    /// <returns>An image W + legend wide and at least H high.</returns>
    /// <exception cref="ArgumentException">The span's length is not W·H, or a value is not finite.</exception>
    public static Image Render(ReadOnlySpan<float> values, int width, int height, string title)
    {
        ArgumentNullException.ThrowIfNull(title);
        Image.CheckSize(width, height);
        if (values.Length != (long)width * height)
        {
            throw new ArgumentException($"Expected {width}×{height} values, got {values.Length}.", nameof(values));
        }

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

        var image = new Image(width + LegendWidth, Math.Max(height, MinHeight));
        for (int y = 0; y < image.Height; y++)
        {
            image.GetRowSpan(y).Fill(new Rgb24(255, 255, 255));
        }

        for (int y = 0; y < height; y++)
        {
            Span<Rgb24> row = image.GetRowSpan(y);
            ReadOnlySpan<float> source = values.Slice(y * width, width);
            for (int x = 0; x < width; x++)
            {
                row[x] = ColorAt(Normalize(source[x], min, max));
            }
        }

        DrawLegend(image, width + 6, min, max, title);
        return image;
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

    private static void DrawLegend(Image image, int x0, float min, float max, string title)
    {
        const int BarWidth = 12, Top = 14 * Scale;
        int bottom = image.Height - (4 * Scale);
        DrawText(image, x0, 2, title);
        for (int y = Top; y <= bottom; y++)
        {
            Rgb24 colour = ColorAt((bottom - y) / (double)(bottom - Top));
            image.GetRowSpan(y).Slice(x0, BarWidth).Fill(colour);
        }

        const int Ticks = 5;
        for (int k = 0; k < Ticks; k++)
        {
            double f = k / (double)(Ticks - 1);
            int y = bottom - (int)Math.Round(f * (bottom - Top));
            image.GetRowSpan(y).Slice(x0 + BarWidth, 2).Fill(new Rgb24(0, 0, 0));
            double value = min + (f * (max - min));
            string label = value.ToString(value >= 100 || value == Math.Floor(value) ? "0" : "0.#", CultureInfo.InvariantCulture);
            DrawText(image, x0 + BarWidth + 8, Math.Clamp(y - (5 * Scale / 2), 0, image.Height - (5 * Scale)), label);
        }
    }

    /// <summary>Draws text in black with the 3×5 font; characters without a glyph are left blank.</summary>
    internal static void DrawText(Image image, int x, int y, string text)
    {
        foreach (char ch in text)
        {
            if (Font.TryGetValue(ch, out ushort bits))
            {
                for (int gy = 0; gy < 5; gy++)
                {
                    for (int gx = 0; gx < 3; gx++)
                    {
                        if ((bits >> (14 - ((gy * 3) + gx)) & 1) != 0)
                        {
                            for (int sy = 0; sy < Scale; sy++)
                            {
                                int py = y + (gy * Scale) + sy;
                                if (py >= 0 && py < image.Height)
                                {
                                    Span<Rgb24> row = image.GetRowSpan(py);
                                    for (int sx = 0; sx < Scale; sx++)
                                    {
                                        int px = x + (gx * Scale) + sx;
                                        if (px >= 0 && px < image.Width)
                                        {
                                            row[px] = default;
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }

            x += 4 * Scale;
        }
    }

    /// <summary>3×5 glyphs, 15 bits each, row by row from the top-left bit (bit 14).</summary>
    private static readonly Dictionary<char, ushort> Font = new()
    {
        ['0'] = Glyph("111", "101", "101", "101", "111"),
        ['1'] = Glyph("010", "110", "010", "010", "111"),
        ['2'] = Glyph("111", "001", "111", "100", "111"),
        ['3'] = Glyph("111", "001", "111", "001", "111"),
        ['4'] = Glyph("101", "101", "111", "001", "001"),
        ['5'] = Glyph("111", "100", "111", "001", "111"),
        ['6'] = Glyph("111", "100", "111", "101", "111"),
        ['7'] = Glyph("111", "001", "010", "010", "010"),
        ['8'] = Glyph("111", "101", "111", "101", "111"),
        ['9'] = Glyph("111", "101", "111", "001", "111"),
        ['.'] = Glyph("000", "000", "000", "000", "010"),
        ['/'] = Glyph("001", "001", "010", "100", "100"),
        ['r'] = Glyph("000", "110", "101", "100", "100"),
        ['a'] = Glyph("000", "011", "101", "101", "011"),
        ['y'] = Glyph("000", "101", "111", "001", "110"),
        ['s'] = Glyph("000", "011", "110", "011", "110"),
        ['p'] = Glyph("000", "110", "101", "110", "100"),
        ['x'] = Glyph("000", "101", "010", "010", "101"),
        ['e'] = Glyph("000", "011", "111", "100", "011"),
        ['l'] = Glyph("110", "010", "010", "010", "111"),
        ['v'] = Glyph("000", "101", "101", "101", "010"),
    };

    private static ushort Glyph(params string[] rows) =>
        (ushort)Convert.ToInt32(string.Concat(rows), 2);
}
