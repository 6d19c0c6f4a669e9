using System.Runtime.ExceptionServices;

namespace RayLab.Grading;

/// <summary>
/// Long jobs run a few at a time, each on a thread of its own: <c>raylab grade</c> builds and checks submissions this
/// way. Its jobs wait minutes on child processes; on the thread pool they would hold the threads that read those
/// children's output.
/// </summary>
internal static class SideBySide
{
    /// <summary>
    /// Runs <paramref name="body"/> for items 0 to <paramref name="count"/> − 1 in that order, at most
    /// <paramref name="jobs"/> at a time. After the first exception no item starts, the token the running bodies got
    /// is cancelled (so that they stop their children), and once they have returned the exception is rethrown as it
    /// was thrown. When <paramref name="cancellation"/> is cancelled the same happens, and an
    /// <see cref="OperationCanceledException"/> is thrown.
    /// </summary>
    /// <param name="count">How many items; 0 runs nothing.</param>
    /// <param name="jobs">How many items at most run at once, at least 1; 1 runs them on the calling thread.</param>
    /// <param name="body">One item's work: its index, and a token cancelled when the other items fail or the run is cancelled.</param>
    /// <param name="cancellation">Stops the run.</param>
    public static void Run(int count, int jobs, Action<int, CancellationToken> body, CancellationToken cancellation)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(count);
        ArgumentOutOfRangeException.ThrowIfLessThan(jobs, 1);
        ArgumentNullException.ThrowIfNull(body);
        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellation);
        int next = -1;
        ExceptionDispatchInfo? failure = null;
        void Work()
        {
            try
            {
                int i;
                while (!stop.IsCancellationRequested && (i = Interlocked.Increment(ref next)) < count)
                {
                    body(i, stop.Token);
                }
            }
            catch (Exception e)
            {
                if (Interlocked.CompareExchange(ref failure, ExceptionDispatchInfo.Capture(e), null) is null)
                {
                    stop.Cancel();
                }
            }
        }

        if (jobs == 1 || count <= 1)
        {
            Work();
        }
        else
        {
            Thread[] threads = [.. Enumerable.Range(0, Math.Min(jobs, count)).Select(j => new Thread(Work) { IsBackground = true, Name = $"raylab job {j + 1}" })];
            foreach (Thread thread in threads)
            {
                thread.Start();
            }

            foreach (Thread thread in threads)
            {
                thread.Join();
            }
        }

        cancellation.ThrowIfCancellationRequested();
        failure?.Throw();
    }
}
