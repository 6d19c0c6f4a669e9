using System.Runtime.InteropServices;

namespace RayLab.Rendering;

/// <summary>
/// Which band a <see cref="RowLoop"/> thread renders next, in one of two orders.
/// <list type="bullet">
/// <item><b>Ranges</b> (the constructor), for bands that cost less right after the band above on the same thread (the
/// adaptive renderer keeps its corner lines from one row to the next): work stealing over ranges, as TBB's and
/// Embree's schedulers split ranges. Worker w starts with the w-th of equal ranges of consecutive bands and takes its
/// bands from the front, one at a time; a worker whose range is empty steals the back half of the range with the most
/// bands left. A thread renders long runs of consecutive bands, and wherever the costly bands are, the threads finish
/// together: the last pieces stolen are single bands.</item>
/// <item><b>In order</b> (<see cref="InOrder"/>), for bands that cost the same on any thread: every worker takes the
/// next band of one shared count, as pbrt-v4's <c>ParallelFor</c> hands out chunks. The costly bands are taken when the
/// count reaches them, in the middle of the frame, and cheap ones fill in at the end; with ranges they are left for the
/// thieves, and the frame ends on them (the sphere field's horizon rows: up to 25 times a mean row).</item>
/// </list>
/// Each range, and the count, has a cache line to itself.
/// </summary>
internal sealed class BandSchedule
{
    private readonly Range[] _ranges;
    private readonly int _first;
    private readonly bool _scattered;
    private readonly int _group;
    private readonly int _bands;
    private readonly bool _inOrder;
    private Range _next;

    /// <summary>A schedule of bands <paramref name="first"/> to <paramref name="end"/> − 1 for <paramref name="workers"/> threads.</summary>
    /// <param name="first">The first band.</param>
    /// <param name="end">One past the last band.</param>
    /// <param name="workers">The threads that take bands, numbered 0 to <paramref name="workers"/> − 1.</param>
    /// <param name="scattered">For one worker only: the even rows of bands, then the odd ones, so no band follows the one above it (what a band costs on a thread that did not render the band above).</param>
    /// <param name="group">Bands per row, for <paramref name="scattered"/>: the band above a band is <paramref name="group"/> bands back.</param>
    public BandSchedule(int first, int end, int workers, bool scattered = false, int group = 1)
    {
        _first = first;
        _scattered = scattered;
        _group = group;
        _ranges = new Range[workers];
        int bands = end - first;
        _bands = bands;
        for (int w = 0; w < workers; w++)
        {
            _ranges[w].State = Pack((int)((long)bands * w / workers), (int)((long)bands * (w + 1) / workers));
        }
    }

    private BandSchedule(int first, int end, int workers, bool inOrder, bool scattered)
        : this(first, end, workers, scattered) => _inOrder = inOrder;

    /// <summary>A schedule of bands <paramref name="first"/> to <paramref name="end"/> − 1 for <paramref name="workers"/> threads, each taking the next band of one shared count.</summary>
    /// <param name="first">The first band.</param>
    /// <param name="end">One past the last band.</param>
    /// <param name="workers">The threads that take bands, numbered 0 to <paramref name="workers"/> − 1.</param>
    public static BandSchedule InOrder(int first, int end, int workers) => new(first, end, workers, inOrder: true, scattered: false);

    /// <summary>The workers, numbered 0 to <see cref="WorkerCount"/> − 1.</summary>
    public int WorkerCount => _ranges.Length;

    /// <summary>The threads a loop of <paramref name="bands"/> bands uses at most <paramref name="maxDegreeOfParallelism"/> wide (−1: the processor count).</summary>
    public static int Workers(int bands, int maxDegreeOfParallelism) =>
        Math.Max(1, Math.Min(bands, maxDegreeOfParallelism == -1 ? Environment.ProcessorCount : maxDegreeOfParallelism));

    /// <summary>The next band for worker <paramref name="worker"/>: in order, the count's next; else the front of its range, or the back half of the fullest range stolen. False when no band is left.</summary>
    public bool TryTake(int worker, out int band)
    {
        if (_inOrder)
        {
            long next = Interlocked.Increment(ref _next.State) - 1;
            band = next < _bands ? _first + (int)next : 0;
            return next < _bands;
        }

        ref long own = ref _ranges[worker].State;
        while (true)
        {
            long state = Volatile.Read(ref own);
            (int lo, int hi) = Unpack(state);
            if (lo >= hi)
            {
                break;
            }

            if (Interlocked.CompareExchange(ref own, Pack(lo + 1, hi), state) == state)
            {
                band = _first + (_scattered ? Scatter(lo, hi, _group) : lo);
                return true;
            }
        }

        while (true)
        {
            int victim = -1, most = 0;
            long seen = 0;
            for (int v = 0; v < _ranges.Length; v++)
            {
                long state = Volatile.Read(ref _ranges[v].State);
                (int lo, int hi) = Unpack(state);
                if (hi - lo > most)
                {
                    (victim, most, seen) = (v, hi - lo, state);
                }
            }

            if (victim < 0)
            {
                band = 0;
                return false;
            }

            (int vlo, int vhi) = Unpack(seen);
            int mid = vlo + ((vhi - vlo) / 2);
            if (Interlocked.CompareExchange(ref _ranges[victim].State, Pack(vlo, mid), seen) == seen)
            {
                // Only this worker writes its own empty range; thieves skip it until then.
                Volatile.Write(ref own, Pack(mid + 1, vhi));
                band = _first + mid;
                return true;
            }
        }
    }

    /// <summary>
    /// The scattered order's band for the <paramref name="lo"/>-th take of <paramref name="hi"/>, in rows of
    /// <paramref name="group"/> bands: the even rows' bands, then the odd rows'.
    /// </summary>
    private static int Scatter(int lo, int hi, int group)
    {
        int half = ((hi / group) + 1) / 2, row = lo / group, within = lo % group;
        return ((row < half ? 2 * row : (2 * (row - half)) + 1) * group) + within;
    }

    private static long Pack(int lo, int hi) => ((long)lo << 32) | (uint)hi;

    private static (int Lo, int Hi) Unpack(long state) => ((int)(state >> 32), (int)state);

    /// <summary>A worker's range [lo, hi) of bands not yet taken, packed in one word (or the shared count), alone on its cache line (128 bytes either side, for CPUs that fetch lines in pairs).</summary>
    [StructLayout(LayoutKind.Explicit, Size = 256)]
    private struct Range
    {
        [FieldOffset(128)]
        public long State;
    }
}
