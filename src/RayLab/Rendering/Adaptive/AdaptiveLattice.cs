using System.Collections.Concurrent;
using RayLab.Cameras;
using RayLab.Geometry;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The points an adaptive render traces, each once: the (W+1)×(H+1) pixel corners, traced up front; points on
/// pixel edges, shared between the two pixels beside them (and so between threads); and points inside a
/// pixel, kept only while that pixel is evaluated. A corner is kept as the index of what it hit (4 bytes, not
/// a 24-byte intensity: it relies on the scene's flat shading, <see cref="Scene.ColourOf"/>), so the grid is 8 MB
/// at 1920×1080.
/// </summary>
internal sealed class AdaptiveLattice
{
    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly long _size;
    private readonly double _latticeWidth, _latticeHeight;
    private readonly int[] _corners;
    private readonly Intensity[] _palette;
    private readonly ConcurrentDictionary<long, Lazy<Intensity>> _edges = new();
    private long _edgeRays;

    public AdaptiveLattice(Scene scene, ImagePlane plane, int maxDepth, ParallelOptions options)
    {
        _scene = scene;
        _plane = plane;
        _size = 1L << (maxDepth + 1);
        _latticeWidth = plane.Width * (double)_size;
        _latticeHeight = plane.Height * (double)_size;
        int stride = plane.Width + 1;
        // The scene is flat-shaded: a point's value is the ColourOf what it hit, so a corner keeps that index + 1
        // (0 the background, k + 1 sphere k) and this palette holds the colours.
        _palette = [.. Enumerable.Range(-1, scene.Spheres.Count + 1).Select(scene.ColourOf)];
        _corners = new int[(long)stride * (plane.Height + 1)];
        Parallel.For(0, plane.Height + 1, options, j =>
        {
            Span<int> row = _corners.AsSpan(j * stride, stride);
            for (int i = 0; i < row.Length; i++)
            {
                Ray ray = _plane.GetRayAt(i, j);
                row[i] = _scene.Nearest(ray, _plane.TMin, _plane.TMax) + 1;
            }
        });
    }

    /// <summary>
    /// True when pixel (<paramref name="x"/>, <paramref name="y"/>)'s four corners hit the same thing: a flat pixel
    /// (when the sampler does not insist on centres), whose value is that thing's, <paramref name="value"/>.
    /// </summary>
    public bool TryFlat(int x, int y, out Intensity value)
    {
        int stride = _plane.Width + 1;
        ReadOnlySpan<int> top = _corners.AsSpan((y * stride) + x, 2), bottom = _corners.AsSpan(((y + 1) * stride) + x, 2);
        int id = top[0];
        value = _palette[id];
        return top[1] == id && bottom[0] == id && bottom[1] == id;
    }

    /// <summary>Steps per pixel side.</summary>
    public long Size => _size;

    /// <summary>Rays traced for pixel corners and pixel-edge points so far.</summary>
    public long SharedRays => _corners.LongLength + Interlocked.Read(ref _edgeRays);

    public Intensity Corner(long lx, long ly) => _palette[_corners[((ly / _size) * (_plane.Width + 1)) + (lx / _size)]];

    public Intensity Edge(long lx, long ly)
    {
        long key = (ly * ((_plane.Width * _size) + 1)) + lx;
        return _edges.GetOrAdd(key, _ => new Lazy<Intensity>(() =>
        {
            Interlocked.Increment(ref _edgeRays);
            return Trace(lx, ly);
        })).Value;
    }

    public Intensity Trace(long lx, long ly)
    {
        Ray ray = _plane.GetRay(WindowMapping.Alpha(lx, _latticeWidth), WindowMapping.Beta(ly, _latticeHeight));
        return _scene.Trace(ray, _plane.TMin, _plane.TMax);
    }

    /// <summary>One thread's view: interior points cached per pixel, the rest from the shared lattice.</summary>
    internal struct Source(AdaptiveLattice lattice) : ILatticeSource
    {
        private readonly Dictionary<long, Intensity> _interior = new();

        /// <summary>Interior rays this thread traced.</summary>
        public long Rays { get; private set; }

        /// <summary>Forgets the previous pixel's interior points.</summary>
        public readonly void NextPixel()
        {
            if (_interior.Count > 0)
            {
                _interior.Clear();
            }
        }

        public Intensity Centre(long lx, long ly)
        {
            Rays++;
            return lattice.Trace(lx, ly);
        }

        public Intensity At(long lx, long ly, out double weight)
        {
            bool onColumn = lx % lattice.Size == 0, onRow = ly % lattice.Size == 0;
            if (onColumn && onRow)
            {
                weight = 0.25;
                return lattice.Corner(lx, ly);
            }

            if (onColumn || onRow)
            {
                weight = 0.5;
                return lattice.Edge(lx, ly);
            }

            weight = 1;
            long key = (ly << 32) ^ lx;
            if (!_interior.TryGetValue(key, out Intensity value))
            {
                value = lattice.Trace(lx, ly);
                _interior.Add(key, value);
                Rays++;
            }

            return value;
        }
    }
}
