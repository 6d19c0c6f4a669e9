using BenchmarkDotNet.Attributes;
using RayLab.Reports.Imaging;
using SkiaSharp;

namespace RayLab.Benchmarks;

/// <summary>
/// RayLab's own PNG encoder (its defaults: Up filter, Optimal level) against SkiaSharp's PNG, JPEG and WebP on the
/// same rendered 1920×1080 two-sphere picture (<see cref="PngSizes.Picture"/>). Skia's rows encode a ready
/// <see cref="SKPixmap"/>; <see cref="ToSKBitmap"/> is the RGB24 → RGBA copy <c>Image.Save</c> adds before them.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 9)]
public class SkiaEncodeBenchmarks : IDisposable
{
    private Image _image = null!;
    private SKBitmap _bitmap = null!;
    private readonly MemoryStream _stream = new();

    /// <summary>Frees the bitmap and the output stream.</summary>
    [GlobalCleanup]
    public void Dispose()
    {
        _bitmap?.Dispose();
        _stream.Dispose();
        GC.SuppressFinalize(this);
    }

    [GlobalSetup]
    public void Setup()
    {
        _image = PngSizes.Picture();
        _bitmap = _image.ToSKBitmap();
    }

    [Benchmark(Baseline = true)]
    public long RayLabPng()
    {
        _stream.SetLength(0);
        _image.Save(_stream, ImageFormat.Png);
        return _stream.Length;
    }

    [Benchmark]
    public long SkiaPngZlib6() => Encode(new SKPngEncoderOptions(SKPngEncoderFilterFlags.AllFilters, 6));

    [Benchmark]
    public long SkiaPngZlib1() => Encode(new SKPngEncoderOptions(SKPngEncoderFilterFlags.AllFilters, 1));

    [Benchmark]
    public long SkiaJpeg90() => Encode(new SKJpegEncoderOptions(90, SKJpegEncoderDownsample.Downsample444, SKJpegEncoderAlphaOption.Ignore));

    [Benchmark]
    public long SkiaWebp90() => Encode(new SKWebpEncoderOptions(SKWebpEncoderCompression.Lossy, 90));

    [Benchmark]
    public int ToSKBitmap()
    {
        using SKBitmap bitmap = _image.ToSKBitmap();
        return bitmap.RowBytes;
    }

    private long Encode(SKPngEncoderOptions options)
    {
        using SKPixmap pixmap = _bitmap.PeekPixels()!;
        using SKData data = pixmap.Encode(options)!;
        return data.Size;
    }

    private long Encode(SKJpegEncoderOptions options)
    {
        using SKPixmap pixmap = _bitmap.PeekPixels()!;
        using SKData data = pixmap.Encode(options)!;
        return data.Size;
    }

    private long Encode(SKWebpEncoderOptions options)
    {
        using SKPixmap pixmap = _bitmap.PeekPixels()!;
        using SKData data = pixmap.Encode(options)!;
        return data.Size;
    }
}

/// <summary>The size of each encoder's file on the benchmark picture (BenchmarkDotNet measures time, not size).</summary>
public static class SkiaSizes
{
    public static void Print(TextWriter output)
    {
        Image image = PngSizes.Picture();
        using SKBitmap bitmap = image.ToSKBitmap();
        using SKPixmap pixmap = bitmap.PeekPixels()!;
        using var own = new MemoryStream();
        image.Save(own, ImageFormat.Png);
        output.WriteLine("| encoder | size |");
        output.WriteLine("|---|---:|");
        output.WriteLine($"| RayLab PNG (Up, Optimal) | {own.Length / 1024.0:F1} KiB |");
        using (SKData d = pixmap.Encode(new SKPngEncoderOptions(SKPngEncoderFilterFlags.AllFilters, 6))!)
        {
            output.WriteLine($"| Skia PNG, zlib 6 | {d.Size / 1024.0:F1} KiB |");
        }

        using (SKData d = pixmap.Encode(new SKPngEncoderOptions(SKPngEncoderFilterFlags.AllFilters, 1))!)
        {
            output.WriteLine($"| Skia PNG, zlib 1 | {d.Size / 1024.0:F1} KiB |");
        }

        using (SKData d = pixmap.Encode(new SKJpegEncoderOptions(90, SKJpegEncoderDownsample.Downsample444, SKJpegEncoderAlphaOption.Ignore))!)
        {
            output.WriteLine($"| Skia JPEG, quality 90, 4:4:4 | {d.Size / 1024.0:F1} KiB |");
        }

        using (SKData d = pixmap.Encode(new SKWebpEncoderOptions(SKWebpEncoderCompression.Lossy, 90))!)
        {
            output.WriteLine($"| Skia WebP, lossy 90 | {d.Size / 1024.0:F1} KiB |");
        }
    }
}
