using System.Buffers;
using System.Runtime.CompilerServices;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Sampling;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The guard of <see cref="AdaptiveSampler.Guard"/> (our own method, after Whitted 1980): whether a sphere's
/// silhouette may pass through a square of the adaptive lattice, although the square's traced points agree.
/// </summary>
/// <remarks>
/// <para>The ray through the square's centre passes at distance <c>p = |f − (f·d / d·d) d|</c> from a sphere's
/// centre (f = o − C: the ray–sphere test's stable discriminant is <c>r² − p²</c>). Every other ray of the square
/// differs from it by a window offset w with <c>|w| ≤ δ = ½ √((|a|·Δα)² + (|b|·Δβ)²)</c>, the square's half-diagonal on
/// the window (a ⊥ b). Orthographic: the rays are parallel and their origins differ by w, so their distances differ by at most
/// δ. Perspective: their directions d + w turn by an angle θ with <c>sin θ ≤ δ / |d|</c> about the eye, and the
/// distance <c>|f| sin∠(f, d)</c> changes by at most <c>|f| θ = |f| asin(δ / |d|)</c>. Calling that bound m, some ray of the square may hit
/// the sphere and another miss it only if <c>|p − r| ≤ m</c>: the square is refined then. The test is exact
/// geometry plus a margin of 10⁻⁹ (|f| + r) for rounding, so it never misses a silhouette that crosses the square
/// (off-axis windows included: a and b are the window's own edges), and it is nearly free where every sphere is
/// farther than m from the square's rays: a square of 1/32 pixel is refined only within about 1/32 pixel of a
/// silhouette. A sphere cut by the near or far plane (or around the eye) has a silhouette where the plane cuts
/// it too; there the square is refined whenever <c>p − m ≤ r</c>. Spheres hidden behind others are tested as
/// well: that costs rays, never accuracy.</para>
/// <para>A square tests only its tile's spheres. A tile (<see cref="TilePixels"/> pixels a side, or a multiple on very
/// large images) keeps the spheres that its own test passes with twice the margin; a coarse tile of
/// <see cref="CoarseTiles"/>² tiles keeps those its test passes with four times the margin, and a tile picks from its
/// coarse tile's. A square inside a tile has rays that are rays of the tile, so a sphere whose silhouette may cross
/// the square fails the tile's test by at most the square's margin plus its centre's offset, both within the tile's
/// margin: the doubled margin keeps every such sphere (rounding and the second-order terms included) and the answer
/// is the one every sphere gives. A tile's list is built when a square first asks for it, by whichever thread asks:
/// a sphere field's guard tests a few spheres per square, not all of them.</para>
/// </remarks>
internal sealed class SilhouetteGuard
{
    /// <summary>Pixels per side of a tile whose spheres a square inside it tests (the adaptive renderer's guard blocks are tiles).</summary>
    public const int TilePixels = 8;

    /// <summary>Tiles per side of a coarse tile.</summary>
    private const int CoarseTiles = 8;

    /// <summary>The most tiles kept: larger images take larger tiles (a power of two times <see cref="TilePixels"/>).</summary>
    private const long MaxTiles = 1 << 20;

    /// <summary>
    /// The fewest spheres for which squares test their tile's: below it a square tests every sphere, and the guard
    /// allocates nothing per frame (the lab's two spheres).
    /// </summary>
    internal const int TiledFrom = 32;

    private readonly ImagePlane _plane;
    private readonly (Double3 Center, double Radius, bool Clipped)[] _spheres;
    private readonly long _size;
    private readonly double _stepWidth, _stepHeight;
    private readonly int[] _all = [];
    private readonly long _tileSteps;
    private readonly int _tilesX, _tilesY, _coarseX;
    private readonly int[]?[]? _tiles, _coarse;

