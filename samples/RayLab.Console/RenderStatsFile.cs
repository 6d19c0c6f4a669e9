using System.Text.Json.Serialization;

namespace RayLab.Cli;

/// <summary>
/// What <c>raylab render --stats</c> writes: the render's settings and counts, and its times — <c>renderMs</c> the
/// render loop alone, <c>warmupMs</c> the warm-up render and <c>commitMs</c> the image's memory first touched (both
/// only with <c>--warmup</c>), <c>encodeMs</c> the image file. Fields that do not apply to the sampler are left out.
/// </summary>
public sealed record RenderStatsFile
{
    /// <summary>The scene file, as given.</summary>
    public required string Scene { get; init; }

    /// <summary>The image file, as given.</summary>
    public required string Output { get; init; }

    /// <summary>Image width in pixels.</summary>
    public int Width { get; init; }

    /// <summary>Image height in pixels.</summary>
    public int Height { get; init; }

    /// <summary>The camera's name (orthographic or perspective).</summary>
    public required string Camera { get; init; }

    /// <summary>The sampler's name.</summary>
    public required string Sampler { get; init; }

    /// <summary>Samples per pixel (0 for the adaptive sampler and the exact reference).</summary>
    public int SamplesPerPixel { get; init; }

    /// <summary>The sampler's seed (0 where none is used).</summary>
    public uint Seed { get; init; }

    /// <summary>Adaptive: the minimum depth.</summary>
    public int? MinDepth { get; init; }

    /// <summary>Adaptive: the maximum depth.</summary>
    public int? MaxDepth { get; init; }

    /// <summary>Adaptive: the contrast threshold.</summary>
    public double? Contrast { get; init; }

    /// <summary>Adaptive: whether every pixel's centre is traced.</summary>
    public bool? Quincunx { get; init; }

    /// <summary>Adaptive: whether the silhouette guard is on.</summary>
    public bool? Guard { get; init; }

    /// <summary>Primary rays traced per pixel.</summary>
    public double RaysPerPixel { get; init; }

    /// <summary>Render threads.</summary>
    public int Threads { get; init; }

    /// <summary>Primary rays traced.</summary>
    public long Rays { get; init; }

    /// <summary>The render loop's wall time in milliseconds (not start-up, loading, warm-up or encoding).</summary>
    public double RenderMs { get; init; }

    /// <summary>The warm-up render (<c>--warmup</c>) in milliseconds; absent without it.</summary>
    public double? WarmupMs { get; init; }

    /// <summary>
    /// Committing the image's memory before the render (<c>--warmup</c>), in milliseconds: its pages first touched, on
    /// every render thread (the render's clock starts after it, as the native anchors' does after they zero their
    /// buffer); absent without <c>--warmup</c>, when the render pays for them.
    /// </summary>
    public double? CommitMs { get; init; }

    /// <summary>Writing the image file, in milliseconds.</summary>
    public double EncodeMs { get; init; }

    /// <summary>The render loop that ran (scalar, vector128, vector256, vector512).</summary>
    public required string Kernel { get; init; }

    /// <summary>Samples the float packets handed to the double loop.</summary>
    public long RetracedSamples { get; init; }

    /// <summary>Why the render fell back to the double loop, if it did.</summary>
    public string? ScalarReason { get; init; }

    /// <summary>The device that rendered: "cpu", or the GPU's name (<c>--device</c>).</summary>
    public string Device { get; init; } = "cpu";
}

/// <summary>The stats file's JSON, generated at compile time (no reflection, so the native build can write it; the serializing code alone, without the metadata that reading would need).</summary>
[JsonSourceGenerationOptions(GenerationMode = JsonSourceGenerationMode.Serialization, WriteIndented = true, PropertyNamingPolicy = JsonKnownNamingPolicy.CamelCase,
    DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull)]
[JsonSerializable(typeof(RenderStatsFile))]
internal sealed partial class RenderStatsJson : JsonSerializerContext;
