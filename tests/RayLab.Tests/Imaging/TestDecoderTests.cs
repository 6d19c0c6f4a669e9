using System.Text;
using RayLab.Imaging;

namespace RayLab.Tests.Imaging;

/// <summary>
/// Known-answer tests for the tests' own PNG and BMP readers, so a round trip through them means something: a
/// reader that accepted anything, or undid a filter the same wrong way the encoder applied it, would fail here.
/// </summary>
public class TestDecoderTests
{
    // ---- CRC-32 -------------------------------------------------------------------------------------

    [Fact]
    public void Bitwise_crc32_matches_the_standard_check_value()
    {
        Assert.Equal(0xCBF43926u, PngTestDecoder.Crc32(Encoding.ASCII.GetBytes("123456789")));
        Assert.Equal(0x00000000u, PngTestDecoder.Crc32([]));
    }

    [Fact]
    public void Bitwise_crc32_of_IEND_is_the_well_known_AE426082()
    {
        Assert.Equal(0xAE426082u, PngTestDecoder.Crc32("IEND"u8));
    }

    [Fact]
    public void System_IO_Hashing_crc32_agrees_with_the_bitwise_one()
    {
        var random = new Random(1234);
        foreach (int length in new[] { 0, 1, 2, 3, 7, 64, 1000, 4097 })
        {
            var data = new byte[length];
            random.NextBytes(data);

            Assert.Equal(PngTestDecoder.Crc32(data), System.IO.Hashing.Crc32.HashToUInt32(data));
        }
    }

    // ---- Paeth --------------------------------------------------------------------------------------

    [Theory]
    [InlineData(1, 2, 3, 1)]      // p = 0: pa = 1, pb = 2, pc = 3 → a
    [InlineData(3, 2, 1, 3)]      // p = 4: pa = 1, pb = 2, pc = 3 → a
    [InlineData(10, 1, 10, 1)]    // p = 1: pa = 9, pb = 0, pc = 9 → b
    [InlineData(10, 20, 15, 15)]  // p = 15: pa = 5, pb = 5, pc = 0 → c
    [InlineData(0, 10, 5, 5)]     // p = 5: pa = 5, pb = 5, pc = 0 → c
    [InlineData(5, 5, 5, 5)]      // all tie → a
    [InlineData(4, 8, 2, 8)]      // p = 10: pa = 6, pb = 2, pc = 8 → b
    [InlineData(200, 100, 150, 150)] // p = 150: pa = 50, pb = 50, pc = 0 → c
    public void Test_paeth_predictor_follows_the_specification(int a, int b, int c, int expected)
    {
        Assert.Equal(expected, PngTestDecoder.PaethPredictor(a, b, c));
    }

    [Fact]
    public void Library_paeth_predictor_agrees_with_the_test_one_for_every_input()
    {
        for (int a = 0; a < 256; a++)
        {
            for (int b = 0; b < 256; b++)
            {
                for (int c = 0; c < 256; c++)
                {
                    int expected = PngTestDecoder.PaethPredictor(a, b, c);
                    int actual = PngEncoder.Paeth(a, b, c);
                    if (actual != expected)
                    {
                        Assert.Fail($"Paeth({a}, {b}, {c}) = {actual}, expected {expected}.");
                    }
                }
            }
        }
    }

    // ---- PNG reader: a hand-filtered 2×5 image using each filter type once ----------------------------

    private static readonly byte[] HandPixels =
    [
        10, 20, 30, 40, 5, 80,        // row 0
        50, 35, 35, 55, 30, 90,       // row 1
        100, 100, 100, 200, 200, 200, // row 2
        0, 255, 1, 2, 3, 4,           // row 3
        7, 8, 9, 10, 11, 12,          // row 4
    ];

    // Filtered by hand from the specification.
    private static readonly byte[] HandFiltered =
    [
        1, 10, 20, 30, 30, 241, 50,     // Sub:     a = 0 for the first pixel, then the left pixel; 5 − 20 wraps to 241
        4, 40, 15, 5, 5, 10, 10,        // Paeth:   first pixel predicts b (above); second predicts a (R), c (G), b (B)
        3, 75, 83, 83, 123, 135, 105,   // Average: floor((a + b) / 2): (0 + 35) / 2 = 17 → 83; (100 + 55) / 2 = 77 → 123
        2, 156, 155, 157, 58, 59, 60,   // Up:      0 − 100 wraps to 156, …
        0, 7, 8, 9, 10, 11, 12,         // None
    ];

    private static byte[] HandPng(byte[]? filtered = null, Func<byte[], byte[]>? patchIhdr = null, bool withIend = true, byte[]? trailing = null)
    {
        byte[] ihdr = PngTestDecoder.Ihdr(2, 5);
        if (patchIhdr != null)
        {
            ihdr = patchIhdr(ihdr);
        }

        var png = new List<byte>(PngTestDecoder.Signature);
        png.AddRange(PngTestDecoder.Chunk("IHDR", ihdr));
        png.AddRange(PngTestDecoder.Chunk("IDAT", PngTestDecoder.Deflate(filtered ?? HandFiltered)));
        if (withIend)
        {
            png.AddRange(PngTestDecoder.Chunk("IEND", []));
        }

        if (trailing != null)
        {
            png.AddRange(trailing);
        }

        return [.. png];
    }

