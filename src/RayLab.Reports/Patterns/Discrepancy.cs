using RayLab.Sampling;

namespace RayLab.Reports.Patterns;

/// <summary>
/// How evenly a point set covers the unit square: the difference between the fraction of points in an
/// anchored box [0, a) × [0, b) and the box's area a·b, over all such boxes.
/// </summary>
/// <remarks>
/// <see cref="L2Star"/> is the root mean square of that difference over all boxes, in Warnock's closed form
/// (T. T. Warnock, "Computational investigations of low-discrepancy point sets", in Applications of Number Theory
/// to Numerical Analysis, 1972; see also Matoušek, Geometric Discrepancy, 1999, §1.4). <see cref="Star"/> is the
/// largest difference, found exactly by checking the boxes whose corners are points' coordinates (Dobkin, Eppstein
/// and Mitchell, "Computing the discrepancy with applications to supersampling patterns", ACM TOG 15(4), 1996),
/// in O(N² log N): meant for small N.
/// </remarks>
public static class Discrepancy
{
    /// <summary>
    /// The L2-star discrepancy T of the points (Warnock 1972), in two dimensions:
    /// T² = 1/9 − (1/(2N)) Σᵢ (1 − xᵢ²)(1 − yᵢ²) + (1/N²) Σᵢ Σⱼ (1 − max(xᵢ, xⱼ))(1 − max(yᵢ, yⱼ)). O(N²).
    /// </summary>
    /// <param name="points">At least one point in [0, 1]².</param>
    /// <returns>T ≥ 0; for N uniform random points its expected square is (1/4 − 1/9)/N.</returns>
    /// <exception cref="ArgumentException">No points.</exception>
    public static double L2Star(ReadOnlySpan<SamplePoint> points)
    {
        if (points.IsEmpty)
        {
            throw new ArgumentException("At least one point is needed.", nameof(points));
        }

        int n = points.Length;
        double single = 0, pairs = 0;
        for (int i = 0; i < n; i++)
        {
            double xi = points[i].X, yi = points[i].Y;
            single += (1 - (xi * xi)) * (1 - (yi * yi));
            pairs += (1 - xi) * (1 - yi); // the diagonal term i = j
            double row = 0;
            for (int j = i + 1; j < n; j++)
            {
                row += (1 - Math.Max(xi, points[j].X)) * (1 - Math.Max(yi, points[j].Y));
            }

            pairs += 2 * row; // the sum is symmetric in i and j
        }

        double squared = (1.0 / 9) - (single / (2.0 * n)) + (pairs / ((double)n * n));
        return Math.Sqrt(Math.Max(0, squared)); // rounding can take an exact 0 a hair below
    }

    /// <summary>
    /// The L2-star discrepancy of the centred n×n grid, (i + ½)/n in each axis, in closed form:
    /// T² = 1/(18 n²) + 7/(288 n⁴) (Warnock's sums factor over the two axes).
    /// </summary>
    /// <param name="n">Points per side, ≥ 1.</param>
    /// <returns>T.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="n"/> is less than 1.</exception>
    public static double L2StarOfCentredGrid(int n)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(n, 1);
        double n2 = (double)n * n;
        return Math.Sqrt((1.0 / (18 * n2)) + (7.0 / (288 * n2 * n2)));
    }

    /// <summary>
    /// The star discrepancy D* = sup over boxes [0, a) × [0, b) of |#points in the box / N − a·b|, exactly: the
    /// supremum is reached at a box whose a and b are points' coordinates or 1, counting the box open (points
    /// missing) or closed (points in excess) (Dobkin, Eppstein and Mitchell 1996).
    /// </summary>
    /// <param name="points">At least one point in [0, 1]².</param>
    /// <returns>D* in (0, 1].</returns>
    /// <exception cref="ArgumentException">No points.</exception>
    public static double Star(ReadOnlySpan<SamplePoint> points)
    {
        if (points.IsEmpty)
        {
            throw new ArgumentException("At least one point is needed.", nameof(points));
        }

        int n = points.Length;
        SamplePoint[] byX = points.ToArray();
        Array.Sort(byX, static (p, q) => p.X.CompareTo(q.X));
        double[] bs = [.. points.ToArray().Select(p => p.Y).Append(1.0).Distinct().Order()];
        var open = new List<double>(n);   // y of the points with x < a
        var closed = new List<double>(n); // y of the points with x ≤ a
        double worst = 0;
        int next = 0;
        // a runs over the distinct x coordinates, then 1.
        double[] xs = [.. byX.Select(p => p.X).Append(1.0).Distinct().Order()];
        foreach (double a in xs)
        {
            open.Clear();
            open.AddRange(closed); // points with x < a are the ones with x ≤ previous a
            while (next < n && byX[next].X <= a)
            {
                Insert(closed, byX[next].Y);
                next++;
            }

            foreach (double b in bs)
            {
                double area = a * b;
                int inOpen = LowerBound(open, b);   // y < b, x < a
                int inClosed = UpperBound(closed, b); // y ≤ b, x ≤ a
                worst = Math.Max(worst, Math.Max(area - ((double)inOpen / n), ((double)inClosed / n) - area));
            }
        }

        return worst;
    }

    private static void Insert(List<double> sorted, double value) => sorted.Insert(UpperBound(sorted, value), value);

    private static int LowerBound(List<double> sorted, double value)
    {
        int lo = 0, hi = sorted.Count;
        while (lo < hi)
        {
            int mid = (lo + hi) >> 1;
            if (sorted[mid] < value) { lo = mid + 1; } else { hi = mid; }
        }

        return lo;
    }

    private static int UpperBound(List<double> sorted, double value)
    {
        int lo = 0, hi = sorted.Count;
        while (lo < hi)
        {
            int mid = (lo + hi) >> 1;
            if (sorted[mid] <= value) { lo = mid + 1; } else { hi = mid; }
        }

        return lo;
    }
}
