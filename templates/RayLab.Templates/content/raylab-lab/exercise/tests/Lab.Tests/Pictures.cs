using RayLab;
using RayLab.Cameras;
using RayLab.ImageSharp;
using RayLab.Metrics;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>Pictures for the checks: RayLab's renders (the oracle), the exact image, and yours as a RayLab image.</summary>
#else
/// <summary>Obrazy dla sprawdzeń: renderowania RayLab (wzorzec), dokładny obraz i Twój jako obraz RayLab.</summary>
#endif
internal static class Pictures
{
#if (en)
    /// <summary>Your bitmap as a RayLab image, byte for byte (RayLab.ImageSharp).</summary>
#else
    /// <summary>Twoja bitmapa jako obraz RayLab, bajt w bajt (RayLab.ImageSharp).</summary>
#endif
    public static Image ToRayLab(LabImage image) => image.Bitmap.ToRayLabImage();

#if (en)
    /// <summary>Each pixel's exact area-weighted colour: what every antialiasing method aims at.</summary>
#else
    /// <summary>Dokładny kolor każdego piksela, średnia po jego polu: cel każdej metody antyaliasingu.</summary>
#endif
    public static Image Exact(Camera camera, int width, int height)
    {
        var exact = new Image(width, height);
        new Renderer().Render(TwoSpheresFile.Scene, camera, RenderMethod.Exact, exact);
        return exact;
    }

#if (en)
    /// <summary>RMSE (8-bit levels) and FLIP's mean against <paramref name="reference"/>, as one line for the output.</summary>
#else
    /// <summary>RMSE (poziomy 8-bitowe) i średni FLIP względem <paramref name="reference"/>, jako jeden wiersz wyjścia.</summary>
#endif
    public static (double Rmse, double Flip, string Line) Measure(Image image, Image reference)
    {
        ImageError error = ImageError.Measure(image, reference);
        double flip = Flip.Compute(reference, image).Mean;
        return (error.Rmse, flip, Msg.Figures(error.Rmse, error.Max, flip));
    }

#if (en)
    /// <summary>The first pixel where two pictures differ by more than <paramref name="levels"/>, and how many do.</summary>
#else
    /// <summary>Pierwszy piksel, w którym dwa obrazy różnią się o więcej niż <paramref name="levels"/>, i ile takich jest.</summary>
#endif
    public static (int Count, int X, int Y, RayLab.Rgb24 Expected, RayLab.Rgb24 Actual) Differences(Image expected, Image actual, int levels)
    {
        int count = 0, fx = -1, fy = -1;
        RayLab.Rgb24 e0 = default, a0 = default;
        for (int y = 0; y < expected.Height; y++)
        {
            for (int x = 0; x < expected.Width; x++)
            {
                RayLab.Rgb24 e = expected.GetPixel(x, y), a = actual.GetPixel(x, y);
                if (Math.Abs(e.R - a.R) > levels || Math.Abs(e.G - a.G) > levels || Math.Abs(e.B - a.B) > levels)
                {
                    if (count++ == 0)
                    {
                        (fx, fy, e0, a0) = (x, y, e, a);
                    }
                }
            }
        }

        return (count, fx, fy, e0, a0);
    }
}

#if (en)
/// <summary>
/// A camera for the checks of sections 4 and 5: RayLab's rays (so those checks do not depend on your cameras), and
/// it remembers the last pixel asked for, which a time limit names.
/// </summary>
#else
/// <summary>
/// Kamera dla sprawdzeń sekcji 4 i 5: promienie RayLab (więc te sprawdzenia nie zależą od Twoich kamer); pamięta
/// ostatni żądany piksel, który wskazuje limit czasu.
/// </summary>
#endif
internal sealed class OracleCamera : LabCamera
{
    private readonly ImagePlane _plane;
    private readonly double _scale;
    private long _last = -1;

    public OracleCamera(LabCamera settings, int width, int height)
    {
        Camera camera = Oracle(settings);
        _plane = camera.GetImagePlane(width, height);
#if (en)
        // direction (p − e)/s: t is the depth
#else
        // kierunek (p − e)/s: t to głębokość
#endif
        _scale = settings is LabPerspectiveCamera p ? 1 / p.S : 1;
        (Position, Target, Up, NearPlane, FarPlane, Fov, Window) = (settings.Position, settings.Target, settings.Up, settings.NearPlane, settings.FarPlane, settings.Fov, settings.Window);
    }

#if (en)
    /// <summary>The last pixel a ray was asked for, e.g. "(12, 34)".</summary>
#else
    /// <summary>Ostatni piksel, dla którego żądano promienia, np. "(12, 34)".</summary>
#endif
    public string LastPixel
    {
        get
        {
            long last = Interlocked.Read(ref _last);
            return last >= 0 ? Msg.Pixel(last % _plane.Width, last / _plane.Width) : Msg.NoPixelYet;
        }
    }

    public override Window GetWindow(int nx, int ny) => _plane.Window;

    public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5)
    {
        StopIfPastLimit();
        Interlocked.Exchange(ref _last, ((long)y * _plane.Width) + x);
        Ray ray = _plane.GetPixelRay(x, y, sx, sy);
        return new Ray(ray.Origin, ray.Direction * _scale);
    }
}
