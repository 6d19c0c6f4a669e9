using System.Buffers.Binary;
using System.IO.Compression;
using System.IO.Hashing;
using RayLab.Imaging;

namespace RayLab.Tests.Imaging;

/// <summary>
/// The PNG encoder's row bands, encoded in parallel and joined into one zlib stream: the pixels decode exactly (by
/// the tests' own decoder) at odd sizes, one row, one column and more than one band; the bytes are the same for any
/// thread count; the stream's Adler-32 is that of all the filtered bytes, summed here byte by byte.
/// </summary>
public sealed class PngBandTests
{
    /// <summary>Width, height: odd sizes, one row, one column, a row wider than a band, several bands.</summary>
    public static TheoryData<int, int> Sizes => new()
    {
        { 1, 1 },
        { 7, 1 },
        { 1, 7 },
        { 333, 19 },
        { 1001, 601 },                                    // 174 rows a band: 4 bands, the last one short; 21 rows a 64 KiB chunk
        { 1, (2 * PngEncoder.RowsPerBand(1)) + 1 },        // one column, 3 bands
        { (PngEncoder.BandBytes / 3) + 5, 1 },            // one row wider than a band
        { (PngEncoder.BandBytes / 3) + 5, 3 },            // three such rows: a band each
    };

    private static byte[] Encode(Image image, int threads, PngFilter filter = PngFilter.Up, CompressionLevel level = CompressionLevel.Optimal)
    {
        using var stream = new MemoryStream();
        PngEncoder.Write(stream, image, level, filter, threads);
        return stream.ToArray();
    }

    [Theory]
    [MemberData(nameof(Sizes))]
    public void Bands_decode_to_exactly_the_pixels_with_the_same_bytes_for_any_thread_count(int width, int height)
    {
        Image image = TestImages.Noise(width, height, seed: width + (height * 31));

        byte[] one = Encode(image, threads: 1);
        byte[] two = Encode(image, threads: 2);
        byte[] all = Encode(image, threads: -1);

        PngTestDecoder.Result png = PngTestDecoder.Decode(two);
        Assert.Equal((width, height), (png.Width, png.Height));
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
        Assert.Equal(one, two);
        Assert.Equal(one, all);
        int bands = (height + PngEncoder.RowsPerBand(width) - 1) / PngEncoder.RowsPerBand(width);
        Assert.Equal(bands, png.ChunkTypes.Count(t => t == "IDAT"));
    }

    [Theory]
    [MemberData(nameof(Sizes))]
    public void The_zlib_stream_is_one_stream_whose_adler32_is_that_of_every_filtered_byte(int width, int height)
    {
        Image image = TestImages.Varied(width, height, seed: 3);

        byte[] zlib = IdatData(Encode(image, threads: 2));

        Assert.Equal(0x78, zlib[0]);
        Assert.Equal(0, ((zlib[0] << 8) | zlib[1]) % 31); // the header check
        byte[] raw = InflateRaw(zlib.AsSpan(2, zlib.Length - 6).ToArray());
        Assert.Equal((long)height * ((width * 3) + 1), raw.LongLength); // a final block before the last band would cut it short
        Assert.Equal(NaiveAdler32(raw), BinaryPrimitives.ReadUInt32BigEndian(zlib.AsSpan(zlib.Length - 4)));
    }

    [Theory]
    [InlineData(nameof(PngFilter.Adaptive), CompressionLevel.Optimal)]
    [InlineData(nameof(PngFilter.Paeth), CompressionLevel.Fastest)]
    [InlineData(nameof(PngFilter.Sub), CompressionLevel.SmallestSize)]
    [InlineData(nameof(PngFilter.None), CompressionLevel.NoCompression)]
    public void Every_filter_and_level_decodes_across_bands(string filterName, CompressionLevel level)
    {
        PngFilter filter = Enum.Parse<PngFilter>(filterName); // the filter enum is internal; a public test takes its name
        Image image = TestImages.Varied(1001, 400, seed: 11); // 3 bands

        byte[] one = Encode(image, threads: 1, filter, level);
        byte[] two = Encode(image, threads: 2, filter, level);

        Assert.Equal(one, two);
        PngTestDecoder.Result png = PngTestDecoder.Decode(two);
        Assert.Equal(image.PixelBytes.ToArray(), png.Rgb);
        if (filter != PngFilter.Adaptive)
        {
            Assert.All(png.RowFilters, f => Assert.Equal((byte)filter, f));
        }
    }

