using RayLab.Sampling;

namespace RayLab.Reports.Patterns;

/// <summary>
/// A test function on the pixel [0, 1]² with its exact integral, placed anew in each realisation (a random centre
/// or direction), so that an error measured over many pixels is an average over positions, not the luck of one.
/// </summary>
/// <remarks>
/// The functions follow the test set of Christensen, Kensler and Kilpatrick, "Progressive multi-jittered sample
/// sequences" (EGSR 2018) and the classes of Pilleboue et al., "Variance analysis for Monte Carlo integration"
/// (SIGGRAPH 2015): a disc (a curved edge, the lab's sphere outline), a Gaussian (smooth) and a bilinear step (an
/// edge whose value ramps along it, smooth on each side). For an edge the literature's RMSE slopes are −0.5 for
/// random points, −0.75 for jittered (Mitchell, "Consequences of stratified sampling in graphics", SIGGRAPH 1996);
/// for smooth functions −1 for jittered and low-discrepancy sets (up to log factors).
/// </remarks>
public abstract class Integrand
{
    private protected Integrand() { }

    /// <summary>The disc edge: 1 inside a disc of radius 0.3 with a random centre in [0.3, 0.7]², else 0. Exact: π·0.3².</summary>
    public static Integrand DiscEdge { get; } = new Disc();

    /// <summary>A Gaussian exp(−|x − c|²/(2σ²)), σ = 0.15, random centre c in [0.3, 0.7]²; exact by the error function.</summary>
    public static Integrand Gaussian { get; } = new GaussianBump();

    /// <summary>
    /// The bilinear step: x·y on one side of a line through a random point of [0.3, 0.7]² at a random angle, 0 on the
    /// other. Exact: the integral of x·y over the clipped polygon (Green's theorem).
    /// </summary>
    public static Integrand BilinearStep { get; } = new Step();

    /// <summary>The three test functions, in the order the figures show them.</summary>
    public static IReadOnlyList<Integrand> All { get; } = [DiscEdge, Gaussian, BilinearStep];

    /// <summary>The short name used in files and tables, e.g. <c>disc</c>.</summary>
    public abstract string Name { get; }

    /// <summary>A line for a figure's legend or a table.</summary>
    public abstract string Description { get; }

    /// <summary>Realisation <paramref name="realisation"/> of the function: its placement depends on it and the seed only.</summary>
    /// <param name="realisation">Which realisation.</param>
    /// <param name="seed">The seed.</param>
    /// <returns>The placed function and its exact integral over [0, 1]².</returns>
    public abstract (Func<double, double, double> Function, double Exact) Place(int realisation, uint seed);

    /// <summary>The Monte Carlo (quasi-Monte Carlo) estimate: the mean of the function at the points.</summary>
    /// <param name="function">The placed function.</param>
    /// <param name="points">The points.</param>
    public static double Estimate(Func<double, double, double> function, ReadOnlySpan<SamplePoint> points)
    {
        ArgumentNullException.ThrowIfNull(function);
        double sum = 0;
        foreach (SamplePoint p in points)
        {
            sum += function(p.X, p.Y);
        }

        return sum / points.Length;
    }

    private protected static double Unit(int realisation, uint seed, int which) =>
        CounterHash.ToUnit(CounterHash.SampleHash(CounterHash.PixelKey(realisation, which, seed ^ 0x9E3779B9u), 7 * which));

    private sealed class Disc : Integrand
    {
        private const double Radius = 0.3;

        public override string Name => "disc";

        public override string Description => "disc edge (r = 0.3)";

        public override (Func<double, double, double> Function, double Exact) Place(int realisation, uint seed)
        {
            double cx = 0.3 + (0.4 * Unit(realisation, seed, 1)), cy = 0.3 + (0.4 * Unit(realisation, seed, 2));
            return ((x, y) => ((x - cx) * (x - cx)) + ((y - cy) * (y - cy)) < Radius * Radius ? 1 : 0, Math.PI * Radius * Radius);
        }
    }

    private sealed class GaussianBump : Integrand
    {
        private const double Sigma = 0.15;

        public override string Name => "gaussian";

        public override string Description => "Gaussian (σ = 0.15)";

        public override (Func<double, double, double> Function, double Exact) Place(int realisation, uint seed)
        {
            double cx = 0.3 + (0.4 * Unit(realisation, seed, 3)), cy = 0.3 + (0.4 * Unit(realisation, seed, 4));
            double exact = 2 * Math.PI * Sigma * Sigma * Mass(cx) * Mass(cy);
            return ((x, y) => Math.Exp(-(((x - cx) * (x - cx)) + ((y - cy) * (y - cy))) / (2 * Sigma * Sigma)), exact);
        }

        // ∫₀¹ exp(−(t − c)²/(2σ²)) dt / (σ√(2π)) = (erf((1 − c)/(σ√2)) + erf(c/(σ√2))) / 2.
        private static double Mass(double c) => (SpecialFunctions.Erf((1 - c) / (Sigma * Math.Sqrt(2))) + SpecialFunctions.Erf(c / (Sigma * Math.Sqrt(2)))) / 2;
    }

    private sealed class Step : Integrand
    {
        public override string Name => "bilinear-step";

        public override string Description => "bilinear step (x·y on one side of a line)";

        public override (Func<double, double, double> Function, double Exact) Place(int realisation, uint seed)
        {
            double px = 0.3 + (0.4 * Unit(realisation, seed, 5)), py = 0.3 + (0.4 * Unit(realisation, seed, 6));
            double angle = 2 * Math.PI * Unit(realisation, seed, 7);
            double nx = Math.Cos(angle), ny = Math.Sin(angle);
            return ((x, y) => ((x - px) * nx) + ((y - py) * ny) < 0 ? x * y : 0, SpecialFunctions.BilinearOverClippedSquare(px, py, nx, ny));
        }
    }
}
