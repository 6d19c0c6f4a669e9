using RayLab;

namespace MyLab;

#if (en)
/// <summary>
/// 3.1 Orthographic camera: parallel rays, one through each point of the window, all along the gaze −w. The window
/// is centred on Position and ViewHeight high (the lab's first picture: 2, the plane's [−1, 1]); its width follows
/// the image, ViewHeight·nx/ny. Point on the window: p = e + c + α a + β b with a = (u1 − u0) u, b = (v1 − v0) v,
/// c = u0 u + v0 v; the ray starts at p and runs along −w (not from one common point: that would be perspective).
/// </summary>
#else
/// <summary>
/// 3.1 Kamera ortogonalna: promienie równoległe, po jednym przez każdy punkt okna, wszystkie w kierunku −w. Okno
/// ma środek w Position i wysokość ViewHeight (pierwszy obraz z instrukcji: 2, płaszczyzna [−1, 1]); szerokość
/// wynika z obrazu: ViewHeight·nx/ny. Punkt okna: p = e + c + α a + β b, gdzie a = (u1 − u0) u, b = (v1 − v0) v,
/// c = u0 u + v0 v; promień zaczyna się w p i biegnie wzdłuż −w (nie z jednego wspólnego punktu — to byłaby
/// perspektywa).
/// </summary>
#endif
public sealed class LabOrthoCamera : LabCamera
{
#if (en)
    /// <summary>The window's height.</summary>
#else
    /// <summary>Wysokość okna.</summary>
#endif
    public double ViewHeight { get; set; } = 2;

#if (solution)
    /// <inheritdoc/>
    public override Window GetWindow(int nx, int ny)
    {
        if (Window is { } window)
        {
            return window;
        }

        double v1 = ViewHeight / 2, u1 = v1 * nx / ny;
        return new Window(-u1, -v1, u1, v1);
    }

    /// <inheritdoc/>
    public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5)
    {
        (Double3 u, Double3 v, Double3 w) = Frame();
        (double u0, double v0, double u1, double v1) = GetWindow(nx, ny);
        Double3 a = (u1 - u0) * u, b = (v1 - v0) * v, c = (u0 * u) + (v0 * v);
        double alpha = Alpha(x, sx, nx), beta = Beta(y, sy, ny);
        Double3 p = Position + c + (alpha * a) + (beta * b);
        return new Ray(p, -w);
    }
#else
    /// <inheritdoc/>
    public override Window GetWindow(int nx, int ny) => throw ToWrite.Section("3.1", "LabOrthoCamera.GetWindow(nx, ny)");

    /// <inheritdoc/>
    public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5) =>
        throw ToWrite.Section("3.1", "LabOrthoCamera.GetRay(x, y, nx, ny, sx, sy)");
#endif
}
