using RayLab.Reports.Imaging;

namespace RayLab.Reports.Tests.Imaging;

public class HeatMapTests
{
    [Fact]
    public void LowAndHighValuesGetTheEndsOfTheRampAndALegendIsDrawn()
    {
        const int W = 50, H = 40;
        var values = new float[W * H];
        values.AsSpan().Fill(2);
        values[(10 * W) + 20] = 34; // one busy pixel
        Image map = HeatMap.Render(values, W, H);

        Assert.True(map.Width > W, "a legend strip is added on the right");
        Assert.True(map.Height >= H);
        Assert.Equal(HeatMap.ColorAt(0), map.GetPixel(0, 0));
        Assert.Equal(HeatMap.ColorAt(1), map.GetPixel(20, 10));
        Assert.NotEqual(HeatMap.ColorAt(0), HeatMap.ColorAt(1));

        // The legend holds the whole ramp (a bar) and black label pixels (its numbers).
        var legend = new HashSet<Rgb24>();
        for (int y = 0; y < map.Height; y++)
        {
            foreach (Rgb24 p in map.GetRowSpan(y)[W..])
            {
                legend.Add(p);
            }
        }

        Assert.Contains(HeatMap.ColorAt(0), legend);
        Assert.Contains(HeatMap.ColorAt(1), legend);
        Assert.Contains(new Rgb24(0, 0, 0), legend);
        Assert.True(legend.Count > 20, "the bar shows a gradient");
    }

    [Fact]
    public void EveryPixelOfATallMapGetsItsOwnValuesColour()
    {
        // Taller than the bands the pixels are coloured in (the last band partial), with a value per pixel.
        const int W = 37, H = 203;
        var values = new float[W * H];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = (i * 7919) % 1000;
        }

        Image map = HeatMap.Render(values, W, H);

        for (int y = 0; y < H; y++)
        {
            for (int x = 0; x < W; x++)
            {
                Assert.Equal(HeatMap.ColorAt(values[(y * W) + x] / 999.0), map.GetPixel(x, y));
            }
        }
    }

    [Fact]
    public void AMapDrawnIntoAnImageThatHeldAnotherIsTheFreshMap()
    {
        const int W = 30, H = 12;
        var first = new float[W * H];
        var second = new float[W * H];
        for (int i = 0; i < first.Length; i++)
        {
            first[i] = i % 17;
            second[i] = (i * 5) % 3;
        }

        (int width, int height) = HeatMap.SizeFor(W, H);
        var reused = new Image(width, height);
        HeatMap.Render(first, W, H, "levels", reused);
        HeatMap.Render(second, W, H, "levels", reused);

        Assert.Equal(HeatMap.Render(second, W, H, "levels").PixelBytes.ToArray(), reused.PixelBytes.ToArray());
        Assert.Equal("image", Assert.Throws<ArgumentException>(() => HeatMap.Render(second, W, H, "levels", new Image(width, height + 1))).ParamName);
    }

    [Fact]
    public void AShortMapIsPaddedWhiteBelowItsData()
    {
        const int W = 20, H = 10;
        var values = new float[W * H];
        values[0] = 1;
        Image map = HeatMap.Render(values, W, H);

        Assert.True(map.Height > H, "a map shorter than the legend is padded");
        for (int y = H; y < map.Height; y++)
        {
            for (int x = 0; x < W; x++)
            {
                Assert.Equal(new Rgb24(255, 255, 255), map.GetPixel(x, y));
            }
        }
    }

    [Fact]
    public void TheRampGetsBrighterAndIsClamped()
    {
        static int Brightness(Rgb24 c) => c.R + c.G + c.B;
        for (int i = 1; i <= 10; i++)
        {
            Assert.True(Brightness(HeatMap.ColorAt(i / 10.0)) > Brightness(HeatMap.ColorAt((i - 1) / 10.0)));
        }

        Assert.Equal(HeatMap.ColorAt(0), HeatMap.ColorAt(-3));
        Assert.Equal(HeatMap.ColorAt(1), HeatMap.ColorAt(7));
        Assert.Equal(HeatMap.ColorAt(0), HeatMap.ColorAt(double.NaN));
    }

    [Fact]
    public void TheTitleIsDrawnAboveTheBarAndLeavesTheDataAlone()
    {
        const int W = 30, H = 130;
        float[] values = [.. Enumerable.Range(0, W * H).Select(i => (float)(i % 7))];
        Image rays = HeatMap.Render(values, W, H);
        Image levels = HeatMap.Render(values, W, H, "levels");
        Image blank = HeatMap.Render(values, W, H, "");

        Assert.Equal(rays.Width, levels.Width);
        Assert.Equal(rays.Height, levels.Height);
        int titleRows = 20; // the title's band above the bar (the bar and the top label start below it)
        for (int y = 0; y < H; y++)
        {
            Assert.True(rays.GetRowSpan(y)[..W].SequenceEqual(levels.GetRowSpan(y)[..W]), $"data row {y}");
        }

        for (int y = titleRows; y < rays.Height; y++)
        {
            Assert.True(rays.GetRowSpan(y)[W..].SequenceEqual(levels.GetRowSpan(y)[W..]), $"legend row {y} below the title");
        }

        // Antialiased glyphs: count dark pixels rather than pure black ones.
        static int BlackIn(Image map, int x0, int rows) =>
            Enumerable.Range(0, rows).Sum(y => map.GetRowSpan(y)[x0..].ToArray().Count(p => p.R + p.G + p.B < 300));
        Assert.Equal(0, BlackIn(blank, W, titleRows));
        Assert.True(BlackIn(levels, W, titleRows) > 0);
        Assert.NotEqual(BlackIn(rays, W, titleRows), BlackIn(levels, W, titleRows));
    }

    [Fact]
    public void BadInputIsRejected()
    {
        Assert.Equal("values", Assert.Throws<ArgumentException>(() => HeatMap.Render(new float[5], 2, 2)).ParamName);
        Assert.Equal("values", Assert.Throws<ArgumentException>(() => HeatMap.Render([1, float.NaN, 1, 1], 2, 2)).ParamName);
        // A uniform map (every pixel the same) is fine: one colour, no division by zero.
        Image flat = HeatMap.Render([3, 3, 3, 3], 2, 2);
        Assert.Equal(flat.GetPixel(0, 0), flat.GetPixel(1, 1));
    }
}
