using RayLab.Sampling;

namespace RayLab.Reports.Comparison;

/// <summary>The built-in settings a comparison renders, and the check that no two settings share image files.</summary>
public static class ComparePlan
{
    /// <summary>The samplers a comparison can render: every point sampler and <c>adaptive</c> (the exact one is the reference).</summary>
    public static IReadOnlyList<string> Compared { get; } = [.. Samplers.Names, "adaptive"];

    /// <summary>
    /// The built-in settings: each point sampler at each budget (a grid sampler at the nearest square below it, once
    /// per sample count), and for <c>adaptive</c> a line per contrast with a point per maximum depth, plus the guarded
    /// sampler at the smallest contrast.
    /// </summary>
    /// <param name="samplers">Names from <see cref="Compared"/>.</param>
    /// <param name="budgets">Samples per pixel for the point samplers, each ≥ 1.</param>
    /// <param name="maxDepths">The adaptive sampler's maximum depths.</param>
    /// <param name="contrasts">The adaptive sampler's contrasts; used only when <paramref name="samplers"/> has <c>adaptive</c>.</param>
    /// <param name="seed">The point samplers' seed.</param>
    /// <param name="notes">Receives a line for each budget a grid sampler runs differently or leaves out.</param>
    /// <returns>The settings, in rendering order.</returns>
    /// <exception cref="ArgumentException">A sampler is not one of <see cref="Compared"/>, or <c>adaptive</c> is asked for with no contrast.</exception>
    public static IReadOnlyList<CompareCase> BuiltIn(
        IReadOnlyList<string> samplers, IReadOnlyList<int> budgets, IReadOnlyList<int> maxDepths, IReadOnlyList<double> contrasts, uint seed, ICollection<string> notes)
    {
        ArgumentNullException.ThrowIfNull(samplers);
        ArgumentNullException.ThrowIfNull(budgets);
        ArgumentNullException.ThrowIfNull(maxDepths);
        ArgumentNullException.ThrowIfNull(contrasts);
        ArgumentNullException.ThrowIfNull(notes);
        if (samplers.FirstOrDefault(s => !Compared.Contains(s, StringComparer.Ordinal)) is { } unknown)
        {
            throw new ArgumentException($"'{unknown}' is not one of {string.Join(", ", Compared)}", nameof(samplers));
        }

        var cases = new List<CompareCase>();
        foreach (string name in samplers.Where(s => s != "adaptive"))
        {
            AddPointCases(cases, name, budgets, seed, notes);
        }

        if (samplers.Contains("adaptive"))
        {
            AddAdaptiveCases(cases, maxDepths, contrasts);
        }

        return cases;
    }

    /// <summary>One setting per budget of a point sampler; a grid sampler runs the largest n×n within each budget, once per n.</summary>
    private static void AddPointCases(List<CompareCase> cases, string name, IReadOnlyList<int> budgets, uint seed, ICollection<string> notes)
    {
        bool grid = Samplers.Create(name, 1, seed) is GridSampler;
        var seen = new Dictionary<int, int>();
        foreach (int budget in budgets)
        {
            ArgumentOutOfRangeException.ThrowIfLessThan(budget, 1, nameof(budgets));
            int spp = grid ? (int)Math.Pow(Math.Floor(Math.Sqrt(budget)), 2) : budget;
            if (seen.TryGetValue(spp, out int earlier))
            {
                notes.Add($"{name}: budget {budget} would be {spp} samples (an n×n grid), as budget {earlier} is; left out.");
                continue;
            }

            seen[spp] = budget;
            if (spp != budget)
            {
                notes.Add($"{name}: budget {budget} runs as {spp} samples (an n×n grid needs a perfect square).");
            }

            cases.Add(CompareCase.Sampled(Samplers.Create(name, spp, seed), budget));
        }
    }

    /// <summary>The lab's rule at every contrast and depth, then the guarded sampler at the smallest contrast.</summary>
    private static void AddAdaptiveCases(List<CompareCase> cases, IReadOnlyList<int> maxDepths, IReadOnlyList<double> contrasts)
    {
        if (contrasts.Count == 0)
        {
            throw new ArgumentException("adaptive needs at least one contrast", nameof(contrasts));
        }

        foreach (double contrast in contrasts)
        {
            foreach (int depth in maxDepths)
            {
                cases.Add(CompareCase.Adaptive(new AdaptiveSampler(0, depth, contrast)));
            }
        }

        double finest = contrasts.Min();
        foreach (int depth in maxDepths)
        {
            cases.Add(CompareCase.Adaptive(new AdaptiveSampler(0, depth, finest, guard: true)));
        }
    }

    /// <summary>The first <see cref="CompareCase.FileStem"/> two settings share (they would write one image), or null.</summary>
    /// <param name="cases">The settings.</param>
    public static string? SharedFileStem(IEnumerable<CompareCase> cases)
    {
        ArgumentNullException.ThrowIfNull(cases);
        return cases.GroupBy(c => c.FileStem).FirstOrDefault(g => g.Count() > 1)?.Key;
    }
}
