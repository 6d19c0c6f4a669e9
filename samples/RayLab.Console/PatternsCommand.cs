using System.CommandLine;
using RayLab.Reports.Patterns;
using RayLab.Sampling;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary><c>raylab patterns [--sampler NAME …] [--samples N] [--seed S] --out DIR</c>.</summary>
public static class PatternsCommand
{
    /// <summary>Builds the command; its action runs <see cref="PatternsJob.Run"/> with these writers.</summary>
    /// <param name="stdout">Where the summary goes.</param>
    /// <param name="stderr">Where errors go.</param>
    /// <param name="cancellation">Cancels the run (Ctrl+C).</param>
    public static Command Create(TextWriter stdout, TextWriter stderr, CancellationToken cancellation = default)
    {
        var output = new Option<string>("--out") { Description = "The folder for the figures (PNG and SVG), patterns.csv and index.html (created if missing).", Required = true, HelpName = "DIR" };
        var sampler = new Option<string[]>("--sampler")
        {
            Description = $"A sampler to draw and measure; repeat the option for several. Default: all ({string.Join(", ", Samplers.Names)}).",
            HelpName = "NAME",
            AllowMultipleArgumentsPerToken = false,
        };
        var samples = new Option<int>("--samples") { Description = "Points per pixel in the pixel and block figures, 1 to 1024; a perfect square for regular, jittered and multijittered.", DefaultValueFactory = _ => 25, HelpName = "N" };
        var seed = new Option<uint>("--seed") { Description = "The samplers' seed, 0 to 4294967295: the same seed writes the same files.", DefaultValueFactory = _ => 1, HelpName = "S" };
        var patterns = new Command("patterns", "Draw the lab's sampling figures (Rys. 12, 13, the adaptive diagram) and measure each sampler's points: discrepancy, power spectrum, anisotropy, integration error and its slope; writes figures, patterns.csv and index.html.")
        {
            output, sampler, samples, seed,
        };
        patterns.SetAction(result =>
        {
            string[] names = result.GetValue(sampler) ?? [];
            int n = result.GetRequiredValue(samples);
            uint s = result.GetRequiredValue(seed);
            string folder = result.GetRequiredValue(output);
            return CommandExit.Run(stderr, () =>
            {
                PatternSampler[] chosen = [.. (names.Length == 0 ? Samplers.Names : names).Select(Resolve)];
                // Each sampler once, as compare's --samplers has it: a second would be drawn and measured again.
                if (chosen.GroupBy(c => c.Name).FirstOrDefault(g => g.Count() > 1) is { } twice)
                {
                    throw new UsageException($"--sampler: '{twice.Key}' appears twice");
                }

                if (n is < 1 or > 1024)
                {
                    throw new UsageException($"--samples: expected 1 to 1024, got {n}");
                }

                PatternSampler? grid = chosen.FirstOrDefault(c => c.SquaresOnly);
                if (grid is not null && Math.Sqrt(n) % 1 != 0)
                {
                    throw new UsageException($"--samples: {grid.Name} needs a perfect square (1, 4, 9, 16, 25, …), got {n}");
                }

                var command = new List<string> { "raylab patterns" };
                command.AddRange(names.Select(x => $"--sampler {x}"));
                command.Add($"--samples {n} --seed {s} --out {folder}");
                return PatternsJob.Run(new PatternsRequest(folder, chosen, n, s, Command: string.Join(' ', command)), stdout, stderr, cancellation);
            }, $"nothing written to {folder}", $"draw the patterns of {n} samples", cancellation);
        });
        return patterns;
    }

    private static PatternSampler Resolve(string name)
    {
        string? match = Samplers.Names.FirstOrDefault(n => string.Equals(n, name, StringComparison.OrdinalIgnoreCase));
        if (match is null)
        {
            throw new UsageException($"--sampler: unknown sampler '{name}'; expected one of: {string.Join(", ", Samplers.Names)}{Suggestions.DidYouMean(name, Samplers.Names)}");
        }

        return PatternSampler.BuiltIn(match);
    }
}
