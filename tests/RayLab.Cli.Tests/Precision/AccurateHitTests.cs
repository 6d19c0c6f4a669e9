using FsCheck;
using FsCheck.Fluent;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.PrecisionReport;

namespace RayLab.Cli.Tests.Precision;

/// <summary>
/// <see cref="AccurateHit.TryIntersectAccurate"/>: the renderer's decision, with the hit point placed on the
/// surface to within an ulp of |p|. Every residual | |p − C| − R | is evaluated exactly (BigInteger).
/// </summary>
public class AccurateHitTests
{
    private readonly ITestOutputHelper _output;

    public AccurateHitTests(ITestOutputHelper output) => _output = output;

    public static TheoryData<string> HardCaseNames() => [.. HardCase.All.Select(c => c.Name)];

    [Theory]
    [MemberData(nameof(HardCaseNames))]
    public void OnEveryHardCaseTheAccuratePointIsWithinOneUlpOfItsDistanceFromTheOrigin(string name)
    {
        HardCase hard = HardCase.All.Single(c => c.Name == name);
        Sphere sphere = hard.Sphere;
        ImagePlane plane = hard.Camera.GetImagePlane(48, 48);
        int hits = 0;
        double worstAccurate = 0, worstPlain = 0;
        for (int row = 0; row < plane.Height; row++)
        {
            for (int x = 0; x < plane.Width; x++)
            {
                Ray ray = plane.GetPixelRay(x, row, 0.5, 0.5);
                bool plain = sphere.TryIntersect(ray, plane.TMin, plane.TMax, out double tPlain);
                bool accurate = sphere.TryIntersectAccurate(ray, plane.TMin, plane.TMax, out double t, out Double3 p);
                Assert.Equal(plain, accurate);
                if (!accurate)
                {
                    continue;
                }

                hits++;
                Assert.True(double.IsFinite(t) && p.IsFinite, $"pixel ({x}, {row}): t = {t}, p = {p}");
                Assert.True(Math.Abs(t - tPlain) <= 1e-6 * tPlain, $"pixel ({x}, {row}): refined t {t:R} strays from {tPlain:R}");
                worstAccurate = Math.Max(worstAccurate, UlpsOff(p, sphere));
                worstPlain = Math.Max(worstPlain, UlpsOff(ray.At(tPlain), sphere));
            }
        }

        _output.WriteLine($"{name}: {hits} hits; worst | |p − C| − R | in ulp(|p|): accurate {worstAccurate:G3}, TryIntersect + Ray.At {worstPlain:G3}");
        Assert.True(hits > 0);
        Assert.True(worstAccurate <= 1, $"worst accurate residual {worstAccurate:G3} ulp(|p|)");
    }

    [Theory]
    [InlineData(1.0, 100)]
    [InlineData(0.01, 1000)]
    public void OnTheHorizonTheAccuratePointBeatsThePlainOneByOrdersOfMagnitude(double height, double plainAtLeast)
    {
        // The case the method exists for: o − C rounded in double loses the eye's height, so the plain point lies
        // hundreds to thousands of ulp(|p|) off the surface. (If the plain point ever became good, this test would
        // no longer show anything and should be revisited.)
        HardCase hard = HardCase.Horizon(height);
        ImagePlane plane = hard.Camera.GetImagePlane(64, 64);
        double worstAccurate = 0, worstPlain = 0;
        for (int row = 0; row < plane.Height; row++)
        {
            for (int x = 0; x < plane.Width; x++)
            {
                Ray ray = plane.GetPixelRay(x, row, 0.5, 0.5);
                if (hard.Sphere.TryIntersectAccurate(ray, plane.TMin, plane.TMax, out _, out Double3 p))
                {
                    worstAccurate = Math.Max(worstAccurate, UlpsOff(p, hard.Sphere));
                    Assert.True(hard.Sphere.TryIntersect(ray, plane.TMin, plane.TMax, out double tPlain));
                    worstPlain = Math.Max(worstPlain, UlpsOff(ray.At(tPlain), hard.Sphere));
                }
            }
        }

        _output.WriteLine($"R = 1e6, h = {height}: worst residual accurate {worstAccurate:G3} ulp(|p|), plain {worstPlain:G3} ulp(|p|)");
        Assert.True(worstPlain >= plainAtLeast, $"plain residual only {worstPlain:G3} ulp(|p|)");
        Assert.True(worstAccurate <= 0.5, $"accurate residual {worstAccurate:G3} ulp(|p|)");
    }