    /// <summary>The guard for <paramref name="scene"/> seen on <paramref name="plane"/>, with <paramref name="size"/> lattice steps per pixel.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The image plane.</param>
    /// <param name="size">Lattice steps per pixel.</param>
    /// <param name="tiles">Whether squares test their tile's spheres from <see cref="TiledFrom"/> spheres on (else every sphere: the reference the tests compare with).</param>
    public SilhouetteGuard(Scene scene, ImagePlane plane, long size, bool tiles = true)
    {
        _plane = plane;
        _size = size;
        _stepWidth = plane.A.Length / (plane.Width * (double)size);
        _stepHeight = plane.B.Length / (plane.Height * (double)size);
        var spheres = new List<(Double3, double, bool)>();
        foreach (Sphere sphere in scene.Spheres)
        {
            if (sphere.Radius == 0)
            {
                continue;
            }

            SphereVisibility visibility = plane.Visibility(sphere.Center, sphere.Radius);
            if (visibility != SphereVisibility.Hidden)
            {
                spheres.Add((sphere.Center, sphere.Radius, visibility == SphereVisibility.Clipped));
            }
        }

        _spheres = [.. spheres];
        long tilePixels = TilePixels;
        while (Tiles(plane.Width, tilePixels) * Tiles(plane.Height, tilePixels) > MaxTiles)
        {
            tilePixels *= 2;
        }

        _tileSteps = tilePixels * size;
        if (tiles && _spheres.Length >= TiledFrom)
        {
            _all = [.. Enumerable.Range(0, _spheres.Length)];
            _tilesX = (int)Tiles(plane.Width, tilePixels);
            _tilesY = (int)Tiles(plane.Height, tilePixels);
            _coarseX = (_tilesX + CoarseTiles - 1) / CoarseTiles;
            _tiles = new int[_tilesX * _tilesY][];
            _coarse = new int[_coarseX * ((_tilesY + CoarseTiles - 1) / CoarseTiles)][];
        }
    }

