// Tests of the ImageAssert helper itself: it passes when it should and, when it fails, says where and by how much.

namespace RayLab.Tests.Examples;

public sealed class ImageAssertTests
{
    private static readonly Rgb24 Grey = new(100, 100, 100);

    /// <summary>A 4×3 image, every pixel <see cref="Grey"/>.</summary>
    private static Image GreyImage()
    {
        var image = new Image(4, 3);
        for (int y = 0; y < image.Height; y++)
        {
            image.GetRowSpan(y).Fill(Grey);
        }

        return image;
    }

    private static Image With(Image image, int x, int y, Rgb24 pixel)
    {
        image.GetRowSpan(y)[x] = pixel;
        return image;
    }

    [Fact]
    public void EqualImagesPass()
    {
        ImageAssert.Equal(GreyImage(), GreyImage());
        ImageAssert.Equal(GreyImage(), GreyImage(), tolerance: 5);
    }

    [Fact]
    public void OneDifferentPixelFailsNamingItsPlaceAndLevels()
    {
        Image actual = With(GreyImage(), 3, 1, new Rgb24(100, 101, 99));

        var e = Assert.Throws<ImageAssertException>(() => ImageAssert.Equal(GreyImage(), actual));

        Assert.Equal("1 of 12 pixels differ; the first at (x=3, y=1): expected RGB (100, 100, 100), actual RGB (100, 101, 99).", e.Message);
    }

    [Fact]
    public void TheFirstDifferenceIsInReadingOrderAndAllAreCounted()
    {
        // (0, 2) comes after (3, 1): rows first, from the top.
        Image actual = With(With(With(GreyImage(), 0, 2, new Rgb24(0, 0, 0)), 3, 1, new Rgb24(1, 2, 3)), 2, 2, new Rgb24(9, 9, 9));

        var e = Assert.Throws<ImageAssertException>(() => ImageAssert.Equal(GreyImage(), actual));

        Assert.StartsWith("3 of 12 pixels differ; the first at (x=3, y=1): expected RGB (100, 100, 100), actual RGB (1, 2, 3).", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ATolerancePassesSmallDifferencesAndFailsLargerOnes()
    {
        Image actual = With(With(GreyImage(), 1, 0, new Rgb24(103, 97, 100)), 2, 0, new Rgb24(100, 100, 104));

        ImageAssert.Equal(GreyImage(), actual, tolerance: 4);
        var e = Assert.Throws<ImageAssertException>(() => ImageAssert.Equal(GreyImage(), actual, tolerance: 3));
        Assert.Equal("1 of 12 pixels differ by more than 3 levels; the first at (x=2, y=0): expected RGB (100, 100, 100), actual RGB (100, 100, 104).", e.Message);
    }

    [Fact]
    public void DifferentSizesFail()
    {
        var e = Assert.Throws<ImageAssertException>(() => ImageAssert.Equal(GreyImage(), new Image(3, 4)));

        Assert.Equal("Image sizes differ: expected 4×3, actual 3×4.", e.Message);
    }

    [Fact]
    public void PixelEqualChecksOnePixel()
    {
        Image image = With(GreyImage(), 2, 1, new Rgb24(230, 51, 51));

        ImageAssert.PixelEqual(new Rgb24(230, 51, 51), image, 2, 1);
        ImageAssert.PixelEqual(new Intensity(0.9, 0.2, 0.2), image, 2, 1); // the lab's rule: int(256·I)
        ImageAssert.PixelEqual(new Rgb24(228, 53, 51), image, 2, 1, tolerance: 2);
        var e = Assert.Throws<ImageAssertException>(() => ImageAssert.PixelEqual(new Rgb24(230, 51, 51), image, 1, 2));
        Assert.Equal("Pixel (x=1, y=2): expected RGB (230, 51, 51), actual RGB (100, 100, 100).", e.Message);
        e = Assert.Throws<ImageAssertException>(() => ImageAssert.PixelEqual(new Rgb24(227, 51, 51), image, 2, 1, tolerance: 2));
        Assert.Equal("Pixel (x=2, y=1): expected RGB (227, 51, 51), actual RGB (230, 51, 51) by more than 2 levels.", e.Message);
    }

    [Theory]
    [InlineData(-1, 0, "x")]
    [InlineData(4, 0, "x")]
    [InlineData(0, -1, "y")]
    [InlineData(0, 3, "y")]
    public void APixelOutsideTheImageIsAnArgumentError(int x, int y, string parameter)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => ImageAssert.PixelEqual(Grey, GreyImage(), x, y));
        Assert.Equal(parameter, e.ParamName);
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(256)]
    public void AToleranceOutside0To255IsAnArgumentError(int tolerance)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => ImageAssert.Equal(GreyImage(), GreyImage(), tolerance));
        Assert.Equal("tolerance", e.ParamName);
    }

    [Fact]
    public void TheMeanErrorIsAveragedOverEveryChannelOfEveryPixel()
    {
        // 12 pixels × 3 channels = 36 channels; the differences sum to 6 + 12 = 18: a mean of 0.5 levels.
        Image actual = With(With(GreyImage(), 1, 1, new Rgb24(102, 102, 102)), 3, 2, new Rgb24(112, 100, 100));

        Assert.Equal(0.5, ImageAssert.MeanErrorAtMost(GreyImage(), actual, 0.5));
        var e = Assert.Throws<ImageAssertException>(() => ImageAssert.MeanErrorAtMost(GreyImage(), actual, 0.49));
        Assert.Equal("Mean error 0.500 levels per channel, more than 0.49 allowed; the worst pixel (x=3, y=2): expected RGB (100, 100, 100), actual RGB (112, 100, 100).", e.Message);
        Assert.Equal(0, ImageAssert.MeanErrorAtMost(GreyImage(), GreyImage(), 0));
    }

    [Theory]
    [InlineData(-0.1)]
    [InlineData(double.NaN)]
    public void ANegativeMeanBoundIsAnArgumentError(double maxMean)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => ImageAssert.MeanErrorAtMost(GreyImage(), GreyImage(), maxMean));
        Assert.Equal("maxMean", e.ParamName);
    }
}
