namespace RayLab;

/// <summary>
/// How far a render has got, for a progress bar: the renderer counts finished rows, and anyone may read the
/// count from another thread while it runs (no callback runs on the render threads).
/// </summary>
public sealed class RenderProgress
{
    private int _rowsCompleted;
    private int _totalRows;

    /// <summary>Rows of the current (or last) render that are finished.</summary>
    public int RowsCompleted => Volatile.Read(ref _rowsCompleted);

    /// <summary>Rows in the current (or last) render; 0 before a render starts.</summary>
    public int TotalRows => Volatile.Read(ref _totalRows);

    /// <summary>The finished fraction, 0 to 1 (0 before a render starts).</summary>
    public double Fraction => TotalRows == 0 ? 0 : (double)RowsCompleted / TotalRows;

    internal void Start(int totalRows)
    {
        Volatile.Write(ref _rowsCompleted, 0);
        Volatile.Write(ref _totalRows, totalRows);
    }

    internal void CompleteRow() => Interlocked.Increment(ref _rowsCompleted);
}
