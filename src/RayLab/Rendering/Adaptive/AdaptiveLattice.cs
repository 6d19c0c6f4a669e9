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
    private readonly long[]?[] _topPoints, _bottomPoints;
    private readonly ConcurrentBag<Source.Buffers> _buffers = [];

    public AdaptiveLattice(Scene scene, ImagePlane plane, int maxDepth, RenderOptions options)
    {
        _scene = scene;
        _plane = plane;
        _size = 1L << (maxDepth + 1);
        _latticeWidth = plane.Width * (double)_size;
        _latticeHeight = plane.Height * (double)_size;
        int stride = plane.Width + 1;
        _palette = [scene.Background, .. scene.Spheres.Select(sphere => sphere.Color * scene.Ambient)];
        _corners = GC.AllocateUninitializedArray<int>(checked(stride * (plane.Height + 1)));
        _topPoints = new long[]?[plane.Height];
        _bottomPoints = new long[]?[plane.Height];
        Kernel = PointRenderer.ChooseKernel(options.Kernel, scene, plane, out PacketFrame? frame, out _);
        LatticeHits? hits = Kernel == RenderKernel.Scalar ? null : LatticeHits.TryCreate(scene, plane, _size, frame);
        long retraced = 0;
        Parallel.For(0, plane.Height + 1, options.Parallel, j =>
        {
            Span<int> row = _corners.AsSpan(j * stride, stride);
            int again = hits is null ? 0 : Kernel switch
            {
                RenderKernel.Vector512 => TraceCornerRow<Lanes512>(hits, j, row),
                RenderKernel.Vector256 => TraceCornerRow<Lanes256>(hits, j, row),
                _ => TraceCornerRow<Lanes128>(hits, j, row),
            };
            if (hits is null)
            {
                for (int i = 0; i < row.Length; i++)
                {
                    row[i] = LatticeHits.TraceScalar(_scene, _plane, _latticeWidth, _latticeHeight, i * _size, j * _size);
                }
            }

            if (again != 0)
            {
                Interlocked.Add(ref retraced, again);
            }
        });
        RetracedCorners = retraced;
    }

    /// <summary>The loop that traced the corner grid.</summary>
    public RenderKernel Kernel { get; }

    /// <summary>Corners whose float answer was uncertain and were traced again in double.</summary>
    public long RetracedCorners { get; }

    /// <summary>Steps per pixel side.</summary>
    public long Size => _size;

    /// <summary>Rays traced for the pixel corners.</summary>
    public long CornerRays => _corners.LongLength;

    /// <summary>
    /// True when pixel (<paramref name="x"/>, <paramref name="y"/>)'s four corners hit the same thing: a flat pixel
    /// (when the sampler does not insist on centres), whose value is that thing's, <paramref name="value"/>.
    /// </summary>
    public bool TryFlat(int x, int y, out Intensity value)
    {
        int stride = _plane.Width + 1;
        int top = (y * stride) + x, bottom = top + stride;
        int id = _corners[top];
        value = _palette[id];
        return _corners[top + 1] == id && _corners[bottom] == id && _corners[bottom + 1] == id;
    }

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
            buffers = new Source.Buffers(_size);
        }

        return new Source(this, buffers);
    }

    /// <summary>Gives a thread's buffers back for the next thread.</summary>
    public void Return(Source source) => _buffers.Add(source.Storage);

    private int TraceCornerRow<TL>(LatticeHits hits, int j, Span<int> row)
        where TL : struct, ILanes<TL> => _plane.IsOrthographic
            ? hits.TraceRow<TL, OrthographicRays>(j * _size, 0, _size, row)
            : hits.TraceRow<TL, PerspectiveRays>(j * _size, 0, _size, row);

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

        public Intensity Centre(long lx, long ly)
        {
            Rays++;
            return _lattice._palette[_lattice.Trace(lx, ly)];
        }

        public Intensity At(long lx, long ly, out double weight)
        {
            long size = _lattice._size, mask = size - 1;
            bool onColumn = (lx & mask) == 0, onRow = (ly & mask) == 0;
            AdaptiveLattice lattice = _lattice;
            if (onColumn && onRow)
            {
                weight = 0.25;
                return lattice._palette[lattice._corners[((ly / size) * (lattice._plane.Width + 1)) + (lx / size)]];
            }

            if (onRow)
            {
                // Top or bottom pixel edge: shared with another row.
                weight = 0.5;
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
                weight = 0.5;
                int line = lx == _x0 ? _pixel : _pixel + 1;
                slots = _buffers.Lines;
                index = ((line & 1) * (int)(size + 1)) + (int)(ly - _y0);
                stamp = ((ulong)(uint)(_row + 1) << 32) | (uint)line;
            }
            else
            {
                // Inside the pixel: every such point has even coordinates (no square below MaxDepth is refined).
                weight = 1;
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

        /// <summary>
        /// A thread's reusable storage: the pixel's inner lattice and two vertical lines as (stamp, index) pairs,
        /// and the row's notes of horizontal-line points.
        /// </summary>
        internal sealed class Buffers(long size)
        {
            public ulong[] Interior { get; } = new ulong[2 * ((size >> 1) + 1) * ((size >> 1) + 1)];

            public ulong[] Lines { get; } = new ulong[2 * 2 * (size + 1)];

            public List<long> Top { get; } = [];

            public List<long> Bottom { get; } = [];

            public uint Stamp { get; set; }
        }
    }
}
