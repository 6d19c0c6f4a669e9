using RayLab.Rendering;

namespace RayLab.Tests.Rendering;

/// <summary>The row loop's schedule: each worker's own range in order, the back half of the fullest range stolen, every band once; or every band in order from one count.</summary>
public class BandScheduleTests
{
    private static List<int> TakeAll(BandSchedule schedule, int worker)
    {
        var taken = new List<int>();
        while (schedule.TryTake(worker, out int band))
        {
            taken.Add(band);
        }

        return taken;
    }

    [Fact]
    public void OneWorkerTakesEveryBandInOrder() => Assert.Equal([3, 4, 5, 6, 7, 8, 9], TakeAll(new BandSchedule(3, 10, 1), 0));

    [Fact]
    public void TheScatteredOrderNeverTakesABandRightAfterTheOneAboveIt() =>
        Assert.Equal([0, 2, 4, 6, 1, 3, 5], TakeAll(new BandSchedule(0, 7, 1, scattered: true), 0));

    [Fact]
    public void InRowsOfPiecesTheScatteredOrderTakesTheEvenRowsThenTheOddOnes() =>
        Assert.Equal([0, 1, 2, 6, 7, 8, 3, 4, 5, 9, 10, 11], TakeAll(new BandSchedule(0, 12, 1, scattered: true, group: 3), 0));

    [Fact]
    public void AWorkerWhoseRangeIsDoneStealsTheBackHalfOfTheFullestRange()
    {
        // Three workers over 12 bands: [0, 4), [4, 8), [8, 12).
        var schedule = new BandSchedule(0, 12, 3);
        Assert.True(schedule.TryTake(1, out int b));
        Assert.Equal(4, b);
        // Worker 2 renders its own range, then steals [2, 4) from worker 0 (4 left, the fullest; the lower half
        // stays), then [6, 8) from worker 1 (3 left), then [1, 2) from worker 0. Worker 0 then steals worker 1's last.
        var stolen = new List<int>();
        for (int i = 0; i < 9; i++)
        {
            Assert.True(schedule.TryTake(2, out b));
            stolen.Add(b);
        }

        Assert.Equal([8, 9, 10, 11, 2, 3, 6, 7, 1], stolen);
        Assert.Equal([0, 5], TakeAll(schedule, 0));
        Assert.Empty(TakeAll(schedule, 1));
        Assert.False(schedule.TryTake(2, out _));
    }

    [Fact]
    public void InOrderWhicheverWorkerAsksTakesTheNextBand()
    {
        var schedule = BandSchedule.InOrder(3, 9, 3);
        var taken = new List<(int Worker, int Band)>();
        foreach (int worker in new[] { 2, 2, 0, 1, 2, 0 })
        {
            Assert.True(schedule.TryTake(worker, out int band));
            taken.Add((worker, band));
        }

        Assert.Equal([(2, 3), (2, 4), (0, 5), (1, 6), (2, 7), (0, 8)], taken);
        Assert.False(schedule.TryTake(1, out _));
        Assert.False(schedule.TryTake(0, out _));
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void WorkersRacingForBandsTakeEachBandExactlyOnce(bool inOrder)
    {
        const int Bands = 200_000, Workers = 8;
        BandSchedule schedule = inOrder ? BandSchedule.InOrder(5, 5 + Bands, Workers) : new BandSchedule(5, 5 + Bands, Workers);
        using var start = new Barrier(Workers);
        var taken = new List<int>[Workers];
        Thread[] threads = [.. Enumerable.Range(0, Workers).Select(w => new Thread(() =>
        {
            start.SignalAndWait();
            taken[w] = TakeAll(schedule, w);
        }))];
        Array.ForEach(threads, t => t.Start());
        Array.ForEach(threads, t => t.Join());
        Assert.Equal(Enumerable.Range(5, Bands), taken.SelectMany(t => t).Order());
        Assert.All(taken, t => Assert.Equal(t.Count, t.Distinct().Count()));
    }
}
