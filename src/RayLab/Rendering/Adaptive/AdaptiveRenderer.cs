using RayLab.Sampling;
using RayLab.Cameras;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The lab's adaptive antialiasing (section 4.1.4) as a renderer: on the <see cref="RowLoop"/>, a piece of a row at a
/// time (<see cref="Pieces"/>: whole rows but for costly rows on <see cref="PiecesFrom"/> threads or more), each piece's pixel corners are traced as two lines (<see cref="AdaptiveLattice"/>),
/// then each pixel is subdivided where its values disagree (<see cref="AdaptivePixel"/>), each thread with its own
/// reusable buffers. It relies
/// on the scene's flat shading: a point is kept as the index of what it hit, its value that index's
/// <see cref="Scene.ColourOf"/>.
/// </summary>
internal static class AdaptiveRenderer
{
    /// <summary>Pixels per side of the blocks the guard tests first (its tiles): a block no silhouette may cross clears its pixels at once.</summary>
    private const int GuardBlock = SilhouetteGuard.TilePixels;

    /// <summary>
    /// The guard for a flat pixel: false at once when its <see cref="GuardBlock"/>-pixel block is clear of every
    /// silhouette (the test is conservative for every ray of the block, so for the pixel's too), else the pixel's own
    /// test. A block's test serves its <see cref="GuardBlock"/> rows: the thread keeps it for the block row's other rows.
    /// </summary>
    private static bool MayCross(ref GuardState state, int x, int row)
    {
        SilhouetteGuard guard = state.Guard!;
        long size = state.Size;
        if (x / GuardBlock != state.Block)
        {
            int block = state.Block = x / GuardBlock;
            sbyte known = state.Known[block];
            if (known < 0)
            {
                known = guard.MayCross((long)block * GuardBlock * size, (long)(row / GuardBlock) * GuardBlock * size, GuardBlock * size) ? (sbyte)0 : (sbyte)1;
                state.Known[block] = known;
            }

            state.BlockFree = known == 1;
        }

        return !state.BlockFree && guard.MayCross(x * size, row * size, size);
    }

    /// <summary>How many entries from the start of <paramref name="line"/> equal <paramref name="id"/>.</summary>
    private static int RunLength(ReadOnlySpan<int> line, int id)
    {
        int other = line.IndexOfAnyExcept(id);
        return other < 0 ? line.Length : other;
    }

    /// <summary>Writes a run of <paramref name="count"/> flat pixels of one colour from <paramref name="x"/> (one ray each for the heat map); returns its length.</summary>
    private static int Fill(TargetRow pixels, Span<float> counts, int x, int count, Intensity colour, Rgb24 level)
    {
        pixels.Fill(x, count, colour, level);
        counts.Fill(1);
        return count;
    }

    /// <summary>
    /// Writes the flat pixels of the run of <paramref name="run"/> from <paramref name="x"/> up to the first one a
    /// silhouette may cross (<see cref="MayCross"/>); returns how many it wrote.
    /// </summary>
    private static int FillGuarded(ref GuardState state, TargetRow pixels, Span<float> counts, int x, int run, int row, Intensity colour, Rgb24 level)
    {
        int start = x, end = x + run;
        while (x < end)
        {
            if (MayCross(ref state, x, row))
            {
                break;
            }

            // The rest of the pixel's block is clear too when the block is.
            int clear = state.BlockFree ? Math.Min(end, (state.Block + 1) * GuardBlock) : x + 1;
            Fill(pixels, counts.IsEmpty ? default : counts[x..clear], x, clear - x, colour, level);
            x = clear;
        }

        return x - start;
    }

    /// <summary>The fewest threads for which rows are cut into pieces.</summary>
    public const int PiecesFrom = 8;

    /// <summary>The most pieces a row is cut into.</summary>
    public const int MostPieces = 8;

    /// <summary>The narrowest piece: one 16-lane packet of corners.</summary>
    public const int NarrowestPiece = 16;

    /// <summary>
    /// The pieces each row of a <paramref name="width"/>-pixel render on <paramref name="threads"/> threads is cut into,
    /// left to right: <paramref name="requested"/> (at most one a pixel) when it is positive; else, where rows are
    /// costly (<paramref name="costlyRows"/>: the scene is traced through its hierarchy, many spheres) and there are
    /// <see cref="PiecesFrom"/> threads or more, one piece per two threads, at most <see cref="MostPieces"/>, none
    /// narrower than <see cref="NarrowestPiece"/>; else whole rows. A piece is the row loop's unit of work: a row of the
    /// sphere field's horizon costs many times a mean row, and the frame ends when the last unit does. A piece costs
    /// its own set-up, about 160 ns, which is lost in a costly row and not in a cheap one (a two-sphere row costs some
    /// 12 µs). The image, the rays and the points traced again in double are the same however the rows are cut.
    /// </summary>
    public static int Pieces(int width, int threads, bool costlyRows, int requested = 0) =>
        requested > 0 ? Math.Min(requested, Math.Max(1, width))
        : !costlyRows || threads < PiecesFrom ? 1
        : Math.Clamp(Math.Min(threads / 2, width / NarrowestPiece), 1, MostPieces);

    /// <summary>Renders with <paramref name="sampler"/>'s settings; <paramref name="raysPerPixel"/>, if given, receives each pixel's rays.</summary>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, AdaptiveSampler sampler, PixelTarget image, RenderOptions options, float[]? raysPerPixel)
    {
        var loop = RowLoop.Start(options, image.Height);
        var lattice = new AdaptiveLattice(scene, plane, sampler.MinDepth, sampler.MaxDepth, sampler.Quincunx, sampler.Guard, options);
        RowTotals totals = loop.Run(new Rows(lattice, sampler, image, raysPerPixel, Pieces(image.Width, loop.Threads, scene.UsesHierarchy, options.RowPieces)));
        long rays = lattice.CornerRays + lattice.DenseRays + lattice.CentreRays + totals.Rays - lattice.SharedEdgeDuplicates();
        return loop.Finish(rays, lattice.Kernel, lattice.RetracedPoints);
    }

