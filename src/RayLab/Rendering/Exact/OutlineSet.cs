using System.Globalization;
using System.Runtime.InteropServices;
using RayLab.Cameras;
using RayLab.Geometry;

namespace RayLab.Rendering.Exact;

/// <summary>
/// Every border of a scene's picture that the exact reference must follow, as <see cref="Outline"/>s, and the
/// heights where two of them cross.
/// </summary>
/// <remarks>
/// The colour that <see cref="Scene.Trace"/> gives can only change where
/// <list type="bullet">
/// <item>a ray becomes tangent to a sphere (the sphere's outline);</item>
/// <item>a hit crosses the near or the far plane (the circle where that plane cuts a sphere);</item>
/// <item>two spheres are hit at the same point (the circle where the two spheres meet).</item>
/// </list>
/// All of these are pictures of circles, so ellipses, as long as no circle reaches behind a perspective eye.
/// A sphere no visible ray can reach (wholly nearer than the near plane, beyond the far plane or, for the
/// perspective camera, outside the view pyramid) is left out.
/// </remarks>
internal sealed class OutlineSet
{
    private readonly Crossing[] _crossings;
    private readonly int[] _rowStarts;

    private OutlineSet(Outline[] outlines, (Crossing[] Crossings, int[] RowStarts) byRow)
    {
        Outlines = outlines;
        (_crossings, _rowStarts) = byRow;
    }

    /// <summary>The most spheres in view the exact renderer draws (above it, <see cref="Build"/> refuses the scene).</summary>
    public const int MaxSpheresInView = 20_000;

    /// <summary>The outlines that reach into the image.</summary>
    public Outline[] Outlines { get; }

    /// <summary>How many heights there are where two outlines cross (and, to be safe, where they nearly touch).</summary>
    public int CrossingCount => _crossings.Length;

    /// <summary>
    /// The crossings with Y in [<paramref name="row"/>, <paramref name="row"/> + 1) (pixel row <paramref name="row"/>,
    /// and those on its top edge), each with the two outlines that cross there, into <paramref name="into"/>
    /// (cleared first), sorted by Y, then by the pair: the same list at every thread count.
    /// </summary>
    /// <param name="row">The pixel row, 0 at the top; the image's height gives the crossings on its bottom edge.</param>
    /// <param name="into">The list to fill.</param>
    public void CrossingsInRow(int row, List<Crossing> into)
    {
        into.Clear();
        into.AddRange(_crossings.AsSpan(_rowStarts[row], _rowStarts[row + 1] - _rowStarts[row]));
        CollectionsMarshal.AsSpan(into).Sort();
    }

    /// <summary>Finds the outlines of <paramref name="scene"/> as <paramref name="plane"/> sees it.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <param name="parallel">The threads to find the crossings with (and the cancellation); null for the defaults.</param>
    /// <param name="trace">Where to record when the outlines and their crossings were done, for the scaling tool; or null.</param>
    /// <exception cref="UnsupportedSceneException">
    /// A sphere that visible rays can reach extends behind a perspective camera's eye (or within 1e-4 of its
    /// radius of the plane through the eye): its outline is not an ellipse. Or the zoom is so high that double
    /// rounding alone moves its picture by more than 1e-6 of a pixel (<see cref="OutlineProjection.RoundingInPixels"/>).
    /// </exception>
    public static OutlineSet Build(Scene scene, ImagePlane plane, ParallelOptions? parallel = null, RowLoopTrace? trace = null)
    {
        var projection = new OutlineProjection(plane);
        double depthPerT = plane.DepthPerT;
        double near = plane.TMin * depthPerT, far = plane.TMax * depthPerT;
        var kept = new List<(Double3 Centre, double Radius)>();
        var keptIndex = new List<int>();
        var outlines = new List<Outline>();
        for (int i = 0; i < scene.Spheres.Count; i++)
        {
            Sphere sphere = scene.Spheres[i];
            double r = sphere.Radius;
            if (!Keep(plane, projection, sphere, i, kept.Count, out Double3 c))
            {
                continue;
            }

            double depth = -c.Z;
            kept.Add((c, r));
            keptIndex.Add(i);
            outlines.Add(projection.Sphere(c, r));
            foreach (double cut in (ReadOnlySpan<double>)[near, far])
            {
                double offset = depth - cut;
                if (Math.Abs(offset) < r)
                {
                    outlines.Add(projection.Circle(new Double3(c.X, c.Y, -cut), Math.Sqrt((r - offset) * (r + offset)), new Double3(0, 0, 1)));
                }
            }
        }

        foreach ((int i, int j) in MeetingCandidates(scene, keptIndex))
        {
            if (Meeting(kept[i], kept[j]) is { } circle)
            {
                outlines.Add(projection.Circle(circle.Centre, circle.Radius, circle.Normal));
            }
        }

        Outline[] inImage = outlines.Where(o => (o.Hx > 0 || o.Hy > 0)
            && o.Right >= 0 && o.Left <= plane.Width && o.Bottom >= 0 && o.Top <= plane.Height).ToArray();
        trace?.SetUpStep("outlines");
        (Crossing[], int[]) crossings = FindCrossings(inImage, plane.Height, parallel, trace);
        trace?.SetUpStep("crossings");
        return new OutlineSet(inImage, crossings);
    }

