using System.Runtime.CompilerServices;
using RayLab;

namespace MyLab;

#if (en)
/// <summary>Which parts of the lab are written: tries each class on a tiny input and lists the sections that still throw NotImplementedException, and those that throw another exception (with where in your code).</summary>
#else
/// <summary>Które części laboratorium są napisane: wywołuje każdą klasę na małym przykładzie i wypisuje sekcje, które wciąż rzucają NotImplementedException, oraz te, które rzucają inny wyjątek (z miejscem w Twoim kodzie).</summary>
#endif
internal static class Progress
{
#if (en)
    /// <summary>Where a section stands: written, still to write, or written and throwing another exception.</summary>
#else
    /// <summary>Stan sekcji: napisana, jeszcze do napisania albo napisana, ale rzuca inny wyjątek.</summary>
#endif
    public enum State
    {
        Written,
        ToWrite,
        Throws,
    }

#if (en)
    /// <summary>
    /// Tries each section's classes on a tiny input, in the lab's order. <c>Detail</c>: for a section still to write,
    /// the method to write (or the other section it waits for); for one that throws, the exception and where in your
    /// code; null for a written one.
    /// </summary>
#else
    /// <summary>
    /// Wywołuje klasy każdej sekcji na małym przykładzie, w kolejności instrukcji. <c>Detail</c>: dla sekcji jeszcze do
    /// napisania metoda do napisania (albo inna sekcja, na którą czeka); dla rzucającej wyjątek wyjątek i miejsce w
    /// Twoim kodzie; null dla napisanej.
    /// </summary>
#endif
    public static List<(string Id, string Title, string Classes, State State, string? Detail)> Probe()
    {
        var scene = new Scene([new Sphere(new Double3(0, 0, 0), 1, new Intensity(1, 0, 0))], new Intensity(0, 0, 1), Intensity.White);
        var probes = new (string Id, Action Try)[]
        {
            ("2.1", () => { var a = new LightIntensity(0.5, -1, 0.25); _ = ((a + a - a) * 2 * 0.5 / 2).ToString(); }),
            ("2.2", () => { _ = LabImage.ToByte(0.5); new LabImage(2, 1).SetPixel(1, 0, new LightIntensity(1)); }),
            ("3", () => { _ = new LabPerspectiveCamera().Frame(); _ = LabCamera.Alpha(0, 0.5, 2) + LabCamera.Beta(0, 0.5, 2); }),
            ("3.1", () => _ = new LabOrthoCamera().GetRay(0, 0, 4, 3)),
            ("3.2", () => _ = new LabPerspectiveCamera().GetRay(0, 0, 4, 3)),
            ("4.1.1", () => _ = new LabRegularSampler(4).GetSamples(new Random(1))),
            ("4.1.2", () => _ = new LabRandomSampler(4).GetSamples(new Random(1))),
            ("4.1.3", () => _ = new LabJitteredSampler(4).GetSamples(new Random(1))),
            ("4.1.4", () => _ = new LabAdaptiveSampler().Pixel(Edge())),
            ("5", () => _ = LabRenderer.Render(scene, new ProbeCamera(), new ProbeSampler(), new LabImage(4, 3))),
        };

        var states = new List<(string, string, string, State, string?)>();
        foreach ((string id, Action probe) in probes)
        {
            (string _, string title, string classes) = Sections.All.First(s => s.Id == id);
            try
            {
                probe();
                states.Add((id, title, classes, State.Written, null));
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                Exception thrown = YourCode.Unwrapped(e);
                if (thrown is not NotImplementedException)
                {
                    states.Add((id, title, classes, State.Throws, YourCode.Describe(thrown)));
                    continue;
                }

#if (en)
                // Another section's NotImplementedException (section 5's probe needs LabImage and LightIntensity): this
                // section waits for that one, which the detail says, rather than look unwritten itself.
#else
                // NotImplementedException innej sekcji (sonda sekcji 5 potrzebuje LabImage i LightIntensity): ta sekcja
                // czeka na tamtą, co mówi opis, zamiast wyglądać na nienapisaną.
#endif
                string own = ToWrite.Section(id, "").Message;
                string other = thrown.Message.Split(' ')[0];
#if (en)
                string detail = thrown.Message.StartsWith(own, StringComparison.Ordinal) ? thrown.Message[own.Length..]
                    : $"needs section {other} {Sections.Title(other)} first";
#else
                string detail = thrown.Message.StartsWith(own, StringComparison.Ordinal) ? thrown.Message[own.Length..]
                    : $"wymaga najpierw sekcji {other} {Sections.Title(other)}";
#endif
                states.Add((id, title, classes, State.ToWrite, detail));
            }
        }

        return states;
    }

#if (en)
    /// <summary>Prints one line per section; returns each section's state (<see cref="Probe"/>).</summary>
#else
    /// <summary>Wypisuje po wierszu na sekcję; zwraca stan każdej sekcji (<see cref="Probe"/>).</summary>
#endif
    public static List<(string Id, string Title, string Classes, State State, string? Detail)> Report(TextWriter output)
    {
        var states = Probe();
        foreach ((string id, string title, string classes, State state, string? detail) in states)
        {
            switch (state)
            {
                case State.Written:
#if (en)
                    output.WriteLine($"  written        {id,-6} {title} ({classes})");
#else
                    output.WriteLine($"  napisane             {id,-6} {title} ({classes})");
#endif
                    break;
                case State.Throws:
#if (en)
                    output.WriteLine($"  throws         {id,-6} {title} ({classes}): {detail}");
#else
                    output.WriteLine($"  rzuca wyjątek        {id,-6} {title} ({classes}): {detail}");
#endif
                    break;
                default:
#if (en)
                    output.WriteLine($"  still to write {id,-6} {title} ({classes}): {detail}");
#else
                    output.WriteLine($"  jeszcze do napisania {id,-6} {title} ({classes}): {detail}");
#endif
                    break;
            }
        }

        return states;
    }

#if (en)
    /// <summary>
    /// 4.1.4's pixel: cut by a hard edge, which a recursion without its depth limit splits for ever. It throws an
    /// exception that says so at the first point off the 1/16-pixel grid (a square deeper than the default MaxDepth
    /// 3, whose squares have sides of 1/8 or more), past 1024 rays (depth 3 needs at most 81) or near the end of the
    /// stack: before the squares are too small for a double to hold a new point, and such a recursion goes on
    /// without tracing one until the stack overflows.
    /// </summary>
#else
    /// <summary>
    /// Piksel sekcji 4.1.4: przecięty ostrą krawędzią, którą rekurencja bez limitu głębokości dzieli bez końca. Rzuca
    /// wyjątek, który to mówi, przy pierwszym punkcie poza siatką co 1/16 piksela (kwadrat głębszy niż domyślne
    /// MaxDepth 3, którego kwadraty mają boki 1/8 lub więcej), po 1024 promieniach (głębokość 3 potrzebuje najwyżej 81)
    /// albo blisko końca stosu: zanim kwadraty staną się za małe, by double pomieścił nowy punkt, bo wtedy taka
    /// rekurencja trwa bez śledzenia promieni, aż stos się przepełni.
    /// </summary>
#endif
    private static Func<double, double, LightIntensity> Edge()
    {
        static bool OnGrid(double v) => Math.Abs((v * 16) - Math.Round(v * 16)) < 1e-9;
        int rays = 0;
        return (x, y) =>
        {
            if (!OnGrid(x) || !OnGrid(y))
            {
#if (en)
                throw new InvalidOperationException(FormattableString.Invariant($"the point ({x:R}, {y:R}) is off the 1/16-pixel grid, so in a square deeper than 3: the recursion does not stop at MaxDepth = 3"));
#else
                throw new InvalidOperationException(FormattableString.Invariant($"punkt ({x:R}, {y:R}) leży poza siatką co 1/16 piksela, więc w kwadracie głębszym niż 3: rekurencja nie zatrzymuje się na MaxDepth = 3"));
#endif
            }

            if (++rays > 1024 || !RuntimeHelpers.TryEnsureSufficientExecutionStack())
            {
#if (en)
                throw new InvalidOperationException($"too many rays in one pixel ({rays}): the recursion does not stop at MaxDepth = 3");
#else
                throw new InvalidOperationException($"za dużo promieni w jednym pikselu ({rays}): rekurencja nie zatrzymuje się na MaxDepth = 3");
#endif
            }

            return x + (2 * y) < 1.1 ? new LightIntensity(1) : new LightIntensity(0);
        };
    }

#if (en)
    // Section 5 on its own: a camera and a sampler that need none of the other sections.
#else
    // Sekcja 5 osobno: kamera i próbkowanie, które nie potrzebują żadnej innej sekcji.
#endif
    private sealed class ProbeCamera : LabCamera
    {
        public override Window GetWindow(int nx, int ny) => new(-1, -1, 1, 1);

