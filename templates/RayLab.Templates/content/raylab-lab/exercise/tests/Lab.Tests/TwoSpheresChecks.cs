using RayLab;
using RayLab.Sampling;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>5: the render loop, and the two-sphere pictures against RayLab's renders and the exact image.</summary>
#else
/// <summary>5: pętla renderowania i obrazy dwóch kul wobec renderowań RayLab i dokładnego obrazu.</summary>
#endif
public sealed class TwoSpheresChecks(ITestOutputHelper output)
{
#if (en)
    /// <summary>
    /// How far your adaptive picture may be from the exact image: RayLab's own adaptive at the same settings
    /// (depth 0–3, contrast 0.05, quincunx) plus this margin, in RMSE levels and in FLIP.
    /// </summary>
#else
    /// <summary>
    /// Jak daleko Twój obraz adaptacyjny może być od dokładnego: tyle co adaptacyjne RayLab przy tych samych
    /// ustawieniach (głębokość 0–3, kontrast 0.05, quincunx) plus ten margines, w poziomach RMSE i we FLIP.
    /// </summary>
#endif
    private const double RmseMargin = 0.25, FlipMargin = 0.002;

    public static TheoryData<string> CameraNames => ["orthographic", "perspective"];

    [Trait("Section", "5")]
    [Theory(DisplayName = English ? "5 Task: the render loop, one ray through each pixel's centre, gives RayLab's picture" : "5 Zadanie: pętla renderowania, jeden promień przez środek piksela, daje obraz RayLab")]
    [MemberData(nameof(CameraNames))]
    public void RenderLoop(string cameraName)
    {
        (int width, int height) = (TwoSpheresFile.Width, TwoSpheresFile.Height);
        LabCamera settings = cameraName == "perspective" ? Perspective() : Orthographic();
        var camera = new OracleCamera(settings, width, height);
        LabImage image = null!;
        long rays = 0;
        TimeSpan time = Run(output, () => camera.LastPixel, () =>
        {
            image = new LabImage(width, height);
            rays = LabRenderer.Render(TwoSpheresFile.Scene, camera, new CentreSampler(), image);
        });

        var expected = new Image(width, height);
        new Renderer().Render(TwoSpheresFile.Scene, Oracle(settings), new RegularSampler(1), expected);
        Image actual = Pictures.ToRayLab(image);
        (int count, int x, int y, RayLab.Rgb24 e, RayLab.Rgb24 a) = Pictures.Differences(expected, actual, 0);
        (_, _, string figures) = Pictures.Measure(actual, Pictures.Exact(Oracle(settings), width, height));
        output.WriteLine(F($"{cameraName} {width}×{height}: {rays} {T("promieni", "rays")}, {time.TotalMilliseconds:F1} ms, {count} {T("pikseli innych niż w RayLab", "pixels unlike RayLab's")}; {T("względem dokładnego obrazu", "against the exact image")}: {figures}"));
        Assert.True(rays == (long)width * height, T(
            $"5 Zadanie: jeden punkt na piksel daje {width * height} promieni, a pętla zwróciła {rays}.",
            $"5 Task: one point per pixel makes {width * height} rays, the loop returned {rays}."));
        Assert.True(count == 0, T(
            $"5 Zadanie ({cameraName}): pętla renderowania powinna dać obraz RayLab (te same promienie, kolor z Scene.Trace, średnia, SetPixel). {count} pikseli się różni; pierwszy ({x}, {y}): RayLab {e}, Twoja pętla {a}.",
            $"5 Task ({cameraName}): the render loop should give RayLab's picture (the same rays, colour from Scene.Trace, the mean, SetPixel). {count} pixels differ; the first ({x}, {y}): RayLab {e}, your loop {a}."));
    }

    [Trait("Section", "5")]
    [Fact(DisplayName = English ? "5 Task: the same picture on every run (a random sampler with the same seed)" : "5 Zadanie: ten sam obraz przy każdym uruchomieniu (losowe próbki z tym samym ziarnem)")]
    public void SameSeedSamePicture()
    {
        const int width = 160, height = 120;
        var camera = new OracleCamera(Perspective(), width, height);
        LabImage first = null!, second = null!;
        Run(output, () => camera.LastPixel, () =>
        {
            (first, second) = (new LabImage(width, height), new LabImage(width, height));
            LabRenderer.Render(TwoSpheresFile.Scene, camera, new DrawingSampler(4), first, seed: 5);
            LabRenderer.Render(TwoSpheresFile.Scene, camera, new DrawingSampler(4), second, seed: 5);
        });
        (int count, int x, int y, RayLab.Rgb24 a, RayLab.Rgb24 b) = Pictures.Differences(Pictures.ToRayLab(first), Pictures.ToRayLab(second), 0);
        output.WriteLine(F($"{width}×{height}, 4 {T("próbki losowe na piksel, dwa razy", "random samples per pixel, twice")}: {count} {T("pikseli różnych", "pixels differ")}"));
        Assert.True(count == 0, T(
            $"5 Zadanie: to samo ziarno powinno dać ten sam obraz przy dowolnej liczbie wątków (jeden generator Random na wiersz, z ziarna i numeru wiersza). {count} pikseli się różni; pierwszy ({x}, {y}): {a}, potem {b}.",
            $"5 Task: the same seed should give the same picture at any thread count (one Random per row, from the seed and the row). {count} pixels differ; the first ({x}, {y}): {a}, then {b}."));
    }

    [Trait("Section", "5")]
    [Theory(DisplayName = English ? "5 Task: two spheres with your camera and your adaptive sampling, close to the exact image (RMSE, FLIP)" : "5 Zadanie: dwie kule Twoją kamerą i Twoim próbkowaniem adaptacyjnym, blisko dokładnego obrazu (RMSE, FLIP)")]
    [MemberData(nameof(CameraNames))]
    public void TwoSpheres(string cameraName)
    {
        (int width, int height) = (TwoSpheresFile.Width, TwoSpheresFile.Height);
        LabCamera camera = cameraName == "perspective" ? Perspective() : Orthographic();
        LabImage image = null!;
        long rays = 0;
        var watched = new WatchedCamera(camera);
        TimeSpan time = Run(output, () => watched.LastPixel, () =>
        {
            image = new LabImage(width, height);
            rays = LabRenderer.Render(TwoSpheresFile.Scene, watched, new LabAdaptiveSampler(maxDepth: 3, contrast: 0.05), image);
        });

        Camera oracle = Oracle(camera);
        Image exact = Pictures.Exact(oracle, width, height);
        var reference = new Image(width, height);
        RenderStatistics stats = new Renderer().Render(TwoSpheresFile.Scene, oracle, new AdaptiveSampler(minDepth: 0, maxDepth: 3, contrast: 0.05, quincunx: true), reference);
        (double rmse, double flip, string yours) = Pictures.Measure(Pictures.ToRayLab(image), exact);
        (double oracleRmse, double oracleFlip, string theirs) = Pictures.Measure(reference, exact);
        output.WriteLine(F($"{cameraName} {width}×{height}: {rays} {T("promieni", "rays")} ({(double)rays / (width * height):F2} {T("na piksel", "per pixel")}), {time.TotalMilliseconds:F1} ms; {T("względem dokładnego obrazu", "against the exact image")}: {yours}"));
        output.WriteLine(F($"RayLab ({T("to samo adaptacyjne", "the same adaptive")}): {stats.PrimaryRays} {T("promieni (rogi wspólne dla sąsiednich pikseli)", "rays (corners shared by neighbouring pixels)")}: {theirs}"));
        Assert.True(rmse <= oracleRmse + RmseMargin && flip <= oracleFlip + FlipMargin, T(
            F($"5 Zadanie ({cameraName}): obraz dwóch kul jest za daleko od dokładnego: {yours}; próbkowanie adaptacyjne RayLab z tymi samymi ustawieniami: {theirs}; dopuszczalne RMSE ≤ {oracleRmse + RmseMargin:F3}, FLIP ≤ {oracleFlip + FlipMargin:F4}. Zobacz najpierw sprawdzenia 3.x i 4.1.4."),
            F($"5 Task ({cameraName}): the two-sphere picture is too far from the exact one: {yours}; RayLab's adaptive at the same settings: {theirs}; allowed RMSE ≤ {oracleRmse + RmseMargin:F3}, FLIP ≤ {oracleFlip + FlipMargin:F4}. See the checks of 3.x and 4.1.4 first.")));
    }

#if (en)
    /// <summary>One point, the pixel's centre.</summary>
#else
    /// <summary>Jeden punkt, środek piksela.</summary>
#endif
    private sealed class CentreSampler : ILabSampler
    {
        public int SamplesPerPixel => 1;

        public (double X, double Y)[] GetSamples(Random random)
        {
            StopIfPastLimit();
            return [(0.5, 0.5)];
        }
    }

#if (en)
    /// <summary>n points drawn from the loop's generator.</summary>
#else
    /// <summary>n punktów losowanych z generatora pętli.</summary>
#endif
    private sealed class DrawingSampler(int n) : ILabSampler
    {
        public int SamplesPerPixel => n;

        public (double X, double Y)[] GetSamples(Random random)
        {
            StopIfPastLimit();
            return [.. Enumerable.Range(0, n).Select(_ => (random.NextDouble(), random.NextDouble()))];
        }
    }

#if (en)
    /// <summary>Your camera, remembering the last pixel asked for (a time limit names it).</summary>
#else
    /// <summary>Twoja kamera, która pamięta ostatni żądany piksel (wskazuje go limit czasu).</summary>
#endif
    private sealed class WatchedCamera : LabCamera
    {
        private readonly LabCamera _camera;
        private long _last = -1;
        private int _width = 1;

        public WatchedCamera(LabCamera camera)
        {
            _camera = camera;
            (Position, Target, Up, NearPlane, FarPlane, Fov, Window) = (camera.Position, camera.Target, camera.Up, camera.NearPlane, camera.FarPlane, camera.Fov, camera.Window);
        }

        public string LastPixel
        {
            get
            {
                long last = Interlocked.Read(ref _last);
                return last >= 0 ? $"{T("piksel", "pixel")} ({last % _width}, {last / _width})" : T("żaden piksel", "no pixel yet");
            }
        }

        public override Window GetWindow(int nx, int ny) => _camera.GetWindow(nx, ny);

        public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5)
        {
            StopIfPastLimit();
            _width = nx;
            Interlocked.Exchange(ref _last, ((long)y * nx) + x);
            return _camera.GetRay(x, y, nx, ny, sx, sy);
        }
    }
}
