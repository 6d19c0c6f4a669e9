using System.Runtime.CompilerServices;

namespace RayLab.Tests.Imaging;

public class ImageTests
{
    // ---- Construction and size checks -----------------------------------------------------------------

    [Theory]
    [InlineData(1, 1)]
    [InlineData(3, 2)]
    [InlineData(17, 5)]
    public void New_image_is_black_with_tightly_packed_RGB24_bytes(int width, int height)
    {
        var image = new Image(width, height);

        Assert.Equal(width, image.Width);
        Assert.Equal(height, image.Height);
        Assert.Equal(width * height * 3, image.PixelBytes.Length);
        Assert.True(image.PixelBytes.IndexOfAnyExcept((byte)0) < 0, "a new image must be black");
    }

    [Theory]
    [InlineData(0, 1)]
    [InlineData(1, 0)]
    [InlineData(0, 0)]
    [InlineData(-1, 5)]
    [InlineData(5, -1)]
    [InlineData(int.MinValue, 1)]
    [InlineData(1, int.MinValue)]
    public void Size_below_one_throws(int width, int height)
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => new Image(width, height));
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(width, height));
    }

    [Fact]
    public void MaxBytes_is_the_largest_array_length()
    {
        Assert.Equal(Array.MaxLength, Image.MaxBytes);
    }

    [Fact]
    public void CheckSize_rejects_a_buffer_larger_than_an_array_without_allocating_it()
    {
        long before = GC.GetAllocatedBytesForCurrentThread();
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(100_000, 100_000));
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.True(allocated < 1_000_000, $"CheckSize allocated {allocated:N0} bytes");
    }

    [Fact]
    public void Constructor_rejects_a_buffer_larger_than_an_array_before_allocating()
    {
        long before = GC.GetAllocatedBytesForCurrentThread();
        Assert.Throws<ArgumentOutOfRangeException>(() => new Image(100_000, 100_000));
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.True(allocated < 1_000_000, $"the failed constructor allocated {allocated:N0} bytes");
    }

    [Fact]
    public void CheckSize_accepts_exactly_up_to_MaxBytes_and_rejects_one_pixel_more()
    {
        int maxPixels = Array.MaxLength / 3; // 715,827,863: W·H·3 = 2,147,483,589 ≤ Array.MaxLength

        Image.CheckSize(1, maxPixels); // must not throw (and allocates nothing)
        Image.CheckSize(maxPixels, 1);
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(1, maxPixels + 1));
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(maxPixels + 1, 1));
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(65_536, 65_536));
    }

    [Fact]
    public void CheckSize_rejects_sizes_just_below_the_long_overflow_threshold()
    {
        // W·H·3 ≈ 8.6e18 still fits in a long, so the check works here.
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(int.MaxValue, 1_342_177_280));
    }

    [Theory]
    [InlineData(int.MaxValue, int.MaxValue)]
    [InlineData(2_000_000_000, 2_000_000_000)]
    public void CheckSize_rejects_sizes_whose_byte_count_overflows_a_long(int width, int height)
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => Image.CheckSize(width, height));
        Assert.Throws<ArgumentOutOfRangeException>(() => new Image(width, height));
    }

    // ---- Pixels ---------------------------------------------------------------------------------------

    [Fact]
    public void Rgb24_is_three_bytes_R_G_B()
    {
        Assert.Equal(3, Unsafe.SizeOf<Rgb24>());

        var image = new Image(1, 1);
        image.GetRowSpan(0)[0] = new Rgb24(1, 2, 3);
        Assert.Equal(new byte[] { 1, 2, 3 }, image.PixelBytes.ToArray());
    }

    public static TheoryData<double, double, double, byte, byte, byte> EightBitRule => new()
    {
        { 0, 0, 0, 0, 0, 0 },
        { 1, 1, 1, 255, 255, 255 },
        { 0.5, 0.25, 2, 128, 64, 255 },
        { Math.BitDecrement(1.0), 1.0 / 256, Math.BitDecrement(1.0 / 256), 255, 1, 0 },
        { double.PositiveInfinity, -0.5, double.NaN, 255, 0, 0 },
        { 100.0 / 256, 200.0 / 256, 254.99 / 256, 100, 200, 254 },
    };

    [Theory]
    [MemberData(nameof(EightBitRule))]
    public void SetPixel_converts_by_the_8_bit_rule_and_GetPixel_reads_it_back(double r, double g, double b, byte er, byte eg, byte eb)
    {
        var image = new Image(4, 3);

        image.SetPixel(2, 1, new Intensity(r, g, b));

        Assert.Equal(new Rgb24(er, eg, eb), image.GetPixel(2, 1));
        Assert.Equal(Rgb24.FromIntensity(new Intensity(r, g, b)), image.GetPixel(2, 1));
        int offset = ((1 * 4) + 2) * 3;
        Assert.Equal(new byte[] { er, eg, eb }, image.PixelBytes.Slice(offset, 3).ToArray());
    }

    [Fact]
    public void SetPixel_changes_only_its_own_pixel()
    {
        var image = new Image(5, 4);

        image.SetPixel(3, 2, Intensity.White);

        for (int y = 0; y < 4; y++)
        {
            for (int x = 0; x < 5; x++)
            {
                Rgb24 expected = (x, y) == (3, 2) ? new Rgb24(255, 255, 255) : default;
                Assert.Equal(expected, image.GetPixel(x, y));
            }
        }

        Assert.Equal(3, image.PixelBytes.ToArray().Count(b => b != 0));
    }

    [Fact]
    public void Every_pixel_round_trips_at_its_documented_byte_offset()
    {
        const int W = 7, H = 5;
        var image = new Image(W, H);
        for (int y = 0; y < H; y++)
        {
            for (int x = 0; x < W; x++)
            {
                // Levels x·16+y, y·32+x, x+y+1 written as exact intensities level/256.
                image.SetPixel(x, y, new Intensity(((x * 16) + y) / 256.0, ((y * 32) + x) / 256.0, (x + y + 1) / 256.0));
            }
        }

        byte[] bytes = image.PixelBytes.ToArray();
        for (int y = 0; y < H; y++)
        {
            for (int x = 0; x < W; x++)
            {
                int i = ((y * W) + x) * 3;
                var expected = new Rgb24((byte)((x * 16) + y), (byte)((y * 32) + x), (byte)(x + y + 1));
                Assert.Equal(expected, image.GetPixel(x, y));
                Assert.Equal(expected, new Rgb24(bytes[i], bytes[i + 1], bytes[i + 2]));
            }
        }
    }

    [Fact]
    public void GetRowSpan_row_0_is_the_top_and_rows_are_tightly_packed()
    {
        const int W = 3, H = 4;
        var image = new Image(W, H);

        for (int y = 0; y < H; y++)
        {
            Span<Rgb24> row = image.GetRowSpan(y);
            Assert.Equal(W, row.Length);
            for (int x = 0; x < W; x++)
            {
                row[x] = new Rgb24((byte)((y * 10) + x), (byte)(100 + (y * 10) + x), (byte)(200 + x + y));
            }
        }

        byte[] bytes = image.PixelBytes.ToArray();
        for (int y = 0; y < H; y++)
        {
            for (int x = 0; x < W; x++)
            {
                Assert.Equal((byte)((y * 10) + x), bytes[(((y * W) + x) * 3) + 0]);
                Assert.Equal((byte)(100 + (y * 10) + x), bytes[(((y * W) + x) * 3) + 1]);
                Assert.Equal((byte)(200 + x + y), bytes[(((y * W) + x) * 3) + 2]);
                Assert.Equal(new Rgb24(bytes[((y * W) + x) * 3], bytes[(((y * W) + x) * 3) + 1], bytes[(((y * W) + x) * 3) + 2]), image.GetPixel(x, y));
            }
        }

        Assert.Equal(new byte[] { 0, 100, 200 }, bytes[..3]); // (0, 0) is the first pixel: top-left
    }

    [Fact]
    public void Writes_through_PixelBytes_are_seen_by_GetPixel_and_GetRowSpan()
    {
        var image = new Image(2, 2);
        Span<byte> bytes = image.PixelBytes;

        bytes[9] = 7;   // pixel (1, 1) red
        bytes[10] = 8;  // green
        bytes[11] = 9;  // blue

        Assert.Equal(new Rgb24(7, 8, 9), image.GetPixel(1, 1));
        Assert.Equal(new Rgb24(7, 8, 9), image.GetRowSpan(1)[1]);
        Assert.Equal(default, image.GetPixel(1, 0));
    }

    [Theory]
    [InlineData(-1, 0)]
    [InlineData(4, 0)]
    [InlineData(0, -1)]
    [InlineData(0, 3)]
    [InlineData(4, 3)]
    [InlineData(int.MinValue, 0)]
    [InlineData(0, int.MaxValue)]
    [InlineData(int.MaxValue, 2)]
    public void Out_of_range_coordinates_throw_and_change_nothing(int x, int y)
    {
        var image = new Image(4, 3);

        Assert.Throws<ArgumentOutOfRangeException>(() => image.GetPixel(x, y));
        Assert.Throws<ArgumentOutOfRangeException>(() => image.SetPixel(x, y, Intensity.White));
        Assert.True(image.PixelBytes.IndexOfAnyExcept((byte)0) < 0, "a rejected SetPixel must not write");
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(3)]
    [InlineData(int.MinValue)]
    [InlineData(int.MaxValue)]
    public void GetRowSpan_out_of_range_throws(int y)
    {
        var image = new Image(4, 3);

        Assert.Throws<ArgumentOutOfRangeException>(() => image.GetRowSpan(y).Length);
    }

    [Fact]
    public void Last_pixel_is_in_range()
    {
        var image = new Image(4, 3);

        image.SetPixel(3, 2, new Intensity(0.5, 0.5, 0.5));

        Assert.Equal(new Rgb24(128, 128, 128), image.GetPixel(3, 2));
        Assert.Equal(new byte[] { 128, 128, 128 }, image.PixelBytes[^3..].ToArray());
    }
}
