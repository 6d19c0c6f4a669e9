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
    [Theory(DisplayName = Msg.RenderLoop)]
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
        output.WriteLine(Msg.RenderLoopLine(cameraName, width, height, rays, time.TotalMilliseconds, count, figures));
        Assert.True(rays == (long)width * height, Msg.RenderLoopRays(width * height, rays));
        Assert.True(count == 0, Msg.RenderLoopPicture(cameraName, count, x, y, e, a));
    }

    [Trait("Section", "5")]
    [Fact(DisplayName = Msg.SameSeedSamePicture)]
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
        output.WriteLine(Msg.SameSeedLine(width, height, count));
        Assert.True(count == 0, Msg.SameSeedPicture(count, x, y, a, b));
    }

    [Trait("Section", "5")]
    [Theory(DisplayName = Msg.TwoSpheres)]
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
        output.WriteLine(Msg.TwoSpheresLine(cameraName, width, height, rays, (double)rays / (width * height), time.TotalMilliseconds, yours));
        output.WriteLine(Msg.TwoSpheresOracleLine(stats.PrimaryRays, theirs));
        Assert.True(rmse <= oracleRmse + RmseMargin && flip <= oracleFlip + FlipMargin, Msg.TwoSpheresTooFar(cameraName, yours, theirs, oracleRmse + RmseMargin, oracleFlip + FlipMargin));
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
                return last >= 0 ? Msg.Pixel(last % _width, last / _width) : Msg.NoPixelYet;
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
