using System.Collections.Concurrent;

namespace RayLab.Grading.Tests;

/// <summary>
/// <see cref="SideBySide"/>, the loop that <c>raylab grade --jobs N</c> builds and checks submissions in: every item
/// once, N at a time; after a failure or Ctrl+C nothing new starts and the running items are told to stop. Each test
/// waits on gates the items open, never on a clock (the minute is only there so that a broken loop fails instead of
/// hanging).
/// </summary>
public sealed class SideBySideTests
{
    private static readonly TimeSpan Gate = TimeSpan.FromMinutes(1);

    [Theory]
    [InlineData(1)]
    [InlineData(3)]
    public void EveryItemRunsOnceAndJobsItemsRunAtOnce(int jobs)
    {
        // The first `jobs` items wait until all of them are inside: the loop must run that many at once, or they never meet.
        const int count = 20;
        var runs = new int[count];
        int inside = 0, most = 0;
        using var met = new CountdownEvent(jobs);
        SideBySide.Run(count, jobs, (i, _) =>
        {
            int now = Interlocked.Increment(ref inside);
            InterlockedMax(ref most, now);
            Interlocked.Increment(ref runs[i]);
            if (i < jobs)
            {
                met.Signal();
                Assert.True(met.Wait(Gate, CancellationToken.None), $"item {i}: the first {jobs} items did not run at once");
            }

            Interlocked.Decrement(ref inside);
        }, TestContext.Current.CancellationToken);

        Assert.All(runs, r => Assert.Equal(1, r));
        Assert.Equal(jobs, most);
    }

    [Fact]
    public void AfterAFailureNoItemStartsAndTheRunningOneIsStopped()
    {
        // Item 0 fails while item 1 is running (a build in progress): item 1's token is cancelled, and although it then
        // returns normally its thread starts no item after it; item 0's exception comes out as it was thrown, not wrapped.
        var started = new ConcurrentBag<int>();
        bool stopped = false;
        using var running = new ManualResetEventSlim();
        var thrown = Assert.Throws<InvalidOperationException>(() => SideBySide.Run(10, 2, (i, stop) =>
        {
            started.Add(i);
            if (i == 0)
            {
                Assert.True(running.Wait(Gate, CancellationToken.None), "item 1 never started");
                throw new InvalidOperationException("disk full");
            }

            if (i == 1)
            {
                running.Set();
                stopped = stop.WaitHandle.WaitOne(Gate);
            }
        }, TestContext.Current.CancellationToken));

        Assert.Equal("disk full", thrown.Message);
        Assert.True(stopped, "the running item's token was not cancelled");
        Assert.Equal([0, 1], started.Order());
    }

    [Fact]
    public void OneJobStopsAtTheFirstFailure()
    {
        var started = new List<int>();
        Assert.Throws<IOException>(() => SideBySide.Run(10, 1, (i, _) =>
        {
            started.Add(i);
            if (i == 3)
            {
                throw new IOException("no space left on device");
            }
        }, TestContext.Current.CancellationToken));

        Assert.Equal([0, 1, 2, 3], started);
    }

    [Fact]
    public void CtrlCStopsTheRunningItemsAndStartsNoMore()
    {
        // Both running items see the cancellation; however they end (one returns, one throws), the run ends cancelled.
        var started = new ConcurrentBag<int>();
        int stopped = 0;
        using var ctrlC = CancellationTokenSource.CreateLinkedTokenSource(TestContext.Current.CancellationToken);
        using var both = new CountdownEvent(2);
        Assert.ThrowsAny<OperationCanceledException>(() => SideBySide.Run(10, 2, (i, stop) =>
        {
            started.Add(i);
            both.Signal();
            if (i == 0)
            {
                Assert.True(both.Wait(Gate, CancellationToken.None), "item 1 never started");
                ctrlC.Cancel();
            }

            if (i < 2 && stop.WaitHandle.WaitOne(Gate))
            {
                Interlocked.Increment(ref stopped);
            }

            if (i == 1)
            {
                stop.ThrowIfCancellationRequested();
            }
        }, ctrlC.Token));

        Assert.Equal(2, stopped);
        Assert.Equal([0, 1], started.Order());
    }

    [Theory]
    [InlineData(-1, 1, "count")]
    [InlineData(1, 0, "jobs")]
    public void BadCountsNameTheirParameter(int count, int jobs, string name) =>
        Assert.Equal(name, Assert.Throws<ArgumentOutOfRangeException>(() => SideBySide.Run(count, jobs, (_, _) => { }, CancellationToken.None)).ParamName);

    private static void InterlockedMax(ref int most, int value)
    {
        int seen;
        while ((seen = Volatile.Read(ref most)) < value && Interlocked.CompareExchange(ref most, value, seen) != seen)
        {
        }
    }
}
