using RayLab.Cameras;
using RayLab.PrecisionReport;

namespace RayLab.Cli.Tests.Precision;

/// <summary>
/// Hard numerical cases for the sphere intersection and the cameras. Every expected hit/miss decision is
/// computed exactly: each double is a dyadic rational m·2^e, so the ray and sphere the library sees are
/// represented without rounding in BigInteger arithmetic (<see cref="ExactSphere"/>, shared with docs/precision.md), and the decision
/// "the line passes within r of C and the sphere is ahead" is |f × d|² ≤ r²|d|² with f·d &lt; 0 (f = o − C),
/// evaluated with no rounding at all. No expected value reuses the library's formula.
/// </summary>
public class HardCaseTests
{
    private readonly ITestOutputHelper _output;

    public HardCaseTests(ITestOutputHelper output) => _output = output;

    // ---------------------------------------------------------------- tiny sphere far away

    [Theory]
    [InlineData("perspective", 1e-4, false)]
    [InlineData("perspective", 1e-5, false)]
    [InlineData("perspective", 1e-6, false)]
    [InlineData("orthographic", 1e-4, false)]
    [InlineData("orthographic", 1e-5, false)]
    [InlineData("orthographic", 1e-6, false)]
    [InlineData("perspective", 1e-4, true)]
    [InlineData("perspective", 1e-5, true)]
    [InlineData("perspective", 1e-6, true)]
    [InlineData("orthographic", 1e-4, true)]
    [InlineData("orthographic", 1e-5, true)]
    [InlineData("orthographic", 1e-6, true)]
    public void ATinyFarSphereIsHitExactlyWhereTheExactDecisionSays(string type, double ratio, bool edge)
    {
        // edge = false: the 32×32 window frames the whole sphere. edge = true: it is zoomed onto the right-hand
        // silhouette, 2e-8 of the silhouette radius wide, so pixel centres straddle it at relative distances
        // from 1e-8 down to the pixel spacing, 6e-10 here (the same cases as docs/precision.md).
        HardCase hard = HardCase.TinyFarSphere(type, ratio, edge);
        Sphere sphere = hard.Sphere;
        Camera camera = hard.Camera;
        (int hits, int wrong, int close, double worstMargin) = CompareImage(sphere, camera.GetImagePlane(32, 32), 1e-12);
        _output.WriteLine($"{type} r/D={ratio:G} {(edge ? "edge" : "whole")}: hits {hits}/1024, wrong {wrong}, within 1e-12 of the silhouette {close}, smallest |relative margin| {worstMargin:G3}");
        Assert.True(edge ? hits > 0 && hits < 1024 : hits > 100 && hits < 1000, $"framing: {hits} hits");
        Assert.Equal(0, wrong);
    }

    // ---------------------------------------------------------------- huge sphere, eye near the surface

    [Theory]
    [InlineData(1.0)]
    [InlineData(0.01)]
    public void AHugeSphereSeenFromJustAboveIsHitExactlyWhereTheExactDecisionSays(double height)
    {
        (Sphere sphere, ImagePlane plane) = Horizon(height);
        (int hits, int wrong, int close, double worstMargin) = CompareImage(sphere, plane, 1e-12);
        _output.WriteLine($"R=1e6, h={height}: hits {hits}/4096, wrong {wrong}, within 1e-12 of the horizon {close}, smallest |relative margin| {worstMargin:G3}");
        Assert.True(hits > 500 && hits < 3600, $"framing: {hits} hits");
        Assert.Equal(0, wrong);
    }

