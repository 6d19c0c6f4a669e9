using RayLab.Imaging;
using RayLab.Scenes;
using SkiaSharp;

namespace RayLab.Tests.Imaging;

/// <summary>
/// RayLab's managed JPEG encoder (JpegLibrary, quality 0–100, 4:4:4), decoded with SkiaSharp's libjpeg-turbo, a
/// decoder independent of it.
/// </summary>
public sealed class JpegEncoderTests
{
    /// <summary>
    /// The largest mean absolute error, in 8-bit levels over all channel values, allowed on the lab's two-sphere
    /// render at quality 90. Measured: 0.505 for this encoder and for Skia's (docs/bench/jpeg.md); the bound leaves
    /// room for another decoder's rounding, not for a lost colour plane or a shifted picture (tens of levels).
    /// </summary>
    private const double MaxMeanError = 0.75;

    private static readonly Lazy<Image> TwoSpheres = new(() =>
    {
        PreparedScene scene = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json")).Prepare();
        Image image = scene.CreateImage();
        scene.Render(new Renderer(), image);
        return image;
    });

    private static byte[] Encode(Image image, int quality)
    {
        using var stream = new MemoryStream();
        JpegEncoder.Write(stream, image, quality);
        return stream.ToArray();
    }

    private static double MeanAbsoluteError(ReadOnlySpan<byte> a, ReadOnlySpan<byte> b)
    {
        Assert.Equal(a.Length, b.Length);
        long sum = 0;
        for (int i = 0; i < a.Length; i++)
        {
            sum += Math.Abs(a[i] - b[i]);
        }

        return (double)sum / a.Length;
    }

    [Fact]
    public void The_two_sphere_render_at_quality_90_decodes_to_its_size_within_the_error_bound()
    {
        Image image = TwoSpheres.Value;

        SkiaDecode.Result decoded = SkiaDecode.Decode(Encode(image, 90));

        Assert.Equal(SKEncodedImageFormat.Jpeg, decoded.Format);
        Assert.Equal((800, 600), (decoded.Width, decoded.Height));
        double error = MeanAbsoluteError(decoded.Rgb, image.PixelBytes);
        Assert.True(error <= MaxMeanError, $"Mean absolute error {error:F3} levels, bound {MaxMeanError}.");
    }

    [Fact]
    public void The_same_image_gives_the_same_bytes()
    {
        Image image = TwoSpheres.Value;

        Assert.Equal(Encode(image, 90), Encode(image, 90));
    }

    [Theory]
    [InlineData(1783)]
    [InlineData(1984)]
    [InlineData(2484)]
    public void The_file_ends_at_its_end_of_image_marker_whatever_the_buffer_size(int seed)
    {
        // Noise pictures 256 wide and 160–255 high whose scan, through a 4 KiB buffer, ends where JpegLibrary
        // 0.4.32's writer advances over a few bytes twice (3 of the first 3000 seeds): without JpegEncoder's trim,
        // 4 stray bytes follow FF D9.
        var random = new Random(seed);
        var image = new Image(256, 160 + random.Next(0, 96));
        random.NextBytes(image.PixelBytes);
        using var small = new MemoryStream();
        using var large = new MemoryStream();

        JpegEncoder.Write(small, image, 90, optimizeCoding: true, bufferSize: 4096);
        JpegEncoder.Write(large, image, 90, optimizeCoding: true, bufferSize: JpegEncoder.BufferSize);

        Assert.Equal([0xFF, 0xD9], small.ToArray()[^2..]);
        Assert.Equal(large.ToArray(), small.ToArray());
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(101)]
    [InlineData(int.MinValue)]
    [InlineData(int.MaxValue)]
    public void A_quality_outside_0_to_100_throws_naming_it(int quality)
    {
        var ex = Assert.Throws<ArgumentOutOfRangeException>(() => JpegEncoder.Write(new MemoryStream(), new Image(8, 8), quality));

        Assert.Equal("quality", ex.ParamName);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(50)]
    [InlineData(100)]
    public void Every_quality_from_0_to_100_writes_a_file_that_decodes(int quality)
    {
        Image image = TestImages.Varied(40, 24, seed: quality);

        SkiaDecode.Result decoded = SkiaDecode.Decode(Encode(image, quality));

        Assert.Equal((40, 24), (decoded.Width, decoded.Height));
    }

