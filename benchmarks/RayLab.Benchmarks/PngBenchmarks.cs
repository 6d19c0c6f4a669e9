using System.IO.Compression;
using BenchmarkDotNet.Attributes;
using RayLab.Imaging;
using RayLab.Sampling;

namespace RayLab.Benchmarks;

/// <summary>PNG encoding of the rendered 1920×1080 two-sphere picture: each row filter at each DEFLATE level.</summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 1, iterationCount: 5)]
public class PngBenchmarks : IDisposable
{
    private Image _image = null!;
    private readonly MemoryStream _stream = new();

    /// <summary>Frees the encoder's output stream.</summary>
    [GlobalCleanup]
    public void Dispose()
    {
        _stream.Dispose();
        GC.SuppressFinalize(this);
    }

    /// <summary>The row filter, by name (the encoder's filter enum is internal).</summary>
    [Params(nameof(PngFilter.None), nameof(PngFilter.Sub), nameof(PngFilter.Up), nameof(PngFilter.Paeth), nameof(PngFilter.Adaptive))]
    public string FilterName { get; set; } = nameof(PngFilter.Up);

    private PngFilter Filter => Enum.Parse<PngFilter>(FilterName);

    [Params(CompressionLevel.Fastest, CompressionLevel.Optimal, CompressionLevel.SmallestSize)]
    public CompressionLevel Level { get; set; }

    [GlobalSetup]
    public void Setup() => _image = PngSizes.Picture();

    [Benchmark]
    public long Encode()
    {
        _stream.SetLength(0);
        PngEncoder.Write(_stream, _image, Level, Filter);
        return _stream.Length;
    }
}

/// <summary>The size each filter and level gives (BenchmarkDotNet measures time, not size).</summary>
public static class PngSizes
{
    /// <summary>The picture the PNG benchmarks encode: the two-sphere scene, 1920×1080, jittered 16 spp.</summary>
    public static Image Picture()
    {
        var image = new Image(BenchScene.Width, BenchScene.Height);
        new Renderer().Render(BenchScene.Scene, BenchScene.Camera, new JitteredSampler(16, 1), image);
        return image;
    }

    public static void Print(TextWriter output)
    {
        Image image = Picture();
        output.WriteLine("| filter | Fastest | Optimal | SmallestSize |");
        output.WriteLine("|---|---:|---:|---:|");
        foreach (PngFilter filter in new[] { PngFilter.None, PngFilter.Sub, PngFilter.Up, PngFilter.Average, PngFilter.Paeth, PngFilter.Adaptive })
        {
            var sizes = new List<string>();
            foreach (CompressionLevel level in new[] { CompressionLevel.Fastest, CompressionLevel.Optimal, CompressionLevel.SmallestSize })
            {
                using var stream = new MemoryStream();
                PngEncoder.Write(stream, image, level, filter);
                sizes.Add($"{stream.Length / 1024.0:F1} KiB");
            }

            output.WriteLine($"| {filter} | {string.Join(" | ", sizes)} |");
        }

        output.WriteLine($"\nRaw RGB: {image.PixelBytes.Length / 1024.0:F0} KiB.");
    }
}