    [Theory]
    [InlineData(1.0)]
    [InlineData(0.01)]
    public void HitsOnAHugeSphereLieOnItsSurfaceToTwoUlpsOfTheRadius(double height)
    {
        // Bound: | |p − C| − R | ≤ 2 ulp(R) = 2 ulp(|p − C|): what double arithmetic on quantities of size R
        // (o − C is already rounded to ulp(R)/2 when h = 0.01) can promise. Residual evaluated exactly as above.
        // Code that needs the point itself uses TryIntersectAccurate: within an ulp of |p| (AccurateHitTests).
        (int n, double worstResidual, double worstUlpsOfP, double worstUlpsOfR) = HorizonResiduals(height);
        _output.WriteLine($"R=1e6, h={height}: {n} hits, worst residual {worstResidual:G3} = {worstUlpsOfP:G3} ulp(|p|) = {worstUlpsOfR:G3} ulp(R)");
        Assert.True(n > 0);
        Assert.True(worstUlpsOfR <= 2, $"worst residual {worstResidual:G3} is {worstUlpsOfR:G3} ulp(R)");
    }

    private static (int Hits, double WorstResidual, double WorstUlpsOfP, double WorstUlpsOfR) HorizonResiduals(double height)
    {
        (Sphere sphere, ImagePlane plane) = Horizon(height);
        double worstUlps = 0, worstResidual = 0;
        int n = 0;
        for (int row = 0; row < plane.Height; row++)
        {
            for (int x = 0; x < plane.Width; x++)
            {
                Ray ray = plane.GetPixelRay(x, row, 0.5, 0.5);
                if (!sphere.TryIntersect(ray, plane.TMin, plane.TMax, out double t))
                {
                    continue;
                }

                n++;
                Assert.True(double.IsFinite(t) && t > 0);
                Double3 p = ray.At(t);
                double residual = Math.Abs(ExactResidual(p, sphere));
                worstUlps = Math.Max(worstUlps, residual / Ulp(p.Length));
                worstResidual = Math.Max(worstResidual, residual);
            }
        }

        return (n, worstResidual, worstUlps, worstResidual / Ulp(sphere.Radius));
    }

    // ---------------------------------------------------------------- special rays

    private static readonly Sphere Unit = new(Double3.Zero, 1, Intensity.White);

    [Fact]
    public void AnExactlyTangentRayIsAHitAtTheTouchingPoint()
    {
        // r² − |f − (f·d/d·d) d|² = 1 − 1 = 0 exactly; the touching point (1, 0, 0) is 5 along the ray.
        Ray ray = new(new Double3(1, 0, 5), new Double3(0, 0, -1));
        Assert.Equal(0, ExactDiscriminantSign(ray, Unit));
        Assert.True(Unit.TryIntersect(ray, 0, 100, out double t));
        Assert.Equal(5.0, t);
        // The same tangent line with an unnormalised direction and a generic tangent point.
        Ray scaled = new(new Double3(0, 1, -3), new Double3(0, 0, 0.25));
        Assert.Equal(0, ExactDiscriminantSign(scaled, Unit));
        Assert.True(Unit.TryIntersect(scaled, 0, 100, out t));
        Assert.Equal(12.0, t);
    }

    [Fact]
    public void AnOriginAtTheCentreSeesTheWallAtDistanceR()
    {
        var sphere = new Sphere(new Double3(1.5, -2.25, 0.75), 2.5, Intensity.White);
        foreach (Double3 d in new[] { new Double3(0, 0, 1), new Double3(3, -4, 0), new Double3(0.36, -0.48, 0.8) })
        {
            Assert.True(sphere.TryIntersect(new Ray(sphere.Center, d), 0, 100, out double t));
            Assert.Equal(2.5 / d.Length, t, 1e-15);
        }
    }

