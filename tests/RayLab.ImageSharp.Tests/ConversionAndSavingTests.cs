using RayLab.Sampling;
using SixLabors.ImageSharp;
using SixLabors.ImageSharp.Formats.Jpeg;
using SixLabors.ImageSharp.Formats.Webp;
using Bitmap = SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>;

namespace RayLab.ImageSharp.Tests;

/// <summary>RayLab's Image to Image&lt;Rgb24&gt; and back, and every format ImageSharp 2.1 writes, decoded back to the rendered pixels.</summary>
public class ConversionAndSavingTests
{
    private static Image Rendered(int w = 160, int h = 120)
    {
        var image = new Image(w, h);
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.05)), image);
        return image;
    }

    [Theory]
    [InlineData(230, 51, 255)]
    [InlineData(0, 0, 0)]
    public void RayLabsPixelReadsAsImageSharpsInAMessage(byte r, byte g, byte b) =>
        Assert.Equal(new SixLabors.ImageSharp.PixelFormats.Rgb24(r, g, b).ToString(), new Rgb24(r, g, b).ToString());

    [Fact]
    public void Converting_to_ImageSharp_and_back_keeps_every_byte()
    {
        Image image = Rendered(97, 61);
        using Bitmap bitmap = image.ToImageSharp();
        Assert.Equal((97, 61), (bitmap.Width, bitmap.Height));
        Assert.Equal(image.PixelBytes.ToArray(), BitmapRenderingTests.Bytes(bitmap));
        Rgb24 p = image.GetPixel(40, 30);
        Assert.Equal((p.R, p.G, p.B), (bitmap[40, 30].R, bitmap[40, 30].G, bitmap[40, 30].B));

        Image back = bitmap.ToRayLabImage();
        Assert.Equal(image.PixelBytes.ToArray(), back.PixelBytes.ToArray());

        bitmap[0, 0] = new SixLabors.ImageSharp.PixelFormats.Rgb24(1, 2, 3); // a copy, not a view
        Assert.NotEqual(new Rgb24(1, 2, 3), image.GetPixel(0, 0));
    }

    /// <summary>
    /// Each extension ImageSharp 2.1 writes with its default encoder, and how far its file may be from the rendered
    /// pixels: the largest and the mean difference in levels. Lossless formats give the pixels back; GIF keeps 256
    /// colours; JPEG (quality 75, 4:2:0) and WebP (lossy, quality 75) blur the spheres' edges on this small picture.
    /// </summary>
    public static TheoryData<string, int, double> Formats => new()
    {
        { ".png", 0, 0 }, { ".bmp", 0, 0 }, { ".tga", 0, 0 }, { ".tiff", 0, 0 }, { ".gif", 32, 1.0 }, { ".jpg", 128, 4.0 }, { ".webp", 128, 3.0 },
    };

    [Theory]
    [MemberData(nameof(Formats))]
    public void Every_format_ImageSharp_writes_decodes_to_the_rendered_pixels(string extension, int maxLevels, double meanLevels)
    {
        Image image = Rendered();
        using var bitmap = new Bitmap(image.Width, image.Height);
        new Renderer().Render(TwoSpheres.Scene, TwoSpheres.Perspective, RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.05)), bitmap);
        string folder = Directory.CreateTempSubdirectory("raylab-imagesharp-").FullName;
        try
        {
            string path = Path.Combine(folder, "obrazkoncowy" + extension);
            bitmap.Save(path); // ImageSharp picks the encoder from the extension, as System.Drawing's Bitmap.Save does
            using Bitmap decoded = SixLabors.ImageSharp.Image.Load<SixLabors.ImageSharp.PixelFormats.Rgb24>(path);
            (double mean, int max) = Difference(image.PixelBytes.ToArray(), BitmapRenderingTests.Bytes(decoded));
            TestContext.Current.TestOutputHelper?.WriteLine($"{extension}: {new FileInfo(path).Length} bytes, {mean:F3} levels off on average, at most {max}");
            Assert.True(max <= maxLevels, $"{extension}: a pixel is {max} levels off (allowed {maxLevels})");
            Assert.True(mean <= meanLevels, $"{extension}: {mean:F3} levels off on average (allowed {meanLevels})");
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void Jpeg_quality_and_lossless_WebP_are_ImageSharp_s_own_options()
    {
        Image image = Rendered();
        using Bitmap bitmap = image.ToImageSharp();
        using var high = new MemoryStream();
        using var low = new MemoryStream();
        bitmap.SaveAsJpeg(high, new JpegEncoder { Quality = 95 });
        bitmap.SaveAsJpeg(low, new JpegEncoder { Quality = 20 });
        Assert.True(low.Length < high.Length, $"quality 20 gave {low.Length} bytes, quality 95 {high.Length}");

        using var webp = new MemoryStream();
        bitmap.SaveAsWebp(webp, new WebpEncoder { FileFormat = WebpFileFormatType.Lossless });
        webp.Position = 0;
        using Bitmap decoded = SixLabors.ImageSharp.Image.Load<SixLabors.ImageSharp.PixelFormats.Rgb24>(webp);
        Assert.Equal(image.PixelBytes.ToArray(), BitmapRenderingTests.Bytes(decoded));
    }

    [Fact]
    public void Ppm_keeps_the_pixels_when_asked_for_binary_RGB()
    {
        Image image = Rendered();
        using Bitmap bitmap = image.ToImageSharp();
        using var ppm = new MemoryStream();
        bitmap.SaveAsPbm(ppm, new SixLabors.ImageSharp.Formats.Pbm.PbmEncoder
        {
            ColorType = SixLabors.ImageSharp.Formats.Pbm.PbmColorType.Rgb,
            Encoding = SixLabors.ImageSharp.Formats.Pbm.PbmEncoding.Binary,
        });
        ppm.Position = 0;
        using Bitmap decoded = SixLabors.ImageSharp.Image.Load<SixLabors.ImageSharp.PixelFormats.Rgb24>(ppm);
        Assert.Equal(image.PixelBytes.ToArray(), BitmapRenderingTests.Bytes(decoded));
    }

    private static (double Mean, int Max) Difference(byte[] a, byte[] b)
    {
        Assert.Equal(a.Length, b.Length);
        long sum = 0;
        int max = 0;
        for (int i = 0; i < a.Length; i++)
        {
            int d = Math.Abs(a[i] - b[i]);
            sum += d;
            max = Math.Max(max, d);
        }

        return ((double)sum / a.Length, max);
    }
}
