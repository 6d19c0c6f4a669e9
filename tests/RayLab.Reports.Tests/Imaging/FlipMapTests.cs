using RayLab.Reports.Imaging;
using RayLab.Metrics;

namespace RayLab.Reports.Tests.Imaging;

/// <summary>FLIP maps in magma colours: the colours NVIDIA's tool uses, its rule for picking one, and the legend.</summary>
public sealed class FlipMapTests
{
    // Entries 0, 64, 128, 192 and 255 of the magma table in NVIDIA's FLIP (src/cpp/FLIP.h, MapMagma, v1.6; matplotlib's
    // magma), as the tool writes them to PNG: round(255·c).
    [Theory]
    [InlineData(0, 0, 0, 4)]
    [InlineData(64, 81, 18, 124)]
    [InlineData(128, 183, 55, 121)]
    [InlineData(192, 252, 137, 97)]
    [InlineData(255, 252, 253, 191)]
    public void TheColoursAreNvidiasMagmaWithinALevel(int entry, int r, int g, int b)
    {
        Rgb24 c = FlipMap.MagmaAt(entry / 255.0);

        Assert.InRange(c.R - r, -1, 1);
        Assert.InRange(c.G - g, -1, 1);
        Assert.InRange(c.B - b, -1, 1);
    }

    [Fact]
    public void AValueTakesTheNearestEntryAndIsClamped()
    {
        // NVIDIA's rule: entry ⌊255·v + ½⌋.
        Assert.Equal(FlipMap.MagmaAt(0), FlipMap.MagmaAt(0.49 / 255));
        Assert.Equal(FlipMap.MagmaAt(1 / 255.0), FlipMap.MagmaAt(0.51 / 255));
        Assert.NotEqual(FlipMap.MagmaAt(0), FlipMap.MagmaAt(1 / 255.0));
        Assert.Equal(FlipMap.MagmaAt(0), FlipMap.MagmaAt(-2));
        Assert.Equal(FlipMap.MagmaAt(0), FlipMap.MagmaAt(double.NaN));
        Assert.Equal(FlipMap.MagmaAt(1), FlipMap.MagmaAt(3));

        // Magma gets brighter all the way: a larger error is never drawn darker.
        static int Brightness(Rgb24 c) => c.R + c.G + c.B;
        for (int i = 1; i < 256; i++)
        {
            Assert.True(Brightness(FlipMap.MagmaAt(i / 255.0)) >= Brightness(FlipMap.MagmaAt((i - 1) / 255.0)), $"entry {i}");
        }
    }

    [Fact]
    public void TheMapColoursEachPixelByItsFlipValue()
    {
        (Image reference, Image test) = Pair(40, 30);
        FlipResult flip = Flip.Compute(reference, test);

        Image map = FlipMap.Render(flip);
        Image legend = FlipMap.RenderWithLegend(flip);

        Assert.Equal((40, 30), (map.Width, map.Height));
        Assert.True(legend.Width > 40, "a colour bar on the right");
        Assert.True(legend.Height >= 30);
        int coloured = 0;
        for (int y = 0; y < 30; y++)
        {
            for (int x = 0; x < 40; x++)
            {
                Assert.Equal(FlipMap.MagmaAt(flip[x, y]), map.GetPixel(x, y));
                Assert.Equal(map.GetPixel(x, y), legend.GetPixel(x, y));
                coloured += flip[x, y] > 0.1 ? 1 : 0;
            }
        }

        Assert.True(coloured > 20, "the square that differs shows");
        Assert.Equal(new Rgb24(255, 255, 255), legend.GetPixel(0, legend.Height - 1)); // padded below the short map

        // Drawn into an image that held another map (the compare report's one image for every picture): the same bytes.
        var reused = new Image(legend.Width, legend.Height);
        FlipMap.RenderWithLegend(Flip.Compute(reference, reference), reused);
        FlipMap.RenderWithLegend(flip, reused);
        Assert.Equal(legend.PixelBytes.ToArray(), reused.PixelBytes.ToArray());

        var bar = new HashSet<Rgb24>();
        for (int y = 0; y < legend.Height; y++)
        {
            foreach (Rgb24 p in legend.GetRowSpan(y)[40..])
            {
                bar.Add(p);
            }
        }

        Assert.Contains(FlipMap.MagmaAt(0), bar);
        Assert.Contains(FlipMap.MagmaAt(1), bar);
        Assert.Contains(new Rgb24(0, 0, 0), bar); // the labels
    }

    [Fact]
    public void IdenticalPicturesGiveABlackMap()
    {
        (Image reference, _) = Pair(16, 12);
        Image map = FlipMap.Render(Flip.Compute(reference, reference));

        for (int y = 0; y < 12; y++)
        {
            Assert.All(map.GetRowSpan(y).ToArray(), p => Assert.Equal(FlipMap.MagmaAt(0), p));
        }
    }

    /// <summary>A grey picture and the same with a bright square in it.</summary>
    internal static (Image Reference, Image Test) Pair(int width, int height)
    {
        var reference = new Image(width, height);
        var test = new Image(width, height);
        for (int y = 0; y < height; y++)
        {
            reference.GetRowSpan(y).Fill(new Rgb24(90, 100, 110));
            test.GetRowSpan(y).Fill(new Rgb24(90, 100, 110));
            if (y >= height / 3 && y < 2 * height / 3)
            {
                test.GetRowSpan(y)[(width / 3)..(2 * width / 3)].Fill(new Rgb24(250, 240, 20));
            }
        }

        return (reference, test);
    }
}