    /// <summary>The adaptive rows in <paramref name="pieces"/> pieces, each thread with its lattice <see cref="AdaptiveLattice.Source"/>.</summary>
    private sealed class Rows(AdaptiveLattice lattice, AdaptiveSampler sampler, PixelTarget image, float[]? raysPerPixel, int pieces) : IRowRenderer<AdaptiveLattice.Source>
    {
        private readonly bool _flatWithoutCentre = !sampler.Quincunx && sampler.MinDepth == 0;

        // The guard may refine a pixel whose points agree: then only the recursion knows its value.
        private readonly bool _dense = lattice.DenseDepth != 0 && lattice.Guard is null;
        private readonly bool _centres = lattice.CentreLine && lattice.Guard is null;

        public AdaptiveLattice.Source Rent() => lattice.Rent(pieces);

        public bool ReusesRowAbove => true;

        public int PiecesPerRow => pieces;

        public void Return(AdaptiveLattice.Source source, ref RowTotals totals)
        {
            totals.Rays += source.Rays - lattice.Return(source);
        }

        public void RenderRow(int row, ref AdaptiveLattice.Source source)
        {
            for (int piece = 0; piece < pieces; piece++)
            {
                RenderPiece(row, piece, ref source);
            }
        }

        public void RenderPiece(int row, int piece, ref AdaptiveLattice.Source source)
        {
            TargetRow pixels = image.Row(row);
            int begin = (int)((long)pixels.Length * piece / pieces), end = (int)((long)pixels.Length * (piece + 1) / pieces);
            source.BeginRow(row, piece, begin, end);
            Span<float> counts = raysPerPixel is null ? default : raysPerPixel.AsSpan((int)((long)row * pixels.Length), pixels.Length);
            var guard = new GuardState(lattice.Guard, lattice.Size, lattice.Guard is null ? default : source.GuardBlocks(row / GuardBlock, (pixels.Length / GuardBlock) + 1));
            for (int x = begin; x < end; x++)
            {
                // Runs first: with neither minimum depth nor quincunx, flat pixels; with a minimum depth, uniform ones.
                x += _flatWithoutCentre ? FlatRun(source, pixels, counts, x, row, ref guard)
                    : _dense ? UniformRun(source, pixels, counts, x, row)
                    : 0;
                if (x == end)
                {
                    break;
                }

                // A pixel whose corners disagree, one the guard stopped a run at, one whose band points disagree, or
                // any pixel with the quincunx: the recursion decides. With the quincunx (corners and centre): a pixel
                // whose traced points all agree is refined no further, and its value is known per colour.
                Intensity value;
                double samples;
                if (!(_centres && source.TryUniformWithCentre(sampler, x, row, out value, out samples)))
                {
                    source.NextPixel(x, row);
                    value = AdaptivePixel.Evaluate(sampler, ref source, x, row, out samples);
                }

                pixels.Set(x, value);
                if (!counts.IsEmpty)
                {
                    counts[x] = (float)samples;
                }
            }

            source.EndRow(row);
        }

        /// <summary>
        /// Most pixels: four corners on the same sphere (or the background), nothing more to trace. The run of flat
        /// pixels from x that hit what corner x hit ends where either corner line first hits something else, or at the
        /// piece's end; the pixel after the run is not flat. Writes the run (up to where the guard stops it); returns
        /// its length.
        /// </summary>
        private int FlatRun(in AdaptiveLattice.Source source, TargetRow pixels, Span<float> counts, int x, int row, ref GuardState guard)
        {
            ReadOnlySpan<int> top = source.TopCorners[x..(source.End + 1)], bottom = source.BottomCorners[x..(source.End + 1)];
            int id = top[0];
            int run = Math.Min(RunLength(top, id), RunLength(bottom, id)) - 1;
            if (run <= 0)
            {
                return 0;
            }

            return guard.Guard is null
                ? Fill(pixels, counts.IsEmpty ? default : counts.Slice(x, run), x, run, lattice.Colour(id), lattice.Level(id))
                : FillGuarded(ref guard, pixels, counts, x, run, row, lattice.Colour(id), lattice.Level(id));
        }

        /// <summary>
        /// With a minimum depth: the run of pixels from x whose band points all hit one thing is refined no further;
        /// the pixel after the run is not uniform. Writes the run; returns its length.
        /// </summary>
        private int UniformRun(in AdaptiveLattice.Source source, TargetRow pixels, Span<float> counts, int x, int row)
        {
            int run = source.UniformRun(x, out int id);
            if (run > 0)
            {
                source.Uniform(sampler, id, x, row, out Intensity uniform, out double charged);
                pixels.Fill(x, run, uniform);
                if (!counts.IsEmpty)
                {
                    counts.Slice(x, run).Fill((float)charged);
                }
            }

            return run;
        }
    }

    /// <summary>A row's guard, what this thread knows of its block row's blocks (−1 untested, 0 may be crossed, 1 clear), and the block its last test was in.</summary>
    private ref struct GuardState(SilhouetteGuard? guard, long size, Span<sbyte> known)
    {
        public readonly SilhouetteGuard? Guard = guard;
        public readonly long Size = size;
        public readonly Span<sbyte> Known = known;
        public int Block = -1;
        public bool BlockFree;
    }
}