    /// <summary>
    /// Throws the <see cref="UnsupportedSceneException"/> that <see cref="Build"/> would throw for <paramref name="scene"/> seen through <paramref name="plane"/>,
    /// without making the outlines: the same test of each sphere, nothing kept.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <exception cref="UnsupportedSceneException">As <see cref="Build"/>.</exception>
    public static void Check(Scene scene, ImagePlane plane)
    {
        var projection = new OutlineProjection(plane);
        int inView = 0;
        for (int i = 0; i < scene.Spheres.Count; i++)
        {
            if (Keep(plane, projection, scene.Spheres[i], i, inView, out _))
            {
                inView++;
            }
        }
    }

    /// <summary>
    /// Whether sphere <paramref name="index"/> can be seen (it gets an outline), with its centre in camera
    /// coordinates; throws when it can be seen but not outlined.
    /// </summary>
    /// <param name="plane">The camera's image plane.</param>
    /// <param name="projection">The plane's outline projection.</param>
    /// <param name="sphere">The sphere.</param>
    /// <param name="index">Its index in the scene.</param>
    /// <param name="inView">How many spheres before it were kept.</param>
    /// <param name="c">Its centre in camera coordinates.</param>
    private static bool Keep(ImagePlane plane, OutlineProjection projection, Sphere sphere, int index, int inView, out Double3 c)
    {
        double r = sphere.Radius;
        c = projection.ToCamera(sphere.Center);
        double depth = -c.Z;
        if (r == 0 || plane.Visibility(sphere.Center, r) == SphereVisibility.Hidden || !plane.MayBeInView(c, r))
        {
            return false;
        }

        if (!plane.IsAheadOfEye(depth, r))
        {
            string span = string.Create(CultureInfo.InvariantCulture, $"from {depth - r:G6} to {depth + r:G6}");
            throw new UnsupportedSceneException(index, $"reaches behind the perspective camera (its depth along the gaze runs {span}): "
                + "the exact sampler needs every sphere it can see wholly in front of the eye, its nearest point at a depth "
                + "above 1e-4 of its radius (move the sphere or the camera, or use a point sampler)");
        }

        ThrowIfBeyondDoublePrecision(index, projection.RoundingInPixels(c, r));
        ThrowIfOneTooMany(index, inView);
        return true;
    }

    private static void ThrowIfBeyondDoublePrecision(int sphere, double rounding)
    {
        if (!(rounding <= 1e-6))
        {
            string amount = rounding.ToString("G2", CultureInfo.InvariantCulture);
            throw new UnsupportedSceneException(sphere, $"is seen at a zoom beyond double precision: rounding alone can move its picture by {amount} "
                + "pixels, and the exact sampler needs at most 1e-6 (widen the window, or move the camera closer to the sphere)");
        }
    }

    private static void ThrowIfOneTooMany(int sphere, int inView)
    {
        if (inView == MaxSpheresInView)
        {
            throw new UnsupportedSceneException(sphere, $"is one sphere more in view than the exact sampler draws: at most {MaxSpheresInView} "
                + "(its time grows with the crossings of their outlines; use a point sampler or the adaptive one)");
        }
    }

    /// <summary>
    /// The pairs (i &lt; j, positions in the kept list, in the order of the all-pairs loop) whose boxes meet: every
    /// pair without a hierarchy; with one, only the pairs it finds (the same circles, in the same order).
    /// </summary>
    private static List<(int I, int J)> MeetingCandidates(Scene scene, List<int> keptIndex)
    {
        var pairs = new List<(int, int)>();
        SphereHierarchy? hierarchy = scene.Hierarchy;
        if (hierarchy is null)
        {
            for (int i = 0; i < keptIndex.Count; i++)
            {
                for (int j = i + 1; j < keptIndex.Count; j++)
                {
                    pairs.Add((i, j));
                }
            }

            return pairs;
        }

        var position = new Dictionary<int, int>(keptIndex.Count);
        for (int k = 0; k < keptIndex.Count; k++)
        {
            position[keptIndex[k]] = k;
        }

        for (int i = 0; i < keptIndex.Count; i++)
        {
            Sphere sphere = scene.Spheres[keptIndex[i]];
            Double3 r = new(sphere.Radius, sphere.Radius, sphere.Radius);
            int self = i;
            var found = new List<int>();
            hierarchy.VisitOverlapping(sphere.Center - r, sphere.Center + r, other =>
            {
                if (position.TryGetValue(other, out int j) && j > self)
                {
                    found.Add(j);
                }

                return true;
            });
            found.Sort();
            foreach (int j in found)
            {
                pairs.Add((i, j));
            }
        }

        return pairs;
    }

