using RayLab.Sampling;
using System.Collections.Concurrent;
using RayLab.Cameras;
using RayLab.Rendering.Point;
using RayLab.Rendering.Point.Packets;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The points an adaptive render traces, each once, kept as the index of what they hit (0 the background,
/// k + 1 sphere k: the scenes' colours are flat): the (W+1)×(H+1) pixel corners, traced up front for the whole
/// image (by the SIMD packet tracer where the frame allows it, <see cref="LatticeHits"/>); the rest per thread
/// by a <see cref="Source"/>, without a dictionary or an allocation per point.
/// </summary>
/// <remarks>
/// Points on a pixel's left and right edges are shared with the pixel beside it in the same row, which the same
/// thread evaluates next, so they are kept in a buffer per vertical pixel line. Points on a pixel's top and bottom
/// edges are shared with another row, perhaps on another thread: each row traces those it needs (the value is the
/// same either way) and notes which, so that a point both rows traced is counted as one ray.
/// </remarks>
internal sealed class AdaptiveLattice
{
    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly long _size;
    private readonly double _latticeWidth, _latticeHeight;
    private readonly int[] _corners;
    private readonly Intensity[] _palette;
    private readonly Rgb24[] _levels;
    private readonly long[]?[] _topPoints, _bottomPoints;
    private readonly ConcurrentBag<Source.Buffers> _buffers = [];

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
        int stride = plane.Width + 1;
        // The scene is flat-shaded: a point's value is the ColourOf what it hit, so a point keeps that index + 1
        // (0 the background, k + 1 sphere k) and this palette holds the colours.
        _palette = [.. Enumerable.Range(-1, scene.Spheres.Count + 1).Select(scene.ColourOf)];
        _levels = [.. _palette.Select(Rgb24.FromIntensity)];
        _corners = GC.AllocateUninitializedArray<int>(checked(stride * (plane.Height + 1)));
        _topPoints = new long[]?[plane.Height];
        _bottomPoints = new long[]?[plane.Height];
        Kernel = PointRenderer.ChooseKernel(options.Kernel, scene, plane, out PacketFrame? frame, out _);
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
        long retraced = 0;
        // The rows this render fills (all, or a band of Renderer.RenderRows) need the corner lines from their top to their bottom.
        (int first, int end) = options.Rows(plane.Height);
        _rows = end - first;
        CornerRays = (long)stride * (end > first ? _rows + 1 : 0);
        Parallel.For(first, end > first ? end + 1 : first, options.Parallel, j =>
        {
            int again = TraceLine(j * _size, 0, _size, _corners.AsSpan(j * stride, stride));
            if (again != 0)
            {
                Interlocked.Add(ref retraced, again);
            }
        });
        _retraced = retraced;
    }

    private long _retraced;

    /// <summary>How many rows of pixels this render fills.</summary>
    private readonly int _rows;

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
        : (((_plane.Width * (1L << DenseDepth)) + 1) * ((_rows * (1L << DenseDepth)) + 1)) - CornerRays
          + ((long)_plane.Width * _rows << (2 * DenseDepth));

    /// <summary>
    /// With the quincunx (and no minimum depth): every pixel's centre is traced, a row at a time as one lattice line,
    /// W·H rays in all.
    /// </summary>
    public bool CentreLine { get; }

    /// <summary>Rays for the pixel centres of <see cref="CentreLine"/>.</summary>
    public long CentreRays => CentreLine ? (long)_plane.Width * _rows : 0;

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
            RenderKernel.Vector512 => TraceLine<Lanes512>(_hits, ly, lxStart, lxStep, ids),
            RenderKernel.Vector256 => TraceLine<Lanes256>(_hits, ly, lxStart, lxStep, ids),
            _ => TraceLine<Lanes128>(_hits, ly, lxStart, lxStep, ids),
        };
    }

    /// <summary>The silhouette guard, when the sampler has one.</summary>
    public SilhouetteGuard? Guard { get; }

    /// <summary>The loop that traced the corner grid.</summary>
    public RenderKernel Kernel { get; }

    /// <summary>Steps per pixel side.</summary>
    public long Size => _size;

    /// <summary>Rays traced for the pixel corners.</summary>
    public long CornerRays { get; }

    /// <summary>What the pixel corners on horizontal pixel line <paramref name="j"/> (0 the top edge) hit, W + 1 entries.</summary>
    public ReadOnlySpan<int> CornerLine(int j) => _corners.AsSpan(j * (_plane.Width + 1), _plane.Width + 1);

    /// <summary>The 8-bit colour of a flat pixel all of whose corners hit <paramref name="id"/>.</summary>
    public Rgb24 Level(int id) => _levels[id];

    /// <summary>
    /// Points on horizontal pixel lines (other than corners) that more than one row traced: each row's sorted list
    /// of its top-edge points against the row above's list of its bottom-edge points.
    /// </summary>
    public long SharedEdgeDuplicates()
    {
        long duplicates = 0;
        for (int y = 1; y < _topPoints.Length; y++)
        {
            long[]? above = _bottomPoints[y - 1], below = _topPoints[y];
            if (above is null || below is null)
            {
                continue;
            }

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
                    duplicates++;
                    i++;
                    j++;
                }
            }
        }

        return duplicates;
    }

    /// <summary>A thread's source for one row at a time, with buffers reused across rows and renders' threads.</summary>
    public Source Rent()
    {
        if (!_buffers.TryTake(out Source.Buffers? buffers))
        {
            buffers = new Source.Buffers(_size, DenseDepth == 0 ? 0 : ((2 << DenseDepth) + 1) * DenseStride, CentreLine ? _plane.Width : 0, _palette.Length);
        }

        return new Source(this, buffers);
    }

    /// <summary>Gives a thread's buffers back for the next thread.</summary>
    public void Return(Source source) => _buffers.Add(source.Storage);

    private int TraceLine<TL>(LatticeHits hits, long ly, long lxStart, long lxStep, Span<int> ids)
        where TL : struct, ILanes<TL> => _plane.IsOrthographic
            ? hits.TraceRow<TL, OrthographicProjection>(ly, lxStart, lxStep, ids)
            : hits.TraceRow<TL, PerspectiveProjection>(ly, lxStart, lxStep, ids);

    private int Trace(long lx, long ly) => LatticeHits.TraceScalar(_scene, _plane, _latticeWidth, _latticeHeight, lx, ly);

    /// <summary>
    /// One thread's view of the lattice, a row at a time: corners from the grid; points on the vertical pixel lines
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

        /// <summary>Starts a row: with a minimum depth, its band of minimum-depth points is traced, line by line.</summary>
        public readonly void BeginRow(int row)
        {
            AdaptiveLattice lattice = _lattice;
            int m = lattice.DenseDepth;
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
            AdaptiveLattice lattice = _lattice;
            int stride = lattice._plane.Width + 1, top = (row * stride) + x, bottom = top + stride;
            int[] corners = lattice._corners;
            int id = corners[top];
            if (corners[top + 1] != id || corners[bottom] != id || corners[bottom + 1] != id || _buffers.Centres[x] != id)
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

        /// <summary>Ends a row: its notes of horizontal-line points go to the lattice, sorted.</summary>
        public readonly void EndRow(int row)
        {
            _lattice._topPoints[row] = Take(_buffers.Top);
            _lattice._bottomPoints[row] = Take(_buffers.Bottom);

            static long[]? Take(List<long> points)
            {
                if (points.Count == 0)
                {
                    return null;
                }

                long[] sorted = [.. points];
                Array.Sort(sorted);
                points.Clear();
                return sorted;
            }
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
                return lattice._palette[lattice._corners[((ly / size) * (lattice._plane.Width + 1)) + (lx / size)]];
            }

            if (onRow)
            {
                // Top or bottom pixel edge: shared with another row.
                (ly == _y0 ? _buffers.Top : _buffers.Bottom).Add(lx);
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
        /// A thread's reusable storage: the pixel's inner lattice and two vertical lines as (stamp, index) pairs,
        /// and the row's notes of horizontal-line points.
        /// </summary>
        internal sealed class Buffers(long size, int denseEntries, int centres, int paletteLength)
        {
            public int[] Centres { get; } = new int[centres];

            public int[] Dense { get; } = new int[denseEntries];

            public Intensity[] UniformValue { get; } = new Intensity[paletteLength];

            public double[] UniformSamples { get; } = new double[paletteLength];

            public bool[] UniformKnown { get; } = new bool[paletteLength];

            public ulong[] Interior { get; } = new ulong[2 * ((size >> 1) + 1) * ((size >> 1) + 1)];

            public ulong[] Lines { get; } = new ulong[2 * 2 * (size + 1)];

            public List<long> Top { get; } = [];

            public List<long> Bottom { get; } = [];

            public uint Stamp { get; set; }

            /// <summary>The row whose band of minimum-depth points <see cref="Dense"/> holds (−1: none yet).</summary>
            public int DenseRow { get; set; } = -1;

            /// <summary>Points of that band's bottom line traced again in double.</summary>
            public int BottomLineRetraced { get; set; }
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
