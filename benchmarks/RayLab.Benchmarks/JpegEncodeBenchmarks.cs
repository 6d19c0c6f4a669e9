using BenchmarkDotNet.Attributes;
using RayLab.ImageSharp;
using RayLab.Reports.Imaging;
using RayLab.Scenes;
using SixLabors.ImageSharp;
using SkiaSharp;
using StbImageWriteSharp;

namespace RayLab.Benchmarks;

/// <summary>
/// JPEG at quality 90 on RayLab's pictures: Skia (libjpeg-turbo, 4:4:4, as <c>Image.Save</c> writes it today, with
/// its RGB24 → RGBA copy), JpegLibrary through RayLab's <see cref="Imaging.JpegEncoder"/> (4:4:4, with Huffman tables
/// fitted to the image as Skia's are, and with the standard tables), and
/// StbImageWriteSharp, which chooses its subsampling from the quality: 4:2:0 up to 90, 4:4:4 from 91 (both measured).
/// Sizes and errors: <c>-- jpeg-sizes</c> (<see cref="JpegSizes"/>); docs/bench/jpeg.md has the table.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 9)]
public class JpegEncodeBenchmarks : IDisposable
{
    private readonly MemoryStream _stream = new();
    private Image _image = null!;

    /// <summary>bench-1080: the two-sphere scene at 1920×1080, jittered 16 spp; lab-800x600: samples/scenes/two-spheres.json as the lab renders it.</summary>
    [Params("bench-1080", "lab-800x600")]
    public string Picture { get; set; } = "bench-1080";

    [GlobalSetup]
    public void Setup() => _image = JpegPictures.Get(Picture);

    /// <summary>Frees the output stream.</summary>
    [GlobalCleanup]
    public void Dispose()
    {
        _stream.Dispose();
        GC.SuppressFinalize(this);
    }

    [Benchmark(Baseline = true)]
    public long Skia90() => Encode(JpegCandidate.Skia90);

    [Benchmark]
    public long JpegLibrary90() => Encode(JpegCandidate.JpegLibrary90);

    [Benchmark]
    public long JpegLibrary90Standard() => Encode(JpegCandidate.JpegLibrary90Standard);

    [Benchmark]
    public long Stb90() => Encode(JpegCandidate.Stb90);

    [Benchmark]
    public long Stb91() => Encode(JpegCandidate.Stb91);

    private long Encode(JpegCandidate candidate)
    {
        _stream.SetLength(0);
        JpegCandidates.Write(candidate, _stream, _image);
        return _stream.Length;
    }
}

/// <summary>The encoders measured.</summary>
public enum JpegCandidate
{
    /// <summary>Skia's libjpeg-turbo at quality 90, 4:4:4 (RayLab's SkiaEncoder, including its RGBA copy).</summary>
    Skia90,

    /// <summary>JpegLibrary at quality 90, 4:4:4, Huffman tables fitted to the image (RayLab's JpegEncoder).</summary>
    JpegLibrary90,

    /// <summary>JpegLibrary at quality 90, 4:4:4, the standard Huffman tables (one pass).</summary>
    JpegLibrary90Standard,

    /// <summary>StbImageWriteSharp at quality 90 (it subsamples chroma 4:2:0 at 90 and below).</summary>
    Stb90,

    /// <summary>StbImageWriteSharp at quality 91, its lowest quality with 4:4:4.</summary>
    Stb91,

    /// <summary>ImageSharp 2.1 (RayLab.ImageSharp's path) at quality 90, its default sampling there (4:2:0), on a ready bitmap.</summary>
    ImageSharp90,

    /// <summary>ImageSharp 2.1 at quality 90 with 4:4:4 asked for, on a ready bitmap.</summary>
    ImageSharp90Ycc444,
}

/// <summary>Writes one candidate's JPEG.</summary>
public static class JpegCandidates
{
    /// <summary>Each picture's ImageSharp bitmap, made once (the adapter's user renders into one; no copy is timed).</summary>
    private static readonly System.Runtime.CompilerServices.ConditionalWeakTable<Image, SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>> Bitmaps = new();

