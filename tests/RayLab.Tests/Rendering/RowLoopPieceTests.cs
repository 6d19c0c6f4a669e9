using RayLab.Rendering;

namespace RayLab.Tests.Rendering;

/// <summary>
/// The row loop's bands when a renderer cuts its rows into pieces: every piece of every row once, numbered row by row,
/// so one thread writes the image a row at a time.
/// </summary>
public class RowLoopPieceTests
{
    /// <summary>Records which (row, piece) each call renders, and on which thread's scratch.</summary>
    private sealed class Recorder(int pieces, bool reusesRowAbove) : IRowRenderer<List<(int Row, int Piece)>>
    {
        public List<List<(int Row, int Piece)>> Scratches { get; } = [];

        public bool ReusesRowAbove => reusesRowAbove;

        public int PiecesPerRow => pieces;

        public List<(int Row, int Piece)> Rent()
        {
            var scratch = new List<(int Row, int Piece)>();
            lock (Scratches)
            {
                Scratches.Add(scratch);
            }

            return scratch;
        }

        public void RenderRow(int row, ref List<(int Row, int Piece)> scratch) => throw new InvalidOperationException("a renderer in pieces is asked for pieces");

        public void RenderPiece(int row, int piece, ref List<(int Row, int Piece)> scratch) => scratch.Add((row, piece));
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void OneThreadRendersEachRowsPiecesLeftToRightThenTheNextRow(bool reusesRowAbove)
    {
        var recorder = new Recorder(3, reusesRowAbove);
        var options = new RenderOptions(1, RenderKernel.Auto, null, default) { FirstRow = 2, EndRow = 5 };
        RowLoop.Start(options, 10).Run(recorder);
        Assert.Equal([(2, 0), (2, 1), (2, 2), (3, 0), (3, 1), (3, 2), (4, 0), (4, 1), (4, 2)], Assert.Single(recorder.Scratches));
    }

    [Fact]
    public void ManyThreadsRenderEveryPieceOfEveryRowOnce()
    {
        var recorder = new Recorder(5, reusesRowAbove: true);
        var progress = new RenderProgress();
        RowLoop.Start(new RenderOptions(6, RenderKernel.Auto, progress, default), 37).Run(recorder);
        var all = recorder.Scratches.SelectMany(s => s).Order().ToList();
        Assert.Equal([.. Enumerable.Range(0, 37).SelectMany(row => Enumerable.Range(0, 5).Select(piece => (row, piece)))], all);
        Assert.Equal((37, 37), (progress.RowsCompleted, progress.TotalRows));
    }

    [Theory]
    [InlineData(1)]
    [InlineData(6)]
    public void ProgressCountsEveryPieceOnceOnAnyThreadCountAndStartsAfreshEachRender(int threads)
    {
        var progress = new RenderProgress();
        RowLoop.Start(new RenderOptions(threads, RenderKernel.Auto, progress, default), 150).Run(new Recorder(2, reusesRowAbove: true));
        Assert.Equal((150, 150), (progress.RowsCompleted, progress.TotalRows));
        RowLoop.Start(new RenderOptions(threads, RenderKernel.Auto, progress, default), 40).Run(new Recorder(1, reusesRowAbove: false));
        Assert.Equal((40, 40), (progress.RowsCompleted, progress.TotalRows));
    }

    [Fact]
    public void ProgressCountsThePiecesOfEveryThreadNumberThoseBeyondTheSlotsToo()
    {
        // Each thread counts in a slot of its own; past the 64th, threads share slots.
        var progress = new RenderProgress();
        progress.Start(150, 2);
        for (int worker = 0; worker < 300; worker++)
        {
            progress.CompletePiece(worker);
        }

        Assert.Equal((150, 150, 1.0), (progress.RowsCompleted, progress.TotalRows, progress.Fraction));
    }
}
