using System.Runtime.CompilerServices;
using RayLab;
using RayLab.Rendering.Inspection;
using RayLab.Sampling;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>4.1.1–4.1.4: your sampling methods against RayLab's.</summary>
#else
/// <summary>4.1.1–4.1.4: Twoje metody próbkowania wobec metod RayLab.</summary>
#endif
public sealed class SamplingChecks(ITestOutputHelper output)
{
    private const int Pixels = 2000;

    [Trait("Section", "4.1.1")]
    [Theory(DisplayName = Msg.Regular)]
    [InlineData(1)]
    [InlineData(4)]
    [InlineData(25)]
    public void Regular(int n) => Run(output, () =>
    {
        var expected = Enumerable.Range(0, n).Select(i => new RegularSampler(n).GetSample(0, 0, i)).Select(p => (p.X, p.Y)).Order().ToArray();
        var random = new Random(1);
        for (int pixel = 0; pixel < 3; pixel++)
        {
            (double X, double Y)[] actual = new LabRegularSampler(n).GetSamples(random).Order().ToArray();
            string got = string.Join(" ", actual.Take(6).Select(p => F($"({p.X:F3}, {p.Y:F3})")));
            Assert.True(actual.Length == n, Msg.RegularCount(n, actual.Length, got));
            for (int i = 0; i < n; i++)
            {
                if (Math.Abs(actual[i].X - expected[i].X) > 1e-12 || Math.Abs(actual[i].Y - expected[i].Y) > 1e-12)
                {
                    Assert.Fail(Msg.RegularPoint(n, pixel, expected[i].X, expected[i].Y, actual[i].X, actual[i].Y, got));
                }
            }
        }

        output.WriteLine(Msg.RegularAsRayLab(n));
    });

    [Trait("Section", "4.1.2")]
    [Fact(DisplayName = Msg.Random)]
    public void Random() => Run(output, () =>
    {
        const int n = 16;
        var random = new Random(7);
        var sampler = new LabRandomSampler(n);
        int[] cells = new int[16];
        var first = new HashSet<(double, double)>();
        for (int pixel = 0; pixel < Pixels; pixel++)
        {
            (double X, double Y)[] points = sampler.GetSamples(random);
            Assert.True(points.Length == n, Msg.RandomCount(n, points.Length));
            foreach ((double x, double y) in points)
            {
                InPixel("4.1.2", pixel, x, y);
                cells[((int)(y * 4) * 4) + (int)(x * 4)]++;
            }

            first.Add(points[0]);
        }

        double chi2 = ChiSquare(cells), oracle = OracleChiSquare(new RandomSampler(n, 7), n);
        output.WriteLine(Msg.RandomLine(Pixels, n, chi2, oracle, first.Count));
        Assert.True(first.Count > Pixels * 0.99, Msg.RandomRepeats(first.Count, Pixels));
        Assert.True(chi2 < 37.7, Msg.RandomNotUniform(string.Join(", ", cells), Pixels * n / 16, chi2, oracle));
    });

    [Trait("Section", "4.1.3")]
    [Theory(DisplayName = Msg.Jittered)]
    [InlineData(16)]
    [InlineData(25)]
    public void Jittered(int n) => Run(output, () =>
    {
        int k = (int)Math.Round(Math.Sqrt(n));
        var random = new Random(11);
        var sampler = new LabJitteredSampler(n);
        double offsets = 0, squares = 0;
        int count = 0;
        for (int pixel = 0; pixel < Pixels; pixel++)
        {
            (double X, double Y)[] points = sampler.GetSamples(random);
            Assert.True(points.Length == n, Msg.JitteredCount(n, points.Length));
            var seen = new Dictionary<(int, int), (double, double)>();
            foreach ((double x, double y) in points)
            {
                InPixel("4.1.3", pixel, x, y);
                (int i, int j) = ((int)(x * k), (int)(y * k));
                if (seen.TryGetValue((i, j), out (double X, double Y) other))
                {
                    Assert.Fail(Msg.JitteredTwoInCell(n, k, pixel, i, j, other.X, other.Y, x, y));
                }

                seen.Add((i, j), (x, y));
                double inCell = (x * k) - i;
                offsets += inCell;
                squares += inCell * inCell;
                count++;
            }
        }

        double mean = offsets / count, variance = (squares / count) - (mean * mean);
        output.WriteLine(Msg.JitteredLine(Pixels, n, mean, variance));
        Assert.True(Math.Abs(variance - (1.0 / 12)) < 0.01, Msg.JitteredNotUniform(variance));
    });