        public override Ray GetRay(int x, int y, int nx, int ny, double sx = 0.5, double sy = 0.5) =>
            new(new Double3(-1 + (2 * (x + sx) / nx), 1 - (2 * (y + sy) / ny), 5), new Double3(0, 0, -1));
    }

    private sealed class ProbeSampler : ILabSampler
    {
        public int SamplesPerPixel => 1;

        public (double X, double Y)[] GetSamples(Random random) => [(0.5, 0.5)];
    }
}

#if (en)
/// <summary>
/// What your classes use that the lab does not allow (the checks' uses.json: RayLab's own intensity, image, cameras or
/// samplers in place of yours, reflection, native code, processes), read from this program's own built assembly
/// with RayLab.Grading, as the checks and the grader read it.
/// </summary>
#else
/// <summary>
/// Czego Twoje klasy używają, a na co laboratorium nie pozwala (uses.json z testów: natężenia, obrazu, kamer lub
/// próbkowania z RayLab w miejsce Twoich, refleksji, kodu natywnego, procesów), odczytane ze zbudowanego programu
/// przez RayLab.Grading, tak jak czytają je testy i ocenianie.
/// </summary>
#endif
internal static class OwnCode
{
#if (en)
    /// <summary>Prints one line per refused use; returns how many there are (0 where the list is missing).</summary>
#else
    /// <summary>Wypisuje po wierszu na niedozwolone użycie; zwraca ich liczbę (0, gdy brak listy).</summary>
#endif
    public static int Report(TextWriter output)
    {
        string list = Path.Combine(AppContext.BaseDirectory, "uses.json");
        if (!File.Exists(list))
        {
            return 0;
        }

        IReadOnlyList<RayLab.Grading.UseFinding> findings =
            RayLab.Grading.UseList.Load(list).Check(RayLab.Grading.AssemblyUses.Read(typeof(OwnCode).Assembly.Location));
        foreach (RayLab.Grading.UseFinding finding in findings)
        {
#if (en)
            output.WriteLine($"  not your own   {string.Join(", ", finding.Sections),-6} {finding.Message(polish: false)}");
#else
            output.WriteLine($"  nie Twój kod         {string.Join(", ", finding.Sections),-6} {finding.Message(polish: true)}");
#endif
        }

        return findings.Count;
    }
}
