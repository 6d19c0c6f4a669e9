using RayLab;
using RayLab.Cameras;
using RayLab.ImageSharp;
using RayLab.Metrics;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

/// <summary>Pictures for the checks: RayLab's renders (the oracle), the exact image, and yours as a RayLab image.</summary>
internal static class Pictures
{
    /// <summary>Your bitmap as a RayLab image, byte for byte (RayLab.ImageSharp).</summary>
    public static Image ToRayLab(LabImage image) => image.Bitmap.ToRayLabImage();

    /// <summary>Each pixel's exact area-weighted colour: what every antialiasing method aims at.</summary>
    public static Image Exact(Camera camera, int width, int height)
    {
        var exact = new Image(width, height);
        new Renderer().Render(TwoSpheresFile.Scene, camera, RenderMethod.Exact, exact);
        return exact;
    }

    /// <summary>RMSE (8-bit levels) and FLIP's mean against <paramref name="reference"/>, as one line for the output.</summary>
    public static (double Rmse, double Flip, string Line) Measure(Image image, Image reference)
    {
        ImageError error = ImageError.Measure(image, reference);
        double flip = Flip.Compute(reference, image).Mean;
        return (error.Rmse, flip, F($"RMSE {error.Rmse:F3} {T("poziomu", "levels")}, max {error.Max}, FLIP {flip:F4}"));
    }

    /// <summary>The first pixel where two pictures differ by more than <paramref name="levels"/>, and how many do.</summary>
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

/// <summary>
/// A camera for the checks of sections 4 and 5: RayLab's rays (so those checks do not depend on your cameras), and
/// it remembers the last pixel asked for, which a time limit names.
/// </summary>
internal sealed class OracleCamera : LabCamera
{
    private readonly ImagePlane _plane;
    private readonly double _scale;
    private long _last = -1;

    public OracleCamera(LabCamera settings, int width, int height)
    {
        Camera camera = Oracle(settings);
        _plane = camera.GetImagePlane(width, height);
        _scale = settings is LabPerspectiveCamera p ? 1 / p.S : 1; // direction (p − e)/s: t is the depth
        (Position, Target, Up, NearPlane, FarPlane, Fov, Window) = (settings.Position, settings.Target, settings.Up, settings.NearPlane, settings.FarPlane, settings.Fov, settings.Window);
    }

    /// <summary>The last pixel a ray was asked for, e.g. "(12, 34)".</summary>
    public string LastPixel
    {
        get
        {
            long last = Interlocked.Read(ref _last);
            return last >= 0 ? $"{T("piksel", "pixel")} ({last % _plane.Width}, {last / _plane.Width})" : T("żaden piksel", "no pixel yet");
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
