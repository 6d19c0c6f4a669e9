using RayLab.Geometry;
using RayLab.Rendering;

namespace RayLab.Scaling;

/// <summary>
/// Where one render's time goes on one thread, medians over rounds: the set-up inside the render's clock before the
/// rows (preparation; for exact, the outlines, whose crossings are found in parallel), each band of the row loop,
/// the work after the rows; and outside the clock the hierarchy (built once per scene), the image's buffer and the
/// PNG encode. Each band is timed twice: in order (a thread that rendered the band above keeps its lines) and
/// scattered (it did not). Times are the rendering thread's CPU time, so that other processes on a shared machine
/// do not count, less one reading of that clock per band (<see cref="ThreadClock.ReadingTicks"/>).
/// </summary>
internal sealed class Profile
{
    public required double PreparationMs { get; init; }
    public required double ParallelPreparationMs { get; init; }
    public required double AfterMs { get; init; }
    public required double[] BandMs { get; init; }

    /// <summary>Bands per row: each row's pieces are consecutive bands, left to right.</summary>
    public int Pieces { get; init; } = 1;
    public required double[] ScatteredBandMs { get; init; }
    public required double HierarchyMs { get; init; }
    public required double BuffersMs { get; init; }
    public required double EncodeMs { get; init; }

    public double RowsMs => BandMs.Sum();

    /// <summary>
    /// A what-if: the same render with each band cut into <paramref name="pieces"/> bands of equal cost (in order, then
    /// the next band's: a row's bands stay consecutive), as a loop over smaller bands would schedule it if a band's
    /// cost were spread evenly along it.
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
            Pieces = Pieces * pieces,
            ScatteredBandMs = Cut(ScatteredBandMs),
            HierarchyMs = HierarchyMs,
            BuffersMs = BuffersMs,
            EncodeMs = EncodeMs,
        };
    }

    /// <summary>
    /// The same render with every band's time scaled so the rows' work is <paramref name="rowsMs"/>: what a cut of the
    /// rows gains from the schedule alone, with the machine's drift between profiles and the cut's own cost left out.
    /// </summary>
    public Profile WithRowsWork(double rowsMs)
    {
        double scale = rowsMs / RowsMs;
        return new Profile
        {
            PreparationMs = PreparationMs,
            ParallelPreparationMs = ParallelPreparationMs,
            AfterMs = AfterMs,
            BandMs = [.. BandMs.Select(ms => ms * scale)],
            Pieces = Pieces,
            ScatteredBandMs = [.. ScatteredBandMs.Select(ms => ms * scale)],
            HierarchyMs = HierarchyMs,
            BuffersMs = BuffersMs,
            EncodeMs = EncodeMs,
        };
    }

    /// <summary>
    /// The profiles of case <paramref name="c"/>, one for each count of pieces in <paramref name="pieces"/> that the
    /// adaptive renderer cuts its rows into (0: its own choice), their renders taken in the same rounds, so that the
    /// machine's speed drifting between rounds does not read as a difference between the cuts.
    /// </summary>
    public static Dictionary<int, Profile> Take(Case c, int rounds, int[] pieces)
    {
        Scene scene = c.Description.Scene;
        double hierarchy = Median(rounds, () => Time(() => SphereHierarchy.Build(scene.Spheres)));
        Renderer[] renderers = [.. pieces.Select(p => new Renderer { MaxDegreeOfParallelism = 1, RowPieces = p })];
        Image image = c.Prepared.CreateImage();
        foreach (Renderer renderer in renderers)
        {
            c.Prepared.Render(renderer, image); // the JIT, the hierarchy, the pool's buffers
        }

        var traces = pieces.Select(_ => (InOrder: new List<RowLoopTrace>(), Scattered: new List<RowLoopTrace>())).ToArray();
        for (int r = 0; r < rounds; r++)
        {
            for (int i = 0; i < renderers.Length; i++)
            {
                foreach ((List<RowLoopTrace> list, bool scatter) in new[] { (traces[i].InOrder, false), (traces[i].Scattered, true) })
                {
                    var trace = new RowLoopTrace { Scattered = scatter, Clock = ThreadClock.Now, Frequency = ThreadClock.Frequency };
                    // The garbage of the renders before (their traces, a field's frame constants) is collected here,
                    // not inside the next render: the collection would land in the same render of every round (the
                    // renders allocate alike) and read as that cut's set-up.
                    GC.Collect();
                    GC.WaitForPendingFinalizers();
                    renderers[i].Trace = trace;
                    c.Prepared.Render(renderers[i], image);
                    renderers[i].Trace = null;
                    list.Add(trace);
                }
            }
        }

        double buffers = Median(rounds, () => Wall(() =>
        {
            var fresh = new Image(image.Width, image.Height);
            for (int y = 0; y < fresh.Height; y += 1)
            {
                fresh.GetRowSpan(y)[0] = default;
            }
        }));
        double encode = Median(rounds, () => Wall(() => image.Save(Stream.Null, ImageFormat.Png)));
        long reading = ThreadClock.ReadingTicks();
        double Band(RowLoopTrace t, int b) => Cpu(Math.Max(0, t.BandTicks[b] - reading));
        var profiles = new Dictionary<int, Profile>();
        for (int i = 0; i < pieces.Length; i++)
        {
            (List<RowLoopTrace> inOrder, List<RowLoopTrace> scattered) = traces[i];
            int bands = inOrder[0].BandTicks.Length;
            profiles[pieces[i]] = new Profile
            {
                Pieces = bands / c.Description.Height,
                PreparationMs = Median(inOrder.Select(t => Cpu(t.RowsStarted - t.Started))),
                // The set-up's part that runs in parallel, the exact outlines' search for crossing pairs, from the same
                // renders' steps (timed apart, the machine's speed between the two measurements would count as serial
                // work); gathering the crossings by row after it is serial.
                ParallelPreparationMs = Median(inOrder.Select(t => StepMs(t, "crossing pairs"))),
                AfterMs = Median(inOrder.Select(t => Cpu(t.Finished - t.RowsEnded))),
                BandMs = [.. Enumerable.Range(0, bands).Select(b => Median(inOrder.Select(t => Band(t, b))))],
                ScatteredBandMs = [.. Enumerable.Range(0, bands).Select(b => Median(scattered.Select(t => Band(t, b))))],
                HierarchyMs = scene.UsesHierarchy ? hierarchy : 0,
                BuffersMs = buffers,
                EncodeMs = encode,
            };
        }

        return profiles;
    }

    public void PrintPhases()
    {
        Console.WriteLine();
        Console.WriteLine("| phase (one thread, medians) | ms | in renderMs | scales |");
        Console.WriteLine("|---|---:|---|---|");
        Console.WriteLine($"| hierarchy (once per scene) | {HierarchyMs:F2} | no | – |");
        Console.WriteLine($"| preparation (set-up in the clock) | {PreparationMs:F2} | yes | {(ParallelPreparationMs > 0 ? $"{ParallelPreparationMs:F2} of it (the search for the outlines' crossings)" : "no")} |");
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
