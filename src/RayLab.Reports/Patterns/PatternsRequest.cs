using RayLab.Sampling;

namespace RayLab.Reports.Patterns;

/// <summary>A sampler for <c>raylab patterns</c>: its name and how to make it with N samples per pixel.</summary>
/// <param name="Name">The name in file names, legends and tables (letters, digits, '-').</param>
/// <param name="Create">Makes the sampler with N points per pixel and the given seed.</param>
/// <param name="SquaresOnly">True when the sampler takes perfect squares only (an n×n grid).</param>
public sealed record PatternSampler(string Name, Func<int, uint, IPixelSampler> Create, bool SquaresOnly = false)
{
    /// <summary>A built-in sampler by its name (<see cref="Samplers.Names"/>).</summary>
    /// <param name="name">The name.</param>
    public static PatternSampler BuiltIn(string name) =>
        new(name, (n, seed) => Samplers.Create(name, n, seed), name is "regular" or "jittered" or "multijittered");
}

/// <summary>What <c>raylab patterns</c> draws and measures.</summary>
/// <param name="OutputFolder">The folder for the figures, <c>patterns.csv</c> and <c>index.html</c>.</param>
/// <param name="Samplers">The samplers, in the order the figures show them.</param>
/// <param name="Samples">Points per pixel in the pixel and block figures (the lab's 25).</param>
/// <param name="Seed">The samplers' seed.</param>
/// <param name="SpectrumSamples">Points per pixel for the spectra (a square and a power of two suit every sampler).</param>
/// <param name="SpectrumRealisations">Pixels each spectrum averages over (≥ 1000 for Ulichney's measures).</param>
/// <param name="Measures">Realisations of the discrepancy and error measures.</param>
/// <param name="Command">The command line that made the report, shown in <c>index.html</c>.</param>
public sealed record PatternsRequest(
    string OutputFolder,
    IReadOnlyList<PatternSampler> Samplers,
    int Samples = 25,
    uint Seed = 1,
    int SpectrumSamples = 64,
    int SpectrumRealisations = 1024,
    PatternMeasureOptions? Measures = null,
    string Command = "raylab patterns");