    [Fact]
    public void RandomSpheresAndRaysAtEveryScaleGiveTheSameDecisionAndAPointOnTheSurface()
    {
        // Centres and radii from 2^−30 to 2^30, origins from just outside the surface to 2^20 radii away, rays
        // aimed at points just inside, on or just outside the surface (grazing rays included), directions of any
        // length. Bound: an ulp of |p| (rounding p's coordinates), plus 2^−100 |o − C|²/R for the double-double
        // working precision — the latter only matters for an origin extremely far away in radii.
        double worst = 0;
        int hits = 0;
        PropertyCheck.ForAll(RayAndSphere, 3000, c =>
        {
            bool plain = c.Sphere.TryIntersect(c.Ray, 0, double.PositiveInfinity, out double tPlain);
            bool accurate = c.Sphere.TryIntersectAccurate(c.Ray, 0, double.PositiveInfinity, out double t, out Double3 p);
            Assert.Equal(plain, accurate);
            if (!accurate)
            {
                return;
            }

            hits++;
            Assert.True(double.IsFinite(t) && p.IsFinite);
            double f2 = ExactSphere.LengthSquared(c.Ray.Origin - c.Sphere.Center);
            double bound = ExactSphere.Ulp(p.Length) + Math.ScaleB(f2 / c.Sphere.Radius, -100);
            double residual = Math.Abs(ExactSphere.Residual(p, c.Sphere));
            worst = Math.Max(worst, residual / bound);
            Assert.True(residual <= bound, $"residual {residual:G3}, bound {bound:G3}");
        });
        _output.WriteLine($"{hits} hits of 3000; worst residual / bound {worst:G3}");
        Assert.True(hits > 1000, $"only {hits} hits: the generator should aim most rays at the sphere");
    }

