using RayLab.Metrics;

namespace RayLab.Reports.Imaging;

/// <summary>
/// A FLIP error map (<see cref="FlipResult"/>) as a picture, in the magma colour map NVIDIA's FLIP tool writes its
/// maps in: black where the two images cannot be told apart, through purple and orange, to pale yellow at 1. Pixel
/// value v takes entry ⌊255·v + ½⌋ of the 256-entry map, as the tool does. The entries are ScottPlot's magma table
/// (matplotlib's, cut to bytes), within one level per channel of the tool's (which rounds the same table).
/// </summary>
public static class FlipMap
{
    /// <summary>The colour bar's title in <see cref="RenderWithLegend(FlipResult)"/>.</summary>
    public const string LegendTitle = "FLIP";

    private static readonly Rgb24[] Magma = CreateMagma();

    /// <summary>
    /// The magma colour of a FLIP value: entry ⌊255·<paramref name="value"/> + ½⌋ of the map (0 black, 1 pale yellow),
    /// computed in single precision as the tool computes it.
    /// </summary>
    /// <param name="value">A FLIP value; clamped to [0, 1], NaN taken as 0.</param>
    public static Rgb24 MagmaAt(double value) => Magma[Entry((float)value)];

    /// <summary>The map's entry for a value: ⌊255·v + ½⌋ in float, v clamped to [0, 1] and NaN taken as 0.</summary>
    private static int Entry(float value) => (int)((Math.Clamp(float.IsNaN(value) ? 0 : value, 0f, 1f) * 255f) + 0.5f);

    /// <summary>The map alone, one magma pixel per pixel of the images compared (what NVIDIA's tool writes).</summary>
    /// <param name="flip">The FLIP result.</param>
    /// <returns>An image of the map's size.</returns>
    public static Image Render(FlipResult flip)
    {
        ArgumentNullException.ThrowIfNull(flip);
        var image = new Image(flip.Width, flip.Height);
        Paint(flip, image);
        return image;
    }

    /// <summary>
    /// The map with a colour bar from 0 to 1 on its right, titled <see cref="LegendTitle"/>, as the compare report's
    /// error images have theirs (a short map is padded below in white so the bar stays legible).
    /// </summary>
    /// <param name="flip">The FLIP result.</param>
    /// <returns>An image <see cref="HeatMap"/>'s legend wider than the map and at least as high.</returns>
    public static Image RenderWithLegend(FlipResult flip)
    {
        ArgumentNullException.ThrowIfNull(flip);
        (int width, int height) = HeatMap.SizeFor(flip.Width, flip.Height);
        var image = new Image(width, height);
        RenderWithLegend(flip, image);
        return image;
    }

    /// <summary>
    /// <see cref="RenderWithLegend(FlipResult)"/> into <paramref name="image"/> (of <see cref="HeatMap.SizeFor"/> the
    /// map's size), every pixel of which is written: for a caller that draws many maps of one size into one image.
    /// </summary>
    internal static void RenderWithLegend(FlipResult flip, Image image)
    {
        ArgumentNullException.ThrowIfNull(flip);
        ArgumentNullException.ThrowIfNull(image);
        HeatMap.CheckCanvas(image, flip.Width, flip.Height);
        HeatMap.PadBelow(image, flip.Height);

        Paint(flip, image);
        HeatMap.DrawLegend(image, flip.Width, 0, 1, LegendTitle, MagmaAt, _ => "0.##");
    }

    /// <summary>Colours the map into the image's first W columns, in bands of rows in parallel (a 1080p map is 2 million look-ups).</summary>
    private static void Paint(FlipResult flip, Image image)
    {
        int width = flip.Width;
        const int BandRows = 64;
        Parallel.For(0, (flip.Height + BandRows - 1) / BandRows, band =>
        {
            ReadOnlySpan<float> map = flip.Map;
            for (int y = band * BandRows; y < Math.Min(flip.Height, (band + 1) * BandRows); y++)
            {
                Span<Rgb24> row = image.GetRowSpan(y);
                ReadOnlySpan<float> source = map.Slice(y * width, width);
                for (int x = 0; x < width; x++)
                {
                    row[x] = Magma[Entry(source[x])];
                }
            }
        });
    }

    private static Rgb24[] CreateMagma()
    {
        var magma = new ScottPlot.Colormaps.Magma();
        var table = new Rgb24[256];
        for (int i = 0; i < table.Length; i++)
        {
            ScottPlot.Color c = magma.GetColor(i / 255.0);
            table[i] = new Rgb24(c.R, c.G, c.B);
        }

        return table;
    }
}
