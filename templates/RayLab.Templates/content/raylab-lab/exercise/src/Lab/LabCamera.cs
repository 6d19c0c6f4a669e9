using RayLab;

namespace MyLab;

#if (en)
/// <summary>
/// 3 Camera: the lab's properties (Position, Target, Up, NearPlane, FarPlane, Fov), the orthonormal frame u, v, w
/// and the pixel's place on the window. Target is a point (the camera looks from Position towards it); the gaze is
/// g = Target − Position. Frame: w = −g/|g|, u = (up × w)/|up × w| (no minus sign: u points right), v = w × u.
/// Window coordinates of a point (sx, sy) inside pixel (x, y), row 0 at the top: α = (x + sx)/nx,
/// β = 1 − (y + sy)/ny; the pixel's centre is sx = sy = 0.5.
/// </summary>
#else
/// <summary>
/// 3 Kamera: właściwości z instrukcji (Position, Target, Up, NearPlane, FarPlane, Fov), ortonormalna baza u, v, w
/// i położenie piksela na oknie. Target to punkt (kamera patrzy z Position w jego stronę); kierunek patrzenia
/// g = Target − Position. Baza: w = −g/|g|, u = (up × w)/|up × w| (bez minusa: u wskazuje w prawo), v = w × u.
/// Współrzędne na oknie punktu (sx, sy) wewnątrz piksela (x, y), wiersz 0 na górze: α = (x + sx)/nx,
/// β = 1 − (y + sy)/ny; środek piksela to sx = sy = 0.5.
/// </summary>
#endif
public abstract class LabCamera
{
    /// <summary>e.</summary>
    public Double3 Position { get; set; } = new(0, 0, 0);

#if (en)
    /// <summary>A point.</summary>
#else
    /// <summary>Punkt.</summary>
#endif
    public Double3 Target { get; set; } = new(0, 0, 1);

    /// <summary>up.</summary>
    public Double3 Up { get; set; } = new(0, 1, 0);

    /// <summary>t ≥ NearPlane.</summary>
    public double NearPlane { get; set; } = 1;

    /// <summary>t ≤ FarPlane.</summary>
    public double FarPlane { get; set; } = 1000;

#if (en)
    /// <summary>The vertical field of view, degrees: tan(Fov/2) = (v1 − v0)/(2 s).</summary>
#else
    /// <summary>Pionowy kąt widzenia w stopniach: tg(Fov/2) = (v1 − v0)/(2 s).</summary>
#endif
    public double Fov { get; set; } = 60;

#if (en)
    /// <summary>u0, v0, u1, v1; null: from Fov (3.2) or ViewHeight (3.1) and the image's nx/ny.</summary>
#else
    /// <summary>u0, v0, u1, v1; null: z Fov (3.2) albo ViewHeight (3.1) i nx/ny obrazu.</summary>
#endif
    public Window? Window { get; set; }

#if (solution)
    /// <summary>u, v, w.</summary>
    public (Double3 U, Double3 V, Double3 W) Frame()
    {
        Double3 g = Target - Position;
        Double3 w = -Double3.Normalize(g);
        Double3 u = Double3.Normalize(Double3.Cross(Up, w));
        Double3 v = Double3.Cross(w, u);
        return (u, v, w);
    }

    /// <summary>α = (x + sx)/nx.</summary>
    public static double Alpha(int x, double sx, int nx) => (x + sx) / nx;

    /// <summary>β = 1 − (y + sy)/ny.</summary>
    public static double Beta(int y, double sy, int ny) => 1 - ((y + sy) / ny);
#else
    /// <summary>u, v, w.</summary>
    public (Double3 U, Double3 V, Double3 W) Frame() => throw ToWrite.Section("3", "LabCamera.Frame()");

    /// <summary>α = (x + sx)/nx.</summary>
    public static double Alpha(int x, double sx, int nx) => throw ToWrite.Section("3", "LabCamera.Alpha(x, sx, nx)");

    /// <summary>β = 1 − (y + sy)/ny.</summary>
    public static double Beta(int y, double sy, int ny) => throw ToWrite.Section("3", "LabCamera.Beta(y, sy, ny)");
#endif

#if (en)
    /// <summary>The window (u0, v0, u1, v1) for an image of nx × ny pixels; a Window that is set, as it is. The checks compare it with RayLab's within 1e-9, so the order of the operations (a double's rounding) does not matter.</summary>
#else
    /// <summary>Okno (u0, v0, u1, v1) dla obrazu nx × ny pikseli; ustawione Window bez zmian. Testy porównują je z RayLab z dokładnością 1e-9, więc kolejność działań (zaokrąglenia double) nie ma znaczenia.</summary>
#endif
    public abstract Window GetWindow(int nx, int ny);

#if (en)
    /// <summary>The ray through the point (sx, sy) of pixel (x, y) of an nx × ny image.</summary>
#else
    /// <summary>Promień przez punkt (sx, sy) piksela (x, y) obrazu nx × ny.</summary>
#endif
    public abstract Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5);
}
