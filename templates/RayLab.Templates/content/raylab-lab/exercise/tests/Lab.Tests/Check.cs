using System.Diagnostics;
using System.Globalization;
using RayLab;
using RayLab.Scenes;

namespace MyLab.Tests;

#if (en)
/// <summary>
/// What every check shares: a time limit that names the pixel a hanging method was working on, a
/// NotImplementedException turned into a skipped check (still to write, which is not wrong), and the figures written
/// where dotnet test shows them (the test's output, and the failure message). Its own frames are hidden from stack
/// traces (<see cref="StackTraceHiddenAttribute"/>): a failure's stack starts in your code or in the check. The
/// checks' names and messages are in <see cref="Msg"/>.
/// </summary>
#else
/// <summary>
/// Co mają wspólnego wszystkie sprawdzenia: limit czasu, który wskazuje piksel zapętlonej metody, NotImplementedException
/// zamieniony na pominięte sprawdzenie (jeszcze do napisania, co nie jest błędem) i liczby wypisane tam, gdzie pokazuje
/// je dotnet test (wyjście testu i komunikat błędu). Jego własne ramki są ukryte w stosie
/// (<see cref="StackTraceHiddenAttribute"/>): stos błędu zaczyna się w Twoim kodzie albo w sprawdzeniu. Nazwy i
/// komunikaty sprawdzeń są w <see cref="Msg"/>.
/// </summary>
#endif
[StackTraceHidden]
internal static class Check
{
#if (en)
    /// <summary>
    /// How long one check may take; a method that runs longer is taken as hanging. 45 s, below the 60 s that
    /// <c>raylab grade</c> gives one check by default (<c>--check-timeout</c>): the check stops first, so its own
    /// message is the one you and the instructor read. <see cref="Variable"/> sets another number of seconds (e.g. a
    /// smaller one for a quick try).
    /// </summary>
#else
    /// <summary>
    /// Ile może trwać jedno sprawdzenie; metoda, która trwa dłużej, uchodzi za zapętloną. 45 s, mniej niż 60 s, które
    /// <c>raylab grade</c> domyślnie daje jednemu sprawdzeniu (<c>--check-timeout</c>): sprawdzenie kończy się
    /// pierwsze, więc jego komunikat czytasz Ty i prowadzący. <see cref="Variable"/> ustawia inną liczbę sekund (np.
    /// mniejszą, do szybkiej próby).
    /// </summary>
#endif
    public static readonly TimeSpan Limit =
        double.TryParse(Environment.GetEnvironmentVariable(Variable), NumberStyles.Float, CultureInfo.InvariantCulture, out double seconds) && seconds > 0
            ? TimeSpan.FromSeconds(seconds)
            : TimeSpan.FromSeconds(45);

#if (en)
    /// <summary>The environment variable that sets <see cref="Limit"/> in seconds.</summary>
#else
    /// <summary>Zmienna środowiskowa, która ustawia <see cref="Limit"/> w sekundach.</summary>
#endif
    public const string Variable = "LAB_TIME_LIMIT_S";

#if (en)
    /// <summary>How long a method past the limit has to stop, once the checks' own objects refuse to go on.</summary>
#else
    /// <summary>Ile czasu ma metoda po limicie, żeby się zatrzymać, gdy obiekty sprawdzeń odmawiają dalszej pracy.</summary>
#endif
    private static readonly TimeSpan Grace = TimeSpan.FromSeconds(5);

#if (en)
    /// <summary>The running check's stop signal, seen by its work and the threads it starts (Parallel.For's among them).</summary>
#else
    /// <summary>Sygnał zatrzymania trwającego sprawdzenia, widoczny w jego pracy i wątkach, które ona uruchamia (także Parallel.For).</summary>
#endif
    private static readonly AsyncLocal<CancellationToken> Stopping = new();