    // The circle where two spheres meet, if their surfaces cross.
    private static (Double3 Centre, double Radius, Double3 Normal)? Meeting((Double3 Centre, double Radius) a, (Double3 Centre, double Radius) b)
    {
        Double3 axis = b.Centre - a.Centre;
        double d = axis.Length;
        if (!(d < a.Radius + b.Radius) || !(d > Math.Abs(a.Radius - b.Radius)))
        {
            return null; // apart, touching, or one inside the other
        }

        Double3 n = axis / d;
        double along = ((d * d) + (a.Radius * a.Radius) - (b.Radius * b.Radius)) / (2 * d);
        double radius = Math.Sqrt(Math.Max((a.Radius - along) * (a.Radius + along), 0));
        return (a.Centre + (along * n), radius, n);
    }

    internal static (Crossing[] Crossings, int[] RowStarts) FindCrossings(Outline[] outlines, int height, ParallelOptions? parallel, RowLoopTrace? trace = null)
    {
        var lists = new List<List<Crossing>>();

        // Only pairs whose heights overlap can cross: outlines by their top, each paired with those starting
        // above its bottom (a sweep down the image; every pair the all-pairs loop would find, as i < j). The pairs
        // are solved in parallel, each thread keeps its crossings in a list, and the lists are gathered by pixel row;
        // a row sorts its own (CrossingsInRow), in parallel, so the order is always the same.
        int[] byTop = [.. Enumerable.Range(0, outlines.Length).OrderBy(k => outlines[k].Top)];
        parallel ??= new ParallelOptions();
        // Outlines low in a deep scene overlap many others in height: their pairs are taken by stealing, as rows are.
        int workers = outlines.Length < 64 ? 1 : BandSchedule.Workers(byTop.Length, parallel.MaxDegreeOfParallelism);
        CrewFor.Run(new BandSchedule(0, byTop.Length, workers), () => new List<Crossing>(), (int s, int _, ref List<Crossing> found) =>
        {
            Span<double> thetas = stackalloc double[4];
            for (int u = s + 1; u < byTop.Length && outlines[byTop[u]].Top <= outlines[byTop[s]].Bottom; u++)
            {
                int i = Math.Min(byTop[s], byTop[u]), j = Math.Max(byTop[s], byTop[u]);
                Outline a = outlines[i], b = outlines[j];
                if (a.Hy == 0 || b.Hy == 0 || a.Right < b.Left || b.Right < a.Left || a.Bottom < b.Top || b.Bottom < a.Top)
                {
                    continue; // a horizontal segment is a break at its own height already
                }

                if (ClearlyApart(a, b))
                {
                    continue; // no root near the unit circle: the quartic would give none
                }

                // Walk the smaller ellipse by its angle and substitute it into the larger one's equation.
                (Outline walk, Outline fixedOne) = a.Hx + a.Hy <= b.Hx + b.Hy ? (a, b) : (b, a);
                int count = CrossingAngles(walk, fixedOne, thetas);
                for (int k = 0; k < count; k++)
                {
                    double y = walk.PointAt(thetas[k]).Y;
                    if (y >= 0 && y <= height)
                    {
                        found.Add(new Crossing(y, i, j));
                    }
                }
            }
        }, found =>
        {
            lock (lists)
            {
                lists.Add(found);
            }
        }, parallel.CancellationToken);

        trace?.SetUpStep("crossing pairs");
        return ByRow(lists, height);
    }

    /// <summary>
    /// The crossings of every list gathered by pixel row: counted by row, then placed, so row r's are
    /// <c>Crossings[RowStarts[r]..RowStarts[r + 1]]</c>, in no set order. Two steps per crossing on one thread, where
    /// sorting them all here would take some log n steps each (on the 960-sphere field, 16 000 crossings, a thousand
    /// of them in the horizon's rows).
    /// </summary>
    /// <param name="lists">The crossings each thread found.</param>
    /// <param name="height">The image's height: every crossing's <see cref="Crossing.Y"/> is in [0, height].</param>
    private static (Crossing[] Crossings, int[] RowStarts) ByRow(List<List<Crossing>> lists, int height)
    {
        var starts = new int[height + 2];
        foreach (List<Crossing> list in lists)
        {
            foreach (Crossing c in CollectionsMarshal.AsSpan(list))
            {
                starts[Row(c.Y) + 1]++;
            }
        }

        for (int r = 0; r <= height; r++)
        {
            starts[r + 1] += starts[r];
        }

        var placed = new Crossing[starts[height + 1]];
        int[] next = starts[..(height + 1)];
        foreach (List<Crossing> list in lists)
        {
            foreach (Crossing c in CollectionsMarshal.AsSpan(list))
            {
                placed[next[Row(c.Y)]++] = c;
            }
        }

        return (placed, starts);

        int Row(double y) => Math.Clamp((int)y, 0, height);
    }

