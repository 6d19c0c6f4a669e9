using RayLab;

namespace MyLab;

#if (en)
/// <summary>
/// 3.2 Perspective camera: every ray starts at the centre of projection e = Position. The plane lies at distance
/// s in front of e; the window (u0, v0)–(u1, v1) on it, centred by default with tan(Fov/2) = (v1 − v0)/(2 s) and
/// square pixels, (u1 − u0)/(v1 − v0) = nx/ny; an off-axis window is allowed. a = (u1 − u0) u, b = (v1 − v0) v,
/// c = u0 u + v0 v − s w (the window's lower-left corner, relative to e); p = e + c + α a + β b; the ray is
/// e + t (p − e). Here its direction is (p − e)/s, so that t is the depth along −w and NearPlane ≤ t ≤ FarPlane.
/// </summary>
#else
/// <summary>
/// 3.2 Kamera perspektywiczna: każdy promień wychodzi ze środka rzutowania e = Position. Płaszczyzna leży w
/// odległości s przed e; okno (u0, v0)–(u1, v1) na niej, domyślnie wyśrodkowane, z tg(Fov/2) = (v1 − v0)/(2 s) i
/// kwadratowymi pikselami, (u1 − u0)/(v1 − v0) = nx/ny; okno może być niewyśrodkowane. a = (u1 − u0) u,
/// b = (v1 − v0) v, c = u0 u + v0 v − s w (lewy dolny róg okna względem e); p = e + c + α a + β b; promień to
/// e + t (p − e). Tu jego kierunek to (p − e)/s, żeby t było głębokością wzdłuż −w i NearPlane ≤ t ≤ FarPlane.
/// </summary>
#endif
public sealed class LabPerspectiveCamera : LabCamera
{
#if (en)
    /// <summary>The plane's distance from e, s &gt; 0.</summary>
#else
    /// <summary>Odległość płaszczyzny od e, s &gt; 0.</summary>
#endif
    public double S { get; set; } = 1;

#if (solution)
    /// <inheritdoc/>
    public override Window GetWindow(int nx, int ny)
    {
        if (Window is { } window)
        {
            return window;
        }

        double v1 = S * Math.Tan(Fov * Math.PI / 360), u1 = v1 * nx / ny;
        return new Window(-u1, -v1, u1, v1);
    }

    /// <inheritdoc/>
    public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5)
    {
        (Double3 u, Double3 v, Double3 w) = Frame();
        (double u0, double v0, double u1, double v1) = GetWindow(nx, ny);
        Double3 a = (u1 - u0) * u, b = (v1 - v0) * v, c = (u0 * u) + (v0 * v) - (S * w);
        double alpha = Alpha(x, sx, nx), beta = Beta(y, sy, ny);
        Double3 pMinusE = c + (alpha * a) + (beta * b);
        return new Ray(Position, pMinusE / S);
    }
#else
    /// <inheritdoc/>
    public override Window GetWindow(int nx, int ny) => throw ToWrite.Section("3.2", "LabPerspectiveCamera.GetWindow(nx, ny)");

    /// <inheritdoc/>
    public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5) =>
        throw ToWrite.Section("3.2", "LabPerspectiveCamera.GetRay(x, y, nx, ny, sx, sy)");
#endif
}
