using RayLab;
using RayLab.Cameras;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>3, 3.1, 3.2: your cameras' frame, window and rays against RayLab's cameras with the same settings.</summary>
#else
/// <summary>3, 3.1, 3.2: baza, okno i promienie Twoich kamer wobec kamer RayLab o tych samych ustawieniach.</summary>
#endif
public sealed class CameraChecks(ITestOutputHelper output)
{
    private const double Tolerance = 1e-9;

    private static readonly (int X, int Y, double Sx, double Sy)[] Points =
        [(0, 0, 0.5, 0.5), (799, 599, 0.5, 0.5), (400, 300, 0.5, 0.5), (123, 456, 0.5, 0.5), (0, 0, 0, 0), (799, 599, 1, 1), (250, 80, 0.25, 0.75)];

#if (en)
    /// <summary>Cameras of each kind: the lab's, a non-default up and s, an off-axis window.</summary>
#else
    /// <summary>Kamery każdego rodzaju: z instrukcji, z innym up i s, z oknem niewyśrodkowanym.</summary>
#endif
    private static IEnumerable<(string Name, LabCamera Camera)> Cameras(bool perspective)
    {
        if (perspective)
        {
            yield return (T("perspektywiczna z zadania", "the task's perspective camera"), Perspective());
            yield return (T("domyślna (e = 0, patrzy na (0, 0, 1))", "the default (e = 0, looking at (0, 0, 1))"), new LabPerspectiveCamera());
            yield return ("s = 2.5, up = (1, 1, 0), Fov 70", new LabPerspectiveCamera
            {
                Position = new Double3(1, 2, 3), Target = new Double3(-1, 0, -2), Up = new Double3(1, 1, 0), S = 2.5, Fov = 70,
            });
            yield return (T("okno niewyśrodkowane (0.1, −0.2)–(0.9, 0.4), s = 1.5", "an off-axis window (0.1, −0.2)–(0.9, 0.4), s = 1.5"), new LabPerspectiveCamera
            {
                Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), S = 1.5, Window = new Window(0.1, -0.2, 0.9, 0.4),
            });
        }
        else
        {
            yield return (T("ortogonalna z zadania", "the task's orthographic camera"), Orthographic());
            yield return (T("domyślna (okno [−1, 1])", "the default (window [−1, 1])"), new LabOrthoCamera());
            yield return ("up = (1, 1, 0), ViewHeight 3", new LabOrthoCamera
            {
                Position = new Double3(1, 2, 3), Target = new Double3(-1, 0, -2), Up = new Double3(1, 1, 0), ViewHeight = 3,
            });
            yield return (T("okno niewyśrodkowane (0.5, −1)–(2.5, 0.5)", "an off-axis window (0.5, −1)–(2.5, 0.5)"), new LabOrthoCamera
            {
                Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), Window = new Window(0.5, -1, 2.5, 0.5),
            });
        }
    }

    [Trait("Section", "3")]
    [Fact(DisplayName = English ? "3 Camera: the frame w = −g/|g|, u = (up × w)/|up × w|, v = w × u" : "3 Kamera: baza w = −g/|g|, u = (up × w)/|up × w|, v = w × u")]
    public void Frame() => Run(output, () =>
    {
        foreach ((string name, LabCamera camera) in Cameras(true).Concat(Cameras(false)))
        {
            ImagePlane plane = Oracle(camera).GetImagePlane(800, 600);
            (Double3 u, Double3 v, Double3 w) = camera.Frame();
            Near(T($"3 Kamera ({name}): w = −g/|g| z g = Target − Position", $"3 Camera ({name}): w = −g/|g| with g = Target − Position"), plane.W, w);
            Near(T($"3 Kamera ({name}): u = (up × w)/|up × w| (bez minusa z instrukcji: u wskazuje w prawo)", $"3 Camera ({name}): u = (up × w)/|up × w| (without the lab's minus sign: u points right)"), plane.U, u);
            Near(T($"3 Kamera ({name}): v = w × u", $"3 Camera ({name}): v = w × u"), plane.V, v);
            output.WriteLine($"{name}: u {V(u)}, v {V(v)}, w {V(w)}");
        }
    });

    [Trait("Section", "3")]
    [Fact(DisplayName = English ? "3 Camera: the pixel's place on the window, α = (x + sx)/nx, β = 1 − (y + sy)/ny" : "3 Kamera: położenie piksela na oknie, α = (x + sx)/nx, β = 1 − (y + sy)/ny")]
    public void PixelCentre() => Run(output, () =>
    {
        ImagePlane plane = new PerspectiveCamera().GetImagePlane(800, 600);
        foreach ((int x, int y, double sx, double sy) in Points)
        {
            double alpha = LabCamera.Alpha(x, sx, 800), beta = LabCamera.Beta(y, sy, 600);
            Assert.True(Math.Abs(alpha - plane.Alpha(x, sx)) < 1e-12, T(
                F($"3 Kamera: piksel ({x}, {y}) z 800 kolumn, sx = {sx}: α = (x + sx)/nx = {plane.Alpha(x, sx):R} (środek piksela to x + 0.5, nie x), a Alpha dało {alpha:R}."),
                F($"3 Camera: pixel ({x}, {y}) of 800, point sx = {sx}: α = (x + sx)/nx = {plane.Alpha(x, sx):R} (the pixel's centre is x + 0.5, not x), Alpha gave {alpha:R}.")));
            Assert.True(Math.Abs(beta - plane.Beta(y, sy)) < 1e-12, T(
                F($"3 Kamera: piksel ({x}, {y}) z 600 wierszy, sy = {sy}: β = 1 − (y + sy)/ny = {plane.Beta(y, sy):R} (wiersz 0 na górze), a Beta dało {beta:R}."),
                F($"3 Camera: pixel ({x}, {y}) of 600 rows, sy = {sy}: β = 1 − (y + sy)/ny = {plane.Beta(y, sy):R} (row 0 at the top), Beta gave {beta:R}.")));
        }

        output.WriteLine(F($"{Points.Length} {T("punktów jak w RayLab", "points as RayLab's")}"));
    });

    [Trait("Section", "3.1")]
    [Fact(DisplayName = English ? "3.1 Orthographic camera: the window, ViewHeight high, width from nx/ny" : "3.1 Kamera ortogonalna: okno o wysokości ViewHeight, szerokość z nx/ny")]
    public void OrthographicWindow() => Run(output, () => SameWindows(false));

    [Trait("Section", "3.1")]
    [Fact(DisplayName = English ? "3.1 Orthographic camera: parallel rays through each pixel, as RayLab's (off-axis window, non-default up)" : "3.1 Kamera ortogonalna: równoległe promienie przez każdy piksel, jak w RayLab (okno niewyśrodkowane, inne up)")]
    public void OrthographicRays() => Run(output, () => SameRays(false));

    [Trait("Section", "3.2")]
    [Fact(DisplayName = English ? "3.2 Perspective camera: the window from Fov and s, tan(Fov/2) = (v1 − v0)/(2 s)" : "3.2 Kamera perspektywiczna: okno z Fov i s, tg(Fov/2) = (v1 − v0)/(2 s)")]
    public void PerspectiveWindow() => Run(output, () => SameWindows(true));

    [Trait("Section", "3.2")]
    [Fact(DisplayName = English ? "3.2 Perspective camera: the ray e + t (p − e) through each pixel, as RayLab's (off-axis window, non-default s and up)" : "3.2 Kamera perspektywiczna: promień e + t (p − e) przez każdy piksel, jak w RayLab (okno niewyśrodkowane, inne s i up)")]
    public void PerspectiveRays() => Run(output, () => SameRays(true));

    private void SameWindows(bool perspective)
    {
        string section = perspective ? T("3.2 Kamera perspektywiczna", "3.2 Perspective camera") : T("3.1 Kamera ortogonalna", "3.1 Orthographic camera");
        foreach ((string name, LabCamera camera) in Cameras(perspective))
        {
            Window expected = Oracle(camera).GetImagePlane(800, 600).Window, actual = camera.GetWindow(800, 600);
            bool same = Math.Abs(expected.U0 - actual.U0) < Tolerance && Math.Abs(expected.V0 - actual.V0) < Tolerance
                && Math.Abs(expected.U1 - actual.U1) < Tolerance && Math.Abs(expected.V1 - actual.V1) < Tolerance;
            output.WriteLine($"{name}: {actual}");
            Assert.True(same, T(
                $"{section} ({name}), 800×600: okno (u0, v0, u1, v1) powinno być {expected}, a GetWindow dało {actual}.",
                $"{section} ({name}), 800×600: the window (u0, v0, u1, v1) should be {expected}, GetWindow gave {actual}."));
        }
    }

    private void SameRays(bool perspective)
    {
        string section = perspective ? T("3.2 Kamera perspektywiczna", "3.2 Perspective camera") : T("3.1 Kamera ortogonalna", "3.1 Orthographic camera");
        string formula = perspective
            ? T("c = u0 u + v0 v − s w, p = e + c + α a + β b, promień z e w kierunku p − e", "c = u0 u + v0 v − s w, p = e + c + α a + β b, the ray from e towards p − e")
            : T("p = e + c + α a + β b z c = u0 u + v0 v, promień z p w kierunku −w", "p = e + c + α a + β b with c = u0 u + v0 v, the ray from p along −w");
        int compared = 0;
        foreach ((string name, LabCamera camera) in Cameras(perspective))
        {
            ImagePlane plane = Oracle(camera).GetImagePlane(800, 600);
            foreach ((int x, int y, double sx, double sy) in Points)
            {
                Ray expected = plane.GetPixelRay(x, y, sx, sy), actual = camera.GetRay(x, y, 800, 600, sx, sy);
                Double3 d = Double3.Normalize(expected.Direction), da = Double3.Normalize(actual.Direction);
#if (en)
                // perspective: e; orthographic: the point p on the window
#else
                // perspektywiczna: e; ortogonalna: punkt p na oknie
#endif
                Double3 o = expected.Origin, oa = actual.Origin;
                string where = F($"{T("piksel", "pixel")} ({x}, {y}), {T("punkt", "point")} ({sx}, {sy})");
                if ((o - oa).Length > Tolerance * Math.Max(1, o.Length) || (d - da).Length > Tolerance)
                {
                    Assert.Fail(T(
                        $"{section} ({name}), {where}: RayLab daje promień z {V(expected.Origin)} w kierunku {V(d)} (znormalizowany), a Twoja kamera z {V(actual.Origin)} w kierunku {V(da)}. Wzór: {formula}.",
                        $"{section} ({name}), {where}: RayLab gives the ray from {V(expected.Origin)} along {V(d)} (normalized), your camera from {V(actual.Origin)} along {V(da)}. The formula: {formula}."));
                }

                compared++;
            }
        }

        output.WriteLine(F($"{compared} {T("promieni jak w RayLab", "rays as RayLab's")}"));
    }

    private static void Near(string what, Double3 expected, Double3 actual)
    {
        if ((expected - actual).Length > Tolerance)
        {
            Assert.Fail(T($"{what}: powinno być {V(expected)}, a jest {V(actual)}.", $"{what}: should be {V(expected)}, is {V(actual)}."));
        }
    }
}