    [Fact]
    public void Higher_quality_gives_a_larger_file_with_a_smaller_error()
    {
        Image image = TwoSpheres.Value;
        byte[] low = Encode(image, 50), high = Encode(image, 95);

        Assert.True(high.Length > low.Length, $"{high.Length} bytes at 95, {low.Length} at 50.");
        Assert.True(
            MeanAbsoluteError(SkiaDecode.Decode(high).Rgb, image.PixelBytes) < MeanAbsoluteError(SkiaDecode.Decode(low).Rgb, image.PixelBytes));
    }

    [Fact]
    public void Sizes_that_are_not_multiples_of_8_decode_to_their_size_without_dark_edges()
    {
        // Blocks past the right and bottom edge repeat the last pixels; padding them with zeros instead rings into
        // the last column and row.
        var image = new Image(37, 21);
        foreach (ref byte b in image.PixelBytes)
        {
            b = 200;
        }

        SkiaDecode.Result decoded = SkiaDecode.Decode(Encode(image, 90));

        Assert.Equal((37, 21), (decoded.Width, decoded.Height));
        Assert.All(decoded.Rgb, b => Assert.InRange(b, 198, 202));
    }

    [Fact]
    public void The_file_is_JFIF_with_all_three_components_at_full_resolution()
    {
        byte[] jpeg = Encode(new Image(16, 16), 90);

        Assert.Equal([0xFF, 0xD8, 0xFF, 0xE0], jpeg[..4]);
        Assert.Equal("JFIF\0"u8.ToArray(), jpeg[6..11]);
        int sof = jpeg.AsSpan().IndexOf([(byte)0xFF, (byte)0xC0]);
        Assert.True(sof > 0, "No baseline start-of-frame marker.");
        Assert.Equal(3, jpeg[sof + 9]);
        // Component id and sampling factors (horizontal << 4 | vertical) of Y, Cb, Cr: 1×1 each is 4:4:4.
        Assert.Equal([1, 0x11], jpeg[(sof + 10)..(sof + 12)]);
        Assert.Equal([2, 0x11], jpeg[(sof + 13)..(sof + 15)]);
        Assert.Equal([3, 0x11], jpeg[(sof + 16)..(sof + 18)]);
        Assert.Equal([0xFF, 0xD9], jpeg[^2..]);
    }

    [Fact]
    public void A_thin_red_line_keeps_its_colour_where_4_2_0_smears_it()
    {
        // A one-pixel red column on the lab's dark background, as a sphere's outline meets it.
        var image = new Image(64, 32);
        for (int y = 0; y < image.Height; y++)
        {
            Span<Rgb24> row = image.GetRowSpan(y);
            row.Fill(new Rgb24(25, 25, 38));
            row[31] = new Rgb24(230, 51, 51);
        }

        double ours = LineRedError(SkiaDecode.Decode(Encode(image, 90)).Rgb);
        using SKBitmap bitmap = ToBitmap(image);
        using SKPixmap pixmap = bitmap.PeekPixels()!;
        using SKData subsampled = pixmap.Encode(new SKJpegEncoderOptions(90, SKJpegEncoderDownsample.Downsample420, SKJpegEncoderAlphaOption.Ignore))!;
        double skia420 = LineRedError(SkiaDecode.Decode(subsampled.ToArray()).Rgb);

        Assert.True(ours <= 20, $"The red line's red is off by {ours:F1} levels on average.");
        Assert.True(skia420 > 2 * ours, $"4:2:0 is off by {skia420:F1}, 4:4:4 by {ours:F1}: the test does not tell them apart.");

        double LineRedError(byte[] rgb)
        {
            double sum = 0;
            for (int y = 0; y < image.Height; y++)
            {
                sum += Math.Abs(rgb[(((y * image.Width) + 31) * 3)] - 230);
            }

            return sum / image.Height;
        }
    }

    /// <summary>The image as an opaque RGBA bitmap for Skia's own encoder (this project has the core only, not RayLab.Reports' SkiaBitmaps).</summary>
    private static SKBitmap ToBitmap(Image image)
    {
        var bitmap = new SKBitmap(new SKImageInfo(image.Width, image.Height, SKColorType.Rgba8888, SKAlphaType.Opaque));
        for (int y = 0; y < image.Height; y++)
        {
            Span<Rgb24> row = image.GetRowSpan(y);
            for (int x = 0; x < image.Width; x++)
            {
                bitmap.SetPixel(x, y, new SKColor(row[x].R, row[x].G, row[x].B));
            }
        }

        return bitmap;
    }
}
