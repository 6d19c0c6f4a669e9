using System.Diagnostics;
using RayLab.Rendering;

namespace RayLab.Scaling;

/// <summary>
/// What waking the row loop's crew costs, without a render: the calling thread first sleeps, or keeps its core busy,
/// for a spell, then runs an empty loop on the crew (<see cref="WorkerCrew.TryRun"/>) that only records when each worker
/// starts. Worker 0, this thread, waits until every other worker has started, so none is skipped. Where the other
/// vCPUs sat idle through a busy spell (as the crew's do while one thread renders alone, or while the image's pages are
/// committed), a virtual machine must wake them, and their threads start late: the last worker's start is what a
/// render's rows lose at their beginning (the wall breakdown's "last worker starts").
/// </summary>
internal static class Wake
{
    private static readonly (string Spell, double Ms, bool Busy)[] Spells =
        [("both slept 5 ms", 5, false), ("this thread busy 1 ms", 1, true), ("this thread busy 5 ms", 5, true), ("this thread busy 20 ms", 20, true)];

    public static void Print(int[] threads, int rounds)
    {
        Console.WriteLine();
        Console.WriteLine($"## Waking the crew ({rounds} wakes per row, after 10 not counted)");
        Console.WriteLine();
        Console.WriteLine("| workers | before the wake | last worker starts, µs: median | 10th percentile | 90th percentile | mean start, µs: median |");
        Console.WriteLine("|---:|---|---:|---:|---:|---:|");
        foreach (int n in threads.Where(n => n > 1))
        {
            foreach ((string spell, double ms, bool busy) in Spells)
            {
                var last = new List<double>();
                var mean = new List<double>();
                for (int round = -10; round < rounds; round++)
                {
                    if (busy)
                    {
                        Spin(ms);
                    }
                    else
                    {
                        Thread.Sleep(TimeSpan.FromMilliseconds(ms));
                    }

                    (double lastUs, double meanUs) = Once(n);
                    if (round >= 0)
                    {
                        last.Add(lastUs);
                        mean.Add(meanUs);
                    }
                }

                last.Sort();
                Console.WriteLine($"| {n} | {spell} | {Profile.Median(last):F1} | {last[last.Count / 10]:F1} | {last[last.Count * 9 / 10]:F1} | {Profile.Median(mean):F1} |");
            }
        }
    }

    /// <summary>One wake of <paramref name="workers"/> − 1 crew threads: the last start and the mean start, in µs after the wake began.</summary>
    private static (double Last, double Mean) Once(int workers)
    {
        var started = new long[workers];
        int waiting = workers - 1;
        long begun = Stopwatch.GetTimestamp();
        bool ran = WorkerCrew.Shared.TryRun(workers, worker =>
        {
            if (worker != 0)
            {
                started[worker] = Stopwatch.GetTimestamp();
                Interlocked.Decrement(ref waiting);
                return;
            }

            var spin = new SpinWait();
            while (Volatile.Read(ref waiting) != 0)
            {
                spin.SpinOnce();
            }
        });
        if (!ran)
        {
            throw new InvalidOperationException("the crew is serving another loop");
        }

        double Us(long ticks) => (ticks - begun) * 1e6 / Stopwatch.Frequency;
        return (Us(started.Skip(1).Max()), started.Skip(1).Average(Us));
    }

    private static void Spin(double ms)
    {
        long end = Stopwatch.GetTimestamp() + (long)(ms * Stopwatch.Frequency / 1000);
        double x = 1;
        while (Stopwatch.GetTimestamp() < end)
        {
            x = Math.Sqrt(x + 1);
        }

        GC.KeepAlive(x);
    }
}