    [Fact]
    public void AnOriginOnTheSurfaceGoingInOutOrTangentIsNeverNaN()
    {
        var surface = new Double3(0, 0, 1); // exactly on the surface
        // Going in along −z: roots 0 and 2.
        Assert.True(Unit.TryIntersect(new Ray(surface, new Double3(0, 0, -1)), 0, 100, out double t));
        Assert.Equal(0.0, t);
        Assert.True(Unit.TryIntersect(new Ray(surface, new Double3(0, 0, -1)), 1e-9, 100, out t));
        Assert.Equal(2.0, t, 1e-15);
        // Going in along a generic chord: with the origin on the surface the roots are 0 and −2 (o·d)/|d|².
        var chordDir = new Double3(0, -0.6, -0.8);
        Assert.True(Unit.TryIntersect(new Ray(surface, chordDir), 1e-9, 100, out t));
        Assert.Equal(2 * 0.8 / chordDir.LengthSquared, t, 1e-15);
        // Going out along +z: the root 0 is a hit with tMin = 0; with tMin > 0 nothing is ahead.
        Assert.True(Unit.TryIntersect(new Ray(surface, new Double3(0, 0, 1)), 0, 100, out t));
        Assert.Equal(0.0, t);
        Assert.False(Unit.TryIntersect(new Ray(surface, new Double3(0, 0, 1)), 1e-9, 100, out t));
        Assert.False(double.IsNaN(t));
        // Tangent at the origin: both roots 0.
        Assert.True(Unit.TryIntersect(new Ray(surface, new Double3(0.36, -0.48, 0)), 0, 100, out t));
        Assert.Equal(0.0, t);
        Assert.False(Unit.TryIntersect(new Ray(surface, new Double3(0.36, -0.48, 0)), 1e-9, 100, out t));
        Assert.False(double.IsNaN(t));
    }

    [Fact]
    public void ASphereBehindTheOriginIsNotHit()
    {
        Assert.False(Unit.TryIntersect(new Ray(new Double3(0.3, -0.2, 5), new Double3(0.01, 0.02, 1)), 0, 1e300, out double t));
        Assert.False(double.IsNaN(t));
        var far = new Sphere(new Double3(-1e6, 2e6, -3e6), 10, Intensity.White);
        Assert.False(far.TryIntersect(new Ray(Double3.Zero, new Double3(1, -2, 3)), 0, double.PositiveInfinity, out _));
        Assert.True(far.TryIntersect(new Ray(Double3.Zero, new Double3(-1, 2, -3)), 0, double.PositiveInfinity, out t));
        Assert.Equal(1e6 - (10 / Math.Sqrt(14)), t, 1e6 * 1e-12);
    }

