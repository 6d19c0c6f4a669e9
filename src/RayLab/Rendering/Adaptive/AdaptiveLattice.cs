using System.Runtime.InteropServices;
using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The points an adaptive render traces, each once, kept as the index of what they hit (0 the background,
/// k + 1 sphere k: the scenes' colours are flat), a row of pixels at a time by a thread's <see cref="Source"/>, in
/// memory of O(W) per thread: the row's two lines of W + 1 pixel corners (by the SIMD packet tracer where the frame
/// allows it, <see cref="LatticeHits"/>), then the points the recursion asks for, without a dictionary or an
/// allocation per point. Nothing of size W×H is kept.
/// </summary>
/// <remarks>
/// <para>The row loop hands a thread runs of consecutive rows, top to bottom: a row's top corner line is the bottom
/// line of the row above when the same thread rendered that row just before (the lines roll), else traced again (the
/// value is the same either way, and the count of rays and of points traced again in double counts each line once).</para>
/// <para>Points on a pixel's left and right edges are shared with the pixel beside it in the same row, which the same
/// thread evaluates next, so they are kept in a buffer per vertical pixel line. Points on a pixel's top and bottom
/// edges are shared with another row: each row traces those it needs and notes which, so that a point both rows
/// traced is counted as one ray — at once when the same thread rendered the row above just before, else once the
/// render is done.</para>
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
        Kernel = KernelChoice.Choose(options.Kernel, scene, plane, out PacketFrame? frame, out _);
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

    /// <summary>Points whose float answer was uncertain and were traced again in double.</summary>
    public long RetracedPoints => Interlocked.Read(ref _retraced);

    /// <summary>
    /// Traces lattice points (<paramref name="lxStart"/> + k·<paramref name="lxStep"/>, <paramref name="ly"/>) into
    /// <paramref name="ids"/>, by the packet path or the double loop; returns the points traced again in double.
    /// </summary>
    private int TraceLine(long ly, long lxStart, long lxStep, Span<int> ids)
    {
        if (_hits is null)
        {
            for (int i = 0; i < ids.Length; i++)
            {
                ids[i] = LatticeHits.TraceScalar(_scene, _plane, _latticeWidth, _latticeHeight, lxStart + (i * lxStep), ly);
            }

            return 0;
        }

        return Kernel switch
        {
            RenderKernel.Vector512 => _hits.TraceRow<Lanes512>(ly, lxStart, lxStep, ids),
            RenderKernel.Vector256 => _hits.TraceRow<Lanes256>(ly, lxStart, lxStep, ids),
            _ => _hits.TraceRow<Lanes128>(ly, lxStart, lxStep, ids),
        };
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
    /// Points on the horizontal pixel lines (other than corners) that both rows beside the line traced, where the two
    /// rows were not rendered one after the other by one thread: each thread's notes of a row's top-edge points
    /// against the notes of the row above's bottom-edge points, matched by line. The threads' buffers then go back to
    /// the pool.
    /// </summary>
    public long SharedEdgeDuplicates()
    {
        var notes = new List<(int Line, bool Top, Source.Buffers Owner, int Note)>();
        foreach (Source.Buffers buffers in _returned)
        {
            for (int n = 0; n < buffers.EdgeNotes.Count; n++)
            {
                (int row, bool top, _, _) = buffers.EdgeNotes[n];
                notes.Add((top ? row : row + 1, top, buffers, n));
            }
        }

        notes.Sort((a, b) => a.Line != b.Line ? a.Line.CompareTo(b.Line) : a.Top.CompareTo(b.Top));
        long duplicates = 0;
        for (int k = 1; k < notes.Count; k++)
        {
            if (notes[k].Line == notes[k - 1].Line && notes[k].Top && !notes[k - 1].Top)
            {
                duplicates += Common(notes[k - 1].Owner.EdgeNote(notes[k - 1].Note), notes[k].Owner.EdgeNote(notes[k].Note));
            }
        }

        foreach (Source.Buffers buffers in _returned)
        {
            _options.Return(buffers);
        }

        _returned.Clear();
        return duplicates;
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

    /// <summary>A thread's source for one row at a time, its buffers kept across rows, threads and renders (<see cref="RenderOptions.Pool"/>).</summary>
    public Source Rent()
    {
        var buffers = _options.Rent<Source.Buffers>();
        buffers.Prepare(_plane.Width, _size, DenseDepth == 0 ? 0 : ((2 << DenseDepth) + 1) * DenseStride, CentreLine, _palette.Length);
        return new Source(this, buffers);
    }

    /// <summary>A thread is done (called under the row loop's lock): its last row's bottom-edge notes are kept, and its buffers go back to the pool after <see cref="SharedEdgeDuplicates"/>.</summary>
    public void Return(Source source)
    {
        source.Storage.FlushBottomPoints();
        _returned.Add(source.Storage);
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
        private int _row, _pixel;
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

        /// <summary>What the pixel corners on the row's top edge hit, W + 1 entries.</summary>
        public readonly ReadOnlySpan<int> TopCorners => _buffers.TopCorners;

        /// <summary>What the pixel corners on the row's bottom edge hit, W + 1 entries.</summary>
        public readonly ReadOnlySpan<int> BottomCorners => _buffers.BottomCorners;

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

        /// <summary>
        /// Starts a row: its two corner lines (the top one taken from the row above when this thread rendered it),
        /// its centres with the quincunx, and with a minimum depth its band of minimum-depth points, line by line.
        /// </summary>
        public readonly void BeginRow(int row)
        {
            AdaptiveLattice lattice = _lattice;
            int m = lattice.DenseDepth;
            TraceCorners(row);
            if (lattice.CentreLine)
            {
                long centres = lattice.TraceLine((row * lattice._size) + (lattice._size / 2), lattice._size / 2, lattice._size, _buffers.Centres);
                if (centres != 0)
                {
                    Interlocked.Add(ref lattice._retraced, centres);
                }
            }

            if (m == 0)
            {
                return;
            }

            long g = lattice._size >> (m + 1), y0 = row * lattice._size;
            int stride = lattice.DenseStride, last = 2 << m, first = 0;
            long again = 0;
            if (row > 0 && _buffers.DenseRow == row - 1)
            {
                // This thread's last row was the one above: its bottom line is this row's top line, taken rather than
                // traced again (its points traced again in double counted as if it were, so the count does not
                // depend on which thread took which row).
                _buffers.Dense.AsSpan(last * stride, stride).CopyTo(_buffers.Dense);
                again += _buffers.BottomLineRetraced;
                first = 1;
            }

            for (int k = first; k <= last; k++)
            {
                // Even lines: the depth-m squares' corners, every 2g; odd lines: their centres, between them.
                int traced = (k & 1) == 0
                    ? lattice.TraceLine(y0 + (k * g), 0, 2 * g, _buffers.Dense.AsSpan(k * stride, stride))
                    : lattice.TraceLine(y0 + (k * g), g, 2 * g, _buffers.Dense.AsSpan(k * stride, stride - 1));
                again += traced;
                _buffers.BottomLineRetraced = traced;
            }

            _buffers.DenseRow = row;

            if (again != 0)
            {
                Interlocked.Add(ref lattice._retraced, again);
            }
        }

        /// <summary>
        /// The row's corner lines: the top one is the last row's bottom one when this thread rendered the row above,
        /// else traced; the bottom one traced. Points traced again in double count once per line: the bottom line's
        /// always, the top line's only on row 0.
        /// </summary>
        private readonly void TraceCorners(int row)
        {
            AdaptiveLattice lattice = _lattice;
            Buffers buffers = _buffers;
            long again = 0;
            if (buffers.CornerLine == row)
            {
                (buffers.Top, buffers.Bottom) = (buffers.Bottom, buffers.Top);
            }
            else
            {
                int traced = lattice.TraceLine(row * lattice._size, 0, lattice._size, buffers.TopCorners);
                again += row == 0 ? traced : 0;
            }

            again += lattice.TraceLine((row + 1) * lattice._size, 0, lattice._size, buffers.BottomCorners);
            buffers.CornerLine = row + 1;
            if (again != 0)
            {
                Interlocked.Add(ref lattice._retraced, again);
            }
        }

        /// <summary>
        /// How many pixels from <paramref name="x"/> on have every minimum-depth point hit the same thing,
        /// <paramref name="id"/> (what the first one's top-left point hit): no square of theirs is refined further, so
        /// their value and rays are those of that thing alone (<see cref="Uniform"/>). The pixel after the run is not
        /// uniform.
        /// </summary>
        public readonly int UniformRun(int x, out int id)
        {
            AdaptiveLattice lattice = _lattice;
            int m = lattice.DenseDepth, stride = lattice.DenseStride, first = x << m, across = 1 << m;
            int[] dense = _buffers.Dense;
            id = dense[first];
            int run = lattice._plane.Width - x;
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
            ReadOnlySpan<int> top = _buffers.TopCorners, bottom = _buffers.BottomCorners;
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
        /// Ends a row: its notes of horizontal-line points, sorted. Its top-edge points that the row above traced too
        /// are taken off its rays when this thread rendered that row just before; else its top-edge notes, and the
        /// bottom-edge notes of the row this thread rendered last, go to the lattice for <see cref="SharedEdgeDuplicates"/>.
        /// </summary>
        public void EndRow(int row)
        {
            Buffers buffers = _buffers;
            buffers.TopPoints.Sort();
            buffers.BottomPoints.Sort();
            if (row > 0 && buffers.PointsRow == row - 1)
            {
                Rays -= Common(CollectionsMarshal.AsSpan(buffers.AboveBottomPoints), CollectionsMarshal.AsSpan(buffers.TopPoints));
            }
            else
            {
                buffers.FlushBottomPoints();
                if (row > 0)
                {
                    buffers.Note(row, top: true, buffers.TopPoints);
                }
            }

            (buffers.AboveBottomPoints, buffers.BottomPoints) = (buffers.BottomPoints, buffers.AboveBottomPoints);
            buffers.PointsRow = row;
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
            weight = onColumn && onRow ? 0.25 : onColumn || onRow ? 0.5 : 1;
            if (TryDense(lx, ly, out Intensity known))
            {
                return known;
            }

            if (onColumn && onRow)
            {
                return lattice._palette[(ly == _y0 ? _buffers.TopCorners : _buffers.BottomCorners)[(int)(lx / size)]];
            }

            if (onRow)
            {
                // Top or bottom pixel edge: shared with another row.
                (ly == _y0 ? _buffers.TopPoints : _buffers.BottomPoints).Add(lx);
                Rays++;
                return lattice._palette[lattice.Trace(lx, ly)];
            }

            ulong[] slots;
            int index;
            ulong stamp;
            if (onColumn)
            {
                // Left or right pixel edge: the right one is the next pixel's left one.
                int line = lx == _x0 ? _pixel : _pixel + 1;
                slots = _buffers.Lines;
                index = ((line & 1) * (int)(size + 1)) + (int)(ly - _y0);
                stamp = ((ulong)(uint)(_row + 1) << 32) | (uint)line;
            }
            else
            {
                // Inside the pixel: every such point has even coordinates (no square below MaxDepth is refined).
                slots = _buffers.Interior;
                index = ((int)((ly - _y0) >> 1) * (int)((size >> 1) + 1)) + (int)((lx - _x0) >> 1);
                stamp = _pixelStamp;
            }

            ulong slot = slots[index + index];
            if (slot == stamp)
            {
                return lattice._palette[(int)slots[index + index + 1]];
            }

            int id = lattice.Trace(lx, ly);
            slots[index + index] = stamp;
            slots[index + index + 1] = (ulong)id;
            Rays++;
            return lattice._palette[id];
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
                        value = lattice._palette[_buffers.Dense[(k * lattice.DenseStride) + (lx >> (shift + 1))]];
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
            public int[] Top { get; set; } = [];

            public int[] Bottom { get; set; } = [];

            /// <summary>The row's top corner line, W + 1 entries.</summary>
            public Span<int> TopCorners => Top;

            /// <summary>The row's bottom corner line, W + 1 entries.</summary>
            public Span<int> BottomCorners => Bottom;

            /// <summary>The pixel line whose corners <see cref="Bottom"/> holds (−1: none yet).</summary>
            public int CornerLine { get; set; } = -1;

            public int[] Centres { get; private set; } = [];

            public int[] Dense { get; private set; } = [];

            public Intensity[] UniformValue { get; private set; } = [];

            public double[] UniformSamples { get; private set; } = [];

            public bool[] UniformKnown { get; private set; } = [];

            public ulong[] Interior { get; private set; } = [];

            public ulong[] Lines { get; private set; } = [];

            public List<long> TopPoints { get; } = [];

            public List<long> BottomPoints { get; set; } = [];

            /// <summary>The bottom-edge notes, sorted, of the row this thread rendered last (<see cref="PointsRow"/>).</summary>
            public List<long> AboveBottomPoints { get; set; } = [];

            /// <summary>The row whose bottom-edge notes <see cref="AboveBottomPoints"/> holds (−1: none).</summary>
            public int PointsRow { get; set; } = -1;

            public uint Stamp { get; set; }

            /// <summary>The row whose band of minimum-depth points <see cref="Dense"/> holds (−1: none yet).</summary>
            public int DenseRow { get; set; } = -1;

            /// <summary>Points of that band's bottom line traced again in double.</summary>
            public int BottomLineRetraced { get; set; }

            /// <summary>The guard's notes on one block row's blocks (see <see cref="GuardBlocks"/>).</summary>
            public sbyte[] GuardBlocks { get; set; } = [];

            /// <summary>The block row <see cref="GuardBlocks"/> holds (−1: none).</summary>
            public int GuardBlockRow { get; set; } = -1;

            /// <summary>The rows whose top or bottom-edge points this thread noted for <see cref="SharedEdgeDuplicates"/>, each a slice of <see cref="EdgePoints"/>.</summary>
            public List<(int Row, bool Top, int Start, int Count)> EdgeNotes { get; } = [];

            /// <summary>The noted points, sorted within each note.</summary>
            public List<long> EdgePoints { get; } = [];

            /// <summary>Notes row <paramref name="row"/>'s top or bottom-edge points (nothing when there are none).</summary>
            public void Note(int row, bool top, List<long> points)
            {
                if (points.Count != 0)
                {
                    EdgeNotes.Add((row, top, EdgePoints.Count, points.Count));
                    EdgePoints.AddRange(points);
                }
            }

            /// <summary>The points of note <paramref name="note"/>.</summary>
            public ReadOnlySpan<long> EdgeNote(int note) => CollectionsMarshal.AsSpan(EdgePoints).Slice(EdgeNotes[note].Start, EdgeNotes[note].Count);

            /// <summary>Notes the last row's bottom-edge points (the next row is not this thread's, or it is done).</summary>
            public void FlushBottomPoints()
            {
                if (PointsRow >= 0)
                {
                    Note(PointsRow, top: false, AboveBottomPoints);
                    AboveBottomPoints.Clear();
                    PointsRow = -1;
                }
            }

            /// <summary>
            /// Sizes the buffers for a render of <paramref name="width"/> pixels a row and <paramref name="size"/>
            /// lattice steps a pixel side (arrays of another length are replaced), and forgets the last render.
            /// </summary>
            public void Prepare(int width, long size, int denseEntries, bool centres, int paletteLength)
            {
                Top = Sized(Top, width + 1);
                Bottom = Sized(Bottom, width + 1);
                Centres = Sized(Centres, centres ? width : 0);
                Dense = Sized(Dense, denseEntries);
                UniformValue = Sized(UniformValue, paletteLength);
                UniformSamples = Sized(UniformSamples, paletteLength);
                UniformKnown = Sized(UniformKnown, paletteLength);
                Interior = Sized(Interior, (int)(2 * ((size >> 1) + 1) * ((size >> 1) + 1)));
                Lines = Sized(Lines, (int)(2 * 2 * (size + 1)));
                Array.Clear(UniformKnown);
                Array.Clear(Interior);
                Array.Clear(Lines);
                TopPoints.Clear();
                BottomPoints.Clear();
                AboveBottomPoints.Clear();
                EdgeNotes.Clear();
                EdgePoints.Clear();
                Stamp = 0;
                CornerLine = DenseRow = GuardBlockRow = PointsRow = -1;
                BottomLineRetraced = 0;

                static T[] Sized<T>(T[] kept, int length) => kept.Length == length ? kept : new T[length];
            }
        }
    }
}

/// <summary>A lattice whose every point has one value: a pixel none of whose traced points disagree.</summary>
/// <param name="value">The value.</param>
/// <param name="size">Lattice steps per pixel side, for the share of each point charged to the pixel.</param>
internal readonly struct ConstantSource(Intensity value, long size) : ILatticeSource
{
    public Intensity At(long lx, long ly, out double weight)
    {
        bool onColumn = (lx & (size - 1)) == 0, onRow = (ly & (size - 1)) == 0;
        weight = onColumn && onRow ? 0.25 : onColumn || onRow ? 0.5 : 1;
        return value;
    }

    public Intensity Centre(long lx, long ly) => value;

    public bool MayCross(long x0, long y0, long size) => false;
}