    [Theory]
    [InlineData(CompressionLevel.NoCompression, 0, 0)]
    [InlineData(CompressionLevel.Fastest, 1, 0)]
    [InlineData(CompressionLevel.Optimal, 4, 1)]
    [InlineData(CompressionLevel.SmallestSize, 9, 3)]
    public void Each_level_is_its_zlib_level_and_the_header_says_its_class(CompressionLevel level, int zlibLevel, int levelClass)
    {
        Image image = TestImages.Varied(333, 19, seed: 7); // one band: its DEFLATE data is one whole stream
        byte[] zlib = IdatData(Encode(image, threads: 1, PngFilter.None, level));

        // With the None filter the filtered bytes are each row's 0 and its pixels (19 rows: one 64 KiB chunk, written at
        // once); compressing them at the zlib level the level stands for must give the same DEFLATE bytes.
        int rowBytes = image.Width * 3;
        byte[] filtered = new byte[image.Height * (rowBytes + 1)];
        for (int y = 0; y < image.Height; y++)
        {
            image.PixelBytes.Slice(y * rowBytes, rowBytes).CopyTo(filtered.AsSpan((y * (rowBytes + 1)) + 1));
        }

        using var expected = new MemoryStream();
        using (var deflate = new DeflateStream(expected, new ZLibCompressionOptions { CompressionLevel = zlibLevel }, leaveOpen: true))
        {
            deflate.Write(filtered);
        }

        Assert.Equal(levelClass, zlib[1] >> 6);
        Assert.Equal(0, ((zlib[0] << 8) | zlib[1]) % 31);
        Assert.Equal(expected.ToArray(), zlib.AsSpan(2, zlib.Length - 6).ToArray());
    }

    [Fact]
    public void A_level_outside_the_enum_is_refused_by_name_before_anything_is_written()
    {
        using var stream = new MemoryStream();

        var e = Assert.Throws<ArgumentOutOfRangeException>(() => PngEncoder.Write(stream, new Image(2, 2), (CompressionLevel)42));

        Assert.Equal("level", e.ParamName);
        Assert.Equal(0, stream.Length);
    }

    [Fact]
    public void The_first_row_of_every_band_is_filtered_against_the_row_above_it()
    {
        // Every row the same: with Up, every row after the first is all zeros, band boundaries included.
        var image = new Image(1001, 400);
        Span<byte> pixels = image.PixelBytes;
        for (int i = 0; i < pixels.Length; i++)
        {
            pixels[i] = (byte)((i % (image.Width * 3)) * 7);
        }

        byte[] zlib = IdatData(Encode(image, threads: 2));
        byte[] raw = InflateRaw(zlib.AsSpan(2, zlib.Length - 6).ToArray());

        int stride = (image.Width * 3) + 1;
        for (int y = 1; y < image.Height; y++)
        {
            Assert.True(raw.AsSpan(y * stride, stride).SequenceEqual(new byte[] { 2 }.Concat(new byte[stride - 1]).ToArray()), $"row {y}");
        }
    }

    [Theory]
    [InlineData(0)]
    [InlineData(-2)]
    public void A_thread_count_of_zero_or_below_minus_one_is_refused_by_name(int threads)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => PngEncoder.Write(new MemoryStream(), new Image(2, 2), maxDegreeOfParallelism: threads));
        Assert.Equal("maxDegreeOfParallelism", e.ParamName);
    }

    [Fact]
    public void Adler32_of_two_pieces_combines_to_that_of_the_whole()
    {
        var random = new Random(5);
        foreach (int length in new[] { 0, 1, 2, 100, 65520, 65521, 65522, 200_000, 1_000_003 })
        {
            byte[] data = new byte[length];
            random.NextBytes(data);
            if (length > 10)
            {
                data.AsSpan(0, length / 3).Fill(0xFF); // long runs of the largest byte push the sums past the modulus
            }

            foreach (int cut in new[] { 0, length / 2, length - 1, length }.Where(c => c >= 0 && c <= length).Distinct())
            {
                uint a = Adler32.HashToUInt32(data.AsSpan(0, cut)), b = Adler32.HashToUInt32(data.AsSpan(cut));

                Assert.Equal(NaiveAdler32(data), Adler32Combine.Combine(a, b, length - cut));
            }
        }
    }

    /// <summary>The IDAT chunks' data, joined (the zlib stream).</summary>
    private static byte[] IdatData(byte[] png)
    {
        var data = new List<byte>();
        for (int at = 8; at < png.Length;)
        {
            int length = BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(at));
            if (System.Text.Encoding.ASCII.GetString(png, at + 4, 4) == "IDAT")
            {
                data.AddRange(png.AsSpan(at + 8, length).ToArray());
            }

            at += 12 + length;
        }

        return [.. data];
    }

    /// <summary>Inflates raw DEFLATE data up to its final block.</summary>
    private static byte[] InflateRaw(byte[] deflate)
    {
        using var input = new MemoryStream(deflate);
        using var output = new MemoryStream();
        using (var inflate = new DeflateStream(input, CompressionMode.Decompress))
        {
            inflate.CopyTo(output);
        }

        return output.ToArray();
    }

    /// <summary>RFC 1950's definition, one byte at a time.</summary>
    private static uint NaiveAdler32(ReadOnlySpan<byte> data)
    {
        uint a = 1, b = 0;
        foreach (byte d in data)
        {
            a = (a + d) % 65521;
            b = (b + a) % 65521;
        }

        return (b << 16) | a;
    }
}
