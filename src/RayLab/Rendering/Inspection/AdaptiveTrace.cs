using System.Numerics;
using RayLab.Cameras;
using RayLab.Rendering.Adaptive;
using RayLab.Sampling;

namespace RayLab.Rendering.Inspection;

/// <summary>
/// One pixel of the lab's adaptive recursion, traced as the renderer traces it (<see cref="AdaptivePixel"/>): the
/// points in trace order with the share the combination rule gives each, the squares the recursion looked at, and the
/// value it gave the pixel. <see cref="Renderer.TracePixel"/> and <see cref="AdaptiveDiagram"/> are built on it.
/// </summary>
/// <param name="Points">The traced points, in trace order, each with its weight.</param>
/// <param name="Squares">The pixel, and the quadrants of each refined square.</param>
/// <param name="Value">The pixel's value by the recursion (what the renderer writes).</param>
internal sealed record AdaptiveTrace(IReadOnlyList<TracedPoint> Points, IReadOnlyList<AdaptiveSquare> Squares, Intensity Value)
{
    /// <summary>Traces pixel (<paramref name="px"/>, <paramref name="py"/>) with <paramref name="sampler"/>'s settings.</summary>
    public static AdaptiveTrace Run(Scene scene, ImagePlane plane, AdaptiveSampler sampler, int px, int py)
    {
        var source = new Recorder(scene, plane, sampler);
        Intensity evaluated = AdaptivePixel.Evaluate(sampler, ref source, px, py, out _);
        long size = source.Size, x0 = px * size, y0 = py * size;

        // A square was refined exactly when its centre was traced; each point's weight is the renderer's
        // combination rule applied to the points themselves.
        var squares = new List<AdaptiveSquare>();
        PointWeights weights;
        if (source.Centres.Contains((x0 + (size / 2), y0 + (size / 2))))
        {
            weights = Square(x0, y0, size, 0);
        }
        else
        {
            squares.Add(new AdaptiveSquare(0, 0, 1, 0, false));
            weights = CombinationRule.Mean(
                PointWeights.Of(x0, y0), PointWeights.Of(x0 + size, y0), PointWeights.Of(x0, y0 + size), PointWeights.Of(x0 + size, y0 + size));
        }

        PointWeights Square(long sx, long sy, long side, int depth)
        {
            squares.Add(new AdaptiveSquare((sx - x0) / (double)size, (sy - y0) / (double)size, side / (double)size, depth, true));
            long h = side / 2, q = side / 4;
            PointWeights centre = PointWeights.Of(sx + h, sy + h);
            return CombinationRule.Mean(
                Quadrant(sx, sy, sx, sy), Quadrant(sx + h, sy, sx + side, sy), Quadrant(sx, sy + h, sx, sy + side), Quadrant(sx + h, sy + h, sx + side, sy + side));

            // The quadrant at (qx, qy) whose corner (cx, cy) is a corner of the square.
            PointWeights Quadrant(long qx, long qy, long cx, long cy)
            {
                if (q > 0 && source.Centres.Contains((qx + q, qy + q)))
                {
                    return Square(qx, qy, h, depth + 1);
                }

                squares.Add(new AdaptiveSquare((qx - x0) / (double)size, (qy - y0) / (double)size, h / (double)size, depth + 1, false));
                return CombinationRule.Quadrant(PointWeights.Of(cx, cy), centre);
            }
        }

        var points = new TracedPoint[source.Order.Count];
        for (int i = 0; i < points.Length; i++)
        {
            ((long lx, long ly), Intensity v) = source.Order[i];
            points[i] = new TracedPoint((lx - x0) / (double)size, (ly - y0) / (double)size, v, weights.WeightOf((lx, ly)));
        }

        return new AdaptiveTrace(points, squares, evaluated);
    }

    // Each lattice point's share of the pixel's value: the combination rule's arithmetic on weights instead of intensities.
    private readonly struct PointWeights(Dictionary<(long, long), double> shares)
        : IAdditionOperators<PointWeights, PointWeights, PointWeights>, IMultiplyOperators<PointWeights, double, PointWeights>
    {
        public static PointWeights Of(long lx, long ly) => new(new() { [(lx, ly)] = 1 });

        public static PointWeights operator +(PointWeights a, PointWeights b)
        {
            var sum = new Dictionary<(long, long), double>(a.Shares);
            foreach (((long, long) point, double share) in b.Shares)
            {
                sum[point] = sum.GetValueOrDefault(point) + share;
            }

            return new PointWeights(sum);
        }

        public static PointWeights operator *(PointWeights a, double s) => new(a.Shares.ToDictionary(p => p.Key, p => p.Value * s));

        private Dictionary<(long, long), double> Shares => shares;

        public double WeightOf((long, long) point) => Shares.GetValueOrDefault(point);
    }

    // Traces lattice points straight through the camera, each once, and remembers the order.
    private struct Recorder(Scene scene, ImagePlane plane, AdaptiveSampler sampler) : ILatticeSource
    {
        public readonly long Size = 1L << (sampler.MaxDepth + 1);
        private readonly SilhouetteGuard? _guard = sampler.Guard ? new SilhouetteGuard(scene, plane, 1L << (sampler.MaxDepth + 1)) : null;
        public readonly List<((long X, long Y) Point, Intensity Value)> Order = [];
        public readonly HashSet<(long, long)> Centres = [];
        private readonly Dictionary<(long, long), Intensity> _seen = [];

        public readonly Intensity At(long lx, long ly, out double weight)
        {
            weight = 1;
            if (!_seen.TryGetValue((lx, ly), out Intensity value))
            {
                value = Shoot(lx, ly);
                _seen.Add((lx, ly), value);
                Order.Add(((lx, ly), value));
            }

            return value;
        }

        public readonly bool MayCross(long x0, long y0, long size) => _guard?.MayCross(x0, y0, size) ?? false;

        public readonly Intensity Centre(long lx, long ly)
        {
            Centres.Add((lx, ly));
            return At(lx, ly, out _);
        }

        private readonly Intensity Shoot(long lx, long ly) => plane.Trace(
            scene,
            plane.GetRay(WindowMapping.Alpha(lx, plane.Width * (double)Size), WindowMapping.Beta(ly, plane.Height * (double)Size)));
    }
}
