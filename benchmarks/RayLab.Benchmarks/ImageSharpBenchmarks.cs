using BenchmarkDotNet.Attributes;
using RayLab.ImageSharp;
using RayLab.Sampling;
using SixLabors.ImageSharp;
using SixLabors.ImageSharp.Formats.Jpeg;
using SixLabors.ImageSharp.Formats.Png;
using Bitmap = SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>;

namespace RayLab.Benchmarks;

/// <summary>
/// The bench frame (1920×1080, jittered 16 spp, 2 threads) rendered into RayLab's <see cref="Image"/> and into an
/// ImageSharp <c>Image&lt;Rgb24&gt;</c> in one run, alternating: the adapter writes each row into the bitmap's own
/// memory, so the two should be the same speed.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 15)]
public class ImageSharpFrameBenchmarks : IDisposable
{
    private readonly Image _image = new(BenchScene.Width, BenchScene.Height);
    private readonly Bitmap _bitmap = new(BenchScene.Width, BenchScene.Height);
    private readonly Renderer _renderer = new() { MaxDegreeOfParallelism = 2 };
    private readonly IPixelSampler _sampler = new JitteredSampler(16, 1);

    /// <summary>Frees the bitmap.</summary>
    [GlobalCleanup]
    public void Dispose()
    {
        _bitmap.Dispose();
        GC.SuppressFinalize(this);
    }

    [Benchmark(Baseline = true)]
    public long IntoImage() => _renderer.Render(BenchScene.Scene, BenchScene.Camera, _sampler, _image).PrimaryRays;

    [Benchmark]
    public long IntoImageSharpBitmap() => _renderer.Render(BenchScene.Scene, BenchScene.Camera, _sampler, _bitmap).PrimaryRays;
}

/// <summary>
/// The same rendered 1920×1080 picture (<see cref="PngSizes.Picture"/>) saved by the core's encoders and by
/// ImageSharp 2.1's: PNG at each one's defaults, and JPEG at quality 90 (the core: JpegLibrary, 4:4:4; ImageSharp: its
/// default 4:2:0 for colour at that quality), plus the copies between the two image types.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 2, iterationCount: 15)]
public class ImageSharpEncodeBenchmarks : IDisposable
{
    private Image _image = null!;
    private Bitmap _bitmap = null!;
    private readonly MemoryStream _stream = new();

    /// <summary>Frees the bitmap and the stream.</summary>
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
        _bitmap = _image.ToImageSharp();
    }

    [Benchmark(Baseline = true)]
    public long CorePng()
    {
        _stream.SetLength(0);
        _image.Save(_stream, ImageFormat.Png);
        return _stream.Length;
    }

    [Benchmark]
    public long ImageSharpPng()
    {
        _stream.SetLength(0);
        _bitmap.SaveAsPng(_stream, new PngEncoder());
        return _stream.Length;
    }

    [Benchmark]
    public long CoreJpeg90()
    {
        _stream.SetLength(0);
        _image.Save(_stream, ImageFormat.Jpeg, 90);
        return _stream.Length;
    }

    [Benchmark]
    public long ImageSharpJpeg90()
    {
        _stream.SetLength(0);
        _bitmap.SaveAsJpeg(_stream, new JpegEncoder { Quality = 90 });
        return _stream.Length;
    }

    [Benchmark]
    public int ToImageSharp()
    {
        using Bitmap copy = _image.ToImageSharp();
        return copy.Width;
    }

    [Benchmark]
    public int ToRayLabImage() => _bitmap.ToRayLabImage().Width;
}
