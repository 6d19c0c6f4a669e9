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
    [Theory(DisplayName = English ? "4.1.1 Regular sampling: the k×k grid of cell centres, the same in every pixel" : "4.1.1 Próbkowanie regularne: siatka k×k środków komórek, ta sama w każdym pikselu")]
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
            Assert.True(actual.Length == n, T($"4.1.1 Próbkowanie regularne, n = {n}: powinno być {n} punktów, jest {actual.Length}: {got}", $"4.1.1 Regular sampling, n = {n}: there should be {n} points, there are {actual.Length}: {got}"));
            for (int i = 0; i < n; i++)
            {
                if (Math.Abs(actual[i].X - expected[i].X) > 1e-12 || Math.Abs(actual[i].Y - expected[i].Y) > 1e-12)
                {
                    Assert.Fail(T(
                        F($"4.1.1 Próbkowanie regularne, n = {n} (siatka {Math.Sqrt(n)}×{Math.Sqrt(n)}), piksel {pixel}: powinien być punkt ({expected[i].X:F4}, {expected[i].Y:F4}) = ((i + 0.5)/k, (j + 0.5)/k), a jest ({actual[i].X:F4}, {actual[i].Y:F4}). Twoje punkty: {got} …"),
                        F($"4.1.1 Regular sampling, n = {n} ({Math.Sqrt(n)}×{Math.Sqrt(n)} grid), pixel {pixel}: the point ({expected[i].X:F4}, {expected[i].Y:F4}) = ((i + 0.5)/k, (j + 0.5)/k) should be there, got ({actual[i].X:F4}, {actual[i].Y:F4}). Your points: {got} …")));
                }
            }
        }

        output.WriteLine(F($"n = {n}: {T("siatka jak w RayLab", "the grid as RayLab's")}"));
    });

    [Trait("Section", "4.1.2")]
    [Fact(DisplayName = English ? "4.1.2 Random sampling: uniform points in the pixel, different in each pixel" : "4.1.2 Próbkowanie losowe: punkty równomiernie w pikselu, inne w każdym pikselu")]
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
            Assert.True(points.Length == n, T($"4.1.2 Próbkowanie losowe: n = {n}, a punktów jest {points.Length}.", $"4.1.2 Random sampling: n = {n}, got {points.Length} points."));
            foreach ((double x, double y) in points)
            {
                InPixel("4.1.2", pixel, x, y);
                cells[((int)(y * 4) * 4) + (int)(x * 4)]++;
            }

            first.Add(points[0]);
        }

        double chi2 = ChiSquare(cells), oracle = OracleChiSquare(new RandomSampler(n, 7), n);
        output.WriteLine(F($"{Pixels} {T("pikseli", "pixels")} × {n}: χ² = {chi2:F1} ({T("RayLab", "RayLab")}: {oracle:F1}; {T("próg", "limit")} 37.7), {first.Count} {T("różnych pierwszych punktów", "different first points")}"));
        Assert.True(first.Count > Pixels * 0.99, T(
            $"4.1.2 Próbkowanie losowe: pierwszy punkt powtarza się między pikselami ({first.Count} różnych na {Pixels}): każdy piksel losuje nowe punkty.",
            $"4.1.2 Random sampling: the first point repeats between pixels ({first.Count} different in {Pixels}): every pixel draws new points."));
        Assert.True(chi2 < 37.7, T(
            F($"4.1.2 Próbkowanie losowe: punkty nie są równomierne w pikselu. W 16 komórkach siatki 4×4 jest {string.Join(", ", cells)} punktów (równo: {Pixels * n / 16}); χ² = {chi2:F1} > 37.7 (p = 0.001). RayLab: χ² = {oracle:F1}."),
            F($"4.1.2 Random sampling: the points are not uniform in the pixel. The 16 cells hold {string.Join(", ", cells)} points (uniform: {Pixels * n / 16}); χ² = {chi2:F1} > 37.7 (p = 0.001). RayLab: χ² = {oracle:F1}.")));
    });

    [Trait("Section", "4.1.3")]
    [Theory(DisplayName = English ? "4.1.3 Jittered sampling: exactly one random point in each cell of the k×k grid (stratification)" : "4.1.3 Próbkowanie jittered: dokładnie jeden losowy punkt w każdej komórce siatki k×k (stratyfikacja)")]
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
            Assert.True(points.Length == n, T($"4.1.3 Próbkowanie jittered: n = {n}, a punktów jest {points.Length}.", $"4.1.3 Jittered sampling: n = {n}, got {points.Length} points."));
            var seen = new Dictionary<(int, int), (double, double)>();
            foreach ((double x, double y) in points)
            {
                InPixel("4.1.3", pixel, x, y);
                (int i, int j) = ((int)(x * k), (int)(y * k));
                if (seen.TryGetValue((i, j), out (double X, double Y) other))
                {
                    Assert.Fail(T(
                        F($"4.1.3 Próbkowanie jittered, n = {n}, siatka {k}×{k}, piksel {pixel}: w komórce ({i}, {j}) są dwa punkty, ({other.X:F4}, {other.Y:F4}) i ({x:F4}, {y:F4}); instrukcja: jeden losowy punkt w każdej komórce, ((i + rand())/k, (j + rand())/k)."),
                        F($"4.1.3 Jittered sampling, n = {n}, {k}×{k} grid, pixel {pixel}: cell ({i}, {j}) holds two points, ({other.X:F4}, {other.Y:F4}) and ({x:F4}, {y:F4}); the lab: one random point in each cell, ((i + rand())/k, (j + rand())/k).")));
                }

                seen.Add((i, j), (x, y));
                double inCell = (x * k) - i;
                offsets += inCell;
                squares += inCell * inCell;
                count++;
            }
        }

        double mean = offsets / count, variance = (squares / count) - (mean * mean);
        output.WriteLine(F($"{Pixels} {T("pikseli", "pixels")} × {n}: {T("po jednym punkcie w każdej komórce", "one point in each cell")}; {T("położenie w komórce", "place in the cell")}: {T("średnia", "mean")} {mean:F3} (0.5), {T("wariancja", "variance")} {variance:F4} (1/12 = 0.0833)"));
        Assert.True(Math.Abs(variance - (1.0 / 12)) < 0.01, T(
            F($"4.1.3 Próbkowanie jittered: punkt nie jest losowany równomiernie w komórce — wariancja położenia w komórce {variance:F4}, a dla rand() to 1/12 = 0.0833 (0 znaczy: zawsze środek, jak w próbkowaniu regularnym)."),
            F($"4.1.3 Jittered sampling: the point in a cell is not uniformly random — the variance of its place in the cell is {variance:F4}, for rand() it is 1/12 = 0.0833 (0 means: always the centre, as regular sampling).")));
    });

    [Trait("Section", "4.1.4")]
    [Theory(DisplayName = English ? "4.1.4 Adaptive sampling: the same rays and the same value in each pixel as RayLab's adaptive (the lab's rule and weights)" : "4.1.4 Próbkowanie adaptacyjne: te same promienie i ta sama wartość w każdym pikselu co adaptacyjne RayLab (reguła i wagi z instrukcji)")]
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
                _where = F($"{T("piksel", "pixel")} ({x}, {y})");
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
                        throw new InvalidOperationException(T(
                            F($"punkt ({sx:R}, {sy:R}) leży poza siatką co 1/16 piksela, więc w kwadracie głębszym niż 3: rekurencja nie zatrzymuje się na MaxDepth = 3"),
                            F($"the point ({sx:R}, {sy:R}) is off the 1/16-pixel grid, so in a square deeper than 3: the recursion does not stop at MaxDepth = 3")));
                    }

                    if (++calls > 1024 || !RuntimeHelpers.TryEnsureSufficientExecutionStack())
                    {
                        throw new InvalidOperationException(T(
                            F($"za dużo promieni w jednym pikselu ({calls}): rekurencja nie zatrzymuje się na MaxDepth = 3"),
                            F($"too many rays in one pixel ({calls}): the recursion does not stop at MaxDepth = 3")));
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
                    Assert.Fail(T(
                        F($"4.1.4 Próbkowanie adaptacyjne ({cameraName}, {width}×{height}, głębokość 0–3, kontrast 0.05), piksel ({x}, {y}): instrukcja daje {diagram.Points.Count} promieni: {theirs}; wartość {I(expected)}. Twoja metoda: {points.Count} promieni: {yours}; wartość {I(value)}. Reguła: podobszar dzielony, gdy jego róg różni się od środka o więcej niż kontrast; wagi: kwadrat = ¼ Σ v(q), v(q) = (róg + środek)/2 albo wartość podzielonego podobszaru."),
                        F($"4.1.4 Adaptive sampling ({cameraName}, {width}×{height}, depth 0–3, contrast 0.05), pixel ({x}, {y}): the lab's rule gives {diagram.Points.Count} rays: {theirs}; value {I(expected)}. Your method: {points.Count} rays: {yours}; value {I(value)}. The rule: a quadrant is split when its corner differs from the centre by more than the contrast; weights: square = ¼ Σ v(q), v(q) = (corner + centre)/2 or the split quadrant's value.")));
                }
            }
        }

        output.WriteLine(F($"{cameraName} {width}×{height}: {rays} {T("promieni", "rays")} ({(double)rays / (width * height):F2} {T("na piksel", "per pixel")}), RayLab {oracleRays}; {refined} {T("pikseli podzielonych", "pixels split")}"));
    });

    private string _where = T("przed pierwszym pikselem", "before the first pixel");

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
            Assert.Fail(T(F($"{section}: punkt ({x:R}, {y:R}) piksela {pixel} leży poza kwadratem jednostkowym [0, 1) × [0, 1)."), F($"{section}: point ({x:R}, {y:R}) of pixel {pixel} lies outside the unit square [0, 1) × [0, 1).")));
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