    [Fact]
    public void SpecialRaysKeepTheirExactAnswers()
    {
        var unit = new Sphere(Double3.Zero, 1, Intensity.White);
        // Exactly tangent: touches (1, 0, 0) at t = 5.
        Assert.True(unit.TryIntersectAccurate(new Ray(new Double3(1, 0, 5), new Double3(0, 0, -1)), 0, 100, out double t, out Double3 p));
        Assert.Equal((5.0, new Double3(1, 0, 0)), (t, p));
        // Origin on the surface, going out: t = 0 and p is the origin.
        Assert.True(unit.TryIntersectAccurate(new Ray(new Double3(0, 0, 1), new Double3(0, 0, 1)), 0, 100, out t, out p));
        Assert.Equal((0.0, new Double3(0, 0, 1)), (t, p));
        // The near root clipped: the far one, as TryIntersect chose.
        Assert.True(unit.TryIntersectAccurate(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)), 4.5, 100, out t, out p));
        Assert.Equal((6.0, new Double3(0, 0, -1)), (t, p));
        // Misses stay misses, with no point.
        Assert.False(unit.TryIntersectAccurate(new Ray(new Double3(0, 0, 5), new Double3(0, 0, 1)), 0, 100, out _, out p));
        Assert.Equal(default, p);
        Assert.False(new Sphere(Double3.Zero, 0, Intensity.White).TryIntersectAccurate(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)), 0, 100, out _, out _));
        Assert.Throws<ArgumentNullException>(() => ((Sphere)null!).TryIntersectAccurate(new Ray(Double3.Zero, Double3.UnitY), 0, 1, out _, out _));
    }

    [Theory]
    [InlineData(1e150)]
    [InlineData(1e-150)]
    public void ScenesAtTheEndsOfTheRangeTryIntersectHandlesKeepThePointOnTheSurface(double scale)
    {
        // TryIntersect squares r, so it works up to |C|, r ≈ 1e154 and down to ≈ 1e-154. Within that range the
        // double-double products would overflow (b² ≈ |C|⁴ at 1e150) or lose their error terms to underflow
        // (at 1e-150): the method scales by powers of two first.
        var centre = new Double3(0.36 * scale, -0.48 * scale, 0.8 * scale);
        double distance = Math.Sqrt(ExactSphere.LengthSquared(centre / scale)) * scale;
        var sphere = new Sphere(centre, distance / 4, Intensity.White);
        foreach (Double3 d in new[] { centre / scale, new Double3(0.37, -0.47, 0.81), new Double3(0.36, -0.48 + 0.2, 0.8) })
        {
            var ray = new Ray(Double3.Zero, d);
            Assert.True(sphere.TryIntersect(ray, 0, double.PositiveInfinity, out double tPlain));
            Assert.True(sphere.TryIntersectAccurate(ray, 0, double.PositiveInfinity, out double t, out Double3 p));
            Assert.Equal(tPlain, t, tPlain * 1e-13);
            Assert.True(UlpsOff(p, sphere) <= 1, $"direction {d}: {UlpsOff(p, sphere):G3} ulp(|p|)");
        }
    }

    [Fact]
    public void DoubleDoubleSumsAndProductsOfTwoDoublesAreExact()
    {
        PropertyCheck.ForAll(Gen.Two(Scaled(-500, 500)), 2000, pair =>
        {
            (double a, double b) = pair;
            DoubleDouble s = DoubleDouble.TwoSum(a, b);
            Assert.Equal(Dyadic.From(a).Add(Dyadic.From(b)), Dyadic.From(s.Hi).Add(Dyadic.From(s.Lo)), DyadicComparer.Instance);
            DoubleDouble p = DoubleDouble.TwoProduct(a, b);
            if (double.IsFinite(p.Hi) && Math.Abs(p.Hi) > 1e-290)
            {
                Assert.Equal(Dyadic.From(a).Mul(Dyadic.From(b)), Dyadic.From(p.Hi).Add(Dyadic.From(p.Lo)), DyadicComparer.Instance);
            }
        });
    }

    /// <summary>How far a point is off the surface, in ulp(|p|), evaluated exactly.</summary>
    private static double UlpsOff(Double3 p, Sphere sphere) => Math.Abs(ExactSphere.Residual(p, sphere)) / ExactSphere.Ulp(p.Length);

    public sealed record RayCase(Sphere Sphere, Ray Ray)
    {
        public override string ToString() => $"sphere C = {Sphere.Center}, R = {Sphere.Radius:R}; ray o = {Ray.Origin}, d = {Ray.Direction}";
    }

    private static Gen<double> Scaled(int lo, int hi) =>
        PropertyCheck.Signed.SelectMany(m => PropertyCheck.PowerOfTwo(lo, hi), (m, s) => m * s);

    private static Gen<Double3> UnitVector { get; } =
        Gen.Three(PropertyCheck.Signed).Select(v => new Double3(v.Item1, v.Item2, v.Item3)).Where(v => v.Length > 0.1).Select(Double3.Normalize);

    private static Gen<RayCase> RayAndSphere { get; } =
        from centre in Gen.Three(Scaled(-30, 30))
        from radius in PropertyCheck.Between(0.5, 1).SelectMany(m => PropertyCheck.PowerOfTwo(-30, 30), (m, s) => m * s)
        from toOrigin in UnitVector
        from away in PropertyCheck.PowerOfTwo(-40, 20)
        from toTarget in UnitVector
        from side in Gen.Elements(-1.0, 0.0, 1.0)
        from off in PropertyCheck.PowerOfTwo(-50, -1)
        from length in PropertyCheck.PowerOfTwo(-20, 20)
        let c = new Double3(centre.Item1, centre.Item2, centre.Item3)
        let o = c + (radius * (1 + away) * toOrigin)
        let target = c + (radius * (1 + (side * off)) * toTarget)
        where (target - o).LengthSquared > 0
        select new RayCase(new Sphere(c, radius, Intensity.White), new Ray(o, length * (target - o)));

    /// <summary>Compares dyadic values, not representations (2·2^0 equals 1·2^1).</summary>
    private sealed class DyadicComparer : IEqualityComparer<Dyadic>
    {
        public static readonly DyadicComparer Instance = new();

        public bool Equals(Dyadic x, Dyadic y) => x.Sub(y).Sign == 0;

        public int GetHashCode(Dyadic obj) => 0;
    }
}
