using RayLab;

namespace MyLab.Tests;

/// <summary>The image and the 8-bit rule (2.2): level = int(256·I), from 0 to 255.</summary>
public class EightBitTests
{
    [Theory]
    [InlineData(0.0, 0)]
    [InlineData(0.1, 25)]            // 25.6 → 25: int() cuts, it does not round
    [InlineData(0.5, 128)]
    [InlineData(255.0 / 256, 255)]   // everything from 255/256 up is full brightness
    [InlineData(1.0, 255)]           // 256 would not fit in a byte: clamped to 255
    [InlineData(3.0, 255)]
    [InlineData(-0.5, 0)]            // below 0: clamped to 0
    public void LevelIsIntOf256TimesI(double intensity, int level) =>
        Assert.Equal(level, Intensity.ToLevel(intensity));

    [Fact]
    public void NegativeIntensityBecomesZero()
    {
        var intensity = new Intensity(-0.5, 0.25, -2);

        Assert.Equal(0, intensity.R);
        Assert.Equal(0.25, intensity.G);
        Assert.Equal(0, intensity.B);
    }

    [Fact]
    public void APixelGetsTheLevelsOfItsIntensity()
    {
        var image = new Image(2, 1);
        image.SetPixel(1, 0, new Intensity(0.9, 0.2, 2));

        Assert.Equal(new Rgb24(230, 51, 255), image.GetPixel(1, 0));
        Assert.Equal(new Rgb24(0, 0, 0), image.GetPixel(0, 0)); // a new image is black
    }
}