    /// <summary>A height where two outlines cross (or nearly touch).</summary>
    /// <param name="Y">The height.</param>
    /// <param name="First">The outline with the smaller index.</param>
    /// <param name="Second">The other outline.</param>
    internal readonly record struct Crossing(double Y, int First, int Second) : IComparable<Crossing>
    {
        /// <inheritdoc/>
        public int CompareTo(Crossing other) =>
            Y != other.Y ? Y.CompareTo(other.Y) : First != other.First ? First.CompareTo(other.First) : Second.CompareTo(other.Second);
    }

    // True when neither ellipse is nearly flat and their extents along the line through their centres leave a gap of
    // 1 % of their sum: then every point of each lies outside the other by a margin (|L⁻¹ d| ≥ 1.01 for the ellipse
    // |L⁻¹ d| = 1, as d·u ≤ |L⁻¹ d| |Lᵀ u|) some hundred times what moving θ off the real line by the root test's
    // 1e-6 can change, so the quartic has no root that CrossingAngles would count and solving it can be skipped
    // (on the 960-sphere field, a fifth of the pairs whose boxes overlap).
    private static bool ClearlyApart(Outline a, Outline b)
    {
        if (!NotFlat(a) || !NotFlat(b))
        {
            return false;
        }

        // The extent of an ellipse along u (not normalised) is |Lᵀ u| = √((ux P + uy Hy)² + (ux Q)²), times |u|.
        double ux = b.Xc - a.Xc, uy = b.Yc - a.Yc;
        double ea = Math.Sqrt(Square((ux * a.P) + (uy * a.Hy)) + Square(ux * a.Q));
        double eb = Math.Sqrt(Square((ux * b.P) + (uy * b.Hy)) + Square(ux * b.Q));
        return (ux * ux) + (uy * uy) > 1.01 * (ea + eb);

        // The smaller axis at least 1 % of the larger: λmin/λmax ≥ det Σ/(tr Σ)² ≥ 1e-4, with det Σ = (Q Hy)².
        static bool NotFlat(Outline o) => Square(o.Q * o.Hy) >= 1e-4 * Square((o.Hx * o.Hx) + (o.Hy * o.Hy));

        static double Square(double v) => v * v;
    }

    // The angles θ of `walk` where it meets `fixedOne`, from g(θ) = 0 with g a trigonometric polynomial of degree ≤ 2.
    private static int CrossingAngles(Outline walk, Outline fixedOne, Span<double> thetas)
    {
        // Point of `walk` relative to the other's centre: dx = x0 + P cos θ + Q sin θ, dy = y0 + Hy cos θ.
        double x0 = walk.Xc - fixedOne.Xc, y0 = walk.Yc - fixedOne.Yc;
        double p = fixedOne.P, q = fixedOne.Q, h = fixedOne.Hy;
        // e = p·dy − h·dx is the component across the direction (p, h); a segment (q ≈ 0) is the line e = 0.
        double e0 = (p * y0) - (h * x0), e1 = (p * walk.Hy) - (h * walk.P), e2 = -h * walk.Q;
        if (q * h <= 1e-12 * ((p * p) + (q * q) + (h * h)))
        {
            return TrigRoots.Solve(e0, e1, e2, 0, 0, thetas);
        }

        // The ellipse is |L⁻¹ (dx, dy)|² = 1 with L = [[p, q], [h, 0]]; times det L² = (q h)²:
        // (q·dy)² + (p·dy − h·dx)² − (q h)² = 0.
        var (a0, a1, b1, a2, b2) = Square(q * y0, q * walk.Hy, 0);
        var (f0, f1, g1, f2, g2) = Square(e0, e1, e2);
        return TrigRoots.Solve(a0 + f0 - (q * h * q * h), a1 + f1, b1 + g1, a2 + f2, b2 + g2, thetas);
    }

    // (k0 + k1 cos θ + k2 sin θ)² as a0 + a1 cos θ + b1 sin θ + a2 cos 2θ + b2 sin 2θ.
    private static (double, double, double, double, double) Square(double k0, double k1, double k2) =>
        ((k0 * k0) + (((k1 * k1) + (k2 * k2)) / 2), 2 * k0 * k1, 2 * k0 * k2, ((k1 * k1) - (k2 * k2)) / 2, k1 * k2);
}
