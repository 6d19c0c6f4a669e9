using System.IO.Compression;
using BenchmarkDotNet.Attributes;
using RayLab.Imaging;
using RayLab.Sampling;

namespace RayLab.Benchmarks;

/// <summary>
/// Which zlib level <see cref="PngEncoder"/>'s <see cref="CompressionLevel.Optimal"/> should be: the Up-filtered rows
/// of the rendered 1920×1080 two-sphere pictures (jittered 16 spp and the exact image), DEFLATE-compressed as the
/// encoder does — in its 12 bands, each its own stream, on one thread — at zlib levels 1, 4, 6 and 9. Sizes:
/// <c>-- png-sizes</c>.
/// </summary>
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 9)]
public class ZlibLevelBenchmarks
{
    private byte[][] _bands = null!;

    [Params("jittered 16", "exact")]
    public string Picture { get; set; } = "jittered 16";

    [Params(1, 4, 6, 9)]
    public int ZlibLevel { get; set; }

    [GlobalSetup]
    public void Setup() => _bands = ZlibLevels.Bands(ZlibLevels.Render(Picture));

    [Benchmark]
    public long Deflate() => ZlibLevels.DeflatedLength(_bands, ZlibLevel);
}

/// <summary>The pictures, bands and sizes <see cref="ZlibLevelBenchmarks"/> measures.</summary>
public static class ZlibLevels
{
    /// <summary>The two-sphere scene at 1920×1080, jittered 16 spp or exact.</summary>
    public static Image Render(string picture)
    {
        var image = new Image(BenchScene.Width, BenchScene.Height);
        if (picture == "exact")
        {
            new Renderer().Render(BenchScene.Scene, BenchScene.Camera, RenderMethod.Exact, image);
        }
        else
        {
            new Renderer().Render(BenchScene.Scene, BenchScene.Camera, new JitteredSampler(16, 1), image);
        }

        return image;
    }

    /// <summary>The image's rows with PNG's Up filter, cut into the encoder's bands (its own filter and band size).</summary>
    public static byte[][] Bands(Image image)
    {
        int rowBytes = image.Width * 3;
        int rowsPerBand = PngEncoder.RowsPerBand(image.Width);
        byte[] zeros = new byte[rowBytes]; // the row above the first
        var bands = new List<byte[]>();
        ReadOnlySpan<byte> pixels = image.PixelBytes;
        for (int y0 = 0; y0 < image.Height; y0 += rowsPerBand)
        {
            int rows = Math.Min(rowsPerBand, image.Height - y0);
            byte[] band = new byte[rows * (rowBytes + 1)];
            for (int r = 0; r < rows; r++)
            {
                int y = y0 + r;
                ReadOnlySpan<byte> up = y == 0 ? zeros : pixels.Slice((y - 1) * rowBytes, rowBytes);
                PngEncoder.Filter(PngFilter.Up, pixels.Slice(y * rowBytes, rowBytes), up, band.AsSpan(r * (rowBytes + 1), rowBytes + 1));
            }

            bands.Add(band);
        }

        return [.. bands];
    }

    /// <summary>The bands' DEFLATE data at <paramref name="zlibLevel"/>, each band its own stream: the total length.</summary>
    public static long DeflatedLength(byte[][] bands, int zlibLevel)
    {
        long total = 0;
        foreach (byte[] band in bands)
        {
            using var output = new MemoryStream();
            using (var deflate = new DeflateStream(output, new ZLibCompressionOptions { CompressionLevel = zlibLevel }, leaveOpen: true))
            {
                deflate.Write(band);
            }

            total += output.Length;
        }

        return total;
    }

    private static readonly int[] Levels = [1, 4, 6, 9];

    /// <summary>Prints the size table: each picture at zlib levels 1, 4, 6 and 9.</summary>
    public static void Print(TextWriter output)
    {
        output.WriteLine("| picture | level 1 | level 4 | level 6 | level 9 |");
        output.WriteLine("|---|---:|---:|---:|---:|");
        foreach (string picture in new[] { "jittered 16", "exact" })
        {
            byte[][] bands = Bands(Render(picture));
            output.WriteLine($"| {picture} | {string.Join(" | ", Levels.Select(l => $"{DeflatedLength(bands, l) / 1024.0:F1} KiB"))} |");
        }
    }
}
