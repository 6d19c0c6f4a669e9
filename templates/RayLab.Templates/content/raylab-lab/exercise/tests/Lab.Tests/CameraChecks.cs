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
            yield return (Msg.TaskPerspective, Perspective());
            yield return (Msg.DefaultPerspective, new LabPerspectiveCamera());
            yield return ("s = 2.5, up = (1, 1, 0), Fov 70", new LabPerspectiveCamera
            {
                Position = new Double3(1, 2, 3), Target = new Double3(-1, 0, -2), Up = new Double3(1, 1, 0), S = 2.5, Fov = 70,
            });
            yield return (Msg.OffAxisPerspective, new LabPerspectiveCamera
            {
                Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), S = 1.5, Window = new Window(0.1, -0.2, 0.9, 0.4),
            });
        }
        else
        {
            yield return (Msg.TaskOrthographic, Orthographic());
            yield return (Msg.DefaultOrthographic, new LabOrthoCamera());
            yield return ("up = (1, 1, 0), ViewHeight 3", new LabOrthoCamera
            {
                Position = new Double3(1, 2, 3), Target = new Double3(-1, 0, -2), Up = new Double3(1, 1, 0), ViewHeight = 3,
            });
            yield return (Msg.OffAxisOrthographic, new LabOrthoCamera
            {
                Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), Window = new Window(0.5, -1, 2.5, 0.5),
            });
        }
    }

    [Trait("Section", "3")]
    [Fact(DisplayName = Msg.Frame)]
    public void Frame() => Run(output, () =>
    {
        foreach ((string name, LabCamera camera) in Cameras(true).Concat(Cameras(false)))
        {
            ImagePlane plane = Oracle(camera).GetImagePlane(800, 600);
            (Double3 u, Double3 v, Double3 w) = camera.Frame();
            Near(Msg.FrameW(name), plane.W, w);
            Near(Msg.FrameU(name), plane.U, u);
            Near(Msg.FrameV(name), plane.V, v);
            output.WriteLine($"{name}: u {V(u)}, v {V(v)}, w {V(w)}");
        }
    });

    [Trait("Section", "3")]
    [Fact(DisplayName = Msg.PixelCentre)]
    public void PixelCentre() => Run(output, () =>
    {
        ImagePlane plane = new PerspectiveCamera().GetImagePlane(800, 600);
        foreach ((int x, int y, double sx, double sy) in Points)
        {
            double alpha = LabCamera.Alpha(x, sx, 800), beta = LabCamera.Beta(y, sy, 600);
            Assert.True(Math.Abs(alpha - plane.Alpha(x, sx)) < 1e-12, Msg.AlphaWrong(x, y, sx, plane.Alpha(x, sx), alpha));
            Assert.True(Math.Abs(beta - plane.Beta(y, sy)) < 1e-12, Msg.BetaWrong(x, y, sy, plane.Beta(y, sy), beta));
        }

        output.WriteLine(Msg.PointsAsRayLab(Points.Length));
    });

    [Trait("Section", "3.1")]
    [Fact(DisplayName = Msg.OrthographicWindow)]
    public void OrthographicWindow() => Run(output, () => SameWindows(false));

    [Trait("Section", "3.1")]
    [Fact(DisplayName = Msg.OrthographicRays)]
    public void OrthographicRays() => Run(output, () => SameRays(false));

    [Trait("Section", "3.2")]
    [Fact(DisplayName = Msg.PerspectiveWindow)]
    public void PerspectiveWindow() => Run(output, () => SameWindows(true));

    [Trait("Section", "3.2")]
    [Fact(DisplayName = Msg.PerspectiveRays)]
    public void PerspectiveRays() => Run(output, () => SameRays(true));

    private void SameWindows(bool perspective)
    {
        string section = perspective ? Msg.PerspectiveSection : Msg.OrthographicSection;
        foreach ((string name, LabCamera camera) in Cameras(perspective))
        {
            Window expected = Oracle(camera).GetImagePlane(800, 600).Window, actual = camera.GetWindow(800, 600);
            bool same = Math.Abs(expected.U0 - actual.U0) < Tolerance && Math.Abs(expected.V0 - actual.V0) < Tolerance
                && Math.Abs(expected.U1 - actual.U1) < Tolerance && Math.Abs(expected.V1 - actual.V1) < Tolerance;
            output.WriteLine($"{name}: {actual}");
            Assert.True(same, Msg.WindowWrong(section, name, expected, actual));
        }
    }

    private void SameRays(bool perspective)
    {
        string section = perspective ? Msg.PerspectiveSection : Msg.OrthographicSection;
        string formula = perspective ? Msg.PerspectiveFormula : Msg.OrthographicFormula;
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
                string where = Msg.PixelPoint(x, y, sx, sy);
                if ((o - oa).Length > Tolerance * Math.Max(1, o.Length) || (d - da).Length > Tolerance)
                {
                    Assert.Fail(Msg.RayWrong(section, name, where, expected.Origin, d, actual.Origin, da, formula));
                }

                compared++;
            }
        }

        output.WriteLine(Msg.RaysAsRayLab(compared));
    }

    private static void Near(string what, Double3 expected, Double3 actual)
    {
        if ((expected - actual).Length > Tolerance)
        {
            Assert.Fail(Msg.ShouldBe(what, expected, actual));
        }
    }
}
