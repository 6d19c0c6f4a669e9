using System.Diagnostics;
using System.Globalization;
using RayLab;
using RayLab.Scenes;
using SixLabors.ImageSharp;

namespace MyLab;

#if (en)
/// <summary>
/// Lab II, section 5: renders the two spheres with your orthographic and your perspective camera and your adaptive
/// sampling into out/two-spheres-orthographic.png, out/two-spheres-perspective.png and out/obrazkoncowy.jpg.
/// <c>dotnet run --project src/Lab -- check</c> only lists which parts are written.
/// </summary>
#else
/// <summary>
/// Laboratorium II, sekcja 5: renderuje dwie kule Twoją kamerą ortogonalną i perspektywiczną z Twoim próbkowaniem
/// adaptacyjnym do out/two-spheres-orthographic.png, out/two-spheres-perspective.png i out/obrazkoncowy.jpg.
/// <c>dotnet run --project src/Lab -- check</c> tylko wypisuje, które części są napisane.
/// </summary>
#endif
internal static class Program
{
    private static int Main(string[] args)
    {
#if (en)
        Console.WriteLine("Lab II: camera, sampling, image, intensity");
#else
        Console.WriteLine("Laboratorium II: kamera, próbkowanie, obraz, natężenie");
#endif
        var states = Progress.Report(Console.Out);
        string[] toWrite = [.. states.Where(p => p.State == Progress.State.ToWrite).Select(p => $"{p.Id} {p.Title}")];
        string[] throwing = [.. states.Where(p => p.State == Progress.State.Throws).Select(p => p.Id)];
        int missing = toWrite.Length;
        int refused = OwnCode.Report(Console.Out);
        int warnings = BuildWarnings.Report(Console.Out);
        if (missing > 0 || throwing.Length > 0 || refused > 0 || args.Contains("check"))
        {
#if (en)
            Console.WriteLine(missing > 0 ? $"{missing} of {Sections.All.Length} parts still to write; the checks: dotnet test"
                : throwing.Length > 0 ? "Every part is written; the checks: dotnet test"
                : "Every part is written; the checks: dotnet test; the pictures: dotnet run --project src/Lab");
            if (throwing.Length > 0)
            {
                Console.WriteLine($"Sections that throw an exception: {string.Join(", ", throwing)} (where: above)");
            }
#else
            Console.WriteLine(missing > 0 ? $"Do napisania zostało {missing} z {Sections.All.Length} części; sprawdzenie: dotnet test"
                : throwing.Length > 0 ? "Wszystkie części są napisane; sprawdzenie: dotnet test"
                : "Wszystkie części są napisane; sprawdzenie: dotnet test; obrazy: dotnet run --project src/Lab");
            if (throwing.Length > 0)
            {
                Console.WriteLine($"Sekcje, które rzucają wyjątek: {string.Join(", ", throwing)} (gdzie: wyżej)");
            }
#endif
            if (refused > 0)
            {
#if (en)
                Console.WriteLine($"{refused} uses of what the lab does not allow (above): each fails its section, in the checks and in grading");
#else
                Console.WriteLine($"{refused} użyć tego, na co laboratorium nie pozwala (wyżej): każde oblewa swoją sekcję, w testach i przy ocenianiu");
#endif
            }

            if (warnings > 0)
            {
#if (en)
                Console.WriteLine($"Compiler warnings (above): {warnings}; they stop nothing, but each points at a likely mistake");
#else
                Console.WriteLine($"Ostrzeżenia kompilatora (wyżej): {warnings}; niczego nie blokują, ale każde wskazuje prawdopodobny błąd");
#endif
            }

            if (!args.Contains("check"))
            {
#if (en)
                // The pictures need every part, written and allowed: say that none was made, and what stands in the way.
#else
                // Do obrazów potrzebne są wszystkie części, napisane i dozwolone: powiedz, że żaden nie powstał, i co przeszkadza.
#endif
#if (en)
                string[] why = [.. new[] { missing > 0 ? $"missing: {string.Join(", ", toWrite)}" : "", throwing.Length > 0 ? $"throwing an exception: {string.Join(", ", throwing)}" : "",
                    refused > 0 ? "uses of what the lab does not allow (above)" : "" }.Where(p => p.Length > 0)];
                Console.WriteLine($"No picture was made: the pictures need every part; {string.Join("; ", why)}");
#else
                string[] why = [.. new[] { missing > 0 ? $"brakuje: {string.Join(", ", toWrite)}" : "", throwing.Length > 0 ? $"rzucają wyjątek: {string.Join(", ", throwing)}" : "",
                    refused > 0 ? "użycia tego, na co laboratorium nie pozwala (wyżej)" : "" }.Where(p => p.Length > 0)];
                Console.WriteLine($"Nie powstał żaden obraz: do obrazów potrzebne są wszystkie części; {string.Join("; ", why)}");
#endif
            }

            return missing > 0 || throwing.Length > 0 || refused > 0 ? 1 : 0;
        }

        try
        {
            Render();
            return 0;
        }
        catch (SceneFileException e)
        {
            Console.Error.WriteLine(e.Message);
            return 2;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
#if (en)
            Console.Error.WriteLine($"The render stopped: {YourCode.Describe(e)}");
#else
            Console.Error.WriteLine($"Renderowanie przerwane: {YourCode.Describe(e)}");
#endif
            return 1;
        }
    }

