namespace RayLab.Tests;

/// <summary>
/// The bytes this thread allocates in an action's steady state, as <see cref="GC.GetAllocatedBytesForCurrentThread"/>
/// counts them: the least of a few runs. A run can count work that happens once on a thread, not on every call (the
/// runtime loading a type or promoting a method while other tests run beside it: 7,992 bytes once, in a full parallel
/// run with 16 processors, for a sampler that allocates nothing); an allocation the action makes every time shows in
/// every run.
/// </summary>
internal static class Allocations
{
    /// <summary>The least bytes that one of <paramref name="runs"/> runs of <paramref name="action"/> allocates on this thread.</summary>
    public static long Of(Action action, int runs = 3)
    {
        long least = long.MaxValue;
        for (int run = 0; run < runs; run++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            action();
            least = Math.Min(least, GC.GetAllocatedBytesForCurrentThread() - before);
        }

        return least;
    }
}
