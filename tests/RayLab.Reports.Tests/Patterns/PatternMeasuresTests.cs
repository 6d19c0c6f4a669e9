using RayLab.Reports.Patterns;
using RayLab.Sampling;

namespace RayLab.Reports.Tests.Patterns;

public class PatternMeasuresTests
{
    [Theory]
    [InlineData(4)]
    [InlineData(7)]
    [InlineData(25)]
    [InlineData(64)]
    public void A_sampler_claiming_n_rooks_has_one_point_per_row_and_column(int n)
    {
        foreach (string name in new[] { "nrooks", "cmj", "multijittered" })
        {
            if (name != "nrooks" && Math.Sqrt(n) % 1 != 0)
            {
                continue; // cmj and multijittered are n-rooks on their n×n grid; nrooks at any N
            }

            for (int pixel = 0; pixel < 10; pixel++)
            {
                SamplePoint[] points = PatternPoints.Of(Samplers.Create(name, n, 11), pixel, 3);
                Assert.Equal(n, points.Select(p => (int)(p.X * n)).Distinct().Count());
                Assert.Equal(n, points.Select(p => (int)(p.Y * n)).Distinct().Count());
            }
        }
    }

    [Fact]
    public void Random_points_are_not_n_rooks()
    {
        SamplePoint[] points = PatternPoints.Of(new RandomSampler(25, 1), 0, 0);
        Assert.True(points.Select(p => (int)(p.X * 25)).Distinct().Count() < 25);
    }

    [Fact]
    public void The_test_functions_exact_integrals_match_a_fine_quadrature()
    {
        const int Side = 2000;
        foreach (Integrand integrand in Integrand.All)
        {
            for (int r = 0; r < 3; r++)
            {
                (Func<double, double, double> f, double exact) = integrand.Place(r, 1);
                double sum = 0;
                for (int j = 0; j < Side; j++)
                {
                    for (int i = 0; i < Side; i++)
                    {
                        sum += f((i + 0.5) / Side, (j + 0.5) / Side);
                    }
                }

                Assert.Equal(exact, sum / Side / Side, 2e-4);
            }
        }
    }

    [Fact]
    public void Slopes_follow_the_literature_random_half_jittered_three_quarters_on_an_edge()
    {
        int[] counts = [16, 64, 256, 1024];
        var options = new PatternMeasureOptions(DiscrepancyRealisations: 1, StarMaxSamples: 0, IntegrationRealisations: 512);
        double Slope(Func<int, IPixelSampler> make, string function)
        {
            IReadOnlyList<PatternMeasure> measures = PatternMeasures.Measure(make, counts, options);
            return PatternMeasures.Slope(counts, [.. measures.Select(m => m.Rmse[function])]);
        }

        Assert.InRange(Slope(n => new RandomSampler(n, 1), "disc"), -0.6, -0.4);
        Assert.InRange(Slope(n => new JitteredSampler(n, 1), "disc"), -0.85, -0.65);
        // Owen-scrambled nets converge like N^(−3/2) on smooth functions (Owen 1997): at least as fast as −1.
        Assert.InRange(Slope(n => new SobolSampler(n, 1), "gaussian"), -1.7, -0.9);
    }

    [Fact]
    public void The_measures_do_not_depend_on_the_thread_count()
    {
        int[] counts = [4, 9, 16];
        var one = PatternMeasures.Measure(n => new JitteredSampler(n, 2), counts, new PatternMeasureOptions(4, 16, 16, 1, 1));
        var many = PatternMeasures.Measure(n => new JitteredSampler(n, 2), counts, new PatternMeasureOptions(4, 16, 16, 1, 4));
        for (int i = 0; i < counts.Length; i++)
        {
            Assert.Equal(one[i].L2Star, many[i].L2Star);
            Assert.Equal(one[i].Star, many[i].Star);
            Assert.Equal(one[i].Rmse, many[i].Rmse);
        }
    }

    [Fact]
    public void Counts_are_the_powers_of_two_and_squares_from_4_to_1024()
    {
        IReadOnlyList<int> counts = PatternMeasures.Counts();
        Assert.Equal(4, counts[0]);
        Assert.Equal(1024, counts[^1]);
        Assert.Contains(8, counts);
        Assert.Contains(25, counts);
        Assert.DoesNotContain(10, counts);
        Assert.All(PatternMeasures.Counts(squaresOnly: true), c => Assert.Equal(c, (int)Math.Pow(Math.Round(Math.Sqrt(c)), 2)));
    }
}
