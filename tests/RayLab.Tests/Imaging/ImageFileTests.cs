using System.Buffers.Binary;
using RayLab.Imaging;

namespace RayLab.Tests.Imaging;

/// <summary>PNG and BMP output, read back by the tests' own decoders, and <see cref="Image.Save(string)"/>'s file handling.</summary>
public sealed class ImageFileTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    public static TheoryData<int, int> Sizes => new()
    {
        { 1, 1 },
        { 1, 9 },
        { 2, 3 },
        { 3, 2 },
        { 4, 4 },
        { 5, 17 },
        { 17, 9 },
        { 64, 24 },
        { 333, 19 },
    };

    private static byte[] ToBytes(Image image, ImageFormat format)
    {
        using var stream = new MemoryStream();
        image.Save(stream, format);
        return stream.ToArray();
    }

    // ---- PNG ------------------------------------------------------------------------------------------

    [Theory]
    [MemberData(nameof(Sizes))]
    public void Png_saved_to_a_file_decodes_to_exactly_the_pixel_bytes(int width, int height)
    {
        Image image = TestImages.Varied(width, height, seed: (width * 1000) + height);
        string path = _dir.File("out.png");

        image.Save(path);

        SkiaDecode.Result png = SkiaDecode.Decode(File.ReadAllBytes(path));
        Assert.Equal(width, png.Width);
        Assert.Equal(height, png.Height);
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Theory]
    [MemberData(nameof(Sizes))]
    public void Png_written_to_a_stream_decodes_to_exactly_the_pixel_bytes(int width, int height)
    {
        Image image = TestImages.Noise(width, height, seed: width + (height * 7919));

        byte[] bytes = ToBytes(image, ImageFormat.Png);

        SkiaDecode.Result png = SkiaDecode.Decode(bytes);
        Assert.Equal((width, height), (png.Width, png.Height));
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Fact]
    public void Png_adaptive_filter_uses_every_filter_type_and_each_still_decodes()
    {
        Image image = TestImages.Varied(96, 40, seed: 42);
        using var stream = new MemoryStream();
        PngEncoder.Write(stream, image, System.IO.Compression.CompressionLevel.Optimal, PngFilter.Adaptive);

        PngTestDecoder.Result png = PngTestDecoder.Decode(stream.ToArray());

        Assert.Equal(new byte[] { 0, 1, 2, 3, 4 }, png.RowFilters.Distinct().Order());
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Fact]
    public void Png_files_use_the_up_filter_by_default()
    {
        Image image = TestImages.Varied(40, 12, seed: 9);

        PngTestDecoder.Result png = PngTestDecoder.Decode(ToBytes(image, ImageFormat.Png));

        Assert.All(png.RowFilters, f => Assert.Equal((byte)PngFilter.Up, f));
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Theory]
    [InlineData(nameof(PngFilter.None))]
    [InlineData(nameof(PngFilter.Sub))]
    [InlineData(nameof(PngFilter.Up))]
    [InlineData(nameof(PngFilter.Average))]
    [InlineData(nameof(PngFilter.Paeth))]
    public void Png_with_one_fixed_filter_uses_it_on_every_row_and_decodes(string filterName)
    {
        PngFilter filter = Enum.Parse<PngFilter>(filterName); // the filter enum is internal; a public test takes its name
        Image image = TestImages.Varied(67, 23, seed: 5);
        using var stream = new MemoryStream();
        PngEncoder.Write(stream, image, System.IO.Compression.CompressionLevel.Fastest, filter);

        PngTestDecoder.Result png = PngTestDecoder.Decode(stream.ToArray());

        Assert.All(png.RowFilters, f => Assert.Equal((byte)filter, f));
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Theory]
    [InlineData(16, 1)]
    [InlineData(96, 2)]
    [InlineData(333, 3)]
    public void Png_adaptive_filter_picks_the_filter_with_the_smallest_sum_for_each_kind_of_row(int width, int seed)
    {
        Image image = TestImages.Varied(width, 2 * TestImages.BandHeight, seed);
        using var stream = new MemoryStream();
        PngEncoder.Write(stream, image, System.IO.Compression.CompressionLevel.Optimal, PngFilter.Adaptive);

        PngTestDecoder.Result png = PngTestDecoder.Decode(stream.ToArray());

        // Rows 1, 3, 4, 6 and 8 of each band are built so that Sub, Up, None, Average and Paeth win outright.
        for (int band = 0; band < image.Height; band += TestImages.BandHeight)
        {
            Assert.Equal(1, png.RowFilters[band + 1]);
            Assert.Equal(2, png.RowFilters[band + 3]);
            Assert.Equal(0, png.RowFilters[band + 4]);
            Assert.Equal(3, png.RowFilters[band + 6]);
            Assert.Equal(4, png.RowFilters[band + 8]);
        }

        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Fact]
    public void Png_of_extreme_values_round_trips()
    {
        var image = new Image(6, 4);
        for (int i = 0; i < image.PixelBytes.Length; i++)
        {
            image.PixelBytes[i] = (i / 3 % 2 == 0) ^ (i / 18 % 2 == 0) ? (byte)255 : (byte)0; // checkerboard
        }

        image.PixelBytes[^1] = 1;

        SkiaDecode.Result png = SkiaDecode.Decode(ToBytes(image, ImageFormat.Png));

        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
    }

    [Fact]
    public void Png_file_is_signature_IHDR_IDAT_IEND_with_the_expected_header()
    {
        var image = new Image(333, 2);

        byte[] bytes = ToBytes(image, ImageFormat.Png);

        Assert.Equal(PngTestDecoder.Signature, bytes[..8]);
        Assert.Equal(13u, BinaryPrimitives.ReadUInt32BigEndian(bytes.AsSpan(8)));
        Assert.Equal("IHDR"u8.ToArray(), bytes[12..16]);
        Assert.Equal(333, BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(16)));
        Assert.Equal(2, BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(20)));
        Assert.Equal(new byte[] { 8, 2, 0, 0, 0 }, bytes[24..29]);
        Assert.Equal(new byte[] { 0, 0, 0, 0, (byte)'I', (byte)'E', (byte)'N', (byte)'D', 0xAE, 0x42, 0x60, 0x82 }, bytes[^12..]);
        Assert.Equal(["IHDR", "IDAT", "IEND"], PngTestDecoder.Decode(bytes).ChunkTypes);
    }

    [Fact]
    public void Png_from_file_and_from_stream_are_identical()
    {
        Image image = TestImages.Varied(17, 9, seed: 5);
        string path = _dir.File("same.png");

        image.Save(path);

        Assert.Equal(ToBytes(image, ImageFormat.Png), File.ReadAllBytes(path));
    }

    [Fact]
    public void Png_of_intensities_set_with_SetPixel_decodes_to_their_8_bit_levels()
    {
        var image = new Image(3, 2);
        image.SetPixel(0, 0, new Intensity(1, 0.5, 0));
        image.SetPixel(1, 0, new Intensity(Math.BitDecrement(1.0), 1.0 / 256, Math.BitDecrement(1.0 / 256)));
        image.SetPixel(2, 1, new Intensity(5, -1, 0.25));

        SkiaDecode.Result png = SkiaDecode.Decode(ToBytes(image, ImageFormat.Png));

        Assert.Equal(new byte[] { 255, 128, 0, 255, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 255, 0, 64 }, png.Rgb);
    }

    // ---- BMP ------------------------------------------------------------------------------------------

    [Theory]
    [InlineData(1, 1, 1)]
    [InlineData(1, 6, 1)]
    [InlineData(2, 3, 2)]
    [InlineData(3, 5, 3)]
    [InlineData(4, 4, 0)]
    [InlineData(6, 2, 2)]
    [InlineData(7, 3, 3)]
    [InlineData(17, 9, 1)]
    [InlineData(333, 19, 1)]
    public void Bmp_saved_to_a_file_has_a_valid_header_padded_rows_and_the_same_pixels(int width, int height, int padding)
    {
        Image image = TestImages.Varied(width, height, seed: width + height);
        string path = _dir.File("out.bmp");

        image.Save(path);

        byte[] bytes = File.ReadAllBytes(path);
        int stride = (width * 3) + padding;
        Assert.Equal(0, stride % 4);
        Assert.Equal(54 + (stride * height), bytes.Length);
        Assert.Equal((uint)bytes.Length, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(2)));
        SkiaDecode.Result bmp = SkiaDecode.Decode(bytes);
        Assert.Equal((width, height), (bmp.Width, bmp.Height));
        Assert.Equal(image.PixelBytes.ToArray(), bmp.Rgb);
    }

    [Theory]
    [MemberData(nameof(Sizes))]
    public void Bmp_written_to_a_stream_decodes_to_exactly_the_pixel_bytes(int width, int height)
    {
        Image image = TestImages.Noise(width, height, seed: (width * 31) + height);

        SkiaDecode.Result bmp = SkiaDecode.Decode(ToBytes(image, ImageFormat.Bmp));

        Assert.Equal((width, height), (bmp.Width, bmp.Height));
        Assert.Equal(image.PixelBytes.ToArray(), bmp.Rgb);
    }

    [Fact]
    public void Bmp_header_fields_are_exactly_as_specified()
    {
        byte[] bytes = ToBytes(new Image(3, 2), ImageFormat.Bmp);

        Assert.Equal((byte)'B', bytes[0]);
        Assert.Equal((byte)'M', bytes[1]);
        Assert.Equal(54u + 24u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(2)));
        Assert.Equal(0u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(6)));   // reserved
        Assert.Equal(54u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(10))); // pixel data offset
        Assert.Equal(40u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(14))); // BITMAPINFOHEADER
        Assert.Equal(3, BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(18)));
        Assert.Equal(2, BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(22)));    // positive: bottom-up
        Assert.Equal((ushort)1, BinaryPrimitives.ReadUInt16LittleEndian(bytes.AsSpan(26)));
        Assert.Equal((ushort)24, BinaryPrimitives.ReadUInt16LittleEndian(bytes.AsSpan(28)));
        Assert.Equal(0u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(30)));  // BI_RGB
        Assert.Equal(24u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(34))); // image size: stride 12 × 2
    }

    [Fact]
    public void Bmp_stores_the_bottom_row_first_in_BGR_order_with_zero_padding()
    {
        var image = new Image(2, 2);
        image.GetRowSpan(0)[0] = new Rgb24(1, 2, 3);
        image.GetRowSpan(0)[1] = new Rgb24(4, 5, 6);
        image.GetRowSpan(1)[0] = new Rgb24(7, 8, 9);
        image.GetRowSpan(1)[1] = new Rgb24(10, 11, 12);

        byte[] bytes = ToBytes(image, ImageFormat.Bmp);

        Assert.Equal(70, bytes.Length);
        Assert.Equal(new byte[] { 9, 8, 7, 12, 11, 10, 0, 0, 3, 2, 1, 6, 5, 4, 0, 0 }, bytes[54..]);
    }

    [Fact]
    public void Bmp_from_file_and_from_stream_are_identical()
    {
        Image image = TestImages.Noise(7, 3, seed: 9);
        string path = _dir.File("same.bmp");

        image.Save(path);

        Assert.Equal(ToBytes(image, ImageFormat.Bmp), File.ReadAllBytes(path));
    }

    // ---- Save(path): format choice --------------------------------------------------------------------

    [Theory]
    [InlineData("a.png")]
    [InlineData("a.PNG")]
    [InlineData("a.Png")]
    [InlineData("a.b.pNg")]
    public void Png_extension_is_matched_case_insensitively(string name)
    {
        Image image = TestImages.Noise(5, 3, seed: 1);
        string path = _dir.File(name);

        image.Save(path);

        Assert.Equal(image.PixelBytes.ToArray(), SkiaDecode.Load(path).Rgb);
        Assert.Equal([name], _dir.Entries());
    }

    [Theory]
    [InlineData("a.bmp")]
    [InlineData("a.BMP")]
    [InlineData("a.Bmp")]
    public void Bmp_extension_is_matched_case_insensitively(string name)
    {
        Image image = TestImages.Noise(5, 3, seed: 2);
        string path = _dir.File(name);

        image.Save(path);

        Assert.Equal(image.PixelBytes.ToArray(), SkiaDecode.Load(path).Rgb);
        Assert.Equal([name], _dir.Entries());
    }

    [Theory]
    [InlineData("out.tiff")]
    [InlineData("out.JPE")]
    [InlineData("out")]
    [InlineData("out.")]
    [InlineData("out.png.txt")]
    [InlineData("out.gif")]
    [InlineData("out.webp")]
    public void Unsupported_extension_throws_NotSupported_listing_the_formats_and_creates_nothing(string name)
    {
        var image = new Image(2, 2);

        var ex = Assert.Throws<NotSupportedException>(() => image.Save(_dir.File(name)));

        Assert.DoesNotContain("\n", ex.Message, StringComparison.Ordinal);
        Assert.Contains("registered: .png, .bmp, .jpg, .jpeg", ex.Message, StringComparison.Ordinal);
        Assert.Empty(_dir.Entries());
    }

    [Theory]
    [InlineData("a.png", "PNG")]
    [InlineData("dir/a.BMP", "BMP")]
    [InlineData("x.tar.PnG", "PNG")]
    [InlineData("obrazkoncowy.jpg", "JPEG")]
    [InlineData("a.JPEG", "JPEG")]
    public void FromPath_maps_extensions_case_insensitively(string path, string expected)
    {
        Assert.Equal(expected, ImageFormat.FromPath(path).Name);
    }

    [Theory]
    [InlineData("a.gif")]
    [InlineData("a.jpg.txt")]
    [InlineData("a.webp")]
    [InlineData("a")]
    public void FromPath_rejects_other_extensions(string path)
    {
        var ex = Assert.Throws<NotSupportedException>(() => ImageFormat.FromPath(path));

        Assert.Contains(".png", ex.Message, StringComparison.Ordinal);
        Assert.Contains(".bmp", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void The_core_registers_png_bmp_and_jpeg_first_and_no_webp()
    {
        Assert.Equal([".png", ".bmp", ".jpg", ".jpeg"], ImageFormats.Extensions.Take(4));
        Assert.Equal([ImageFormat.Png, ImageFormat.Bmp, ImageFormat.Jpeg], ImageFormats.All.Take(3));
        Assert.DoesNotContain(".webp", ImageFormats.Extensions);
    }

    [Fact]
    public void Save_to_a_stream_with_no_format_throws()
    {
        var image = new Image(1, 1);
        using var stream = new MemoryStream();

        Assert.Equal("format", Assert.Throws<ArgumentNullException>(() => image.Save(stream, null!)).ParamName);
        Assert.Equal(0, stream.Length);
    }

    [Fact]
    public void Save_rejects_null_and_blank_arguments()
    {
        var image = new Image(1, 1);

        Assert.Throws<ArgumentNullException>(() => image.Save(null!));
        Assert.Throws<ArgumentException>(() => image.Save(""));
        Assert.Throws<ArgumentException>(() => image.Save("   "));
        Assert.Throws<ArgumentNullException>(() => image.Save(null!, ImageFormat.Png));
        Assert.Empty(_dir.Entries());
    }

    // ---- Save(path): file handling --------------------------------------------------------------------

    [Theory]
    [InlineData("missing/out.png")]
    [InlineData("missing/deeper/out.bmp")]
    public void Save_into_a_missing_folder_throws_and_leaves_nothing(string relative)
    {
        var image = new Image(3, 3);
        string path = Path.Combine(_dir.Path, relative);

        Assert.ThrowsAny<IOException>(() => image.Save(path)); // DirectoryNotFoundException is an IOException

        Assert.False(Directory.Exists(Path.Combine(_dir.Path, "missing")));
        Assert.Empty(_dir.Entries());
    }

    [Theory]
    [InlineData("taken.png")]
    [InlineData("taken.bmp")]
    public void Save_that_fails_after_writing_removes_its_temporary_file(string name)
    {
        // A folder already has the target's name, so the final rename fails after the temp file was written.
        Directory.CreateDirectory(_dir.File(name));
        Image image = TestImages.Noise(8, 8, seed: 15);

        Exception ex = Assert.ThrowsAny<Exception>(() => image.Save(_dir.File(name)));

        Assert.True(ex is IOException or UnauthorizedAccessException, $"unexpected {ex.GetType()}: {ex.Message}");
        Assert.Equal([name], _dir.Entries());
        Assert.True(Directory.Exists(_dir.File(name)), "the existing folder must be left alone");
    }

    [Theory]
    [InlineData("result.png")]
    [InlineData("result.bmp")]
    public void Save_leaves_only_the_target_file_behind(string name)
    {
        Image image = TestImages.Varied(17, 9, seed: 3);

        image.Save(_dir.File(name));

        Assert.Equal([name], _dir.Entries());
    }

    [Fact]
    public void Saving_several_files_in_one_folder_leaves_exactly_those_files()
    {
        Image image = TestImages.Noise(4, 4, seed: 4);

        image.Save(_dir.File("a.png"));
        image.Save(_dir.File("b.bmp"));
        image.Save(_dir.File("a.png"));

        Assert.Equal(["a.png", "b.bmp"], _dir.Entries());
    }

    [Theory]
    [InlineData("over.png")]
    [InlineData("over.bmp")]
    public void Save_overwrites_an_existing_larger_file_completely(string name)
    {
        ImageFormat format = ImageFormat.FromPath(name);
        string path = _dir.File(name);
        File.WriteAllBytes(path, Enumerable.Repeat((byte)0xEE, 100_000).ToArray());
        Image image = TestImages.Varied(9, 5, seed: 11);

        image.Save(path);

        byte[] bytes = File.ReadAllBytes(path);
        Assert.Equal(ToBytes(image, format), bytes);
        Assert.Equal(image.PixelBytes.ToArray(), SkiaDecode.Decode(bytes).Rgb);
        Assert.Equal([name], _dir.Entries());
    }

    [Fact]
    public void Save_overwrites_a_previous_image_with_a_new_one()
    {
        string path = _dir.File("twice.png");
        TestImages.Noise(40, 40, seed: 12).Save(path);
        Image second = TestImages.Noise(3, 2, seed: 13);

        second.Save(path);

        SkiaDecode.Result png = SkiaDecode.Decode(File.ReadAllBytes(path));
        Assert.Equal((3, 2), (png.Width, png.Height));
        Assert.Equal(second.PixelBytes.ToArray(), png.Rgb);
        Assert.Equal(["twice.png"], _dir.Entries());
    }

    [Fact]
    public void Save_with_a_relative_path_writes_relative_to_the_current_directory()
    {
        // Resolve the same file both ways rather than changing the process-wide current directory.
        string relative = Path.GetRelativePath(Environment.CurrentDirectory, _dir.File("rel.png"));
        Image image = TestImages.Noise(2, 2, seed: 14);

        image.Save(relative);

        Assert.Equal(["rel.png"], _dir.Entries());
        Assert.Equal(image.PixelBytes.ToArray(), SkiaDecode.Load(_dir.File("rel.png")).Rgb);
    }
}
