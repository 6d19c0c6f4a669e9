using System.Runtime.InteropServices;

namespace RayLab.Scaling;

/// <summary>The calling thread's CPU time in nanoseconds (Linux <c>clock_gettime(CLOCK_THREAD_CPUTIME_ID)</c>): what a band costs, without the time other processes took the core.</summary>
internal static partial class ThreadClock
{
    public const long Frequency = 1_000_000_000;

    private const int ThreadCpuTime = 3;

    public static long Now()
    {
        _ = GetTime(ThreadCpuTime, out TimeSpec t);
        return (t.Seconds * Frequency) + t.Nanoseconds;
    }

    /// <summary>
    /// What one reading of the clock costs, in its own ticks: the median gap between consecutive readings. A band's
    /// time, read before and after it, holds about one reading's cost, which the profile takes off (a profile of
    /// short bands, rows in eight pieces, would otherwise charge each a syscall).
    /// </summary>
    public static long ReadingTicks()
    {
        var gaps = new long[1001];
        for (int i = 0; i < gaps.Length; i++)
        {
            long a = Now();
            gaps[i] = Now() - a;
        }

        Array.Sort(gaps);
        return gaps[gaps.Length / 2];
    }

    [LibraryImport("libc", EntryPoint = "clock_gettime")]
    private static partial int GetTime(int clock, out TimeSpec time);

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }
}
