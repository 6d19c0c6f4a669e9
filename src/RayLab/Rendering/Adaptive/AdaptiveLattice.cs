using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The points an adaptive render traces, each once, kept as the index of what they hit (0 the background,
/// k + 1 sphere k: the scenes' colours are flat), a piece of a row of pixels at a time (pixels x0 to x1 − 1) by a
/// thread's <see cref="Source"/>, in memory of O(W) per thread: the piece's two lines of pixel corners (by the SIMD
/// packet tracer where the frame allows it, <see cref="LatticeHits"/>), then the points the recursion asks for,
/// without a dictionary or an allocation per point. Nothing of size W×H is kept.
/// </summary>
/// <remarks>
/// <para>The row loop hands a thread runs of consecutive rows, each row's pieces left to right: a piece's top corner
/// line is the bottom line of the piece above when the same thread rendered that piece last (the lines roll, two
/// corner lines kept by parity, each piece in its own part of them), else traced again (the value is the same either
/// way, and the count of rays and of points traced again in double counts each point of a line once: a corner on the
/// line between two pieces is the left piece's).</para>
/// <para>Points on a pixel's left and right edges are shared with the pixel beside it in the same row, which the same
/// thread evaluates next, so they are kept in a buffer per vertical pixel line. Points on a pixel's top and bottom
/// edges are shared with another row, and those on the line between two pieces with the other piece: each piece
/// traces those it needs and notes which, so that a point both traced is counted as one ray — at once when the same
/// thread rendered the piece above last, else once the render is done.</para>
/// </remarks>
internal sealed class AdaptiveLattice
{
    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly long _size;
    private readonly double _latticeWidth, _latticeHeight;
    private readonly Intensity[] _palette;
    private readonly Rgb24[] _levels;
    private readonly RenderOptions _options;
    private readonly List<Source.Buffers> _returned = [];

    /// <summary>The most entries a thread's band of minimum-depth points may take (16 MB); deeper bands go point by point.</summary>
    private const long MaxDenseEntries = 1 << 22;

    private readonly LatticeHits? _hits;
    private readonly int _denseShift;

    public AdaptiveLattice(Scene scene, ImagePlane plane, int minDepth, int maxDepth, bool quincunx, bool guard, RenderOptions options)
    {
        Guard = guard ? new SilhouetteGuard(scene, plane, 1L << (maxDepth + 1)) : null;
        _scene = scene;
        _plane = plane;
        _size = 1L << (maxDepth + 1);
        _latticeWidth = plane.Width * (double)_size;
        _latticeHeight = plane.Height * (double)_size;
        // The scene is flat-shaded: a point's value is the ColourOf what it hit, so a point keeps that index + 1
        // (0 the background, k + 1 sphere k) and this palette holds the colours.
        _palette = [.. Enumerable.Range(-1, scene.Spheres.Count + 1).Select(scene.ColourOf)];
        _levels = [.. _palette.Select(Rgb24.FromIntensity)];
        _options = options;
        // The frame decides the kernel and whether depth order needs checking; the lattice traverses its own copy of
        // the hierarchy (LatticeHits), so the frame's is not built.
        Kernel = KernelChoice.Choose(options.Kernel, scene, plane, out PacketFrame? frame, out _, withHierarchy: false);
        _hits = Kernel == RenderKernel.Scalar ? null : LatticeHits.TryCreate(scene, plane, _size, frame);
        if (minDepth > 0)
        {
            long across = plane.Width * (1L << minDepth);
            if (((2L << minDepth) + 1) * (across + 1) <= MaxDenseEntries)
            {
                DenseDepth = minDepth;
                DenseStride = (int)across + 1;
                _denseShift = maxDepth - minDepth;
            }
        }

        CentreLine = quincunx && DenseDepth == 0;
    }

    private long _retraced;

    /// <summary>This render's meeting places of horizontal-line notes (<see cref="Meet"/>), rented at the first note, or null.</summary>
    private EdgeSlots? _edges;

    /// <summary>
    /// With a minimum depth m ≥ 1, every pixel's squares at depth m have their corners and centres traced whatever
    /// the values: m, when those points are traced a row of pixels at a time as lattice lines (0 when not).
    /// </summary>
    public int DenseDepth { get; }

    /// <summary>Entries per even lattice line of a row's band of minimum-depth points: W·2^m + 1.</summary>
    public int DenseStride { get; }

    /// <summary>
    /// Rays for the minimum-depth points beyond the pixel corners: the corners of the depth-m squares,
    /// (W·2^m + 1)(H·2^m + 1) less the pixel corners, and their centres, W·H·4^m, each counted once although a
    /// line between two rows of pixels is traced by both when they are on different threads.
    /// </summary>
    public long DenseRays => DenseDepth == 0 ? 0
        : (((_plane.Width * (1L << DenseDepth)) + 1) * ((_plane.Height * (1L << DenseDepth)) + 1)) - CornerRays
          + ((long)_plane.Width * _plane.Height << (2 * DenseDepth));

    /// <summary>
    /// With the quincunx (and no minimum depth): every pixel's centre is traced, a row at a time as one lattice line,
    /// W·H rays in all.
    /// </summary>
    public bool CentreLine { get; }

    /// <summary>Rays for the pixel centres of <see cref="CentreLine"/>.</summary>
    public long CentreRays => CentreLine ? (long)_plane.Width * _plane.Height : 0;

    /// <summary>Points whose float answer was uncertain and were traced again in double (the threads' counts, summed as each returns its buffers).</summary>
    public long RetracedPoints => _retraced;

    /// <summary>
    /// Traces points <paramref name="from"/> to <paramref name="to"/> of a lattice line of <paramref name="length"/>
    /// points, point k at (<paramref name="lxStart"/> + k·<paramref name="lxStep"/>, <paramref name="ly"/>), into
    /// those entries of <paramref name="line"/>, by the packet path or the double loop; returns how many of points
    /// <paramref name="countFrom"/> to <paramref name="to"/> were traced again in double. The packet path traces the
    /// whole line's packets that hold the points (<see cref="LatticeHits.TraceRow{TL, TP}"/>) into
    /// <paramref name="scratch"/>, and copies the points alone: no entry outside the range is written.
    /// </summary>
    private int TraceLine(long ly, long lxStart, long lxStep, int length, Span<int> line, int from, int to, int countFrom, Span<int> scratch)
    {
        if (_hits is null)
        {
            for (int k = from; k <= to; k++)
            {
                line[k] = LatticeHits.TraceScalar(_scene, _plane, _latticeWidth, _latticeHeight, lxStart + (k * lxStep), ly);
            }

            return 0;
        }

        return Kernel switch
        {
            RenderKernel.Vector512 => TracePackets<Lanes512>(_hits, ly, lxStart, lxStep, length, line, from, to, countFrom, scratch),
            RenderKernel.Vector256 => TracePackets<Lanes256>(_hits, ly, lxStart, lxStep, length, line, from, to, countFrom, scratch),
            _ => TracePackets<Lanes128>(_hits, ly, lxStart, lxStep, length, line, from, to, countFrom, scratch),
        };
    }

    /// <summary><see cref="TraceLine"/>'s packet path, in packets of <typeparamref name="TL"/>'s lanes.</summary>
    private static int TracePackets<TL>(LatticeHits hits, long ly, long lxStart, long lxStep, int length, Span<int> line, int from, int to, int countFrom, Span<int> scratch)
        where TL : struct, ILanes<TL>
    {
        int lanes = TL.Count;
        int first = from - (from % lanes), end = Math.Min(length, ((to / lanes) + 1) * lanes);
        // The packets hold exactly the points (a whole line, say): straight into the line.
        bool exact = first == from && end == to + 1;
        Span<int> ids = exact ? line[from..end] : scratch[..(end - first)];
        int retraced = hits.TraceRow<TL>(ly, lxStart, lxStep, ids, first, countFrom, to + 1);
        if (!exact)
        {
            ids[(from - first)..(to - first + 1)].CopyTo(line[from..]);
        }

        return retraced;
    }

    /// <summary>The silhouette guard, when the sampler has one.</summary>
    public SilhouetteGuard? Guard { get; }

    /// <summary>The loop that traces the pixel corners.</summary>
    public RenderKernel Kernel { get; }

    /// <summary>Steps per pixel side.</summary>
    public long Size => _size;

    /// <summary>Rays traced for the pixel corners, (W + 1)(H + 1), each counted once.</summary>
    public long CornerRays => (_plane.Width + 1L) * (_plane.Height + 1L);

    /// <summary>The 8-bit colour of a flat pixel all of whose corners hit <paramref name="id"/>.</summary>
    public Rgb24 Level(int id) => _levels[id];

    /// <summary>The linear colour of a flat pixel all of whose corners hit <paramref name="id"/>.</summary>
    public Intensity Colour(int id) => _palette[id];

    /// <summary>
    /// Points on the vertical line between two pieces of a row that both pieces traced: every thread noted such points
    /// as keys (<see cref="Source.Buffers.Key"/>), and a key noted twice is one duplicate. (Points on a horizontal
    /// pixel line that two threads traced are taken off as the rows run: <see cref="Meet"/>.) The threads' buffers
    /// then go back to the pool.
    /// </summary>
    public long SharedEdgeDuplicates()
    {
        long duplicates = 0;
        if (_returned.Count != 0)
        {
            // The first thread's list takes everyone's keys: it is cleared when its buffers are next prepared.
            List<long> keys = _returned[0].SharedPoints;
            for (int i = 1; i < _returned.Count; i++)
            {
                keys.AddRange(_returned[i].SharedPoints);
            }

            Span<long> sorted = CollectionsMarshal.AsSpan(keys);
            sorted.Sort();
            for (int k = 1; k < sorted.Length; k++)
            {
                duplicates += sorted[k] == sorted[k - 1] ? 1 : 0;
            }
        }

        foreach (Source.Buffers buffers in _returned)
        {
            _options.Return(buffers);
        }

        _returned.Clear();
        if (_edges is { } edges)
        {
            Array.Clear(edges.Slots);
            _options.Return(edges);
            _edges = null;
        }

        return duplicates;
    }

    /// <summary>
    /// Piece <paramref name="piece"/>'s notes <paramref name="points"/> (sorted lx) on horizontal pixel line
    /// <paramref name="line"/> (0 the top of row 0), from the row above or the row below, where one thread did not
    /// render both pieces one after the other: the two pieces' notes meet in the line's slot. The first to come leaves
    /// a copy there; the second counts the points both traced and returns that count, for its rays. Each side comes
    /// at most once a render, so every point two threads traced is counted once, while the rows run, on whichever
    /// thread finishes the pair: nothing is left to merge on one thread after the rows.
    /// </summary>
    private int Meet(Source.Buffers buffers, int line, int piece, List<long> points)
    {
        if (points.Count == 0)
        {
            return 0; // nothing in common with anything
        }

        int pieces = buffers.PointsRowOf.Length;
        EdgeNotes?[] slots = Edges(pieces);
        ref EdgeNotes? slot = ref slots[(line * pieces) + piece];
        EdgeNotes? other = Volatile.Read(ref slot);
        if (other is null)
        {
            EdgeNotes mine = buffers.Keep(points);
            other = Interlocked.CompareExchange(ref slot, mine, null);
            if (other is null)
            {
                return 0;
            }

            buffers.Unkeep();
        }

        return Common(other.Points.AsSpan(0, other.Count), CollectionsMarshal.AsSpan(points));
    }

    /// <summary>The slots of <see cref="Meet"/>, one per horizontal pixel line and piece, rented by the first thread that needs them.</summary>
    private EdgeNotes?[] Edges(int pieces)
    {
        EdgeSlots? edges = Volatile.Read(ref _edges);
        if (edges is null)
        {
            var rented = _options.Rent<EdgeSlots>();
            int length = (_plane.Height + 1) * pieces;
            if (rented.Slots.Length != length)
            {
                rented.Slots = new EdgeNotes?[length];
            }

            edges = Interlocked.CompareExchange(ref _edges, rented, null);
            if (edges is null)
            {
                return rented.Slots;
            }

            _options.Return(rented);
        }

        return edges.Slots;
    }

    /// <summary>How many values two ascending lists have in common.</summary>
    private static int Common(ReadOnlySpan<long> above, ReadOnlySpan<long> below)
    {
        int common = 0;
        for (int i = 0, j = 0; i < above.Length && j < below.Length;)
        {
            if (above[i] < below[j])
            {
                i++;
            }
            else if (above[i] > below[j])
            {
                j++;
            }
            else
            {
                common++;
                i++;
                j++;
            }
        }

        return common;
    }

    /// <summary>
    /// A thread's source for a piece of a row at a time, rows cut into <paramref name="pieces"/>, its buffers kept
    /// across rows, threads and renders (<see cref="RenderOptions.Pool"/>).
    /// </summary>
    public Source Rent(int pieces)
    {
        var buffers = _options.Rent<Source.Buffers>();
        buffers.Prepare(_plane.Width, _size, DenseDepth == 0 ? 0 : (2 << DenseDepth) + 1, DenseStride, CentreLine, _palette.Length, pieces);
        return new Source(this, buffers);
    }

    /// <summary>
    /// A thread is done (called under the row loop's lock): its kept bottom-edge notes meet their rows below
    /// (<see cref="Meet"/>), and its buffers go back to the pool after <see cref="SharedEdgeDuplicates"/>.
    /// </summary>
    /// <returns>Points this thread traced that another traced too, to take off its rays.</returns>
    public long Return(Source source)
    {
        Source.Buffers buffers = source.Storage;
        long duplicates = 0;
        for (int piece = 0; piece < buffers.PointsRowOf.Length; piece++)
        {
            duplicates += FlushBottomPoints(buffers, piece);
        }

        _retraced += buffers.Retraced;
        _returned.Add(buffers);
        return duplicates;
    }

    /// <summary>
    /// The bottom-edge notes <paramref name="buffers"/> kept for piece <paramref name="piece"/> meet the row below's
    /// (<see cref="Meet"/>): that row is not this thread's next for the piece, or the thread is done.
    /// </summary>
    /// <returns>Points both traced.</returns>
    private int FlushBottomPoints(Source.Buffers buffers, int piece)
    {
        int row = buffers.PointsRowOf[piece];
        if (row < 0)
        {
            return 0;
        }

        int common = Meet(buffers, row + 1, piece, buffers.AboveBottomPointsOf[piece]);
        buffers.AboveBottomPointsOf[piece].Clear();
        buffers.PointsRowOf[piece] = -1;
        return common;
    }

    private int Trace(long lx, long ly) => LatticeHits.TraceScalar(_scene, _plane, _latticeWidth, _latticeHeight, lx, ly);

    /// <summary>
    /// One thread's view of the lattice, a row at a time: corners from the row's two corner lines; points on the vertical pixel lines
    /// from a buffer per line (the right edge of one pixel is the left edge of the next); points on the horizontal
    /// pixel lines traced and noted for the ray count; points inside the pixel from a buffer over the pixel's
    /// lattice, valid while its stamp is the pixel's (so nothing is cleared between pixels).
    /// </summary>
    internal struct Source : ILatticeSource
    {
        private readonly AdaptiveLattice _lattice;
        private readonly Buffers _buffers;
        private long _x0, _y0;
        private int _row, _pixel, _piece, _begin, _end;
        private uint _pixelStamp;

        public Source(AdaptiveLattice lattice, Buffers buffers)
        {
            _lattice = lattice;
            _buffers = buffers;
        }

        /// <summary>The buffers, to give back.</summary>
        public readonly Buffers Storage => _buffers;

        /// <summary>Rays this source traced: centres, inner points, points on vertical and horizontal pixel lines.</summary>
        public long Rays { get; private set; }

        /// <summary>What the pixel corners on the row's top edge hit, corner x at [x] (those of the piece, x0 to x1).</summary>
        public readonly ReadOnlySpan<int> TopCorners => _buffers.Corners(_row, _piece);

        /// <summary>What the pixel corners on the row's bottom edge hit, corner x at [x] (those of the piece, x0 to x1).</summary>
        public readonly ReadOnlySpan<int> BottomCorners => _buffers.Corners(_row + 1, _piece);

        /// <summary>
        /// The guard's notes on the blocks of block row <paramref name="blockRow"/>, <paramref name="count"/> of them:
        /// kept while this thread renders that block row's rows, all −1 (untested) when it starts another.
        /// </summary>
        public readonly Span<sbyte> GuardBlocks(int blockRow, int count)
        {
            Buffers buffers = _buffers;
            if (buffers.GuardBlocks.Length != count)
            {
                buffers.GuardBlocks = new sbyte[count];
                buffers.GuardBlockRow = -1;
            }

            if (buffers.GuardBlockRow != blockRow)
            {
                buffers.GuardBlocks.AsSpan().Fill(-1);
                buffers.GuardBlockRow = blockRow;
            }

            return buffers.GuardBlocks;
        }

        /// <summary>One past the last pixel of the piece (x1).</summary>
        public readonly int End => _end;

        /// <summary>
        /// Starts piece <paramref name="piece"/> of a row, pixels <paramref name="begin"/> to <paramref name="end"/> − 1:
        /// their two corner lines (the top one taken from the piece above when this thread rendered that piece last),
        /// their centres with the quincunx, and with a minimum depth their band of minimum-depth points, line by line.
        /// </summary>
        public void BeginRow(int row, int piece, int begin, int end)
        {
            _row = row;
            _piece = piece;
            _begin = begin;
            _end = end;
            AdaptiveLattice lattice = _lattice;
            int m = lattice.DenseDepth;
            TraceCorners(row);
            if (lattice.CentreLine)
            {
                long size = lattice._size;
                long centres = lattice.TraceLine((row * size) + (size / 2), size / 2, size, lattice._plane.Width, _buffers.Centres, begin, end - 1, begin, _buffers.Scratch);
                _buffers.Retraced += centres;
            }

            if (m == 0)
            {
                return;
            }

            long g = lattice._size >> (m + 1), y0 = row * lattice._size;
            Buffers buffers = _buffers;
            int stride = buffers.DenseStride, points = lattice.DenseStride, last = 2 << m, first = 0, lo = begin << m, across = (end - begin) << m;
            long again = 0;
            if (row > 0 && buffers.DenseRowOf[piece] == row - 1)
            {
                // This thread rendered the piece above last: its bottom line is this piece's top line, taken rather
                // than traced again (its points traced again in double counted as if it were, so the count does not
                // depend on which thread took which piece).
                buffers.Dense.AsSpan((last * stride) + piece + lo, across + 1).CopyTo(buffers.Dense.AsSpan(piece + lo));
                again += buffers.BottomLineRetracedOf[piece];
                first = 1;
            }

            for (int k = first; k <= last; k++)
            {
                // Even lines: the depth-m squares' corners, every 2g (the first one the piece on the left's too);
                // odd lines: their centres, between them. Each piece's part of a line starts `piece` entries on, so
                // the corner two pieces share is kept twice.
                Span<int> line = buffers.Dense.AsSpan((k * stride) + piece, stride - piece);
                int traced = (k & 1) == 0
                    ? lattice.TraceLine(y0 + (k * g), 0, 2 * g, points, line, lo, lo + across, begin == 0 ? 0 : lo + 1, buffers.Scratch)
                    : lattice.TraceLine(y0 + (k * g), g, 2 * g, points - 1, line, lo, lo + across - 1, lo, buffers.Scratch);
                again += traced;
                buffers.BottomLineRetracedOf[piece] = traced;
            }

            buffers.DenseRowOf[piece] = row;
            buffers.Retraced += again;
        }

        /// <summary>
        /// The piece's corner lines, corners x0 to x1: the top one is kept from the piece above when this thread
        /// rendered that piece last, else traced; the bottom one traced. Points traced again in double count once per
        /// line: the bottom line's always, the top line's only on row 0; and corner x0 only in the first piece (it is
        /// the piece on the left's last).
        /// </summary>
        private readonly void TraceCorners(int row)
        {
            AdaptiveLattice lattice = _lattice;
            Buffers buffers = _buffers;
            long size = lattice._size, again = 0;
            int begin = _begin, end = _end, piece = _piece, countFrom = begin == 0 ? 0 : begin + 1, length = lattice._plane.Width + 1;
            if (buffers.CornerLineOf[piece] != row)
            {
                int traced = lattice.TraceLine(row * size, 0, size, length, buffers.Corners(row, piece), begin, end, countFrom, buffers.Scratch);
                again += row == 0 ? traced : 0;
            }

            again += lattice.TraceLine((row + 1) * size, 0, size, length, buffers.Corners(row + 1, piece), begin, end, countFrom, buffers.Scratch);
            buffers.CornerLineOf[piece] = row + 1;
            buffers.Retraced += again;
        }

        /// <summary>
        /// How many pixels from <paramref name="x"/> to the piece's end have every minimum-depth point hit the same
        /// thing, <paramref name="id"/> (what the first one's top-left point hit): no square of theirs is refined
        /// further, so their value and rays are those of that thing alone (<see cref="Uniform"/>). The pixel after the
        /// run is not uniform.
        /// </summary>
        public readonly int UniformRun(int x, out int id)
        {
            AdaptiveLattice lattice = _lattice;
            int m = lattice.DenseDepth, stride = _buffers.DenseStride, first = _piece + (x << m), across = 1 << m;
            int[] dense = _buffers.Dense;
            id = dense[first];
            int run = _end - x;
            for (int k = 0, offset = first; k <= 2 << m && run > 0; k++, offset += stride)
            {
                // Even lines: pixel x + i needs its across + 1 corners from first + i·across equal; odd lines: its
                // across centres from there. Only the part of the line the run so far covers is looked at.
                bool even = (k & 1) == 0;
                ReadOnlySpan<int> line = dense.AsSpan(offset, (run * across) + (even ? 1 : 0));
                int same = line.IndexOfAnyExcept(id);
                if (same >= 0)
                {
                    run = even ? (same - 1) / across : same / across;
                }
            }

            return run;
        }

        /// <summary>
        /// With <see cref="CentreLine"/>: true when pixel <paramref name="x"/>'s four corners and its centre hit the same
        /// thing, so no quadrant is refined; its value and rays are then worked out once per thread, as for
        /// <see cref="UniformRun"/>.
        /// </summary>
        public readonly bool TryUniformWithCentre(AdaptiveSampler sampler, int x, int row, out Intensity value, out double samples)
        {
            ReadOnlySpan<int> top = TopCorners, bottom = BottomCorners;
            int id = top[x];
            if (top[x + 1] != id || bottom[x] != id || bottom[x + 1] != id || _buffers.Centres[x] != id)
            {
                value = default;
                samples = 0;
                return false;
            }

            Uniform(sampler, id, x, row, out value, out samples);
            return true;
        }

        /// <summary>The value and rays of a pixel every traced point of which hit <paramref name="id"/>, worked out once per thread and colour.</summary>
        public readonly void Uniform(AdaptiveSampler sampler, int id, int x, int row, out Intensity value, out double samples)
        {
            if (!_buffers.UniformKnown[id])
            {
                var constant = new ConstantSource(_lattice._palette[id], _lattice._size);
                _buffers.UniformValue[id] = AdaptivePixel.Evaluate(sampler, ref constant, x, row, out double charged);
                _buffers.UniformSamples[id] = charged;
                _buffers.UniformKnown[id] = true;
            }

            value = _buffers.UniformValue[id];
            samples = _buffers.UniformSamples[id];
        }

        /// <summary>Starts pixel (<paramref name="x"/>, <paramref name="row"/>).</summary>
        public void NextPixel(int x, int row)
        {
            _row = row;
            _pixel = x;
            _x0 = x * _lattice._size;
            _y0 = row * _lattice._size;
            _pixelStamp = ++_buffers.Stamp;
            if (_pixelStamp == 0)
            {
                // After 2³² pixels the stamps wrap: forget everything once.
                Array.Clear(_buffers.Interior);
                Array.Clear(_buffers.Lines);
                _pixelStamp = _buffers.Stamp = 1;
            }
        }

        /// <summary>
        /// Ends a piece of a row: its notes of horizontal-line points, sorted. Its top-edge points that the piece above
        /// traced too are taken off its rays when this thread rendered that piece last; else its top-edge notes, and
        /// the bottom-edge notes this thread kept for the piece, meet the other side's (<see cref="Meet"/>).
        /// </summary>
        public void EndRow(int row)
        {
            Buffers buffers = _buffers;
            int piece = _piece;
            buffers.TopPoints.Sort();
            buffers.BottomPoints.Sort();
            if (row > 0 && buffers.PointsRowOf[piece] == row - 1)
            {
                Rays -= Common(CollectionsMarshal.AsSpan(buffers.AboveBottomPointsOf[piece]), CollectionsMarshal.AsSpan(buffers.TopPoints));
            }
            else
            {
                Rays -= _lattice.FlushBottomPoints(buffers, piece);
                if (row > 0)
                {
                    Rays -= _lattice.Meet(buffers, row, piece, buffers.TopPoints);
                }
            }

            (buffers.AboveBottomPointsOf[piece], buffers.BottomPoints) = (buffers.BottomPoints, buffers.AboveBottomPointsOf[piece]);
            buffers.PointsRowOf[piece] = row;
            buffers.TopPoints.Clear();
            buffers.BottomPoints.Clear();
        }

        public readonly bool MayCross(long x0, long y0, long size) => _lattice.Guard?.MayCross(x0, y0, size) ?? false;

        public Intensity Centre(long lx, long ly)
        {
            if (TryDense(lx, ly, out Intensity known))
            {
                return known;
            }

            if (_lattice.CentreLine && ly - _y0 == _lattice._size / 2 && lx - _x0 == _lattice._size / 2)
            {
                return _lattice._palette[_buffers.Centres[_pixel]];
            }

            Rays++;
            return _lattice._palette[_lattice.Trace(lx, ly)];
        }

        public Intensity At(long lx, long ly, out double weight)
        {
            long size = _lattice._size, mask = size - 1;
            bool onColumn = (lx & mask) == 0, onRow = (ly & mask) == 0;
            AdaptiveLattice lattice = _lattice;
            weight = AdaptivePixel.Share(lx, ly, size);
            if (TryDense(lx, ly, out Intensity known))
            {
                return known;
            }

            if (onColumn && onRow)
            {
                return lattice._palette[(ly == _y0 ? TopCorners : BottomCorners)[(int)(lx / size)]];
            }

            if (onRow)
            {
                // Top or bottom pixel edge: shared with another row.
                (ly == _y0 ? _buffers.TopPoints : _buffers.BottomPoints).Add(lx);
                Rays++;
                return lattice._palette[lattice.Trace(lx, ly)];
            }

            if (onColumn)
            {
                // Left or right pixel edge: the right one is the next pixel's left one; on the line between two
                // pieces, the other piece's too.
                int line = lx == _x0 ? _pixel : _pixel + 1;
                int index = ((line & 1) * (int)(size + 1)) + (int)(ly - _y0);
                bool betweenPieces = (line == _begin && line != 0) || (line == _end && line != lattice._plane.Width);
                return lattice._palette[Kept(_buffers.Lines, index, ((ulong)(uint)(_row + 1) << 32) | (uint)line, lx, ly, betweenPieces)];
            }

            // Inside the pixel: every such point has even coordinates (no square below MaxDepth is refined).
            int inside = ((int)((ly - _y0) >> 1) * (int)((size >> 1) + 1)) + (int)((lx - _x0) >> 1);
            return lattice._palette[Kept(_buffers.Interior, inside, _pixelStamp, lx, ly, shared: false)];
        }

        /// <summary>
        /// What (<paramref name="lx"/>, <paramref name="ly"/>) hit: from entry <paramref name="index"/> of
        /// <paramref name="slots"/> while its stamp is <paramref name="stamp"/>, else traced and kept there (and noted
        /// for <see cref="SharedEdgeDuplicates"/> when another piece may trace it too).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private int Kept(ulong[] slots, int index, ulong stamp, long lx, long ly, bool shared)
        {
            if (slots[index + index] == stamp)
            {
                return (int)slots[index + index + 1];
            }

            int id = _lattice.Trace(lx, ly);
            slots[index + index] = stamp;
            slots[index + index + 1] = (ulong)id;
            if (shared)
            {
                _buffers.SharedPoints.Add(_buffers.Key(lx, ly));
            }

            Rays++;
            return id;
        }

        /// <summary>The value at (lx, ly) when it is one of the row's minimum-depth points, already traced.</summary>
        private readonly bool TryDense(long lx, long ly, out Intensity value)
        {
            AdaptiveLattice lattice = _lattice;
            int m = lattice.DenseDepth;
            if (m != 0)
            {
                int shift = lattice._denseShift;
                long g = 1L << shift, y = ly - _y0;
                if ((y & (g - 1)) == 0)
                {
                    long k = y >> shift, x = lx & ((2 * g) - 1);
                    if (x == ((k & 1) == 0 ? 0 : g))
                    {
                        value = lattice._palette[_buffers.Dense[(k * _buffers.DenseStride) + _piece + (lx >> (shift + 1))]];
                        return true;
                    }
                }
            }

            value = default;
            return false;
        }

        /// <summary>
        /// A thread's reusable storage, O(W): the row's two corner lines, its centres and its band of minimum-depth
        /// points; the pixel's inner lattice and two vertical lines as (stamp, index) pairs; the row's notes of
        /// horizontal-line points. Kept across renders (<see cref="Prepare"/> sizes it for each).
        /// </summary>
        internal sealed class Buffers
        {
            private readonly int[][] _corners = [[], []];

            /// <summary>
            /// Corner line <paramref name="line"/>'s entries for piece <paramref name="piece"/>, corner x at [x]: the
            /// lines are kept by parity, each piece's part starting <paramref name="piece"/> entries on, so the corner
            /// two pieces share is kept once for each and no piece writes another's.
            /// </summary>
            public Span<int> Corners(int line, int piece) => _corners[line & 1].AsSpan(piece);

            /// <summary>For each piece, the corner line its part of <see cref="Corners"/> holds last (−1: none yet).</summary>
            public int[] CornerLineOf { get; private set; } = [];

            /// <summary>Room for a line's packets: the whole packets that hold a piece's points, traced before the points are copied out.</summary>
            public int[] Scratch { get; private set; } = [];

            public int[] Centres { get; private set; } = [];

            public int[] Dense { get; private set; } = [];

            public Intensity[] UniformValue { get; private set; } = [];

            public double[] UniformSamples { get; private set; } = [];

            public bool[] UniformKnown { get; private set; } = [];

            public ulong[] Interior { get; private set; } = [];

            public ulong[] Lines { get; private set; } = [];

            public List<long> TopPoints { get; } = [];

            public List<long> BottomPoints { get; set; } = [];

            /// <summary>For each piece, the bottom-edge notes, sorted, of the row this thread rendered it in last (<see cref="PointsRowOf"/>).</summary>
            public List<long>[] AboveBottomPointsOf { get; private set; } = [];

            /// <summary>For each piece, the row whose bottom-edge notes <see cref="AboveBottomPointsOf"/> holds (−1: none).</summary>
            public int[] PointsRowOf { get; private set; } = [];

            public uint Stamp { get; set; }

            /// <summary>
            /// The points this thread traced again in double, summed into <see cref="RetracedPoints"/> when it returns its
            /// buffers: a count every thread added to at once would sit on the lattice's cache line, which every thread
            /// reads, and each add would take that line from the others.
            /// </summary>
            public long Retraced { get; set; }

            /// <summary>
            /// Entries per line of <see cref="Dense"/>: W·2^m + 1, plus one per piece (each piece's part of a line
            /// starts <c>piece</c> entries on, as in <see cref="Corners"/>).
            /// </summary>
            public int DenseStride { get; private set; }

            /// <summary>For each piece, the row whose band of minimum-depth points its part of <see cref="Dense"/> holds (−1: none yet).</summary>
            public int[] DenseRowOf { get; private set; } = [];

            /// <summary>For each piece, the points of that band's bottom line traced again in double.</summary>
            public int[] BottomLineRetracedOf { get; private set; } = [];

            /// <summary>The guard's notes on one block row's blocks (see <see cref="GuardBlocks"/>).</summary>
            public sbyte[] GuardBlocks { get; set; } = [];

            /// <summary>The block row <see cref="GuardBlocks"/> holds (−1: none).</summary>
            public int GuardBlockRow { get; set; } = -1;

            /// <summary>
            /// The points on a vertical line between two pieces that this thread traced, as keys (<see cref="Key"/>),
            /// for <see cref="SharedEdgeDuplicates"/>.
            /// </summary>
            public List<long> SharedPoints { get; } = [];

            /// <summary>Copies of this render's notes left in <see cref="Meet"/>'s slots, the first <see cref="_kept"/> in use; reused by the next render.</summary>
            private readonly List<EdgeNotes> _keptNotes = [];

            private int _kept;

            /// <summary>Lattice points per lattice line, W·S + 1.</summary>
            private long _lineLength;

            /// <summary>Lattice point (<paramref name="lx"/>, <paramref name="ly"/>)'s number, row by row: one key per point.</summary>
            public long Key(long lx, long ly) => (ly * _lineLength) + lx;

            /// <summary>A copy of <paramref name="points"/> that stays as it is until the next render (<see cref="Prepare"/>).</summary>
            public EdgeNotes Keep(List<long> points)
            {
                if (_kept == _keptNotes.Count)
                {
                    _keptNotes.Add(new EdgeNotes());
                }

                EdgeNotes notes = _keptNotes[_kept++];
                if (notes.Points.Length < points.Count)
                {
                    notes.Points = new long[Math.Max(points.Count, 2 * notes.Points.Length)];
                }

                points.CopyTo(notes.Points);
                notes.Count = points.Count;
                return notes;
            }

            /// <summary>The copy <see cref="Keep"/> made last is not needed.</summary>
            public void Unkeep() => _kept--;

            /// <summary>
            /// Sizes the buffers for a render of <paramref name="width"/> pixels a row, cut into
            /// <paramref name="pieces"/>, and <paramref name="size"/> lattice steps a pixel side, with
            /// <paramref name="denseLines"/> lines of <paramref name="densePoints"/> minimum-depth points (arrays of another
            /// length are replaced), and forgets the last render.
            /// </summary>
            public void Prepare(int width, long size, int denseLines, int densePoints, bool centres, int paletteLength, int pieces)
            {
                _corners[0] = Sized(_corners[0], width + 1 + pieces);
                _corners[1] = Sized(_corners[1], width + 1 + pieces);
                CornerLineOf = Sized(CornerLineOf, pieces);
                DenseStride = denseLines == 0 ? 0 : densePoints + pieces;
                Scratch = Sized(Scratch, Math.Max(width + 1, densePoints) + 16);
                Centres = Sized(Centres, centres ? width : 0);
                Dense = Sized(Dense, denseLines * DenseStride);
                DenseRowOf = Sized(DenseRowOf, pieces);
                BottomLineRetracedOf = Sized(BottomLineRetracedOf, pieces);
                PointsRowOf = Sized(PointsRowOf, pieces);
                if (AboveBottomPointsOf.Length != pieces)
                {
                    AboveBottomPointsOf = [.. Enumerable.Range(0, pieces).Select(_ => new List<long>())];
                }

                UniformValue = Sized(UniformValue, paletteLength);
                UniformSamples = Sized(UniformSamples, paletteLength);
                UniformKnown = Sized(UniformKnown, paletteLength);
                Interior = Sized(Interior, (int)(2 * ((size >> 1) + 1) * ((size >> 1) + 1)));
                Lines = Sized(Lines, (int)(2 * 2 * (size + 1)));
                Array.Clear(UniformKnown);
                Array.Clear(Interior);
                Array.Clear(Lines);
                Array.Fill(CornerLineOf, -1);
                Array.Fill(DenseRowOf, -1);
                Array.Fill(PointsRowOf, -1);
                Array.Clear(BottomLineRetracedOf);
                TopPoints.Clear();
                BottomPoints.Clear();
                foreach (List<long> kept in AboveBottomPointsOf)
                {
                    kept.Clear();
                }

                SharedPoints.Clear();
                _kept = 0;
                _lineLength = (width * size) + 1;
                Stamp = 0;
                Retraced = 0;
                GuardBlockRow = -1;

                static T[] Sized<T>(T[] kept, int length) => kept.Length == length ? kept : new T[length];
            }
        }
    }
}

/// <summary>A piece's notes of the points it traced on a horizontal pixel line (sorted lx), left for the piece on the line's other side.</summary>
internal sealed class EdgeNotes
{
    /// <summary>The notes, the first <see cref="Count"/> in use.</summary>
    public long[] Points { get; set; } = [];

    /// <summary>How many of <see cref="Points"/> are notes.</summary>
    public int Count { get; set; }
}

/// <summary>One render's slots where two pieces' <see cref="EdgeNotes"/> meet, one per horizontal pixel line and piece; kept across renders.</summary>
internal sealed class EdgeSlots
{
    /// <summary>The slots, (H + 1)·pieces, each null until a piece leaves its notes.</summary>
    public EdgeNotes?[] Slots { get; set; } = [];
}

/// <summary>A lattice whose every point has one value: a pixel none of whose traced points disagree.</summary>
/// <param name="value">The value.</param>
/// <param name="size">Lattice steps per pixel side, for the share of each point charged to the pixel.</param>
internal readonly struct ConstantSource(Intensity value, long size) : ILatticeSource
{
    public Intensity At(long lx, long ly, out double weight)
    {
        weight = AdaptivePixel.Share(lx, ly, size);
        return value;
    }

    public Intensity Centre(long lx, long ly) => value;

    public bool MayCross(long x0, long y0, long size) => false;
}
