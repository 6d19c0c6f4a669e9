using System.IO.Compression;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;
using RayLab.Imaging;

namespace RayLab.Benchmarks;

/// <summary>
/// The PNG encoder's speed on 1 and 2 threads: the rendered 1920×1080 two-sphere picture (6.2 MB of RGB), the
/// default filter (Up) and level (Optimal), as <c>raylab render</c> writes it. The MB/s column is raw RGB megabytes
/// (10^6 bytes) per second of the mean time.
/// </summary>
[Config(typeof(Config))]
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 15)]
public class PngThreadBenchmarks : IDisposable
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

    [Params(1, 2)]
    public int Threads { get; set; }

    [GlobalSetup]
    public void Setup() => _image = PngSizes.Picture();

    [Benchmark]
    public long Encode()
    {
        _stream.SetLength(0);
        PngEncoder.Write(_stream, _image, CompressionLevel.Optimal, PngFilter.Up, Threads);
        return _stream.Length;
    }

    private sealed class Config : ManualConfig
    {
        public Config() => AddColumn(new MegabytesPerSecond());
    }

    /// <summary>Raw RGB megabytes encoded per second of the mean time.</summary>
    private sealed class MegabytesPerSecond : IColumn
    {
        public string Id => nameof(MegabytesPerSecond);

        public string ColumnName => "MB/s";

        public bool AlwaysShow => true;

        public ColumnCategory Category => ColumnCategory.Custom;

        public int PriorityInCategory => 0;

        public bool IsNumeric => true;

        public UnitType UnitType => UnitType.Dimensionless;

        public string Legend => "Raw RGB megabytes (10^6 bytes) encoded per second of the mean time";

        public string GetValue(Summary summary, BenchmarkCase benchmarkCase) => GetValue(summary, benchmarkCase, SummaryStyle.Default);

        public string GetValue(Summary summary, BenchmarkCase benchmarkCase, SummaryStyle style)
        {
            double? meanNs = summary[benchmarkCase]?.ResultStatistics?.Mean;
            return meanNs is > 0 ? (BenchScene.Width * BenchScene.Height * 3 / (meanNs.Value / 1e9) / 1e6).ToString("F0", System.Globalization.CultureInfo.InvariantCulture) : "-";
        }

        public bool IsAvailable(Summary summary) => true;

        public bool IsDefault(Summary summary, BenchmarkCase benchmarkCase) => false;
    }
}
