using System.Diagnostics;

namespace RayLab.Rendering;

/// <summary>
/// A renderer as <see cref="RowLoop"/> sees it: a scratch for each thread, and one row (or one piece of a row) at a
/// time. A row's pixels must depend only on the row, never on which thread or scratch renders it, so the bytes are the
/// same whatever the thread count.
/// </summary>
/// <typeparam name="TScratch">One thread's working space.</typeparam>
internal interface IRowRenderer<TScratch>
{
    /// <summary>A thread's scratch, new or kept from an earlier render.</summary>
    TScratch Rent();

    /// <summary>Renders row <paramref name="row"/> (0 at the top) with this thread's scratch.</summary>
    void RenderRow(int row, ref TScratch scratch);

    /// <summary>A thread is done: adds its counts to <paramref name="totals"/> (under the loop's lock) and keeps its scratch for reuse.</summary>
    void Return(TScratch scratch, ref RowTotals totals)
    {
    }

    /// <summary>
    /// Whether a row costs less on the thread that rendered the row above it just before (the adaptive renderer keeps
    /// its corner lines): the loop then gives each thread runs of consecutive rows, else the rows in order.
    /// </summary>
    bool ReusesRowAbove => false;

    /// <summary>
    /// How many pieces, left to right, each row is cut into as units of work (1: whole rows). A renderer whose rows
    /// may cost many times a mean row cuts them, so that the last unit a thread takes is short and the threads finish
    /// together.
    /// </summary>
    int PiecesPerRow => 1;

    /// <summary>Renders piece <paramref name="piece"/> (0 at the left) of row <paramref name="row"/>; with one piece a row, the row.</summary>
    void RenderPiece(int row, int piece, ref TScratch scratch) => RenderRow(row, ref scratch);
}

/// <summary>The scratch of a renderer that needs none.</summary>
internal readonly struct NoScratch;

/// <summary>What the threads of one render counted: rays traced beyond the renderer's fixed count, and samples traced again in double.</summary>
internal struct RowTotals
{
    /// <summary>Rays the threads traced.</summary>
    public long Rays;

    /// <summary>Samples whose float answer was uncertain and were traced again in double.</summary>
    public long Retraced;
}

/// <summary>
/// The one row loop every renderer runs on: it owns the clock, the threads (at most
/// <see cref="RenderOptions.MaxDegreeOfParallelism"/>), the row order, the progress count, the cancellation check
/// before each row, each thread's scratch and the <see cref="RenderStatistics"/>. A renderer supplies only "render
/// this row with this scratch" (<see cref="IRowRenderer{TScratch}"/>). Start the loop before the renderer's
/// per-frame set-up, so the set-up is timed too.
/// </summary>
internal readonly struct RowLoop
{
    private readonly RenderOptions _options;
    private readonly int _rows;
    private readonly long _started;

    private RowLoop(RenderOptions options, int rows)
    {
        _options = options;
        _rows = rows;
        (int first, int end) = options.Rows(rows);
        options.Progress?.Start(end - first);
        options.Trace?.Start();
        _started = Stopwatch.GetTimestamp();
    }

    /// <summary>Starts the clock and the progress count for a render of <paramref name="rows"/> rows.</summary>
    public static RowLoop Start(RenderOptions options, int rows) => new(options, rows);

    /// <summary>The threads the loop runs whole rows on: at most one a row of this render's band of rows.</summary>
    public int Threads
    {
        get
        {
            (int first, int end) = _options.Rows(_rows);
            return BandSchedule.Workers(Math.Max(0, end - first), _options.MaxDegreeOfParallelism);
        }
    }

    /// <summary>
    /// Renders every row, the token checked before each band, on <see cref="CrewFor"/> (<see cref="BandSchedule"/>). A
    /// band is a row, or where the renderer cuts rows (<see cref="IRowRenderer{TScratch}.PiecesPerRow"/>) one piece of
    /// a row, numbered row by row, each row's pieces left to right: a thread writes the image a row at a time, and the
    /// band P bands back is the same piece of the row above. Where a row reuses the row above
    /// (<see cref="IRowRenderer{TScratch}.ReusesRowAbove"/>) each thread renders a range of consecutive bands and
    /// steals half of the fullest range when its own is done; else each takes the next band in order. Either way the
    /// threads finish together wherever the costly rows are. A renderer's own exception is rethrown as it was thrown.
    /// </summary>
    /// <returns>What the threads counted.</returns>
    /// <exception cref="OperationCanceledException">The render was cancelled.</exception>
    public RowTotals Run<TScratch>(IRowRenderer<TScratch> renderer)
    {
        var totals = new RowTotals();
        var gate = new Lock();
        // The rows this render fills (all, or Renderer.RenderRows' band).
        (int start, int stop) = _options.Rows(_rows);
        stop = Math.Max(start, stop);
        RenderProgress? progress = _options.Progress;
        RowLoopTrace? trace = _options.Trace;
        int rows = stop - start, pieces = rows == 0 ? 1 : renderer.PiecesPerRow, bands = rows * pieces;
        int workers = BandSchedule.Workers(bands, _options.MaxDegreeOfParallelism);
        bool scattered = trace is { Scattered: true } && workers == 1;
        BandSchedule schedule = renderer.ReusesRowAbove || scattered
            ? new BandSchedule(0, bands, workers, scattered, pieces)
            : BandSchedule.InOrder(0, bands, workers);
        if (pieces > 1)
        {
            progress?.Start(rows, pieces);
        }

        trace?.Begin(bands);
        CrewFor.Run(schedule, renderer.Rent, (int band, int worker, ref TScratch scratch) =>
        {
            long began = trace?.Clock() ?? 0;
            int row = start + (band / pieces);
            renderer.RenderPiece(row, band - ((row - start) * pieces), ref scratch);
            progress?.CompletePiece(worker);
            trace?.Band(band, worker, began, trace.Clock());
        }, scratch =>
        {
            lock (gate)
            {
                renderer.Return(scratch, ref totals);
            }
        }, _options.CancellationToken);
        trace?.End();
        return totals;
    }

    /// <summary>Stops the clock: the render's statistics.</summary>
    /// <param name="rays">Primary rays traced.</param>
    /// <param name="kernel">The loop that rendered.</param>
    /// <param name="retraced">Samples traced again in double.</param>
    /// <param name="scalarReason">Why an auto render took the scalar path, or null.</param>
    public RenderStatistics Finish(long rays, RenderKernel kernel, long retraced = 0, string? scalarReason = null)
    {
        TimeSpan elapsed = Stopwatch.GetElapsedTime(_started);
        _options.Trace?.Finish();
        return new(rays, elapsed) { Kernel = kernel, RetracedSamples = retraced, ScalarReason = scalarReason };
    }
}
