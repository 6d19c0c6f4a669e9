namespace RayLab;

/// <summary>
/// How far a render has got, for a progress bar: the renderer counts finished rows, and anyone may read the
/// count from another thread while it runs (no callback runs on the render threads). A renderer that works in pieces
/// of rows (the adaptive one, on a scene of many spheres and eight threads or more) counts rows' worth of finished pieces.
/// </summary>
public sealed class RenderProgress
{
    // One count per render thread (threads past the 64th share), each on a 128-byte line of its own and none on the
    // array's first line, which every bounds check reads: threads that finish pieces at the same moment then never
    // take a cache line from one another, as they did with one count for all.
    private const int Slots = 64;
    private const int Spacing = 128 / sizeof(int);
    private readonly int[] _completed = new int[(Slots + 1) * Spacing];
    private int _piecesPerRow = 1;
    private int _totalRows;

    /// <summary>Rows of the current (or last) render that are finished, or their worth in finished pieces of rows.</summary>
    public int RowsCompleted
    {
        get
        {
            long pieces = 0;
            for (int slot = 1; slot <= Slots; slot++)
            {
                pieces += Volatile.Read(ref _completed[slot * Spacing]);
            }

            return (int)(pieces / Volatile.Read(ref _piecesPerRow));
        }
    }

    /// <summary>Rows in the current (or last) render; 0 before a render starts.</summary>
    public int TotalRows => Volatile.Read(ref _totalRows);

    /// <summary>The finished fraction, 0 to 1 (0 before a render starts).</summary>
    public double Fraction => TotalRows == 0 ? 0 : (double)RowsCompleted / TotalRows;

    /// <summary>A render of <paramref name="totalRows"/> rows, each done in <paramref name="piecesPerRow"/> pieces, starts.</summary>
    internal void Start(int totalRows, int piecesPerRow = 1)
    {
        for (int slot = 1; slot <= Slots; slot++)
        {
            Volatile.Write(ref _completed[slot * Spacing], 0);
        }

        Volatile.Write(ref _piecesPerRow, piecesPerRow);
        Volatile.Write(ref _totalRows, totalRows);
    }

    /// <summary>A row, or a piece of one, is finished by render thread <paramref name="worker"/> (0, 1, …).</summary>
    internal void CompletePiece(int worker) => Interlocked.Increment(ref _completed[(1 + (worker % Slots)) * Spacing]);
}