    public static string F(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);

#if (en)
    /// <summary>
    /// Called by the checks' own objects your loops call (the cameras and samplers of sections 4 and 5, the adaptive
    /// method's trace): once the check is past its limit they throw, which ends your loop at its next call.
    /// </summary>
#else
    /// <summary>
    /// Wołane przez obiekty sprawdzeń, które wywołują Twoje pętle (kamery i próbkowanie sekcji 4 i 5, śledzenie promieni
    /// metody adaptacyjnej): po limicie sprawdzenia rzucają wyjątek, który kończy Twoją pętlę przy jej następnym
    /// wywołaniu.
    /// </summary>
#endif
    public static void StopIfPastLimit()
    {
        if (Stopping.Value.IsCancellationRequested)
        {
            throw new OperationCanceledException(Msg.TimeLimitPassed, Stopping.Value);
        }
    }

#if (en)
    /// <summary>
    /// Runs <paramref name="work"/> with the time limit; <paramref name="where"/> says where it was when the limit
    /// passed (e.g. the pixel). Returns the elapsed time. Past the limit the work is told to stop
    /// (<see cref="StopIfPastLimit"/>) and given <see cref="Grace"/> to do so; the check fails either way, and says
    /// whether your method stopped. A method that did not stop ends the run with this check (<see cref="StopRun"/>).
    /// </summary>
#else
    /// <summary>
    /// Wykonuje <paramref name="work"/> z limitem czasu; <paramref name="where"/> mówi, gdzie była praca, gdy limit
    /// minął (np. piksel). Zwraca czas trwania. Po limicie praca dostaje sygnał zatrzymania
    /// (<see cref="StopIfPastLimit"/>) i <see cref="Grace"/> na zatrzymanie się; sprawdzenie i tak nie przechodzi, a
    /// komunikat mówi, czy Twoja metoda się zatrzymała. Metoda, która się nie zatrzymała, kończy przebieg na tym
    /// sprawdzeniu (<see cref="StopRun"/>).
    /// </summary>
#endif
    public static TimeSpan Run(ITestOutputHelper output, Func<string> where, Action work)
    {
        var clock = Stopwatch.StartNew();
        using var stop = new CancellationTokenSource();
        var task = Task.Factory.StartNew(() =>
        {
            Stopping.Value = stop.Token;
            work();
        }, CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        if (!Finished(task, Limit))
        {
            string last = where();
            stop.Cancel();
            bool stopped = Finished(task, Grace);
            if (!stopped)
            {
                StopRun();
            }

            throw new Xunit.Sdk.CheckFailure(Msg.PastLimit(Limit.TotalSeconds, last, stopped), null);
        }

        if (task.Exception?.InnerException is { } wrapped)
        {
            Exception e = Unwrapped(wrapped);
            if (e is Xunit.Sdk.IAssertionException)
            {
#if (en)
                // a check's own failure
#else
                // błąd samego sprawdzenia
#endif
                throw new Xunit.Sdk.CheckFailure(e.Message, e);
            }

            if (e is NotImplementedException)
            {
#if (en)
                // Not written yet is not wrong: the check is skipped, with the skeleton's one line (the section and what
                // is to write) and no stack. LabProgress lists the sections still to write once.
#else
                // Jeszcze nienapisane to nie błąd: sprawdzenie jest pominięte, z jednym wierszem szkieletu (sekcja i co
                // napisać), bez stosu. LabProgress raz wypisuje sekcje jeszcze do napisania.
#endif
                Assert.Skip(char.IsAsciiDigit(e.Message[0]) ? e.Message : Msg.NotWrittenYet(e.Message));
            }

            string at = WhereInYourCode(e);
            string position = where();
            string context = position == "—" ? at : $"{at}; {position}";
            throw new Xunit.Sdk.CheckFailure(Msg.YourCodeThrew(e.GetType().Name, e.Message, context), e);
        }

        output.WriteLine(Msg.Time(clock.Elapsed.TotalMilliseconds));
        return clock.Elapsed;
    }

#if (en)
    /// <summary>
    /// The words a check's message holds when it ended the run (<see cref="StopRun"/>): <c>raylab grade</c> looks for
    /// them, and runs again the checks that were not run.
    /// </summary>
#else
    /// <summary>
    /// Słowa, które ma komunikat sprawdzenia, które zakończyło przebieg (<see cref="StopRun"/>): <c>raylab grade</c> ich
    /// szuka i wykonuje ponownie sprawdzenia, które nie zostały wykonane.
    /// </summary>
#endif
    public const string RunStopped = "Check.StopRun";

#if (en)
    /// <summary>
    /// Ends the test run once this check's result is reported (<see cref="StoppableRun"/>): the checks already running
    /// finish, no other starts, and the test process ends, with a method of yours that could not be stopped in it.
    /// </summary>
#else
    /// <summary>
    /// Kończy przebieg testów po zgłoszeniu wyniku tego sprawdzenia (<see cref="StoppableRun"/>): sprawdzenia już trwające
    /// się kończą, żadne inne się nie zaczyna, a proces testów kończy się razem z Twoją metodą, której nie dało się
    /// zatrzymać.
    /// </summary>
#endif
    public static void StopRun() => StoppableRun.Stop.Cancel();

#if (en)
    /// <summary>Whether <paramref name="task"/> ended (its exception, if any, is read later) within <paramref name="time"/>.</summary>
#else
    /// <summary>Czy <paramref name="task"/> skończyło się (jego wyjątek, jeśli jest, czytany jest później) w czasie <paramref name="time"/>.</summary>
#endif
    private static bool Finished(Task task, TimeSpan time)
    {
        try
        {
#if (en)
            // Not the test's cancellation token: once a check ends the run (StopRun) it is cancelled, and the checks
            // still running finish within their own limits.
#else
            // Bez tokenu anulowania testu: gdy sprawdzenie kończy przebieg (StopRun), jest anulowany, a sprawdzenia
            // jeszcze trwające kończą się w swoich własnych limitach.
#endif
            return task.Wait(time);
        }
        catch (AggregateException)
        {
            return true;
        }
    }

#if (en)
    /// <summary>The exception your code threw, out of the wrappers a loop puts around it (Parallel.For's AggregateException).</summary>
#else
    /// <summary>Wyjątek rzucony przez Twój kod, wyjęty z opakowań, w które wkłada go pętla (AggregateException z Parallel.For).</summary>
#endif
    public static Exception Unwrapped(Exception e)
    {
        while (true)
        {
            switch (e)
            {
                case AggregateException { InnerExceptions.Count: > 0 } a:
                    e = a.InnerExceptions[0];
                    break;
                case System.Reflection.TargetInvocationException { InnerException: { } inner }:
                    e = inner;
                    break;
                default:
                    return e;
            }
        }
    }

#if (en)
    /// <summary>
    /// Where in your code (the project in src/Lab) <paramref name="e"/> was thrown: the first frame of its stack in
    /// your assembly, as "src/Lab/File.cs:line, Class.Method". The checks keep their own copy of this (the program's is
    /// in src/Lab/YourCode.cs): they compile against any lab's src/Lab, and raylab grade builds them in the kit's
    /// namespace beside a student's lab in another, so one file cannot serve both.
    /// </summary>
#else
    /// <summary>
    /// Gdzie w Twoim kodzie (projekt w src/Lab) został rzucony <paramref name="e"/>: pierwsza ramka jego stosu w Twoim
    /// zestawie, jako „src/Lab/Plik.cs:wiersz, Klasa.Metoda”. Sprawdzenia mają własną kopię tej funkcji (program ma
    /// swoją w src/Lab/YourCode.cs): kompilują się z src/Lab każdego laboratorium, a raylab grade buduje je w przestrzeni
    /// nazw zestawu obok laboratorium studenta w innej, więc jeden plik nie obsłuży obu.
    /// </summary>
#endif
    public static string WhereInYourCode(Exception e)
    {
        System.Reflection.Assembly yours = typeof(LabCamera).Assembly;
        foreach (StackFrame frame in new StackTrace(e, fNeedFileInfo: true).GetFrames())
        {
            System.Reflection.MethodBase? method = frame.GetMethod();
            if (method?.DeclaringType is not { } type || type.Assembly != yours)
            {
                continue;
            }

            while (type.Name.StartsWith('<') && type.DeclaringType is { } outer)
            {
#if (en)
                // a lambda's or a local function's class: the class it is written in
#else
                // klasa lambdy albo funkcji lokalnej: klasa, w której ją napisano
#endif
                type = outer;
            }

            string name = method.Name.StartsWith('<') ? method.Name[1..method.Name.IndexOf('>', StringComparison.Ordinal)]
                : method.IsConstructor ? type.Name : method.Name;
            string? file = frame.GetFileName();
            if (file is null || frame.GetFileLineNumber() == 0)
            {
                return $"{type.Name}.{name}";
            }

            string path = file.Replace('\\', '/');
            int lab = path.LastIndexOf("/src/Lab/", StringComparison.Ordinal);
            path = lab >= 0 ? path[(lab + 1)..] : Path.GetFileName(path);
            return F($"{path}:{frame.GetFileLineNumber()}, {type.Name}.{name}");
        }

        return Msg.OutsideYourCode;
    }

#if (en)
    /// <summary>
    /// Where your method <paramref name="name"/> of <paramref name="type"/> is written, read from the lab's debugging
    /// symbols (Lab.pdb), as "src/Lab/File.cs:line, Class.Method" (its first line of code): a wrong value names the
    /// method that gave it, and where to look. Just "Class.Method" where the symbols cannot tell.
    /// </summary>
#else
    /// <summary>
    /// Gdzie jest napisana Twoja metoda <paramref name="name"/> typu <paramref name="type"/>, odczytane z symboli
    /// debugowania laboratorium (Lab.pdb), jako „src/Lab/Plik.cs:wiersz, Klasa.Metoda” (jej pierwszy wiersz kodu): zła
    /// wartość wskazuje metodę, która ją dała, i miejsce, gdzie szukać. Samo „Klasa.Metoda”, gdy symbole tego nie mówią.
    /// </summary>
#endif
    public static string Source(Type type, string name) => Source(
        name == type.Name ? type.GetConstructors().FirstOrDefault()
            : type.GetMethods(System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Static | System.Reflection.BindingFlags.DeclaredOnly)
                .FirstOrDefault(m => m.Name == name),
        $"{type.Name}.{name}");

#if (en)
    /// <summary>
    /// Where your <paramref name="method"/> (a constructor, an operator, one overload of several) is written, as
    /// <see cref="Source(Type, string)"/> gives it, named <paramref name="shown"/>: "src/Lab/File.cs:line, shown", or
    /// <paramref name="shown"/> alone where the symbols cannot tell.
    /// </summary>
#else
    /// <summary>
    /// Gdzie jest napisana Twoja metoda <paramref name="method"/> (konstruktor, operator, jedna z kilku przeciążonych),
    /// tak jak podaje to <see cref="Source(Type, string)"/>, nazwana <paramref name="shown"/>: „src/Lab/Plik.cs:wiersz,
    /// nazwa”, albo sama <paramref name="shown"/>, gdy symbole tego nie mówią.
    /// </summary>
#endif
    public static string Source(System.Reflection.MethodBase? method, string shown)
    {
        try
        {
            string? location = method?.DeclaringType?.Assembly.Location;
            if (method is null || string.IsNullOrEmpty(location))
            {
                return shown;
            }

            using var stream = File.OpenRead(location);
            using var pe = new System.Reflection.PortableExecutable.PEReader(stream);
            if (!pe.TryOpenAssociatedPortablePdb(location, path => File.Exists(path) ? File.OpenRead(path) : null, out var provider, out _) || provider is null)
            {
                return shown;
            }

            using (provider)
            {
                var pdb = provider.GetMetadataReader();
                var handle = System.Reflection.Metadata.Ecma335.MetadataTokens.MethodDefinitionHandle(method.MetadataToken);
#if (en)
                // The first line of code: past the opening brace of a method with a body.
#else
                // Pierwszy wiersz kodu: za klamrą otwierającą metody z ciałem.
#endif
                var points = pdb.GetMethodDebugInformation(handle).GetSequencePoints().Where(p => !p.IsHidden).ToList();
                foreach (var point in points.Where(p => points.Count == 1 || p.StartLine != p.EndLine || p.EndColumn - p.StartColumn > 1).Take(1))
                {
                    string path = pdb.GetString(pdb.GetDocument(point.Document).Name).Replace('\\', '/');
                    int lab = path.LastIndexOf("/src/Lab/", StringComparison.Ordinal);
                    return F($"{(lab >= 0 ? path[(lab + 1)..] : Path.GetFileName(path))}:{point.StartLine}, {shown}");
                }
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or BadImageFormatException or InvalidOperationException or NotSupportedException)
        {
#if (en)
            // no symbols to read (none beside the lab, or a sandbox that hides them): the method's name alone
#else
            // brak symboli do odczytania (nie ma ich obok laboratorium albo piaskownica je ukrywa): sama nazwa metody
#endif
        }

        return shown;
    }

#if (en)
    /// <summary>Runs <paramref name="work"/> with the time limit, with no position to report.</summary>
#else
    /// <summary>Wykonuje <paramref name="work"/> z limitem czasu, bez położenia do zgłoszenia.</summary>
#endif
    public static TimeSpan Run(ITestOutputHelper output, Action work) => Run(output, () => "—", work);

#if (en)
    /// <summary>The two spheres as the checks pin them (their own copy of scenes/two-spheres.json).</summary>
#else
    /// <summary>Dwie kule ustalone przez sprawdzenia (ich własna kopia scenes/two-spheres.json).</summary>
#endif
    public static SceneDescription TwoSpheresFile { get; } = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "two-spheres.json"));

#if (en)
    /// <summary>The lab's perspective camera (3.2), pinned: e = (0, 0.5, 6), target 0, Fov 40.</summary>
#else
    /// <summary>Kamera perspektywiczna z instrukcji (3.2), ustalona: e = (0, 0.5, 6), cel 0, Fov 40.</summary>
#endif
    public static LabPerspectiveCamera Perspective() => new()
    {
        Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), Up = new Double3(0, 1, 0), Fov = 40, NearPlane = 0.1, FarPlane = 100,
    };

