using System.Globalization;
using RayLab.Scaling;

// Usage: raylab-scaling [--rounds R] [--threads 1,2] [--model 1,2,4,8,16] [--old K] [CASE ...]
// --old K models the loop before work stealing instead: Parallel.For over bands of K rows (16 was adaptive's, 1 the others').
// A CASE is one row of the issue's table: bench-jittered16, bench-jittered256, bench-adaptive, bench-guard, bench-exact,
// field-jittered16, field-adaptive, field-exact; none: all but bench-jittered256.
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
int rounds = 5;
int[] measured = [1, 2], modelled = [1, 2, 4, 8, 16];
int old = 0;
var names = new List<string>();
for (int i = 0; i < args.Length; i++)
{
    switch (args[i])
    {
        case "--rounds": rounds = int.Parse(args[++i]); break;
        case "--threads": measured = [.. args[++i].Split(',').Select(int.Parse)]; break;
        case "--model": modelled = [.. args[++i].Split(',').Select(int.Parse)]; break;
        case "--old": old = int.Parse(args[++i]); break;
        default: names.Add(args[i]); break;
    }
}

string root = Case.FindRoot();
Case[] cases = [.. (names.Count == 0 ? [.. Case.Defaults] : names).Select(n => Case.Named(n, root))];
Console.WriteLine($"# {Environment.ProcessorCount} processors, {rounds} rounds; load average {File.ReadAllText("/proc/loadavg").Trim()}");
var summary = new List<string>();
foreach (Case c in cases)
{
    Profile profile = Profile.Take(c, rounds);
    Model model = old > 0 ? Model.Old(profile, old) : new Model(profile);
    Console.WriteLine();
    Console.WriteLine($"## {c.Name}: {c.Description.Width}×{c.Description.Height}, {c.Description.Scene.Spheres.Count} spheres, {c.Description.Sampler.Type}");
    profile.PrintPhases();
    Dictionary<int, double> times = Measure.Interleaved(c, measured, rounds);
    Console.WriteLine();
    Console.WriteLine("| threads | model ms | model speed-up | measured ms (median) | measured speed-up |");
    Console.WriteLine("|---:|---:|---:|---:|---:|");
    double model1 = model.Predict(1), measured1 = times.GetValueOrDefault(1, double.NaN);
    var cells = new List<string>();
    foreach (int n in modelled.Union(measured).Order())
    {
        double predicted = model.Predict(n);
        string m = times.TryGetValue(n, out double t) ? $"{t:F2} | {measured1 / t:F2}×" : "– | –";
        Console.WriteLine($"| {n} | {predicted:F2} | {model1 / predicted:F2}× | {m} |");
        cells.Add($"{model1 / predicted:F2}×");
    }

    summary.Add($"| {c.Name} | {model1:F1} | {string.Join(" | ", cells)} | {(times.TryGetValue(2, out double two) ? $"{measured1 / two:F2}×" : "–")} |");
}

Console.WriteLine();
Console.WriteLine($"| case | 1 thread, model ms | {string.Join(" | ", modelled.Union(measured).Order().Select(n => $"model {n}"))} | measured 2 |");
Console.WriteLine($"|---|---:|{string.Join("", modelled.Union(measured).Select(_ => "---:|"))}---:|");
summary.ForEach(Console.WriteLine);
