
namespace RayLab.Tests.Imaging;

/// <summary>The error metrics on synthetic images whose error is known by construction.</summary>
public class ImageErrorTests
{
    private const int W = 4, H = 2;

    [Fact]
    public void AnImageHasNoErrorAgainstItself()
    {
        Image exact = Gradient();
        Assert.Equal(new ImageError(0, 0, 0, 0), ImageError.Measure(exact, Gradient()));
        Assert.All(ImageError.PerPixel(exact, Gradient()), e => Assert.Equal(0f, e));
    }

    [Fact]
    public void OneChannelThreeLevelsOffInOnePixel()
    {
        Image exact = Gradient(), image = Gradient();
        Rgb24 p = image.GetPixel(2, 1);
        image.GetRowSpan(1)[2] = p with { G = (byte)(p.G + 3) };

        ImageError e = ImageError.Measure(image, exact);

        // 24 channel values, one of them off by 3: Σd² = 9, Σ|d| = 3; one pixel of 8 is more than a level off.
        Assert.Equal(Math.Sqrt(9.0 / 24), e.Rmse, 12);
        Assert.Equal(3.0 / 24, e.MeanAbsolute, 12);
        Assert.Equal(3, e.Max);
        Assert.Equal(1.0 / 8, e.FractionOverOneLevel, 12);
        float[] map = ImageError.PerPixel(image, exact);
        Assert.Equal(3f, map[(1 * W) + 2]);
        Assert.Equal(3f, map.Sum());
    }

    [Fact]
    public void EveryByteOneLevelOffIsRmseOneAndNoPixelMoreThanOneLevelOff()
    {
        Image exact = Gradient(), image = Gradient();
        Span<byte> bytes = image.PixelBytes;
        for (int i = 0; i < bytes.Length; i++)
        {
            bytes[i] = (byte)(i % 2 == 0 ? bytes[i] + 1 : bytes[i] - 1); // both signs count
        }

        ImageError e = ImageError.Measure(image, exact);

        Assert.Equal(1, e.Rmse, 12);
        Assert.Equal(1, e.MeanAbsolute, 12);
        Assert.Equal(1, e.Max);
        Assert.Equal(0, e.FractionOverOneLevel);
    }

    [Fact]
    public void ErrorsBelowTheExactLevelCountAndThePixelMapTakesTheWorstChannel()
    {
        Image exact = Gradient(), image = Gradient();
        // Pixel (0, 0): −2 in red, +1 in blue. Pixel (3, 1): −255 in every channel (white against black).
        Rgb24 p = image.GetPixel(0, 0);
        image.GetRowSpan(0)[0] = new Rgb24((byte)(p.R - 2), p.G, (byte)(p.B + 1));
        exact.GetRowSpan(1)[3] = new Rgb24(255, 255, 255);
        image.GetRowSpan(1)[3] = new Rgb24(0, 0, 0);

        ImageError e = ImageError.Measure(image, exact);

        double squares = 4 + 1 + (3 * 255 * 255), absolutes = 2 + 1 + (3 * 255);
        Assert.Equal(Math.Sqrt(squares / 24), e.Rmse, 12);
        Assert.Equal(absolutes / 24, e.MeanAbsolute, 12);
        Assert.Equal(255, e.Max);
        Assert.Equal(2.0 / 8, e.FractionOverOneLevel, 12);
        float[] map = ImageError.PerPixel(image, exact);
        Assert.Equal([2f, 0, 0, 0, 0, 0, 0, 255f], map);

        // Into a caller's buffer, every value written over what it held.
        float[] into = [.. Enumerable.Repeat(-7f, 8)];
        ImageError.PerPixel(image, exact, into);
        Assert.Equal(map, into);
    }

    [Fact]
    public void ImagesOfDifferentSizesAreRejected()
    {
        Assert.Equal("image", Assert.Throws<ArgumentException>(() => ImageError.Measure(new Image(4, 2), new Image(2, 4))).ParamName);
        Assert.Equal("image", Assert.Throws<ArgumentException>(() => ImageError.PerPixel(new Image(4, 2), new Image(4, 3))).ParamName);
        Assert.Equal("image", Assert.Throws<ArgumentException>(() => ImageError.PerPixel(new Image(4, 2), new Image(4, 3), new float[8])).ParamName);
        Assert.Equal("errors", Assert.Throws<ArgumentException>(() => ImageError.PerPixel(new Image(4, 2), new Image(4, 2), new float[9])).ParamName);
    }

    /// <summary>Levels in 10..240, every channel and pixel different, so ±2 never wraps.</summary>
    private static Image Gradient()
    {
        var image = new Image(W, H);
        Span<byte> bytes = image.PixelBytes;
        for (int i = 0; i < bytes.Length; i++)
        {
            bytes[i] = (byte)(10 + (i * 9));
        }

        return image;
    }
}
