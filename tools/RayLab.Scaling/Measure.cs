using System.Diagnostics;
using RayLab.Rendering;

namespace RayLab.Scaling;

/// <summary>
/// Render times measured here, each thread count and each source of threads in turn, round by round, after a warm-up:
/// medians of <see cref="RenderStatistics.RenderTime"/>, and where the wall time of each render went (<see cref="Wall"/>).
/// </summary>
internal static class Measure
{
    /// <summary>The sources of the row loop's threads: the crew it wakes at once, and the .NET thread pool.</summary>
    public static readonly (string Name, bool Crew)[] Loops = [("crew", true), ("thread pool", false)];

    public static Dictionary<(string Loop, int Threads), (double Ms, Wall Wall)> Interleaved(Case c, int[] threads, int rounds, int pieces)
    {
        Renderer[] renderers = [.. threads.Select(n => new Renderer { MaxDegreeOfParallelism = n, RowPieces = pieces })];
        Image image = c.Prepared.CreateImage();
        var times = new Dictionary<(string, int), List<(double Ms, Wall Wall)>>();
        for (int round = -1; round < rounds; round++)
        {
            foreach ((string loop, bool crew) in Loops)
            {
                CrewFor.UseCrew = crew;
                for (int i = 0; i < threads.Length; i++)
                {
                    // One thread runs inline, on neither: it is rendered once and counts for every source.
                    if (threads[i] == 1 && loop != Loops[0].Name)
                    {
                        continue;
                    }

                    var trace = new RowLoopTrace();
                    renderers[i].Trace = trace;
                    TimeSpan cpu = Environment.CpuUsage.TotalTime;
                    double ms = c.Prepared.Render(renderers[i], image).RenderTime.TotalMilliseconds;
                    double cpuMs = (Environment.CpuUsage.TotalTime - cpu).TotalMilliseconds;
                    renderers[i].Trace = null;
                    if (round < 0) // round −1 warms up: the JIT, the threads, the pools
                    {
                        continue;
                    }

                    foreach ((string source, _) in threads[i] == 1 ? Loops : [(loop, crew)])
                    {
                        (times.TryGetValue((source, threads[i]), out var list) ? list : times[(source, threads[i])] = []).Add((ms, Wall.Of(trace, cpuMs)));
                    }
                }
            }
        }

        CrewFor.UseCrew = true;
        return times.ToDictionary(p => p.Key, p => (Profile.Median(p.Value.Select(v => v.Ms)), Wall.Median(p.Value.Select(v => v.Wall))));
    }
}

/// <summary>
/// Where one render's wall time went, in ms: the set-up before the rows, how long after the rows started the last
/// worker took its first row, the rows from first to last, the rows' summed time over all threads, the mean time a
/// worker sat idle between its last row and the end of the rows, the work after them, the set-up's steps, and the
/// process's CPU time over the render (<see cref="Environment.CpuUsage"/>, user and kernel): where that is well below
/// the rows' summed time, the threads' vCPUs were not running for part of their rows (another process, or the
/// hypervisor taking them), which no change to the loop can win back.
/// </summary>
internal readonly record struct Wall(double SetUp, double LastStart, double Rows, double Work, double IdleAtEnd, double After, (string Step, double Ms)[] Steps, double Cpu)
{
    /// <summary>The set-up's steps, each its own time: "outlines 0.61, crossings 3.20".</summary>
    public string StepsText => Steps.Length == 0 ? "–" : string.Join(", ", Steps.Select(s => $"{s.Step} {s.Ms:F2}"));

    public static Wall Of(RowLoopTrace t, double cpu)
    {
        double Ms(long ticks) => ticks * 1000.0 / Stopwatch.Frequency;
        int workers = t.BandWorker.Length == 0 ? 0 : t.BandWorker.Max() + 1;
        var first = Enumerable.Repeat(long.MaxValue, workers).ToArray();
        var last = new long[workers];
        for (int r = 0; r < t.BandTicks.Length; r++)
        {
            int w = t.BandWorker[r];
            first[w] = Math.Min(first[w], t.BandBegan[r]);
            last[w] = Math.Max(last[w], t.BandBegan[r] + t.BandTicks[r]);
        }

        long[] started = [.. first.Where(f => f != long.MaxValue)];
        long[] ended = [.. last.Where(l => l != 0)];
        return new Wall(
            Ms(t.RowsStarted - t.Started),
            started.Length == 0 ? 0 : Ms(started.Max() - t.RowsStarted),
            Ms(t.RowsEnded - t.RowsStarted),
            Ms(t.BandTicks.Sum()),
            ended.Length == 0 ? 0 : ended.Average(e => Ms(t.RowsEnded - e)),
            Ms(t.Finished - t.RowsEnded),
            [.. t.SetUpSteps.Select((s, i) => (s.Step, Ms(s.Ended - (i == 0 ? t.Started : t.SetUpSteps[i - 1].Ended))))],
            cpu);
    }

    public static Wall Median(IEnumerable<Wall> walls)
    {
        Wall[] all = [.. walls];
        return new Wall(
            Profile.Median(all.Select(w => w.SetUp)),
            Profile.Median(all.Select(w => w.LastStart)),
            Profile.Median(all.Select(w => w.Rows)),
            Profile.Median(all.Select(w => w.Work)),
            Profile.Median(all.Select(w => w.IdleAtEnd)),
            Profile.Median(all.Select(w => w.After)),
            [.. all[0].Steps.Select((s, i) => (s.Step, Profile.Median(all.Select(w => w.Steps[i].Ms))))],
            Profile.Median(all.Select(w => w.Cpu)));
    }
}