    [Fact]
    public void Png_reader_undoes_each_filter_type_correctly()
    {
        PngTestDecoder.Result result = PngTestDecoder.Decode(HandPng());

        Assert.Equal(2, result.Width);
        Assert.Equal(5, result.Height);
        Assert.Equal(new byte[] { 1, 4, 3, 2, 0 }, result.RowFilters);
        Assert.Equal(HandPixels, result.Rgb);
        Assert.Equal(["IHDR", "IDAT", "IEND"], result.ChunkTypes);
    }

    [Fact]
    public void Png_reader_concatenates_split_IDAT_chunks()
    {
        byte[] zlib = PngTestDecoder.Deflate(HandFiltered);
        var png = new List<byte>(PngTestDecoder.Signature);
        png.AddRange(PngTestDecoder.Chunk("IHDR", PngTestDecoder.Ihdr(2, 5)));
        png.AddRange(PngTestDecoder.Chunk("IDAT", zlib.AsSpan(0, 5)));
        png.AddRange(PngTestDecoder.Chunk("IDAT", zlib.AsSpan(5)));
        png.AddRange(PngTestDecoder.Chunk("IEND", []));

        Assert.Equal(HandPixels, PngTestDecoder.Decode([.. png]).Rgb);
    }

    [Fact]
    public void Png_reader_rejects_a_bad_signature()
    {
        byte[] png = HandPng();
        png[1] = (byte)'p';

        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(png));
    }

    [Theory]
    [InlineData(8 + 8)]       // inside the IHDR data
    [InlineData(8 + 25 - 1)]  // the last byte of the IHDR CRC
    [InlineData(8 + 25 + 4)]  // the IDAT type
    public void Png_reader_rejects_any_corrupted_chunk(int index)
    {
        byte[] png = HandPng();
        png[index] ^= 0x01;

        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(png));
    }

    [Fact]
    public void Png_reader_rejects_a_corrupted_IEND_crc()
    {
        byte[] png = HandPng();
        png[^1] ^= 0x80;

        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(png));
    }

    [Fact]
    public void Png_reader_requires_IEND_last()
    {
        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(HandPng(withIend: false)));
        Assert.Throws<PngTestDecoder.PngFormatException>(() =>
            PngTestDecoder.Decode(HandPng(trailing: PngTestDecoder.Chunk("tEXt", "a\0b"u8))));
        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(HandPng(trailing: [0])));
    }

    [Theory]
    [InlineData(8, 16)]  // bit depth
    [InlineData(9, 6)]   // colour type RGBA
    [InlineData(9, 0)]   // greyscale
    [InlineData(10, 1)]  // compression
    [InlineData(11, 1)]  // filter method
    [InlineData(12, 1)]  // Adam7
    public void Png_reader_rejects_unsupported_IHDR_fields(int field, byte value)
    {
        byte[] png = HandPng(patchIhdr: ihdr =>
        {
            ihdr[field] = value;
            return ihdr;
        });

        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(png));
    }

    [Fact]
    public void Png_reader_rejects_an_unknown_filter_type_and_a_wrong_data_length()
    {
        byte[] badFilter = (byte[])HandFiltered.Clone();
        badFilter[7] = 5;
        byte[] shortData = HandFiltered[..^1];

        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(HandPng(badFilter)));
        Assert.Throws<PngTestDecoder.PngFormatException>(() => PngTestDecoder.Decode(HandPng(shortData)));
    }

    // ---- SkiaSharp as the tests' decoder ------------------------------------------------------------

    [Fact]
    public void Skia_reads_a_hand_made_bottom_up_bmp_as_rgb_rows_top_first()
    {
        var bmp = new byte[54 + 16];
        "BM"u8.CopyTo(bmp);
        BitConverter.TryWriteBytes(bmp.AsSpan(2), (uint)bmp.Length);
        BitConverter.TryWriteBytes(bmp.AsSpan(10), 54u);
        BitConverter.TryWriteBytes(bmp.AsSpan(14), 40u);
        BitConverter.TryWriteBytes(bmp.AsSpan(18), 2);
        BitConverter.TryWriteBytes(bmp.AsSpan(22), 2);
        BitConverter.TryWriteBytes(bmp.AsSpan(26), (ushort)1);
        BitConverter.TryWriteBytes(bmp.AsSpan(28), (ushort)24);
        byte[] pixels = [9, 8, 7, 12, 11, 10, 0, 0, 3, 2, 1, 6, 5, 4, 0, 0]; // bottom row first, BGR
        pixels.CopyTo(bmp, 54);

        SkiaDecode.Result result = SkiaDecode.Decode(bmp);

        Assert.Equal((2, 2), (result.Width, result.Height));
        Assert.Equal(new byte[] { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 }, result.Rgb);
    }

    [Fact]
    public void Skia_reads_the_hand_filtered_png_as_the_png_reader_does()
    {
        byte[] png = HandPng(HandFiltered);

        Assert.Equal(PngTestDecoder.Decode(png).Rgb, SkiaDecode.Decode(png).Rgb);
    }
}