    /// <summary>True when some sphere's silhouette may pass through the square of <paramref name="size"/> lattice steps at (x0, y0).</summary>
    public bool MayCross(long x0, long y0, long size)
    {
        int[]? tile = _tiles is null ? null : TileOf(x0, y0, size);
        if (tile is { Length: 0 })
        {
            return false; // no sphere near the tile: the centre ray is not needed
        }

        (Double3 origin, Double3 d, double dd, double spread, double turn) = Centre(x0, y0, size);
        if (tile is not null)
        {
            foreach (int i in tile)
            {
                (Double3 center, double radius, bool clipped) = _spheres[i];
                if (Crosses(origin, d, dd, spread, turn, center, radius, clipped, 1))
                {
                    return true;
                }
            }

            return false;
        }

        foreach ((Double3 center, double radius, bool clipped) in _spheres)
        {
            if (Crosses(origin, d, dd, spread, turn, center, radius, clipped, 1))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>The spheres of the tile that holds the square (the tiles exist), or null where the square spans tiles.</summary>
    private int[]? TileOf(long x0, long y0, long size)
    {
        if (x0 < 0 || y0 < 0)
        {
            return null;
        }

        long tx = x0 / _tileSteps, ty = y0 / _tileSteps;
        return tx < _tilesX && ty < _tilesY && (x0 + size - 1) / _tileSteps == tx && (y0 + size - 1) / _tileSteps == ty
            ? Tile((int)tx, (int)ty)
            : null;
    }

    private static long Tiles(int pixels, long tilePixels) => (pixels + tilePixels - 1) / tilePixels;

    /// <summary>The spheres of tile (<paramref name="tx"/>, <paramref name="ty"/>), built on first use.</summary>
    private int[] Tile(int tx, int ty)
    {
        ref int[]? tile = ref _tiles![(ty * _tilesX) + tx];
        return Volatile.Read(ref tile)
            ?? Publish(ref tile, Keep(Coarse(tx / CoarseTiles, ty / CoarseTiles), tx * _tileSteps, ty * _tileSteps, _tileSteps, 2));
    }

    /// <summary>The spheres of coarse tile (<paramref name="cx"/>, <paramref name="cy"/>), built on first use.</summary>
    private int[] Coarse(int cx, int cy)
    {
        ref int[]? coarse = ref _coarse![(cy * _coarseX) + cx];
        long steps = _tileSteps * CoarseTiles;
        return Volatile.Read(ref coarse) ?? Publish(ref coarse, Keep(_all, cx * steps, cy * steps, steps, 4));
    }

    /// <summary>
    /// Puts <paramref name="list"/> in the empty <paramref name="slot"/>, or returns what another thread put there first:
    /// every thread then uses one list (two built at once are equal, so the answers never depend on which stays).
    /// </summary>
    private static int[] Publish(ref int[]? slot, int[] list) => Interlocked.CompareExchange(ref slot, list, null) ?? list;

    /// <summary>The spheres of <paramref name="spheres"/> that the square's test keeps with its margin times <paramref name="slack"/> (and any whose margin is not a number).</summary>
    private int[] Keep(int[] spheres, long x0, long y0, long size, double slack)
    {
        (Double3 origin, Double3 d, double dd, double spread, double turn) = Centre(x0, y0, size);
        if (!(double.IsFinite(spread) && double.IsFinite(turn)))
        {
            return spheres; // no bound for this square: every sphere stays
        }

        int[] scratch = ArrayPool<int>.Shared.Rent(spheres.Length);
        int kept = 0;
        foreach (int i in spheres)
        {
            (Double3 center, double radius, bool clipped) = _spheres[i];
            if (Crosses(origin, d, dd, spread, turn, center, radius, clipped, slack))
            {
                scratch[kept++] = i;
            }
        }

        int[] list = kept == spheres.Length ? spheres : kept == 0 ? [] : scratch[..kept];
        ArrayPool<int>.Shared.Return(scratch);
        return list;
    }

    /// <summary>The square's central ray (origin, direction d), d·d, and how far its other rays may pass from it: a constant and a part per unit of reach.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private (Double3 Origin, Double3 D, double Dd, double Spread, double Turn) Centre(long x0, long y0, long size)
    {
        (Double3 origin, Double3 d, double dd, double delta) = SquareRay(_plane.Basis, _size, _stepWidth, _stepHeight, x0, y0, size);
        (double spread, double turn) = _plane.SquareSpread(delta, dd);
        return (origin, d, dd, spread, turn);
    }

    /// <summary>
    /// <see cref="Centre"/>'s ray on the plane's unmanaged <see cref="RayBasis"/> (the device kernel's too): the central
    /// ray of the square of <paramref name="size"/> steps at (<paramref name="x0"/>, <paramref name="y0"/>) of a lattice of
    /// <paramref name="latticeSize"/> steps per pixel, each step <paramref name="stepWidth"/> by <paramref name="stepHeight"/>
    /// on the window, d·d, and the square's half-diagonal δ on the window.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static (Double3 Origin, Double3 D, double Dd, double Delta) SquareRay(in RayBasis basis, long latticeSize, double stepWidth, double stepHeight, long x0, long y0, long size)
    {
        double half = size * 0.5;
        Ray ray = basis.GetRay(WindowMapping.Alpha(x0 + half, basis.Width * (double)latticeSize), WindowMapping.Beta(y0 + half, basis.Height * (double)latticeSize));
        double delta = half * Math.Sqrt((stepWidth * stepWidth) + (stepHeight * stepHeight));
        Double3 d = ray.Direction;
        return (ray.Origin, d, Double3.Dot(d, d), delta);
    }

    /// <summary>The lattice step's width on the window: <see cref="SquareRay"/>'s <c>stepWidth</c>.</summary>
    internal double StepWidth => _stepWidth;

    /// <summary>The lattice step's height on the window: <see cref="SquareRay"/>'s <c>stepHeight</c>.</summary>
    internal double StepHeight => _stepHeight;

    /// <summary>The spheres the guard tests: radius above 0 and not hidden, each with whether a near or far plane cuts it.</summary>
    internal ReadOnlySpan<(Double3 Center, double Radius, bool Clipped)> Spheres => _spheres;

    /// <summary>
    /// The guard's test for one sphere, its margin times <paramref name="slack"/> (1: the square's own test): the
    /// central ray passes at p from the centre, the square's other rays within the margin of p, so some may hit and
    /// another miss only if <c>|p − r|</c> is within the margin (<c>p − r</c>, for a sphere a plane cuts).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool Crosses(Double3 origin, Double3 d, double dd, double spread, double turn, Double3 center, double radius, bool clipped, double slack)
    {
        Double3 f = origin - center;
        Double3 perp = f - ((Double3.Dot(f, d) / dd) * d);
        double p = perp.Length, reach = f.Length;
        double margin = slack * (spread + (reach * turn) + (1e-9 * (reach + radius)));
        return clipped ? p - margin <= radius : Math.Abs(p - radius) <= margin;
    }
}