    public static void Write(JpegCandidate candidate, Stream stream, Image image)
    {
        switch (candidate)
        {
            case JpegCandidate.Skia90:
                SkiaEncoder.Write(stream, image, SkiaEncoder.Kind.Jpeg, 90);
                break;
            case JpegCandidate.JpegLibrary90:
                Imaging.JpegEncoder.Write(stream, image, 90);
                break;
            case JpegCandidate.JpegLibrary90Standard:
                Imaging.JpegEncoder.Write(stream, image, 90, optimizeCoding: false);
                break;
            case JpegCandidate.Stb90:
                WriteStb(stream, image, 90);
                break;
            case JpegCandidate.Stb91:
                WriteStb(stream, image, 91);
                break;
            case JpegCandidate.ImageSharp90:
                Bitmaps.GetValue(image, ImageConversions.ToImageSharp).SaveAsJpeg(stream, new SixLabors.ImageSharp.Formats.Jpeg.JpegEncoder { Quality = 90 });
                break;
            case JpegCandidate.ImageSharp90Ycc444:
                Bitmaps.GetValue(image, ImageConversions.ToImageSharp).SaveAsJpeg(stream,
                    new SixLabors.ImageSharp.Formats.Jpeg.JpegEncoder { Quality = 90, ColorType = SixLabors.ImageSharp.Formats.Jpeg.JpegColorType.YCbCrRatio444 });
                break;
            default:
                throw new ArgumentOutOfRangeException(nameof(candidate), candidate, null);
        }
    }

    private static unsafe void WriteStb(Stream stream, Image image, int quality)
    {
        fixed (byte* pixels = image.PixelBytes)
        {
            new ImageWriter().WriteJpg(pixels, image.Width, image.Height, ColorComponents.RedGreenBlue, stream, quality);
        }
    }
}

/// <summary>The pictures the JPEG encoders are measured on (rendered once per process).</summary>
public static class JpegPictures
{
    private static readonly Lazy<Image> Bench = new(PngSizes.Picture);

    private static readonly Lazy<Image> Lab = new(() =>
    {
        PreparedScene scene = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json")).Prepare();
        Image image = scene.CreateImage();
        scene.Render(new Renderer(), image);
        return image;
    });

    public static Image Get(string name) => name switch
    {
        "bench-1080" => Bench.Value,
        "lab-800x600" => Lab.Value,
        _ => throw new ArgumentOutOfRangeException(nameof(name), name, "bench-1080 or lab-800x600"),
    };
}

/// <summary>
/// Size, chroma sampling and error of each candidate's JPEG on each picture: the JPEG and the PNG are both decoded
/// with Skia and compared channel by channel (mean absolute error in 8-bit levels, share of channel values within 5
/// levels, largest error). The time column is a cross-check of BenchmarkDotNet's on a loaded machine: the median of
/// <see cref="Rounds"/> rounds that each run every candidate once, in turn, so a change of load hits them all alike.
/// </summary>
public static class JpegSizes
{
    /// <summary>Interleaved rounds per picture for the median time.</summary>
    public const int Rounds = 15;

    public static void Print(TextWriter output)
    {
        output.WriteLine($"| picture | encoder | sampling | size | mean abs. error | within 5 levels | max error | median of {Rounds} interleaved |");
        output.WriteLine("|---|---|---|---:|---:|---:|---:|---:|");
        foreach (string picture in new[] { "bench-1080", "lab-800x600" })
        {
            Image image = JpegPictures.Get(picture);
            using var png = new MemoryStream();
            image.Save(png, ImageFormat.Png);
            byte[] reference = DecodeRgb(png.ToArray(), image.Width, image.Height);
            if (!reference.AsSpan().SequenceEqual(image.PixelBytes))
            {
                throw new InvalidOperationException("The PNG does not decode to the image's pixels.");
            }

            Dictionary<JpegCandidate, double> times = MedianTimes(image);

            foreach (JpegCandidate candidate in Enum.GetValues<JpegCandidate>())
            {
                using var jpeg = new MemoryStream();
                JpegCandidates.Write(candidate, jpeg, image);
                byte[] bytes = jpeg.ToArray();
                byte[] decoded = DecodeRgb(bytes, image.Width, image.Height);
                long sum = 0, within = 0;
                int max = 0;
                for (int i = 0; i < decoded.Length; i++)
                {
                    int e = Math.Abs(decoded[i] - reference[i]);
                    sum += e;
                    within += e <= 5 ? 1 : 0;
                    max = Math.Max(max, e);
                }

                output.WriteLine($"| {picture} | {candidate} | {Sampling(bytes)} | {bytes.Length / 1024.0:F1} KiB | {(double)sum / decoded.Length:F3} | {100.0 * within / decoded.Length:F2} % | {max} | {times[candidate]:F1} ms |");
            }
        }
    }

