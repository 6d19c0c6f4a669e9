using RayLab.Cameras;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>
/// How far a regular n×n grid (one sample at each cell's centre) can be from a pixel's exact area mean.
/// </summary>
/// <remarks>
/// The bound: a cell that no border touches is one colour, so its centre sample is its exact mean; a touched cell
/// is off by at most D, the largest difference between two of the scene's colours (per channel). The pixel is the
/// mean of its n² cells, so <c>|grid − exact| ≤ D · m / n²</c>, with m the number of its cells that a border
/// touches. The borders are the pictures of circles — each sphere's outline, where the near and far planes cut a
/// sphere, where two spheres meet — worked out here from the geometry (not from the renderer), and m is counted by
/// walking each circle in steps shorter than a cell and marking every cell within one step of each point.
/// </remarks>
internal static class GridErrorBound
{
    /// <summary>For every pixel (row 0 first), how many of its n×n cells a border touches.</summary>
    public static int[] TouchedCells(Scene scene, ImagePlane plane, int n)
    {
        int w = plane.Width, h = plane.Height;
        var marked = new bool[w * n, h * n];
        foreach ((Double3 centre, double radius, Double3 normal) in Borders(scene, plane))
        {
            Double3 other = Math.Abs(normal.X) < 0.5 ? new Double3(1, 0, 0) : new Double3(0, 1, 0);
            Double3 t1 = Double3.Normalize(Double3.Cross(normal, other)), t2 = Double3.Cross(normal, t1);
            int steps = 4096;
            for (int pass = 0; pass < 2; pass++)
            {
                double step = 0;
                (double X, double Y)? previous = null;
                var points = new List<(double X, double Y)>(steps + 1);
                for (int i = 0; i <= steps; i++)
                {
                    double theta = 2 * Math.PI * i / steps;
                    Double3 p = centre + (radius * ((Math.Cos(theta) * t1) + (Math.Sin(theta) * t2)));
                    if (!plane.IsOrthographic && -Double3.Dot(p - plane.Eye, plane.W) <= 0)
                    {
                        throw new InvalidOperationException("a border reaches behind the eye: not a test scene");
                    }

                    (double X, double Y) q = ExactReferenceMath.ToPixel(plane, p);
                    if (previous is { } prev)
                    {
                        step = Math.Max(step, Math.Sqrt(((q.X - prev.X) * (q.X - prev.X)) + ((q.Y - prev.Y) * (q.Y - prev.Y))));
                    }

                    previous = q;
                    points.Add(q);
                }

                if (step > 0.25 / n && pass == 0)
                {
                    steps = (int)Math.Min(Math.Ceiling(steps * step * 8 * n), 1 << 24); // aim for ⅛ cell
                    continue;
                }

                // Each point of the circle is within half a step of a sample; mark cells within a whole step.
                double reach = step + (1e-9 / n);
                foreach ((double x, double y) in points)
                {
                    int i0 = Math.Max((int)Math.Floor((x - reach) * n), 0), i1 = Math.Min((int)Math.Floor((x + reach) * n), (w * n) - 1);
                    int j0 = Math.Max((int)Math.Floor((y - reach) * n), 0), j1 = Math.Min((int)Math.Floor((y + reach) * n), (h * n) - 1);
                    for (int i = i0; i <= i1; i++)
                    {
                        for (int j = j0; j <= j1; j++)
                        {
                            marked[i, j] = true;
                        }
                    }
                }

                break;
            }
        }

        var counts = new int[w * h];
        for (int i = 0; i < w * n; i++)
        {
            for (int j = 0; j < h * n; j++)
            {
                if (marked[i, j])
                {
                    counts[((j / n) * w) + (i / n)]++;
                }
            }
        }

        return counts;
    }

    /// <summary>The largest difference, per channel, between two of the colours the picture can show.</summary>
    public static Intensity LargestColourDifference(Scene scene)
    {
        var colours = scene.Spheres.Select(s => s.Color * scene.Ambient).Append(scene.Background).ToArray();
        return new Intensity(Spread(c => c.R), Spread(c => c.G), Spread(c => c.B));

        double Spread(Func<Intensity, double> channel) => colours.Max(channel) - colours.Min(channel);
    }

    // Every circle whose picture can be a border (centre, radius, unit normal), in world coordinates.
    private static IEnumerable<(Double3 Centre, double Radius, Double3 Normal)> Borders(Scene scene, ImagePlane plane)
    {
        double perT = plane.IsOrthographic ? 1 : plane.Distance;
        foreach (Sphere s in scene.Spheres.Where(s => s.Radius > 0))
        {
            double r = s.Radius;
            if (plane.IsOrthographic)
            {
                yield return (s.Center, r, plane.W);
            }
            else
            {
                // The circle where the rays from the eye touch the sphere.
                Double3 q = s.Center - plane.Eye;
                double l2 = q.LengthSquared;
                yield return (plane.Eye + ((1 - (r * r / l2)) * q), r * Math.Sqrt(l2 - (r * r)) / Math.Sqrt(l2), q / Math.Sqrt(l2));
            }

            double depth = -Double3.Dot(s.Center - plane.Eye, plane.W);
            foreach (double cut in new[] { plane.TMin * perT, plane.TMax * perT })
            {
                double offset = depth - cut;
                if (Math.Abs(offset) < r)
                {
                    yield return (s.Center + (offset * plane.W), Math.Sqrt((r * r) - (offset * offset)), plane.W);
                }
            }
        }

        Sphere[] spheres = [.. scene.Spheres];
        for (int i = 0; i < spheres.Length; i++)
        {
            for (int j = i + 1; j < spheres.Length; j++)
            {
                Double3 axis = spheres[j].Center - spheres[i].Center;
                double d = axis.Length, ri = spheres[i].Radius, rj = spheres[j].Radius;
                if (d < ri + rj && d > Math.Abs(ri - rj))
                {
                    double along = ((d * d) + (ri * ri) - (rj * rj)) / (2 * d);
                    yield return (spheres[i].Center + (along / d * axis), Math.Sqrt((ri * ri) - (along * along)), axis / d);
                }
            }
        }
    }
}
