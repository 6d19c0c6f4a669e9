using System.Globalization;
using RayLab.Rendering.Adaptive;
using RayLab.Scaling;

// Usage: raylab-scaling [--rounds R] [--threads 1,2] [--model 1,2,4,8,16] [--pieces P] [--cuts 2,4,8] [--wake W] [CASE ...]
// Per case: the phases of one render on one thread, the model's speed-up at each N (and the model of the loop before
// work stealing: Parallel.For over bands of 16 rows for adaptive, 1 for the others), and the speed-up measured here.
// The summary adds two what-ifs at the most threads: each band (a row, or an adaptive render's piece of a row) cut into
// 4 pieces of equal cost, and the rows' work divided evenly, so the cost of the band as the unit of work shows.
// Adaptive rows are modelled at each thread count cut as the renderer cuts them there (AdaptiveRenderer.Pieces), from a
// one-thread profile of that cut; --pieces P cuts them into P pieces (1: whole rows) at every thread count instead.
// --cuts 2,4,8 adds, for adaptive, the model at the most threads with rows cut into each of those counts (profiled in
// the same rounds), so the renderer's own choice can be weighed against others: as profiled, and with the cut's rows'
// work scaled to whole rows' (the schedule's gain alone).
// A CASE is one row of the issue's table: bench-jittered16, bench-jittered256, bench-adaptive, bench-guard, bench-exact,
// field-jittered16, field-adaptive, field-guard, field-exact; none: all but bench-jittered256.
// --wake W times waking the row loop's crew at each --threads count above 1, W wakes after each of four spells (Wake.cs),
// and renders nothing.
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
const string Usage = "usage: raylab-scaling [--rounds R] [--threads 1,2] [--model 1,2,4,8,16] [--pieces P] [--cuts 2,4,8] [--wake W] [CASE ...]\n"
    + "  CASE: SCENE-METHOD, SCENE bench or field, METHOD jittered16, jittered256, adaptive, guard or exact\n"
    + "  (none: every case but bench-jittered256)\n"
    + "  --wake W: time W wakes of the crew at each --threads count above 1, and render nothing";
int rounds = 5, pieces = 0, wakes = 0;
int[] measured = [1, 2], modelled = [1, 2, 4, 8, 16], cuts = [];
var names = new List<string>();
Case[] cases;
try
{
    for (int i = 0; i < args.Length; i++)
    {
        switch (args[i])
        {
            case "-h" or "--help": Console.WriteLine(Usage); return 0;
            case "--rounds": rounds = Positive(args, ++i, "--rounds")[0]; break;
            case "--threads": measured = Positive(args, ++i, "--threads"); break;
            case "--model": modelled = Positive(args, ++i, "--model"); break;
            case "--pieces": pieces = Positive(args, ++i, "--pieces")[0]; break;
            case "--cuts": cuts = Positive(args, ++i, "--cuts"); break;
            case "--wake": wakes = Positive(args, ++i, "--wake")[0]; break;
            case ['-', ..]: throw new ArgumentException($"{args[i]}: unknown option");
            default: names.Add(args[i]); break;
        }
    }

    if (wakes > 0)
    {
        Console.WriteLine($"# {Environment.ProcessorCount} processors; load average {File.ReadAllText("/proc/loadavg").Trim()}");
        Wake.Print(measured, wakes);
        return 0;
    }

    string root = Case.FindRoot();
    cases = [.. (names.Count == 0 ? [.. Case.Defaults] : names).Select(n => Case.Named(n, root))];
}
catch (Exception e) when (e is ArgumentException or IOException or InvalidOperationException)
{
    Console.Error.WriteLine($"raylab-scaling: error: {e.Message}");
    Console.Error.WriteLine(Usage);
    return 2;
}

