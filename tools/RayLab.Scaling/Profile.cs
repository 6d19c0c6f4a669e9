using RayLab.Geometry;
using RayLab.Rendering;

namespace RayLab.Scaling;

/// <summary>
/// Where one render's time goes on one thread, medians over rounds: the set-up inside the render's clock before the
/// rows (preparation; for exact, the outlines, whose crossings are found in parallel), each band of the row loop,
/// the work after the rows; and outside the clock the hierarchy (built once per scene), the image's buffer and the
/// PNG encode. Each band is timed twice: in order (a thread that rendered the band above keeps its lines) and
/// scattered (it did not). Times are the rendering thread's CPU time, so that other processes on a shared machine
/// do not count.
/// </summary>
internal sealed class Profile
{
    public required double PreparationMs { get; init; }
    public required double ParallelPreparationMs { get; init; }
    public required double AfterMs { get; init; }
    public required double[] BandMs { get; init; }
    public required double[] ScatteredBandMs { get; init; }
    public required double HierarchyMs { get; init; }
    public required double BuffersMs { get; init; }
    public required double EncodeMs { get; init; }

    public double RowsMs => BandMs.Sum();

    /// <summary>
    /// A what-if: the same render with each row cut into <paramref name="pieces"/> bands of equal cost (in order, then
    /// the next row's), as a loop over pieces of rows would schedule it if a row's cost were spread evenly along it.
    /// </summary>
    public Profile InPieces(int pieces)
    {
        double[] Cut(double[] rows) => [.. rows.SelectMany(ms => Enumerable.Repeat(ms / pieces, pieces))];
        return new Profile
        {
            PreparationMs = PreparationMs,
            ParallelPreparationMs = ParallelPreparationMs,
            AfterMs = AfterMs,
            BandMs = Cut(BandMs),
            ScatteredBandMs = Cut(ScatteredBandMs),
            HierarchyMs = HierarchyMs,
            BuffersMs = BuffersMs,
            EncodeMs = EncodeMs,
        };
    }

    public static Profile Take(Case c, int rounds)
    {
        Scene scene = c.Description.Scene;
        double hierarchy = Median(rounds, () => Time(() => SphereHierarchy.Build(scene.Spheres)));
        var renderer = new Renderer { MaxDegreeOfParallelism = 1 };
        Image image = c.Prepared.CreateImage();
        c.Prepared.Render(renderer, image); // the JIT, the hierarchy, the pool's buffers
        var inOrder = new List<RowLoopTrace>();
        var scattered = new List<RowLoopTrace>();
        for (int r = 0; r < rounds; r++)
        {
            foreach ((List<RowLoopTrace> list, bool scatter) in new[] { (inOrder, false), (scattered, true) })
            {
                var trace = new RowLoopTrace { Scattered = scatter, Clock = ThreadClock.Now, Frequency = ThreadClock.Frequency };
                renderer.Trace = trace;
                c.Prepared.Render(renderer, image);
                renderer.Trace = null;
                list.Add(trace);
            }
        }

        // The set-up's part that runs in parallel, the exact outlines' crossing search, from the same renders' steps
        // (timed apart, the machine's speed between the two measurements would count as serial work).
        double crossings = Median(inOrder.Select(t => StepMs(t, "crossings")));
        double buffers = Median(rounds, () => Wall(() =>
        {
            var fresh = new Image(image.Width, image.Height);
            for (int y = 0; y < fresh.Height; y += 1)
            {
                fresh.GetRowSpan(y)[0] = default;
            }
        }));
        double encode = Median(rounds, () => Wall(() => image.Save(Stream.Null, ImageFormat.Png)));
        int bands = inOrder[0].RowTicks.Length;
        return new Profile
        {
            PreparationMs = Median(inOrder.Select(t => Cpu(t.RowsStarted - t.Started))),
            ParallelPreparationMs = crossings,
            AfterMs = Median(inOrder.Select(t => Cpu(t.Finished - t.RowsEnded))),
            BandMs = [.. Enumerable.Range(0, bands).Select(b => Median(inOrder.Select(t => Cpu(t.RowTicks[b]))))],
            ScatteredBandMs = [.. Enumerable.Range(0, bands).Select(b => Median(scattered.Select(t => Cpu(t.RowTicks[b]))))],
            HierarchyMs = scene.UsesHierarchy ? hierarchy : 0,
            BuffersMs = buffers,
            EncodeMs = encode,
        };
    }

    public void PrintPhases()
    {
        Console.WriteLine();
        Console.WriteLine("| phase (one thread, medians) | ms | in renderMs | scales |");
        Console.WriteLine("|---|---:|---|---|");
        Console.WriteLine($"| hierarchy (once per scene) | {HierarchyMs:F2} | no | – |");
        Console.WriteLine($"| preparation (set-up in the clock) | {PreparationMs:F2} | yes | {(ParallelPreparationMs > 0 ? $"{ParallelPreparationMs:F2} of it (the outlines' crossings)" : "no")} |");
        Console.WriteLine($"| rows: {BandMs.Length}, one at a time | {RowsMs:F2} | yes | by the schedule |");
        Console.WriteLine($"| rows, every row scattered | {ScatteredBandMs.Sum():F2} | – | – |");
        Console.WriteLine($"| slowest row | {BandMs.Max():F3} | – | – |");
        Console.WriteLine($"| after the rows | {AfterMs:F2} | yes | no |");
        Console.WriteLine($"| buffers (a new image, its pages touched; wall) | {BuffersMs:F2} | no | – |");
        Console.WriteLine($"| PNG encode (wall, its own threads) | {EncodeMs:F2} | no | – |");
    }

    private static double Cpu(long ticks) => ticks * 1000.0 / ThreadClock.Frequency;

    /// <summary>The CPU time of set-up step <paramref name="step"/> in <paramref name="trace"/> (from the step before it, or the start), 0 where the render had none.</summary>
    private static double StepMs(RowLoopTrace trace, string step)
    {
        int i = trace.SetUpSteps.FindIndex(s => s.Step == step);
        return i < 0 ? 0 : Cpu(trace.SetUpSteps[i].Ended - (i == 0 ? trace.Started : trace.SetUpSteps[i - 1].Ended));
    }

    /// <summary>The calling thread's CPU time for <paramref name="action"/>.</summary>
    private static double Time(Action action)
    {
        long start = ThreadClock.Now();
        action();
        return Cpu(ThreadClock.Now() - start);
    }

    /// <summary>Wall-clock time (the PNG encoder's bands run on several threads).</summary>
    private static double Wall(Action action)
    {
        long start = System.Diagnostics.Stopwatch.GetTimestamp();
        action();
        return System.Diagnostics.Stopwatch.GetElapsedTime(start).TotalMilliseconds;
    }

    private static double Median(int rounds, Func<double> measure) => Median(Enumerable.Range(0, rounds).Select(_ => measure()));

    public static double Median(IEnumerable<double> values)
    {
        double[] sorted = [.. values.Order()];
        return sorted.Length % 2 == 1 ? sorted[sorted.Length / 2] : (sorted[(sorted.Length / 2) - 1] + sorted[sorted.Length / 2]) / 2;
    }
}