    [Trait("Section", "4.1.4")]
    [Theory(DisplayName = Msg.Adaptive)]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void AdaptivePixels(string cameraName) => Run(output, () => _where, () =>
    {
#if (en)
        // A small picture of the two spheres, so that many of its pixels lie on an edge; every pixel compared.
#else
        // Mały obraz dwóch kul, żeby wiele jego pikseli leżało na krawędzi; porównany każdy piksel.
#endif
        const int width = 48, height = 36;
        LabCamera settings = cameraName == "perspective" ? Perspective() : Orthographic();
        Camera camera = Oracle(settings);
        var plane = camera.GetImagePlane(width, height);
        var oracle = new AdaptiveSampler(minDepth: 0, maxDepth: 3, contrast: 0.05, quincunx: true);
        var sampler = new LabAdaptiveSampler(maxDepth: 3, contrast: 0.05);
        long rays = 0, oracleRays = 0;
        int refined = 0;
        for (int y = 0; y < height; y++)
        {
            for (int x = 0; x < width; x++)
            {
                _where = Msg.Pixel(x, y);
                var points = new HashSet<(double, double)>();
                int calls = 0;
                LightIntensity value = sampler.Pixel((sx, sy) =>
                {
                    StopIfPastLimit();
#if (en)
                    // A recursion that does not stop: an exception that says so at its first point past depth 3, before
                    // the check's thread runs out of stack (within some 50 levels the squares are too small for a double
                    // to hold a new point, and such a recursion goes on without tracing one).
#else
                    // Rekurencja, która się nie zatrzymuje: wyjątek, który to mówi, przy jej pierwszym punkcie poniżej
                    // głębokości 3, zanim wątkowi sprawdzenia skończy się stos (po jakichś 50 poziomach kwadraty są za małe,
                    // by double pomieścił nowy punkt, a taka rekurencja trwa dalej bez śledzenia promieni).
#endif
                    if (!OnDepth3Grid(sx) || !OnDepth3Grid(sy))
                    {
                        throw new InvalidOperationException(Msg.OffDepth3Grid(sx, sy));
                    }

                    if (++calls > 1024 || !RuntimeHelpers.TryEnsureSufficientExecutionStack())
                    {
                        throw new InvalidOperationException(Msg.TooManyRays(calls));
                    }

                    points.Add((sx, sy));
                    Intensity c = TwoSpheresFile.Scene.Trace(plane.GetPixelRay(x, y, sx, sy), plane.TMin, plane.TMax);
                    return new LightIntensity(c.R, c.G, c.B);
                });
                AdaptiveDiagram diagram = AdaptiveDiagram.Trace(TwoSpheresFile.Scene, camera, width, height, oracle, x, y);
                rays += points.Count;
                oracleRays += diagram.Points.Count;
                refined += diagram.Points.Count > 5 ? 1 : 0;
                Intensity expected = diagram.Value;
                if (points.Count != diagram.Points.Count
                    || Math.Abs(value.R - expected.R) > 1e-9 || Math.Abs(value.G - expected.G) > 1e-9 || Math.Abs(value.B - expected.B) > 1e-9)
                {
                    string theirs = string.Join(" ", diagram.Points.Select(p => F($"{p.Label}({p.X:0.###}, {p.Y:0.###})")));
                    string yours = string.Join(" ", points.Order().Select(p => F($"({p.Item1:0.###}, {p.Item2:0.###})")));
                    Assert.Fail(Msg.AdaptiveWrong(cameraName, width, height, x, y, diagram.Points.Count, theirs, expected, points.Count, yours, value));
                }
            }
        }

        output.WriteLine(Msg.AdaptiveLine(cameraName, width, height, rays, (double)rays / (width * height), oracleRays, refined));
    });

    private string _where = Msg.BeforeFirstPixel;

#if (en)
    /// <summary>
    /// Whether a point's coordinate can belong to a square of depth 0–3: those have sides of 1/8 pixel or more, so
    /// their corners and centres lie on the 1/16-pixel grid. check's probe (src/Lab/Progress.cs) keeps its own copy of
    /// this guard, for the reason <see cref="Check.WhereInYourCode"/> gives.
    /// </summary>
#else
    /// <summary>
    /// Czy współrzędna punktu może należeć do kwadratu głębokości 0–3: te mają boki 1/8 piksela lub więcej, więc ich
    /// rogi i środki leżą na siatce co 1/16 piksela. Sonda polecenia check (src/Lab/Progress.cs) ma własną kopię tego
    /// warunku, z powodu, który podaje <see cref="Check.WhereInYourCode"/>.
    /// </summary>
#endif
    private static bool OnDepth3Grid(double v) => Math.Abs((v * 16) - Math.Round(v * 16)) < 1e-9;

    private static void InPixel(string section, int pixel, double x, double y)
    {
        if (!(x >= 0 && x < 1 && y >= 0 && y < 1))
        {
            Assert.Fail(Msg.OutsideUnitSquare(section, x, y, pixel));
        }
    }

    private static double ChiSquare(int[] cells)
    {
        double expected = cells.Sum() / (double)cells.Length;
        return cells.Sum(c => (c - expected) * (c - expected) / expected);
    }

    private static double OracleChiSquare(IPixelSampler sampler, int n)
    {
        int[] cells = new int[16];
        for (int pixel = 0; pixel < Pixels; pixel++)
        {
            for (int i = 0; i < n; i++)
            {
                SamplePoint p = sampler.GetSample(pixel, 0, i);
                cells[((int)(p.Y * 4) * 4) + (int)(p.X * 4)]++;
            }
        }

        return ChiSquare(cells);
    }
}
