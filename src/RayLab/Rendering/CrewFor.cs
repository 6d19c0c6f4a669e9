using System.Runtime.ExceptionServices;

namespace RayLab.Rendering;

/// <summary>The body of a <see cref="CrewFor"/> loop: item <paramref name="item"/>, on worker <paramref name="worker"/>, with that worker's state.</summary>
/// <typeparam name="TLocal">One worker's state.</typeparam>
internal delegate void CrewForBody<TLocal>(int item, int worker, ref TLocal local);

/// <summary>
/// The one parallel loop, as pbrt-v4 has one ParallelFor: the items of a <see cref="BandSchedule"/> taken by its
/// workers, the crew's threads (<see cref="WorkerCrew"/>, all woken at once) or, where the crew is busy or threads
/// cannot start, the thread pool's. Each worker has its own state from start to finish; the row loop and the exact
/// outlines' crossing search run on it.
/// </summary>
internal static class CrewFor
{
    /// <summary>Whether the workers are the crew's threads (else the thread pool's), for the scaling tool to measure one against the other.</summary>
    internal static bool UseCrew { get; set; } = true;

    /// <summary>
    /// Runs <paramref name="body"/> for every item of <paramref name="schedule"/> on its workers, each with a state
    /// from <paramref name="start"/> that <paramref name="finish"/> receives on the worker's thread when it is done
    /// (workers finish side by side: <paramref name="finish"/> takes its own lock where it needs one). A
    /// worker stops taking items once another has thrown or <paramref name="token"/> is cancelled; the first exception
    /// is rethrown as it was thrown.
    /// </summary>
    /// <exception cref="OperationCanceledException"><paramref name="token"/> was cancelled.</exception>
    public static void Run<TLocal>(BandSchedule schedule, Func<TLocal> start, CrewForBody<TLocal> body, Action<TLocal> finish, CancellationToken token)
    {
        bool failed = false;

        void Work(int worker)
        {
            TLocal local = start();
            try
            {
                while (!token.IsCancellationRequested && !Volatile.Read(ref failed) && schedule.TryTake(worker, out int item))
                {
                    body(item, worker, ref local);
                }
            }
            catch
            {
                Volatile.Write(ref failed, true);
                throw;
            }
            finally
            {
                finish(local);
            }
        }

        int workers = schedule.WorkerCount;
        if (workers == 1)
        {
            Work(0);
        }
        else if (!(UseCrew && WorkerCrew.Supported && WorkerCrew.Shared.TryRun(workers, Work)))
        {
            try
            {
                Parallel.For(0, workers, new ParallelOptions { MaxDegreeOfParallelism = workers }, Work);
            }
            catch (AggregateException e) when (e.InnerExceptions.Count == 1)
            {
                // The body's own exception (a pixel method's point outside the pixel, say), not Parallel.For's wrapper.
                ExceptionDispatchInfo.Capture(e.InnerExceptions[0]).Throw();
            }
        }

        token.ThrowIfCancellationRequested();
    }
}
