using RayLab;

namespace MyLab;

#if (en)
/// <summary>
/// 5 Task: the render loop. Parallel.For over the image's rows; in each pixel a ray through every point the sampling
/// method gives (or the adaptive method's points), the scene's colour where it hits (Lab I: <see cref="Scene.Trace"/>,
/// between NearPlane and FarPlane), the mean into the bitmap. Returns the number of rays.
/// </summary>
#else
/// <summary>
/// 5 Zadanie: pętla renderowania. Parallel.For po wierszach obrazu; w każdym pikselu promień przez każdy punkt z
/// metody próbkowania (albo punkty metody adaptacyjnej), kolor sceny w miejscu trafienia (laboratorium I:
/// <see cref="Scene.Trace"/>, między NearPlane a FarPlane), średnia do bitmapy. Zwraca liczbę promieni.
/// </summary>
#endif
public static class LabRenderer
{
#if (en)
    /// <summary>The colour the ray sees (Lab I: the nearest sphere's colour × I_a, or the background).</summary>
#else
    /// <summary>Kolor, który widzi promień (laboratorium I: kolor najbliższej kuli × I_a albo tło).</summary>
#endif
    public static LightIntensity Trace(Scene scene, LabCamera camera, Ray ray)
    {
        Intensity colour = scene.Trace(ray, camera.NearPlane, camera.FarPlane);
        return new LightIntensity(colour.R, colour.G, colour.B);
    }

#if (solution)
#if (en)
    /// <summary>Renders with a sampling method (4.1.1–4.1.3); the same seed gives the same picture.</summary>
#else
    /// <summary>Renderuje z metodą próbkowania (4.1.1–4.1.3); to samo ziarno daje ten sam obraz.</summary>
#endif
    public static long Render(Scene scene, LabCamera camera, ILabSampler sampler, LabImage image, int seed = 1)
    {
        int nx = image.Width, ny = image.Height;
        long rays = 0;
        Parallel.For(0, ny, y =>
        {
            var random = new Random(unchecked((seed * 1_000_003) + y)); // jeden generator na wiersz: wynik nie zależy od liczby wątków
            long rowRays = 0;
            for (int x = 0; x < nx; x++)
            {
                (double X, double Y)[] points = sampler.GetSamples(random);
                var sum = new LightIntensity();
                foreach ((double sx, double sy) in points)
                {
                    sum += Trace(scene, camera, camera.GetRay(x, y, nx, ny, sx, sy));
                }

                image.SetPixel(x, y, sum / points.Length);
                rowRays += points.Length;
            }

            Interlocked.Add(ref rays, rowRays);
        });
        return rays;
    }

#if (en)
    /// <summary>Renders with adaptive sampling (4.1.4).</summary>
#else
    /// <summary>Renderuje z próbkowaniem adaptacyjnym (4.1.4).</summary>
#endif
    public static long Render(Scene scene, LabCamera camera, LabAdaptiveSampler sampler, LabImage image)
    {
        int nx = image.Width, ny = image.Height;
        long rays = 0;
        Parallel.For(0, ny, y =>
        {
            long rowRays = 0;
            for (int x = 0; x < nx; x++)
            {
                image.SetPixel(x, y, sampler.Pixel((sx, sy) =>
                {
                    rowRays++;
                    return Trace(scene, camera, camera.GetRay(x, y, nx, ny, sx, sy));
                }));
            }

            Interlocked.Add(ref rays, rowRays);
        });
        return rays;
    }
#else
#if (en)
    /// <summary>Renders with a sampling method (4.1.1–4.1.3); the same seed gives the same picture.</summary>
#else
    /// <summary>Renderuje z metodą próbkowania (4.1.1–4.1.3); to samo ziarno daje ten sam obraz.</summary>
#endif
    public static long Render(Scene scene, LabCamera camera, ILabSampler sampler, LabImage image, int seed = 1) =>
        throw ToWrite.Section("5", "LabRenderer.Render(scene, camera, sampler, image)");

#if (en)
    /// <summary>Renders with adaptive sampling (4.1.4).</summary>
#else
    /// <summary>Renderuje z próbkowaniem adaptacyjnym (4.1.4).</summary>
#endif
    public static long Render(Scene scene, LabCamera camera, LabAdaptiveSampler sampler, LabImage image) =>
        throw ToWrite.Section("5", "LabRenderer.Render(scene, camera, adaptive, image)");
#endif
}