    /// <summary>
    /// The time of the first encode in a fresh process (JIT included, as when the lab saves its one picture):
    /// <c>-- jpeg-first CANDIDATE PICTURE</c>, one process per figure.
    /// </summary>
    public static void PrintFirst(TextWriter output, string candidate, string picture)
    {
        Image image = JpegPictures.Get(picture);
        JpegCandidate which = Enum.Parse<JpegCandidate>(candidate);
        using var stream = new MemoryStream();
        long start = System.Diagnostics.Stopwatch.GetTimestamp();
        JpegCandidates.Write(which, stream, image);
        double first = System.Diagnostics.Stopwatch.GetElapsedTime(start).TotalMilliseconds;
        output.WriteLine($"{picture} {which} first {first:F1} ms");
    }

    private static Dictionary<JpegCandidate, double> MedianTimes(Image image)
    {
        JpegCandidate[] candidates = Enum.GetValues<JpegCandidate>();
        var times = candidates.ToDictionary(c => c, _ => new List<double>());
        using var stream = new MemoryStream();
        for (int round = -2; round < Rounds; round++)
        {
            for (int k = 0; k < candidates.Length; k++)
            {
                // Rotate the order each round; rounds -2 and -1 warm up.
                JpegCandidate candidate = candidates[(k + round + 2) % candidates.Length];
                stream.SetLength(0);
                long start = System.Diagnostics.Stopwatch.GetTimestamp();
                JpegCandidates.Write(candidate, stream, image);
                double ms = System.Diagnostics.Stopwatch.GetElapsedTime(start).TotalMilliseconds;
                if (round >= 0)
                {
                    times[candidate].Add(ms);
                }
            }
        }

        return times.ToDictionary(p => p.Key, p => p.Value.Order().ElementAt(p.Value.Count / 2));
    }

    /// <summary>4:4:4 or 4:2:0 (or the factors as stated) from the first component's sampling factors in the start-of-frame segment.</summary>
    public static string Sampling(byte[] jpeg)
    {
        for (int i = 2; i + 3 < jpeg.Length;)
        {
            if (jpeg[i] != 0xFF)
            {
                throw new InvalidDataException($"No JPEG marker at byte {i}.");
            }

            byte marker = jpeg[i + 1];
            int length = (jpeg[i + 2] << 8) | jpeg[i + 3];
            if (marker is 0xC0 or 0xC1 or 0xC2)
            {
                // Length, precision, height, width, component count, then per component: id, H<<4|V, table.
                byte factors = jpeg[i + 2 + 2 + 1 + 2 + 2 + 1 + 1];
                return factors switch
                {
                    0x11 => "4:4:4",
                    0x22 => "4:2:0",
                    0x21 => "4:2:2",
                    _ => $"Y {factors >> 4}x{factors & 15}",
                };
            }

            i += 2 + length;
        }

        throw new InvalidDataException("No start-of-frame segment.");
    }

    private static byte[] DecodeRgb(byte[] encoded, int width, int height)
    {
        using SKBitmap bitmap = SKBitmap.Decode(encoded) ?? throw new InvalidDataException("Skia cannot decode the file.");
        if (bitmap.Width != width || bitmap.Height != height)
        {
            throw new InvalidDataException($"Decoded {bitmap.Width}×{bitmap.Height}, expected {width}×{height}.");
        }

        byte[] rgb = new byte[width * height * 3];
        for (int y = 0; y < height; y++)
        {
            for (int x = 0; x < width; x++)
            {
                SKColor c = bitmap.GetPixel(x, y);
                int i = ((y * width) + x) * 3;
                rgb[i] = c.Red;
                rgb[i + 1] = c.Green;
                rgb[i + 2] = c.Blue;
            }
        }

        return rgb;
    }
}
