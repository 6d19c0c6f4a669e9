namespace RayLab;

/// <summary>
/// How far a render has got, for a progress bar: the renderer counts finished rows, and anyone may read the
/// count from another thread while it runs (no callback runs on the render threads). A renderer that works in pieces
/// of rows (the adaptive one, on a scene of many spheres and eight threads or more) counts rows' worth of finished pieces.
/// </summary>
public sealed class RenderProgress
{
    private int _piecesCompleted;
    private int _piecesPerRow = 1;
    private int _totalRows;

    /// <summary>Rows of the current (or last) render that are finished, or their worth in finished pieces of rows.</summary>
    public int RowsCompleted => Volatile.Read(ref _piecesCompleted) / Volatile.Read(ref _piecesPerRow);

    /// <summary>Rows in the current (or last) render; 0 before a render starts.</summary>
    public int TotalRows => Volatile.Read(ref _totalRows);

    /// <summary>The finished fraction, 0 to 1 (0 before a render starts).</summary>
    public double Fraction => TotalRows == 0 ? 0 : (double)RowsCompleted / TotalRows;

    /// <summary>A render of <paramref name="totalRows"/> rows, each done in <paramref name="piecesPerRow"/> pieces, starts.</summary>
    internal void Start(int totalRows, int piecesPerRow = 1)
    {
        Volatile.Write(ref _piecesCompleted, 0);
        Volatile.Write(ref _piecesPerRow, piecesPerRow);
        Volatile.Write(ref _totalRows, totalRows);
    }

    /// <summary>A row, or a piece of one, is finished.</summary>
    internal void CompletePiece() => Interlocked.Increment(ref _piecesCompleted);
}
