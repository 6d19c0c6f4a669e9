namespace RayLab.Tests;

public class AllocationsTests
{
    [Fact]
    public void AnAllocationInOneRunOnlyIsNotCounted()
    {
        int runs = 0;
        object? kept = null;
        long allocated = Allocations.Of(() => kept = runs++ == 1 ? new byte[1000] : kept);
        Assert.Equal(3, runs);
        Assert.Equal(0, allocated);
    }

    [Fact]
    public void AnAllocationInEveryRunIsCounted()
    {
        object? kept = null;
        long allocated = Allocations.Of(() => kept = new byte[1000]);
        Assert.InRange(allocated, 1000, 2000);
        GC.KeepAlive(kept);
    }
}
