using RayLab;
using RayLab.Scenes;

namespace MyLab;

#if (en)
/// <summary>The lab's task (section 5): two spheres (scenes/two-spheres.json), seen by your orthographic and your perspective camera.</summary>
#else
/// <summary>Zadanie (sekcja 5): dwie kule (scenes/two-spheres.json) widziane przez Twoją kamerę ortogonalną i perspektywiczną.</summary>
#endif
public static class TwoSpheres
{
#if (en)
    /// <summary>scenes/two-spheres.json: 800×600, the spheres, the background and I_a (Lab I's scene file, read by RayLab).</summary>
#else
    /// <summary>scenes/two-spheres.json: 800×600, kule, tło i I_a (plik sceny z laboratorium I, czytany przez RayLab).</summary>
#endif
    public static SceneDescription Load()
    {
        string path = File.Exists(Path.Combine("scenes", "two-spheres.json"))
            ? Path.Combine("scenes", "two-spheres.json")
            : Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");
        return SceneFile.Load(path);
    }

#if (en)
    /// <summary>3.2: e = (0, 0.5, 6), looking at the origin, Fov 40°.</summary>
#else
    /// <summary>3.2: e = (0, 0.5, 6), patrzy na początek układu, Fov 40°.</summary>
#endif
    public static LabPerspectiveCamera Perspective() => new()
    {
        Position = new Double3(0, 0.5, 6),
        Target = new Double3(0, 0, 0),
        Up = new Double3(0, 1, 0),
        Fov = 40,
        NearPlane = 0.1,
        FarPlane = 100,
    };

#if (en)
    /// <summary>3.1: the same eye and gaze, a window 4.2 high.</summary>
#else
    /// <summary>3.1: to samo oko i kierunek patrzenia, okno o wysokości 4.2.</summary>
#endif
    public static LabOrthoCamera Orthographic() => new()
    {
        Position = new Double3(0, 0.5, 6),
        Target = new Double3(0, 0, 0),
        Up = new Double3(0, 1, 0),
        ViewHeight = 4.2,
        NearPlane = 0.1,
        FarPlane = 100,
    };
}
