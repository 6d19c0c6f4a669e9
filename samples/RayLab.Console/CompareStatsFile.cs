using System.Text.Json.Serialization;

namespace RayLab.Cli;

/// <summary>
/// What <c>raylab compare --stats</c> writes: the run's size and settings, and where its time went — each stage's
/// wall time (<c>stages</c>, in the order each first ran) and the whole run's (<c>totalS</c>, from the start of the
/// command to the report in place).
/// </summary>
public sealed record CompareStatsFile
{
    /// <summary>The scene file, as given.</summary>
    public required string Scene { get; init; }

    /// <summary>Image width in pixels.</summary>
    public int Width { get; init; }

    /// <summary>Image height in pixels.</summary>
    public int Height { get; init; }

    /// <summary>Render threads, or null for every core.</summary>
    public int? Threads { get; init; }

    /// <summary>The processor count the runtime sees.</summary>
    public int ProcessorCount { get; init; }

    /// <summary>How many settings were compared.</summary>
    public int Settings { get; init; }

    /// <summary>How each setting's time was taken.</summary>
    public required string TimeRule { get; init; }

    /// <summary>The device the renders ran on (<see cref="RenderDevice.Name"/>): <c>cpu</c>, <c>cuda: …</c>, <c>ilgpu-cpu</c>.</summary>
    public string Device { get; init; } = "cpu";

    /// <summary>The device's first launch (its kernels' compile and load), in ms, which no render's time includes; null on the CPU.</summary>
    public double? FirstLaunchMs { get; init; }

    /// <summary>The run's wall time in seconds, from the command's start to the report in place.</summary>
    public double TotalS { get; init; }

    /// <summary>The stages, in the order each first ran.</summary>
    public required IReadOnlyList<CompareStatsStage> Stages { get; init; }
}

/// <summary>One stage's line of <see cref="CompareStatsFile"/>.</summary>
/// <param name="Name">The stage, e.g. <c>renders</c>.</param>
/// <param name="Seconds">Its wall time over all its calls, in seconds.</param>
/// <param name="Calls">How many calls.</param>
public sealed record CompareStatsStage(string Name, double Seconds, int Calls);

/// <summary>The compare stats file's JSON, generated at compile time.</summary>
[JsonSourceGenerationOptions(GenerationMode = JsonSourceGenerationMode.Serialization, WriteIndented = true, PropertyNamingPolicy = JsonKnownNamingPolicy.CamelCase,
    DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull)]
[JsonSerializable(typeof(CompareStatsFile))]
internal sealed partial class CompareStatsJson : JsonSerializerContext;