    [Fact]
    public void HitsExactlyAtTMinAndTMaxCountAndJustOutsideDoNot()
    {
        var ray = new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)); // roots exactly 4 and 6
        Assert.True(Unit.TryIntersect(ray, 4, 4, out double t));
        Assert.Equal(4.0, t);
        Assert.True(Unit.TryIntersect(ray, 6, 6, out t));
        Assert.Equal(6.0, t);
        Assert.True(Unit.TryIntersect(ray, 0, 4, out t));
        Assert.Equal(4.0, t);
        Assert.True(Unit.TryIntersect(ray, Math.BitIncrement(4.0), 6, out t));
        Assert.Equal(6.0, t);
        Assert.False(Unit.TryIntersect(ray, 0, Math.BitDecrement(4.0), out _));
        Assert.False(Unit.TryIntersect(ray, Math.BitIncrement(6.0), 100, out _));
        Assert.False(Unit.TryIntersect(ray, Math.BitIncrement(4.0), Math.BitDecrement(6.0), out _));
    }

    [Fact]
    public void ARadiusZeroSphereIsNeverHitEvenThroughItsCentre()
    {
        var point = new Sphere(new Double3(1, 2, 3), 0, Intensity.White);
        Assert.False(point.TryIntersect(new Ray(Double3.Zero, new Double3(1, 2, 3)), 0, 100, out _));
        Assert.False(point.TryIntersect(new Ray(new Double3(1, 2, 3), new Double3(0, 0, 1)), 0, 100, out double t));
        Assert.False(double.IsNaN(t));
    }

    [Theory]
    [InlineData(1e19)]
    [InlineData(1e100)]
    public void ACentreVeryFarAwayIsHitAtTheRightDistanceWithoutNaN(double scale)
    {
        // Along an axis: t = |C| − r exactly in real terms.
        var onAxis = new Sphere(new Double3(scale, 0, 0), 1, Intensity.White);
        Assert.True(onAxis.TryIntersect(new Ray(Double3.Zero, new Double3(1, 0, 0)), 0, double.PositiveInfinity, out double t));
        Assert.Equal(1, t / scale, 1e-12);
        // A generic direction straight at the centre, with a radius a fixed fraction of the distance:
        // t = (|C| − r)/|d| with d = C, i.e. t = 1 − r/|C| = 0.75.
        var centre = new Double3(0.36 * scale, -0.48 * scale, 0.8 * scale);
        double length = Math.Sqrt(ExactSphere.LengthSquared(centre));
        var sphere = new Sphere(centre, 0.25 * length, Intensity.White);
        Assert.True(sphere.TryIntersect(new Ray(Double3.Zero, centre), 0, double.PositiveInfinity, out t));
        Assert.True(double.IsFinite(t));
        Assert.Equal(0.75, t, 0.75e-12);
        // The same sphere from an origin near it must still find the near side.
        var unitDir = new Double3(0.36, -0.48, 0.8);
        Assert.True(sphere.TryIntersect(new Ray(Double3.Zero, unitDir), 0, double.PositiveInfinity, out t));
        Assert.Equal(0.75, t / length, 1e-12);
    }

    [Fact]
    public void ANaNOrZeroDirectionMissesWithoutThrowing()
    {
        var o = new Double3(0, 0, 5);
        foreach (Double3 d in new[]
                 {
                     Double3.Zero, new Double3(double.NaN, 0, -1), new Double3(0, double.NaN, 0), new Double3(double.NaN, double.NaN, double.NaN),
                     new Double3(1e-200, 0, 0), new Double3(0, 0, double.NegativeInfinity),
                 })
        {
            bool hit = Unit.TryIntersect(new Ray(o, d), 0, 100, out double t);
            Assert.False(hit, $"direction {d}");
            Assert.False(double.IsNaN(t));
        }

        // A NaN origin misses too.
        Assert.False(Unit.TryIntersect(new Ray(new Double3(double.NaN, 0, 5), new Double3(0, 0, -1)), 0, 100, out _));
    }

    // ---------------------------------------------------------------- cameras (only what CameraTests lacks)

    [Theory]
    [InlineData(1.0)]
    [InlineData(-3.0)]
    [InlineData(1e-3)]
    public void AnUpVectorAlongAGenericGazeIsRejectedNamingUp(double k)
    {
        // CameraTests covers an axis-aligned gaze, where up × w is exactly 0; for a generic gaze the rounding of
        // w leaves up × w a few ulps long, which must still count as parallel.
        var position = new Double3(1.3, -2.1, 7.7);
        var target = new Double3(-0.4, 0.9, 0.2);
        Double3 gaze = target - position;
        var camera = new PerspectiveCamera { Position = position, Target = target, Up = k * gaze };
        ArgumentException e = Assert.Throws<ArgumentException>(() => camera.GetImagePlane(8, 8));
        Assert.Equal("Up", e.ParamName);
    }

    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void AnUpVectorOneMicroradianFromTheGazeGivesAnOrthonormalRightHandedFrame(string type)
    {
        var position = new Double3(1.3, -2.1, 7.7);
        var target = new Double3(-0.4, 0.9, 0.2);
        Double3 g = Double3.Normalize(target - position);
        // A unit vector perpendicular to g, then up = cos(ε) g + sin(ε) n: 1e-6 rad from the gaze.
        Double3 n = Double3.Normalize(Double3.Cross(g, new Double3(0, 1, 0)));
        const double eps = 1e-6;
        Double3 up = (Math.Cos(eps) * g) + (Math.Sin(eps) * n);
        Camera camera = type == "perspective"
            ? new PerspectiveCamera { Position = position, Target = target, Up = up }
            : new OrthoCamera { Position = position, Target = target, Up = up };
        ImagePlane plane = camera.GetImagePlane(16, 16);
        Assert.Equal(1, plane.U.Length, 1e-6);
        Assert.Equal(1, plane.V.Length, 1e-6);
        Assert.Equal(1, plane.W.Length, 1e-6);
        Assert.Equal(0, Double3.Dot(plane.U, plane.V), 1e-6);
        Assert.Equal(0, Double3.Dot(plane.U, plane.W), 1e-6);
        Assert.Equal(0, Double3.Dot(plane.V, plane.W), 1e-6);
        Assert.Equal(0, (Double3.Cross(plane.U, plane.V) - plane.W).Length, 1e-6);
        Assert.Equal(-1, Double3.Dot(plane.W, g), 1e-12);
        // u = (up × w)/|up × w| with up ≈ g + ε n and w = −g: u ∥ ε (n × −g) = ε (g × n).
        Assert.Equal(1, Double3.Dot(plane.U, Double3.Normalize(Double3.Cross(g, n))), 1e-6);
        double worst = Math.Max(Math.Abs(plane.U.Length - 1), Math.Max(Math.Abs(Double3.Dot(plane.U, plane.V)), Math.Abs(Double3.Dot(plane.V, plane.W))));
        _output.WriteLine($"{type}: up 1e-6 rad from the gaze, worst orthonormality defect {worst:G3}");
    }

    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void AOneByOneImageShootsItsRayThroughTheWindowCentre(string type)
    {
        var position = new Double3(1.3, -2.1, 7.7);
        var target = new Double3(-0.4, 0.9, 0.2);
        Camera camera = type == "perspective"
            ? new PerspectiveCamera { Position = position, Target = target, Fov = 40 }
            : new OrthoCamera { Position = position, Target = target, ViewHeight = 3 };
        ImagePlane plane = camera.GetImagePlane(1, 1);
        Assert.Equal(0.5, plane.Alpha(0, 0.5));
        Assert.Equal(0.5, plane.Beta(0, 0.5));
        Ray ray = plane.GetPixelRay(0, 0, 0.5, 0.5);
        Double3 g = Double3.Normalize(target - position);
        Double3 dir = Double3.Normalize(ray.Direction);
        Assert.Equal(0, (dir - g).Length, 1e-15);
        Assert.Equal(0, (ray.Origin - position).Length, 1e-15);
        // The window is the one a 1×1 (aspect 1) image asks for.
        if (type == "perspective")
        {
            Assert.Equal(2 * Math.Tan(20 * Math.PI / 180), plane.Window.Height, 1e-15);
            Assert.Equal(plane.Window.Height, plane.Window.Width);
        }
        else
        {
            Assert.Equal(3, plane.Window.Height);
            Assert.Equal(3, plane.Window.Width);
        }
    }

    [Fact]
    public void ATinyFieldOfViewOnAWideImageKeepsOneRowsDirectionsDistinctAndOrdered()
    {
        const int N = 16_384;
        var camera = new PerspectiveCamera { Position = new Double3(1.3, -2.1, 7.7), Target = new Double3(-0.4, 0.9, 0.2), Up = new Double3(0.1, 1, 0.3), Fov = 0.01 };
        ImagePlane plane = camera.GetImagePlane(N, N);
        int row = N / 2;
        Double3 previous = plane.GetPixelRay(0, row, 0.5, 0.5).Direction;
        double previousU = Double3.Dot(previous, plane.U);
        double smallestStep = double.PositiveInfinity;
        for (int x = 1; x < N; x++)
        {
            Double3 d = plane.GetPixelRay(x, row, 0.5, 0.5).Direction;
            Assert.NotEqual(previous, d);
            double du = Double3.Dot(d, plane.U);
            Assert.True(du > previousU, $"pixel {x}: d·u = {du:R} not above {previousU:R}");
            smallestStep = Math.Min(smallestStep, du - previousU);
            previous = d;
            previousU = du;
        }

        double expectedStep = plane.Window.Width / N; // |d·w| = s = 1, so the step along u is the window step
        _output.WriteLine($"fov 0.01°, {N} px: smallest d·u step {smallestStep:G4}, nominal {expectedStep:G4}");
        Assert.True(smallestStep > 0.5 * expectedStep);
    }

    [Theory]
    [InlineData(2.0, 1024)]
    [InlineData(1e-6, 1000)]
    public void AnOrthographicCameraFarFromTheOriginKeepsNeighbouringRayOriginsDistinctAndOrdered(double viewHeight, int size)
    {
        var toEye = new Double3(0.36, -0.48, 0.8);
        var camera = new OrthoCamera { Position = 1e5 * toEye, Target = Double3.Zero, Up = new Double3(0.1, 1, 0.3), ViewHeight = viewHeight };
        ImagePlane plane = camera.GetImagePlane(size, size);
        double step = viewHeight / size;
        double worstRelative = 0;
        foreach (int row in new[] { 0, size / 2, size - 1 })
        {
            Double3 previous = plane.GetPixelRay(0, row, 0.5, 0.5).Origin;
            for (int x = 1; x < size; x++)
            {
                Double3 o = plane.GetPixelRay(x, row, 0.5, 0.5).Origin;
                Assert.NotEqual(previous, o);
                double du = Double3.Dot(o - previous, plane.U); // o − previous is exact (Sterbenz)
                Assert.True(du > 0, $"row {row}, pixel {x}: step along u {du:R}");
                worstRelative = Math.Max(worstRelative, Math.Abs(du - step) / step);
                previous = o;
            }
        }

        _output.WriteLine($"ortho at 1e5, view {viewHeight}, {size} px: worst relative deviation of the u step {worstRelative:G3}");
        Assert.True(worstRelative < 0.1, $"step deviates by {worstRelative:G3} of a pixel");
    }

    // ---------------------------------------------------------------- helpers

    private static (Sphere Sphere, ImagePlane Plane) Horizon(double height)
    {
        HardCase hard = HardCase.Horizon(height);
        return (hard.Sphere, hard.Camera.GetImagePlane(64, 64));
    }

    /// <summary>Renders one ray per pixel centre and compares with the exact decision.</summary>
    private static (int Hits, int Wrong, int Close, double WorstMargin) CompareImage(Sphere sphere, ImagePlane plane, double closeMargin)
    {
        int hits = 0, wrong = 0, close = 0;
        double worst = double.PositiveInfinity;
        for (int row = 0; row < plane.Height; row++)
        {
            for (int x = 0; x < plane.Width; x++)
            {
                Ray ray = plane.GetPixelRay(x, row, 0.5, 0.5);
                bool actual = sphere.TryIntersect(ray, plane.TMin, plane.TMax, out double t);
                Assert.False(double.IsNaN(t));
                (bool expected, double margin) = ExactHit(ray, sphere);
                hits += expected ? 1 : 0;
                worst = Math.Min(worst, Math.Abs(margin));
                bool isClose = Math.Abs(margin) < closeMargin;
                close += isClose ? 1 : 0;
                if (actual != expected && !isClose)
                {
                    wrong++;
                }
            }
        }

        return (hits, wrong, close, worst);
    }

    private static (bool Hit, double Margin) ExactHit(Ray ray, Sphere sphere) => ExactSphere.Hit(ray, sphere);

    private static int ExactDiscriminantSign(Ray ray, Sphere sphere) => ExactSphere.DiscriminantSign(ray, sphere);

    private static double ExactResidual(Double3 p, Sphere sphere) => ExactSphere.Residual(p, sphere);

    private static double Ulp(double x) => ExactSphere.Ulp(x);
}