#if (en)
    /// <summary>The lab's orthographic camera (3.1), pinned: the same eye, a window 4.2 high.</summary>
#else
    /// <summary>Kamera ortogonalna z instrukcji (3.1), ustalona: to samo oko, okno o wysokości 4.2.</summary>
#endif
    public static LabOrthoCamera Orthographic() => new()
    {
        Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), Up = new Double3(0, 1, 0), ViewHeight = 4.2, NearPlane = 0.1, FarPlane = 100,
    };

#if (en)
    /// <summary>RayLab's camera with the same settings as yours: the oracle.</summary>
#else
    /// <summary>Kamera RayLab z tymi samymi ustawieniami co Twoja: wzorzec.</summary>
#endif
    public static Camera Oracle(LabCamera camera) => camera switch
    {
        LabOrthoCamera o => new OrthoCamera
        {
            Position = o.Position, Target = o.Target, Up = o.Up, NearPlane = o.NearPlane, FarPlane = o.FarPlane, Fov = o.Fov, ViewHeight = o.ViewHeight, Window = o.Window,
        },
        LabPerspectiveCamera p => new PerspectiveCamera
        {
            Position = p.Position, Target = p.Target, Up = p.Up, NearPlane = p.NearPlane, FarPlane = p.FarPlane, Fov = p.Fov, Distance = p.S, Window = p.Window,
        },
        _ => throw new ArgumentException(Msg.NoRayLabCamera(camera.GetType().Name), nameof(camera)),
    };

#if (en)
    /// <summary>A vector with 6 decimals, for messages.</summary>
#else
    /// <summary>Wektor z 6 miejscami po przecinku, do komunikatów.</summary>
#endif
    public static string V(Double3 v) => F($"({v.X:F6}, {v.Y:F6}, {v.Z:F6})");

#if (en)
    /// <summary>An intensity with 6 decimals, for messages.</summary>
#else
    /// <summary>Natężenie z 6 miejscami po przecinku, do komunikatów.</summary>
#endif
    public static string I(LightIntensity i) => F($"({i.R:F6}, {i.G:F6}, {i.B:F6})");

#if (en)
    /// <summary>An intensity with 6 decimals, for messages.</summary>
#else
    /// <summary>Natężenie z 6 miejscami po przecinku, do komunikatów.</summary>
#endif
    public static string I(Intensity i) => F($"({i.R:F6}, {i.G:F6}, {i.B:F6})");
}
