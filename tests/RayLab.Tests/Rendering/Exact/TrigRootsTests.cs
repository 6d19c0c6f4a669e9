using RayLab.Rendering.Exact;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>
/// The crossings of two outlines come from the roots of g(θ) = a0 + a1 cos θ + b1 sin θ + a2 cos 2θ + b2 sin 2θ; a
/// missed root would be a missed place to split a pixel row, so every sign change of g must be found.
/// </summary>
public class TrigRootsTests
{
    private static double G(double[] c, double t) => c[0] + (c[1] * Math.Cos(t)) + (c[2] * Math.Sin(t)) + (c[3] * Math.Cos(2 * t)) + (c[4] * Math.Sin(2 * t));

    private static double[] Solve(double[] c)
    {
        Span<double> roots = stackalloc double[4];
        int n = TrigRoots.Solve(c[0], c[1], c[2], c[3], c[4], roots);
        return roots[..n].ToArray();
    }

    [Fact]
    public void TwoCrossedEllipsesMeetFourTimes()
    {
        // (2 cos θ, sin θ) on x² + y²/4 = 1: 4 cos² θ + sin² θ / 4 − 1 = 9/8 + (15/8) cos 2θ, zero where cos 2θ = −3/5.
        double[] roots = Solve([1.125, 0, 0, 1.875, 0]);

        Assert.Equal(4, roots.Length);
        Assert.All(roots, t => Assert.Equal(-0.6, Math.Cos(2 * t), 12));
        Assert.Equal(4, roots.Select(t => Math.Round(Math.Atan2(Math.Sin(t), Math.Cos(t)), 6)).Distinct().Count());
    }

    [Theory]
    [InlineData(1, 1, 0, 0, 0, Math.PI)]      // 1 + cos θ touches zero at π
    [InlineData(1, 0, 0, -1, 0, 0)]           // 1 − cos 2θ touches zero at 0 (and π)
    public void ATouchingPointIsStillReported(double a0, double a1, double b1, double a2, double b2, double touching)
    {
        double[] roots = Solve([a0, a1, b1, a2, b2]);

        Assert.Contains(roots, t => Math.Abs(Math.Cos(t - touching) - 1) < 1e-9);
    }

    [Fact]
    public void EverySignChangeOfRandomPolynomialsHasARootNearIt()
    {
        var random = new Random(7);
        const int grid = 20000;
        for (int trial = 0; trial < 300; trial++)
        {
            double[] c = [.. Enumerable.Range(0, 5).Select(_ => (random.NextDouble() * 2) - 1)];
            double[] roots = Solve(c);
            double scale = c.Sum(Math.Abs);
            Assert.All(roots, t => Assert.True(Math.Abs(G(c, t)) <= 1e-9 * scale, $"trial {trial}: g({t}) = {G(c, t)}"));
            for (int i = 0; i < grid; i++)
            {
                double t0 = 2 * Math.PI * i / grid, t1 = 2 * Math.PI * (i + 1) / grid;
                if (Math.Sign(G(c, t0)) * Math.Sign(G(c, t1)) < 0)
                {
                    Assert.Contains(roots, t => Math.Abs(Math.Sin((t - ((t0 + t1) / 2)) / 2)) <= Math.PI / grid);
                }
            }
        }
    }

    [Fact]
    public void APolynomialThatStaysPositiveHasNoRoots()
    {
        Assert.Empty(Solve([2, 1, 0, 0.5, 0]));
        Assert.Empty(Solve([0, 0, 0, 0, 0]));
    }
}
