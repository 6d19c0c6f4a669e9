using RayLab.Cameras;
using RayLab.Sampling;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>
/// The exact reference against truths computed without it: π r², the closed-form area of a disc in a pixel, a
/// pixel cut by an almost straight edge, and a perspective outline integrated numerically. A white sphere on a
/// black background makes a pixel's red value its coverage.
/// </summary>
public class ExactRendererTests
{
    private readonly ITestOutputHelper _output;

    public ExactRendererTests(ITestOutputHelper output) => _output = output;

    private static readonly Intensity Background = new(0.1, 0.1, 0.15);

    private static Scene White(params (Double3 Centre, double Radius)[] spheres) =>
        new(spheres.Select(s => new Sphere(s.Centre, s.Radius, Intensity.White)), Intensity.Black, Intensity.White);

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        Background,
        Intensity.White);

    private static readonly PerspectiveCamera LabCamera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    // An orthographic camera looking down −z from z = 10 (world x, y are the window's u, v) whose pixels are
    // `pixel` world units wide and `pixelHeight` high, with pixel (0, 0)'s top-left corner at world (u0, v1).
    private static OrthoCamera Ortho(double u0, double v1, int width, int height, double pixel, double pixelHeight, double far = 100) => new()
    {
        Position = new Double3(0, 0, 10), Target = Double3.Zero, NearPlane = 0, FarPlane = far,
        Window = new Window(u0, v1 - (height * pixelHeight), u0 + (width * pixel), v1),
    };

    [Theory]
    [InlineData(0.13, -0.07, 0.61, 1.0)]     // 9 pixels across
    [InlineData(0.5, 0.25, 0.003, 1.0)]      // a fifth of a pixel: the adaptive sampler loses such spheres
    [InlineData(-0.2, 0.31, 0.9, 1.7)]      // non-square pixels: the outline is an ellipse
    public void AnOrthographicDiscCoversExactlyPiRSquared(double cx, double cy, double r, double aspect)
    {
        const int W = 37, H = 29;
        double pixel = 2.0 / H; // the window [−W/H, W/H] × [−1, 1] with square pixels, or taller ones
        OrthoCamera camera = Ortho(-W * pixel / 2, aspect, W, H, pixel, aspect * pixel);

        Intensity[] values = ExactLinear.Of(White((new Double3(cx, cy, 0), r)), camera, W, H);

        double area = values.Sum(v => v.R);
        double expected = Math.PI * r * r / (pixel * pixel * aspect); // in pixels
        _output.WriteLine($"disc of radius {r} (pixel aspect {aspect}): coverage − π r² = {area - expected:E2} pixels");
        Assert.True(Math.Abs(area - expected) <= 1e-6, $"coverage {area:R}, π r² = {expected:R}");
    }

    [Theory]
    [InlineData("orthographic")]
    [InlineData("perspective")]
    public void EveryPixelOfACircularOutlineHasTheClosedFormDiscArea(string type)
    {
        // Orthographic: a sphere's outline is a circle of radius r. Perspective: a sphere on the optical axis has a
        // circular outline of radius s·r/√(D² − r²) on the window, here seen through an off-axis window.
        const int W = 40, H = 30;
        var window = new Window(-0.3, -0.2, 0.5, 0.4);
        var centre = new Double3(0, 0, 0);
        const double r = 1, eye = 5;
        Camera camera = type == "orthographic"
            ? new OrthoCamera { Position = new Double3(0, 0, eye), Target = centre, NearPlane = 0, Window = new Window(-1.3, -0.6, 1.1, 1.2) }
            : new PerspectiveCamera { Position = new Double3(0, 0, eye), Target = centre, NearPlane = 0, Window = window };
        ImagePlane plane = camera.GetImagePlane(W, H);
        double radiusOnWindow = type == "orthographic" ? r : r / Math.Sqrt((eye * eye) - (r * r));
        double pixel = plane.Window.Width / W;
        Assert.Equal(pixel, plane.Window.Height / H, 12); // square pixels
        double cx = -plane.Window.U0 / pixel, cy = plane.Window.V1 / pixel, rp = radiusOnWindow / pixel;

        Intensity[] values = ExactLinear.Of(White((centre, r)), camera, W, H);

        double worst = 0;
        for (int row = 0; row < H; row++)
        {
            for (int x = 0; x < W; x++)
            {
                double expected = ExactReferenceMath.DiscRectangleArea(cx, cy, rp, x, row, x + 1, row + 1);
                worst = Math.Max(worst, Math.Abs(values[(row * W) + x].R - expected));
            }
        }

        _output.WriteLine($"{type}: largest |exact − closed-form disc area| {worst:E2}");
        Assert.True(worst <= 1e-9, $"largest difference {worst:E2}");
        Assert.Contains(values, v => v.R > 0.01 && v.R < 0.99); // the outline does cross pixels
    }

    [Fact]
    public void APixelInsideIsTheSphereAndAPixelCutThroughItsCentreByAHugeSphereIsHalfCovered()
    {
        // Pixels 1 world unit wide; a sphere of radius R = 1e6 (wholly in front of the camera, the far plane beyond
        // it) whose rightmost point is pixel (3, 3)'s centre. That pixel's coverage is ½ minus the sliver between
        // the arc and its tangent, ∫ (R − √(R² − u²)) du over |u| ≤ ½: 1/(24 R) up to O(R⁻³).
        const double R = 1e6;
        OrthoCamera camera = Ortho(-4, 4, 8, 8, 1, 1, far: 1e7);
        Scene scene = White((new Double3(-0.5 - R, 0.5, -R), R));

        Intensity[] values = ExactLinear.Of(scene, camera, 8, 8);

        _output.WriteLine($"cut pixel: coverage − (½ − 1/(24 R)) = {values[(3 * 8) + 3].R - (0.5 - (1 / (24 * R))):E2}");
        Assert.Equal(0.5 - (1 / (24 * R)), values[(3 * 8) + 3].R, 1e-9);
        Assert.Equal(1, values[(3 * 8) + 2].R, 1e-12);  // just left of it: inside
        Assert.Equal(1, values[0].R, 1e-12);
        Assert.Equal(0, values[(3 * 8) + 4].R, 1e-12);  // just right of it: outside
    }

    [Theory]
    [InlineData(0.0, 0.0, 0.35)]
    [InlineData(0.9, -0.4, 0.5)]
    [InlineData(-1.3, 0.7, 0.8)]
    public void APerspectiveEllipseMatchesAnIntegralOverItsRows(double x, double y, double r)
    {
        // An off-axis sphere's outline is a tilted ellipse. Reference, straight from the rays: the ray through pixel
        // coordinates (X, Y) has direction d = c + (X/W) a + (1 − Y/H) b, and its line meets the sphere where
        // F = (q·d)² − (|q|² − r²)|d|² ≥ 0 — a quadratic in X for each height Y. A pixel's coverage is the covered
        // length in [x, x + 1] integrated over Y by adaptive Gauss–Kronrod, between the heights where F = 0 meets
        // the pixel's sides or the outline starts or ends (where the length has kinks).
        const int W = 24, H = 18;
        var camera = new PerspectiveCamera { Position = new Double3(0.3, 0.5, 4), Target = new Double3(0, 0, -1), Fov = 50, NearPlane = 0.1, Window = new Window(-0.5, -0.35, 0.6, 0.475) };
        var centre = new Double3(x, y, -0.5);
        ImagePlane plane = camera.GetImagePlane(W, H);

        Intensity[] values = ExactLinear.Of(White((centre, r)), camera, W, H);

        Double3 q = centre - plane.Eye;
        double k = q.LengthSquared - (r * r);
        double worst = 0;
        int edges = 0;
        for (int row = 0; row < H; row++)
        {
            for (int px = 0; px < W; px++)
            {
                List<double> cuts = [row, row + 1, .. Roots(Fit(yy => F(px, yy))), .. Roots(Fit(yy => F(px + 1, yy))), .. Roots(Fit(Discriminant))];
                double[] ys = [.. cuts.Where(c => c >= row && c <= row + 1).Order()];
                double expected = 0;
                for (int i = 0; i + 1 < ys.Length; i++)
                {
                    expected += ExactReferenceMath.Integrate(yy => CoveredLength(yy, px), ys[i], ys[i + 1], 1e-10 * (ys[i + 1] - ys[i]), depth: 45);
                }

                worst = Math.Max(worst, Math.Abs(values[(row * W) + px].R - expected));
                edges += expected > 1e-9 && expected < 1 - 1e-9 ? 1 : 0;
            }
        }

        _output.WriteLine($"{edges} pixels on the outline; largest |exact − row integral| {worst:E2}");
        Assert.True(edges > 10, $"only {edges} pixels on the outline");
        Assert.True(worst <= 1e-9, $"largest difference {worst:E2}");

        double F(double xx, double yy)
        {
            Double3 d = plane.C + ((1 - (yy / H)) * plane.B) + (xx / W * plane.A);
            double qd = Double3.Dot(q, d);
            return (qd * qd) - (k * d.LengthSquared);
        }

        // F(X, Y) as a X² + b X + c for one Y: d = d0 + X dx.
        (double A, double B, double C) InX(double yy)
        {
            Double3 d0 = plane.C + ((1 - (yy / H)) * plane.B), dx = plane.A / W;
            double qd0 = Double3.Dot(q, d0), qdx = Double3.Dot(q, dx);
            return ((qdx * qdx) - (k * dx.LengthSquared), 2 * ((qd0 * qdx) - (k * Double3.Dot(d0, dx))), (qd0 * qd0) - (k * d0.LengthSquared));
        }

        double Discriminant(double yy)
        {
            (double a, double b, double c) = InX(yy);
            return (b * b) - (4 * a * c);
        }

        double CoveredLength(double yy, int px)
        {
            (double a, double b, double c) = InX(yy);
            double[] roots = [.. Roots((a, b, c))];
            return a < 0 && roots.Length == 2 ? Math.Max(0, Math.Min(roots.Max(), px + 1) - Math.Max(roots.Min(), px)) : 0;
        }
    }

    // The coefficients (a, b, c) of a quadratic g(t) = a t² + b t + c from g(0), g(1), g(2).
    private static (double A, double B, double C) Fit(Func<double, double> g)
    {
        double g0 = g(0), g1 = g(1), g2 = g(2), a = (g2 - (2 * g1) + g0) / 2;
        return (a, g1 - g0 - a, g0);
    }

    // The real roots of a t² + b t + c (the stable form: no subtraction of nearly equal numbers).
    private static IEnumerable<double> Roots((double A, double B, double C) p)
    {
        double disc = (p.B * p.B) - (4 * p.A * p.C);
        if (disc <= 0 || p.A == 0)
        {
            yield break;
        }

        double half = -0.5 * (p.B + (p.B >= 0 ? Math.Sqrt(disc) : -Math.Sqrt(disc)));
        yield return half / p.A;
        yield return p.C / half;
    }

    [Fact]
    public void RenderIsTheLinearValuesByTheLabsEightBitRuleAndNeedsNoRays()
    {
        const int W = 64, H = 48;
        var image = new Image(W, H);
        var progress = new RenderProgress();

        RenderStatistics stats = new Renderer { Progress = progress }.Render(TwoSpheres(), LabCamera, RenderMethod.Exact, image);
        Intensity[] linear = ExactLinear.Of(TwoSpheres(), LabCamera, W, H);

        Assert.Equal(0, stats.PrimaryRays);
        Assert.Equal((H, H), (progress.RowsCompleted, progress.TotalRows));
        for (int row = 0; row < H; row++)
        {
            for (int x = 0; x < W; x++)
            {
                Assert.Equal(Rgb24.FromIntensity(linear[(row * W) + x]), image.GetPixel(x, row));
            }
        }
    }

    [Fact]
    public void TheBytesDoNotDependOnTheThreadCount()
    {
        byte[] Render(int threads)
        {
            var image = new Image(97, 61);
            new Renderer { MaxDegreeOfParallelism = threads }.Render(TwoSpheres(), LabCamera, RenderMethod.Exact, image);
            return image.PixelBytes.ToArray();
        }

        byte[] one = Render(1);
        Assert.Equal(one, Render(2));
        Assert.Equal(one, Render(-1));
    }

    [Fact]
    public void ASphereReachingBehindThePerspectiveEyeIsRejectedByIndexWithTheReason()
    {
        Scene scene = White((new Double3(-1.1, 0, 0), 1), (new Double3(0.3, 0.4, 5.5), 1));
        var camera = new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1 };

        var e = Assert.Throws<UnsupportedSceneException>(() => ExactLinear.Of(scene, camera, 32, 24));
        Assert.IsAssignableFrom<ArgumentException>(e);
        Assert.Equal(1, e.SphereIndex);
        Assert.StartsWith("Sphere 1 reaches behind the perspective camera", e.Message);
        Assert.Contains("depth along the gaze runs from -0.5 to 1.5", e.Reason);
        Assert.Throws<UnsupportedSceneException>(() => new Renderer().Render(scene, camera, RenderMethod.Exact, new Image(8, 6)));
        Assert.Throws<UnsupportedSceneException>(() => RenderMethod.Exact.Check(scene, camera, 8, 6));
        RenderMethod.Sampled(new RegularSampler(1)).Check(scene, camera, 8, 6); // only the exact method refuses a scene
    }

    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void ATinySphereFarAwayIsExactAndAZoomBeyondDoublePrecisionIsRejected(string type)
    {
        // A sphere of radius 0.37 seen from 370 000 times its radius, centred in a 32×32 window 2.9 outline radii wide
        // (as in the precision hard cases): its picture is a disc of radius 32/2.9 pixels. Then the window zoomed
        // onto the outline's edge, 2e-8 of its radius wide: double rounding alone moves the outline by a good part
        // of a pixel there, which the exact reference refuses rather than guess.
        const double r = 0.37, ratio = 1e-6;
        var centre = new Double3(3.25, -1.75, 2.5);
        Double3 eye = centre + (r / ratio * new Double3(0.36, -0.48, 0.8));
        double rho = type == "perspective" ? ratio / Math.Sqrt(1 - (ratio * ratio)) : r; // the outline's radius on the window
        Camera Seen(Window window) => type == "perspective"
            ? new PerspectiveCamera { Position = eye, Target = centre, Up = new Double3(0.1, 1, 0.2), NearPlane = 0, FarPlane = 10 * r / ratio, Window = window }
            : new OrthoCamera { Position = eye, Target = centre, Up = new Double3(0.1, 1, 0.2), NearPlane = 0, FarPlane = 10 * r / ratio, Window = window };
        Scene scene = White((centre, r));

        Intensity[] values = ExactLinear.Of(scene, Seen(new Window(-1.5 * rho, -1.3 * rho, 1.4 * rho, 1.6 * rho)), 32, 32);
        var e = Assert.Throws<UnsupportedSceneException>(() =>
            ExactLinear.Of(scene, Seen(new Window(rho * (1 - 1e-8), rho * -1.1e-8, rho * (1 + 1e-8), rho * 0.9e-8)), 32, 32));

        _output.WriteLine($"{type}: coverage − π r² = {values.Sum(v => v.R) - (Math.PI * (32 / 2.9) * (32 / 2.9)):E2} pixels");
        Assert.Equal(Math.PI * (32 / 2.9) * (32 / 2.9), values.Sum(v => v.R), 1e-6);
        Assert.StartsWith("Sphere 0 is seen at a zoom beyond double precision", e.Message);
    }

    [Theory]
    [InlineData(0, 0, 7.5)]    // wholly behind the eye
    [InlineData(6, 0.5, 6)]    // around the eye's plane, but far outside the view pyramid
    [InlineData(0, 0, -150)]   // beyond the far plane
    public void SpheresNoVisibleRayReachesAreLeftOutNotRejected(double x, double y, double z)
    {
        Scene with = new([.. TwoSpheres().Spheres, new Sphere(new Double3(x, y, z), 1, Intensity.White)], Background, Intensity.White);

        Intensity[] expected = ExactLinear.Of(TwoSpheres(), LabCamera, 40, 30);
        Intensity[] actual = ExactLinear.Of(with, LabCamera, 40, 30);

        Assert.Equal(expected, actual);
    }

    [Fact]
    public void TheNearAndFarPlanesCuttingASphereAreExact()
    {
        // An orthographic camera whose eye plane (the near plane, depth 0) cuts a sphere of radius 2 centred at depth
        // 1, with the far plane at depth 2.5. A ray at distance ρ from the centre's axis meets the sphere at depths
        // 1 ∓ √(4 − ρ²): outside the near cut (ρ > √3) the front hit lies in [0, 2.5]; inside it the ray starts in
        // the sphere and sees the far wall only if 1 + √(4 − ρ²) ≤ 2.5, that is ρ ≥ √1.75. So the sphere shows as the
        // ring √1.75 ≤ ρ ≤ 2, of area π (4 − 1.75).
        const int W = 30, H = 30;
        OrthoCamera camera = Ortho(-3, 3, W, H, 0.2, 0.2, far: 2.5);
        Scene scene = White((new Double3(0.1, 0.05, 9), 2));

        Intensity[] values = ExactLinear.Of(scene, camera, W, H);

        Assert.Equal(Math.PI * 2.25 / (0.2 * 0.2), values.Sum(v => v.R), 1e-6);
        Assert.Equal(0, values[(15 * W) + 15].R, 1e-12); // the middle: the far wall is beyond the far plane
    }
}
