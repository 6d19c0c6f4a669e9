using System.Diagnostics.CodeAnalysis;
using System.Runtime.ExceptionServices;

namespace RayLab.Rendering;

/// <summary>
/// Background threads that the row loop wakes all at once, each on its own event, as pbrt-v4's thread pool wakes
/// its workers with one broadcast. The .NET thread pool wakes its threads one after another (a thread that finds
/// work asks for the next), so on 16 cores the last worker of a short render starts after 15 wake-ups in a row.
/// The crew serves one loop at a time; a loop that finds it busy (renders running side by side) gets
/// <see langword="false"/> and runs on the thread pool instead. The calling thread is always worker 0.
/// </summary>
internal sealed class WorkerCrew
{
    private Member[] _members = [];
    private int _busy;

    /// <summary>The process's crew.</summary>
    public static WorkerCrew Shared { get; } = new();

    /// <summary>Whether this runtime can start threads (not in the browser).</summary>
    public static bool Supported { get; } = !OperatingSystem.IsBrowser() && !OperatingSystem.IsWasi();

    /// <summary>
    /// Runs <paramref name="body"/> once as worker 0 on this thread and at most once as each worker 1 to
    /// <paramref name="workers"/> − 1 on the crew's threads, and returns when every started worker is done. A worker
    /// whose thread wakes after worker 0 has returned is skipped: <paramref name="body"/> must leave nothing undone
    /// when another worker does not run (the row loop's workers steal each other's rows). The first exception is
    /// rethrown here once every started worker is done.
    /// </summary>
    /// <returns><see langword="false"/>, having run nothing, when the crew is serving another loop.</returns>
    public bool TryRun(int workers, Action<int> body)
    {
        if (Interlocked.CompareExchange(ref _busy, 1, 0) != 0)
        {
            return false;
        }

        try
        {
            Member[] members = Grow(workers - 1);
            var job = new Job(body);
            for (int i = 0; i < workers - 1; i++)
            {
                members[i].Post(job, i + 1);
            }

            try
            {
                body(0);
            }
            catch (Exception e)
            {
                job.Fail(e);
            }

            job.Close();
            return true;
        }
        finally
        {
            Volatile.Write(ref _busy, 0);
        }
    }

    private Member[] Grow(int count)
    {
        Member[] members = _members;
        if (members.Length >= count)
        {
            return members;
        }

        // Only the loop that holds the crew grows it.
        members = [.. members, .. Enumerable.Range(members.Length, count - members.Length).Select(i => new Member(i + 1))];
        _members = members;
        return members;
    }

    /// <summary>One loop's work: the body, the workers inside it, whether worker 0 has closed it, the first error.</summary>
    [SuppressMessage("Design", "CA1001", Justification = "The last worker sets the event as worker 0 wakes: disposing it could race that Set. It holds no handle unless waited on for long, and the collector takes it.")]
    private sealed class Job(Action<int> body)
    {
        private const int Closed = 1 << 30;
        private readonly ManualResetEventSlim _left = new(false);
        private int _state; // Closed | the workers inside the body
        private Exception? _error;

        /// <summary>A crew thread runs the body as <paramref name="worker"/>, unless worker 0 has closed the job.</summary>
        public void Enter(int worker)
        {
            int state;
            do
            {
                state = Volatile.Read(ref _state);
                if ((state & Closed) != 0)
                {
                    return;
                }
            }
            while (Interlocked.CompareExchange(ref _state, state + 1, state) != state);

            try
            {
                body(worker);
            }
            catch (Exception e)
            {
                Fail(e);
            }

            if (Interlocked.Decrement(ref _state) == Closed)
            {
                _left.Set();
            }
        }

        public void Fail(Exception e) => Interlocked.CompareExchange(ref _error, e, null);

        /// <summary>Worker 0 is done: no worker enters any more; waits for those inside, then rethrows the first error.</summary>
        public void Close()
        {
            if (Interlocked.Add(ref _state, Closed) != Closed)
            {
                _left.Wait();
            }

            if (_error is not null)
            {
                ExceptionDispatchInfo.Throw(_error);
            }
        }
    }

    /// <summary>One crew thread: it sleeps on its own event until a job is posted to it.</summary>
    [SuppressMessage("Design", "CA1001", Justification = "A crew thread lives as long as the process.")]
    private sealed class Member
    {
        private readonly ManualResetEventSlim _wake = new(false);
        private Job? _job;
        private int _worker;

        public Member(int number) =>
            new Thread(Serve) { IsBackground = true, Name = $"RayLab row worker {number}" }.Start();

        public void Post(Job job, int worker)
        {
            _worker = worker;
            Volatile.Write(ref _job, job);
            _wake.Set();
        }

        private void Serve()
        {
            while (true)
            {
                _wake.Wait();
                _wake.Reset();
                // Each post is taken once: a thread that woke late finds either its new post or nothing.
                Job? job = Interlocked.Exchange(ref _job, null);
                job?.Enter(_worker);
            }
        }
    }
}