Console.WriteLine($"# {Environment.ProcessorCount} processors, {rounds} rounds, adaptive rows in {(pieces == 0 ? "the renderer's pieces" : $"{pieces} pieces")}; load average {File.ReadAllText("/proc/loadavg").Trim()}");
var summary = new List<string>();
var poolSummary = new List<string>();
var cutSummary = new List<string>();
int[] all = [.. modelled.Union(measured).Order()];
foreach (Case c in cases)
{
    // The row loop's order for the case: ranges for adaptive (its rows reuse the row above), in order for the others.
    bool inOrder = c.Description.Sampler.Type != "adaptive";
    // Adaptive rows are cut into pieces on many threads: a profile for each cut the thread counts use, and each
    // thread count modelled with its own (the one-thread render, whole rows, the baseline of every speed-up).
    int PiecesAt(int threads) => inOrder ? 1 : pieces > 0 ? pieces : AdaptiveRenderer.Pieces(c.Description.Width, threads, c.Description.Scene.UsesHierarchy);
    Dictionary<int, Profile> profiles = Profile.Take(c, rounds, [.. all.Select(PiecesAt).Append(PiecesAt(1)).Concat(inOrder || cuts.Length == 0 ? [] : [.. cuts, 1]).Distinct().Order()]);
    Profile profile = profiles[PiecesAt(1)];
    Model ModelAt(int threads) => new(profiles[PiecesAt(threads)], inOrder);
    // The loop before work stealing: Parallel.For over bands of 16 rows for adaptive, of 1 row for the others.
    Model before = Model.Old(profile, inOrder ? 1 : 16);
    Console.WriteLine();
    Console.WriteLine($"## {c.Name}: {c.Description.Width}×{c.Description.Height}, {c.Description.Scene.Spheres.Count} spheres, {c.Description.Sampler.Type}{(c.Description.Sampler.Guard ? " --guard" : "")}");
    foreach ((int cutInto, Profile p) in profiles)
    {
        if (profiles.Count > 1)
        {
            Console.WriteLine();
            int[] at = [.. all.Where(n => PiecesAt(n) == cutInto)];
            Console.WriteLine($"Rows in {cutInto} piece{(cutInto == 1 ? "" : "s")} ({(at.Length == 0 ? "--cuts" : $"at {string.Join(", ", at)} threads")}):");
        }

        p.PrintPhases();
    }

    var walls = Measure.Interleaved(c, measured, rounds, pieces);
    Dictionary<int, double> times = walls.Where(p => p.Key.Loop == "crew").ToDictionary(p => p.Key.Threads, p => p.Value.Ms);
    Console.WriteLine();
    Console.WriteLine("| threads | model ms | model speed-up | model of the loop before | measured ms (median) | measured speed-up |");
    Console.WriteLine("|---:|---:|---:|---:|---:|---:|");
    double model1 = ModelAt(1).Predict(1), before1 = before.Predict(1), measured1 = times.GetValueOrDefault(1, double.NaN);
    var cells = new List<string>();
    foreach (int n in all)
    {
        double predicted = ModelAt(n).Predict(n);
        string m = times.TryGetValue(n, out double t) ? $"{t:F2} | {measured1 / t:F2}×" : "– | –";
        Console.WriteLine($"| {n} | {predicted:F2} | {model1 / predicted:F2}× | {before1 / before.Predict(n):F2}× | {m} |");
        cells.Add($"{model1 / predicted:F2}×");
    }

    // Where the measured wall time went, per source of threads (medians; ms).
    Console.WriteLine();
    Console.WriteLine("| threads from | threads | renderMs | set-up | last worker starts | rows | rows' work, all threads | work / work on 1 thread | idle at the end, mean | after | CPU, all threads | CPU / rows' work | set-up's steps |");
    Console.WriteLine("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|");
    foreach ((string loop, _) in Measure.Loops)
    {
        foreach (int n in measured)
        {
            (double ms, Wall w) = walls[(loop, n)];
            double work1 = walls[(loop, measured.Min())].Wall.Work;
            Console.WriteLine($"| {loop} | {n} | {ms:F2} | {w.SetUp:F2} | {w.LastStart:F3} | {w.Rows:F2} | {w.Work:F2} | {w.Work / work1:F2} | {w.IdleAtEnd:F3} | {w.After:F2} | {w.Cpu:F2} | {w.Cpu / w.Work:F2} | {w.StepsText} |");
        }
    }

    double pool1 = walls.GetValueOrDefault(("thread pool", 1)).Ms;
    poolSummary.Add($"| {c.Name} | {string.Join(" | ", measured.Select(n => $"{measured1 / walls[("crew", n)].Ms:F2}× / {pool1 / walls[("thread pool", n)].Ms:F2}×"))} |");

    int most = all[^1];
    // What the band as the unit of work costs at the most threads: the model with each band in 4 pieces of equal cost,
    // and the rows' work divided evenly (no unit at all).
    double cut = model1 / new Model(profiles[PiecesAt(most)].InPieces(4), inOrder).Predict(most);
    // And with whole rows at the most threads, where the renderer cuts them.
    string whole = PiecesAt(most) == 1 || !profiles.TryGetValue(1, out Profile? rows) ? "–" : $"{model1 / new Model(rows, inOrder).Predict(most):F2}×";
    double even = model1 / (model1 - profile.RowsMs + (profile.RowsMs / most) - profile.ParallelPreparationMs + (profile.ParallelPreparationMs / most));
    foreach (int cutInto in inOrder ? [] : cuts)
    {
        cutSummary.Add($"| {c.Name} | {cutInto} | {profiles[cutInto].RowsMs / profiles[1].RowsMs:F3} | {model1 / new Model(profiles[cutInto], inOrder).Predict(most):F2}× | {model1 / new Model(profiles[cutInto].WithRowsWork(profiles[1].RowsMs), inOrder).Predict(most):F2}× |");
    }

    summary.Add($"| {c.Name} | {model1:F1} | {string.Join(" | ", cells)} | {whole} | {cut:F2}× | {even:F2}× | {before1 / before.Predict(most):F2}× | {(times.TryGetValue(2, out double two) ? $"{measured1 / two:F2}×" : "–")} |");
}

Console.WriteLine();
Console.WriteLine($"| case | 1 thread, model ms (CPU) | {string.Join(" | ", all.Select(n => $"model {n}"))} | model {all[^1]}, whole rows | model {all[^1]}, bands in 4 pieces | {all[^1]}, rows' work divided evenly | loop before, model {all[^1]} | measured 2 |");
Console.WriteLine($"|---|---:|{string.Join("", all.Select(_ => "---:|"))}---:|---:|---:|---:|---:|");
summary.ForEach(Console.WriteLine);
if (cutSummary.Count != 0)
{
    Console.WriteLine();
    Console.WriteLine($"| case | rows cut into | rows' work / whole rows' | model {all[^1]} | model {all[^1]}, rows' work as whole rows' |");
    Console.WriteLine("|---|---:|---:|---:|---:|");
    cutSummary.ForEach(Console.WriteLine);
}

Console.WriteLine();
Console.WriteLine("Measured speed-up, the crew's threads / the thread pool's:");
Console.WriteLine();
Console.WriteLine($"| case | {string.Join(" | ", measured)} |");
Console.WriteLine($"|---|{string.Join("", measured.Select(_ => "---:|"))}");
poolSummary.ForEach(Console.WriteLine);
Console.WriteLine();
Console.WriteLine($"load average at the end: {File.ReadAllText("/proc/loadavg").Trim()}");
return 0;

// The comma-separated positive integers after option args[i - 1].
static int[] Positive(string[] args, int i, string option)
{
    if (i >= args.Length)
    {
        throw new ArgumentException($"{option}: expected a value");
    }

    int[] values = [.. args[i].Split(',').Select(v => int.TryParse(v, NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n > 0
        ? n
        : throw new ArgumentException($"{option} {args[i]}: expected positive whole numbers, separated by commas"))];
    return values;
}
