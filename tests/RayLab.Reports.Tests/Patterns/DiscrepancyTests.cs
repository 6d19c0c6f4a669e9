using RayLab.Reports.Patterns;
using RayLab.Sampling;

namespace RayLab.Reports.Tests.Patterns;

public class DiscrepancyTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(5)]
    [InlineData(16)]
    [InlineData(32)]
    public void The_regular_grid_has_the_closed_form_L2_star_discrepancy(int n)
    {
        SamplePoint[] grid = PatternPoints.Of(new RegularSampler(n * n), 3, 7);

        double measured = Discrepancy.L2Star(grid);

        Assert.Equal(Discrepancy.L2StarOfCentredGrid(n), measured, 1e-12);
    }

    [Fact]
    public void The_closed_form_for_one_centred_point_is_Warnocks_sum_by_hand()
    {
        // One point (½, ½): T² = 1/9 − ½ (¾)² + ¼.
        Assert.Equal(Math.Sqrt((1.0 / 9) - (0.5 * 0.75 * 0.75) + 0.25), Discrepancy.L2StarOfCentredGrid(1), 1e-15);
    }

    [Fact]
    public void Random_points_have_the_expected_mean_square_L2_star_discrepancy()
    {
        // E[T²] = (1/4 − 1/9)/N for N independent uniform points.
        const int N = 32, Realisations = 2000;
        var random = new RandomSampler(N, seed: 5);
        double meanSquare = Enumerable.Range(0, Realisations)
            .Select(r => Math.Pow(Discrepancy.L2Star(PatternPoints.Of(random, r % 64, r / 64)), 2)).Average();

        Assert.Equal((0.25 - (1.0 / 9)) / N, meanSquare, 0.05 * (0.25 - (1.0 / 9)) / N);
    }

    [Fact]
    public void The_star_discrepancy_of_one_centred_point_is_three_quarters()
    {
        // The closed box [0, ½]² holds the point (fraction 1) but has area ¼.
        Assert.Equal(0.75, Discrepancy.Star([new SamplePoint(0.5, 0.5)]), 1e-15);
    }

    [Fact]
    public void The_star_discrepancy_matches_a_brute_force_search_over_all_corner_boxes()
    {
        var random = new RandomSampler(12, seed: 9);
        for (int pixel = 0; pixel < 20; pixel++)
        {
            SamplePoint[] points = PatternPoints.Of(random, pixel, 0);
            double[] xs = [.. points.Select(p => p.X).Append(1)];
            double[] ys = [.. points.Select(p => p.Y).Append(1)];
            double brute = 0;
            foreach (double a in xs)
            {
                foreach (double b in ys)
                {
                    double open = points.Count(p => p.X < a && p.Y < b) / 12.0;
                    double closed = points.Count(p => p.X <= a && p.Y <= b) / 12.0;
                    brute = Math.Max(brute, Math.Max((a * b) - open, closed - (a * b)));
                }
            }

            Assert.Equal(brute, Discrepancy.Star(points), 1e-15);
        }
    }

    [Fact]
    public void The_star_discrepancy_bounds_the_L2_star_discrepancy_from_above()
    {
        foreach (string name in Samplers.Names)
        {
            SamplePoint[] points = PatternPoints.Of(Samplers.Create(name, 16, 3), 1, 2);
            Assert.True(Discrepancy.Star(points) >= Discrepancy.L2Star(points), name);
        }
    }

    [Fact]
    public void No_points_is_an_error_naming_the_argument()
    {
        Assert.Equal("points", Assert.Throws<ArgumentException>(() => Discrepancy.L2Star([])).ParamName);
        Assert.Equal("points", Assert.Throws<ArgumentException>(() => Discrepancy.Star([])).ParamName);
    }
}