    private static void Render()
    {
        SceneDescription file = TwoSpheres.Load();
        Scene scene = file.Scene;
        int nx = file.Width, ny = file.Height;
        var adaptive = new LabAdaptiveSampler(maxDepth: 3, contrast: 0.05);
        Directory.CreateDirectory("out");

#if (en)
        // The first render of a run pays for the JIT: a small one first, timed apart and named.
#else
        // Pierwsze renderowanie płaci za kompilację JIT: najpierw małe, mierzone osobno i nazwane.
#endif
        var warmUp = Stopwatch.StartNew();
        Watched("80×60", "orthographic", () => LabRenderer.Render(scene, TwoSpheres.Orthographic(), adaptive, new LabImage(80, 60)));
        Watched("80×60", "perspective", () => LabRenderer.Render(scene, TwoSpheres.Perspective(), adaptive, new LabImage(80, 60)));
#if (en)
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"warm-up (80×60, both cameras, not counted) {warmUp.Elapsed.TotalMilliseconds:F1} ms"));
#else
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"rozgrzewka (80×60, obie kamery, nie liczona) {warmUp.Elapsed.TotalMilliseconds:F1} ms"));
#endif

        foreach ((string name, LabCamera camera) in new (string, LabCamera)[] { ("orthographic", TwoSpheres.Orthographic()), ("perspective", TwoSpheres.Perspective()) })
        {
            var image = new LabImage(nx, ny);
            var clock = Stopwatch.StartNew();
            long rays = Watched($"{nx}×{ny}", name, () => LabRenderer.Render(scene, camera, adaptive, image));
            double ms = clock.Elapsed.TotalMilliseconds;
            string path = Path.Combine("out", $"two-spheres-{name}.png");
            image.Bitmap.SaveAsPng(path);
#if (en)
            // One line per render, which raylab grade reads (the camera and method names are the grader's keys).
#else
            // Jeden wiersz na renderowanie, który czyta raylab grade (nazwy kamery i metody są kluczami oceniającego).
#endif
#if (en)
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{name,-12} adaptive {rays,10:N0} rays ({(double)rays / (nx * ny),5:F2} per pixel) {ms,8:F1} ms   {path}"));
#else
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{name,-12} adaptive {rays,10:N0} promieni ({(double)rays / (nx * ny),5:F2} na piksel) {ms,8:F1} ms   {path}"));
#endif
            if (name == "perspective")
            {
#if (en)
                // 2.2: the lab's own file name
#else
                // 2.2: nazwa pliku z instrukcji
#endif
                image.Bitmap.SaveAsJpeg(Path.Combine("out", "obrazkoncowy.jpg"));
            }
        }

#if (en)
        Console.WriteLine("wrote out/obrazkoncowy.jpg");
#else
        Console.WriteLine("zapisano out/obrazkoncowy.jpg");
#endif
    }

#if (en)
    /// <summary>
    /// Runs one render (<paramref name="size"/>, with the <paramref name="camera"/> camera) with the time limit (60 s,
    /// or LAB_TIME_LIMIT_S seconds): past it the run stops with exit code 1 and says which render did not finish,
    /// instead of going silent.
    /// </summary>
#else
    /// <summary>
    /// Wykonuje jedno renderowanie (<paramref name="size"/>, kamerą <paramref name="camera"/>) z limitem czasu (60 s
    /// albo LAB_TIME_LIMIT_S sekund): po nim program kończy się kodem 1 i mówi, które renderowanie się nie skończyło,
    /// zamiast milczeć.
    /// </summary>
#endif
    private static long Watched(string size, string camera, Func<long> render)
    {
        TimeSpan limit = double.TryParse(Environment.GetEnvironmentVariable("LAB_TIME_LIMIT_S"), NumberStyles.Float, CultureInfo.InvariantCulture, out double seconds) && seconds > 0
            ? TimeSpan.FromSeconds(seconds)
            : TimeSpan.FromSeconds(60);
        using var watchdog = new Timer(_ =>
        {
#if (en)
            Console.Error.WriteLine(string.Create(CultureInfo.InvariantCulture, $"Time limit of {limit.TotalSeconds:0.#} s passed: the {size} render with the {camera} camera did not finish (an endless loop?). dotnet test names the pixel."));
#else
            string kamera = camera == "orthographic" ? "ortogonalną" : "perspektywiczną";
            Console.Error.WriteLine(string.Create(CultureInfo.InvariantCulture, $"Przekroczony limit czasu {limit.TotalSeconds:0.#} s: renderowanie {size} kamerą {kamera} się nie skończyło (zapętlenie?). dotnet test wskaże piksel."));
#endif
            Environment.Exit(1);
        }, null, limit, Timeout.InfiniteTimeSpan);
        return render();
    }
}
