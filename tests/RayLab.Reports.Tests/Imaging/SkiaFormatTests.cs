using RayLab.Reports.Imaging;
using SkiaSharp;

namespace RayLab.Reports.Tests.Imaging;

/// <summary>JPEG and WebP through SkiaSharp, and the <see cref="Image"/> ↔ <see cref="SKBitmap"/> conversion.</summary>
public sealed class SkiaFormatTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public SkiaFormatTests() => ReportsImageFormats.Register();

    public void Dispose() => _dir.Dispose();

    /// <summary>A smooth picture (gradients and a disc with a soft rim): what a render looks like to a lossy codec.</summary>
    private static Image Smooth(int width, int height)
    {
        var image = new Image(width, height);
        for (int y = 0; y < height; y++)
        {
            Span<Rgb24> row = image.GetRowSpan(y);
            for (int x = 0; x < width; x++)
            {
                double d = Math.Sqrt(Math.Pow(x - (width / 2.0), 2) + Math.Pow(y - (height / 2.0), 2)) / (height / 3.0);
                double disc = Math.Clamp((1 - d) * 4, 0, 1);
                row[x] = new Rgb24((byte)(40 + (180 * disc)), (byte)(255 * x / width), (byte)(60 + (120 * y / height)));
            }
        }

        return image;
    }

    private static double MeanAbsoluteDifference(byte[] a, byte[] b) => a.Zip(b).Average(p => Math.Abs(p.First - p.Second));

    [Theory]
    [InlineData("x.jpg", SKEncodedImageFormat.Jpeg)]
    [InlineData("x.JPEG", SKEncodedImageFormat.Jpeg)]
    [InlineData("x.webp", SKEncodedImageFormat.Webp)]
    public void Lossy_files_are_chosen_by_extension_and_decode_to_within_a_level_or_two(string name, SKEncodedImageFormat format)
    {
        Image image = Smooth(96, 64);
        string path = _dir.File(name);

        image.Save(path);

        SkiaDecode.Result decoded = SkiaDecode.Load(path);
        Assert.Equal(format, decoded.Format);
        Assert.Equal((96, 64), (decoded.Width, decoded.Height));
        double mad = MeanAbsoluteDifference(image.PixelBytes.ToArray(), decoded.Rgb);
        Assert.True(mad < 2, $"{name}: mean |difference| {mad:F2} levels");
        Assert.Equal([name], _dir.Entries());
    }

    [Theory]
    [InlineData(".jpg")]
    [InlineData(".webp")]
    public void Higher_quality_is_closer_and_larger(string extension)
    {
        ImageFormat format = ImageFormat.FromPath(extension);
        Image image = Smooth(96, 64);
        using var low = new MemoryStream();
        using var high = new MemoryStream();

        image.Save(low, format, quality: 10);
        image.Save(high, format, quality: 100);

        Assert.True(high.Length > low.Length, $"{high.Length} bytes at 100, {low.Length} at 10");
        byte[] pixels = image.PixelBytes.ToArray();
        Assert.True(MeanAbsoluteDifference(pixels, SkiaDecode.Decode(high.ToArray()).Rgb) < MeanAbsoluteDifference(pixels, SkiaDecode.Decode(low.ToArray()).Rgb));
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(101)]
    public void A_quality_outside_0_to_100_is_rejected_by_name_and_writes_nothing(int quality)
    {
        var image = new Image(4, 4);

        var ex = Assert.Throws<ArgumentOutOfRangeException>(() => image.Save(_dir.File("q.jpg"), quality));

        Assert.Equal("quality", ex.ParamName);
        Assert.Empty(_dir.Entries());
        Assert.Equal("quality", Assert.Throws<ArgumentOutOfRangeException>(() => image.Save(Stream.Null, ReportsImageFormats.Webp, quality)).ParamName);
    }

    [Fact]
    public void Quality_does_not_change_lossless_files()
    {
        Image image = TestImages.Noise(9, 7, seed: 3);
        using var a = new MemoryStream();
        using var b = new MemoryStream();

        image.Save(a, ImageFormat.Png, 5);
        image.Save(b, ImageFormat.Png, 100);

        Assert.Equal(a.ToArray(), b.ToArray());
        Assert.Equal(image.PixelBytes.ToArray(), SkiaDecode.Decode(a.ToArray()).Rgb);
    }

    [Theory]
    [InlineData(1, 1)]
    [InlineData(7, 3)]
    [InlineData(333, 19)]
    public void An_image_goes_to_an_SKBitmap_and_back_unchanged(int width, int height)
    {
        Image image = TestImages.Noise(width, height, seed: width * height);

        using SKBitmap bitmap = image.ToSKBitmap();
        Image back = Image.FromSKBitmap(bitmap);

        Assert.Equal((width, height, SKColorType.Rgba8888, SKAlphaType.Opaque), (bitmap.Width, bitmap.Height, bitmap.ColorType, bitmap.AlphaType));
        Rgb24 p = image.GetPixel(width - 1, height - 1);
        Assert.Equal(new SKColor(p.R, p.G, p.B), bitmap.GetPixel(width - 1, height - 1));
        Assert.Equal(image.PixelBytes.ToArray(), back.PixelBytes.ToArray());
    }

    [Fact]
    public void A_bitmap_of_another_colour_type_is_converted_and_its_alpha_dropped()
    {
        using var bitmap = new SKBitmap(new SKImageInfo(3, 2, SKColorType.Bgra8888, SKAlphaType.Unpremul));
        bitmap.Erase(new SKColor(10, 20, 30, 255));
        bitmap.SetPixel(2, 1, new SKColor(200, 100, 50, 128));

        Image image = Image.FromSKBitmap(bitmap);

        Assert.Equal(new Rgb24(10, 20, 30), image.GetPixel(0, 0));
        Assert.Equal(new Rgb24(200, 100, 50), image.GetPixel(2, 1));
        Assert.Equal("bitmap", Assert.Throws<ArgumentException>(() => Image.FromSKBitmap(new SKBitmap())).ParamName);
        Assert.Throws<ArgumentNullException>(() => Image.FromSKBitmap(null!));
    }
}
