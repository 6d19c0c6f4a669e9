using System.Diagnostics;
using System.Globalization;
using RayLab;
using RayLab.Scenes;

namespace MyLab.Tests;

/// <summary>
/// What every check shares: the language of its messages, a time limit that names the pixel a hanging method was
/// working on, a NotImplementedException turned into a skipped check (still to write, which is not wrong), and the
/// figures written where dotnet test shows them (the test's output, and the failure message). Its own frames are
/// hidden from stack traces (<see cref="StackTraceHiddenAttribute"/>): a failure's stack starts in your code or in
/// the check.
/// </summary>
[StackTraceHidden]
internal static class Check
{
#if (en)
    public const bool English = true;
#else
    public const bool English = false;
#endif

    /// <summary>How long one check may take; a method that runs longer is taken as hanging.</summary>
    public static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);

    public static string T(string pl, string en) => English ? en : pl;

    public static string F(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);

    /// <summary>
    /// Runs <paramref name="work"/> with the time limit; <paramref name="where"/> says where it was when the limit
    /// passed (e.g. the pixel). Returns the elapsed time.
    /// </summary>
    public static TimeSpan Run(ITestOutputHelper output, Func<string> where, Action work)
    {
        var clock = Stopwatch.StartNew();
        var task = Task.Factory.StartNew(work, CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        bool finished;
        try
        {
            finished = task.Wait(Limit, TestContext.Current.CancellationToken);
        }
        catch (AggregateException)
        {
            finished = true; // the exception is reported below
        }

        if (!finished)
        {
            throw new Xunit.Sdk.CheckFailure(T(
                $"Przekroczony limit czasu {Limit.TotalSeconds:F0} s: metoda się nie skończyła (zapętlenie?). Ostatnio: {where()}.",
                $"Time limit of {Limit.TotalSeconds:F0} s passed: the method did not finish (an endless loop?). Last: {where()}."), null);
        }

        if (task.Exception?.InnerException is { } wrapped)
        {
            Exception e = Unwrapped(wrapped);
            if (e is Xunit.Sdk.IAssertionException)
            {
                throw new Xunit.Sdk.CheckFailure(e.Message, e); // a check's own failure
            }

            if (e is NotImplementedException)
            {
                // Not written yet is not wrong: the check is skipped, with the skeleton's one line (the section and what
                // is to write) and no stack. LabProgress lists the sections still to write once.
                Assert.Skip(char.IsAsciiDigit(e.Message[0]) ? e.Message : T($"Jeszcze nie napisane: {e.Message}", $"Not written yet: {e.Message}"));
            }

            string at = WhereInYourCode(e);
            string position = where();
            string context = position == "—" ? at : $"{at}; {position}";
            throw new Xunit.Sdk.CheckFailure(
                T($"Twój kod rzucił {e.GetType().Name}: {e.Message} ({context})", $"Your code threw {e.GetType().Name}: {e.Message} ({context})"),
                e);
        }

        output.WriteLine(F($"{T("czas", "time")}: {clock.Elapsed.TotalMilliseconds:F1} ms"));
        return clock.Elapsed;
    }

    /// <summary>The exception your code threw, out of the wrappers a loop puts around it (Parallel.For's AggregateException).</summary>
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

    /// <summary>
    /// Where in your code (the project in src/Lab) <paramref name="e"/> was thrown: the first frame of its stack in
    /// your assembly, as "src/Lab/File.cs:line, Class.Method". The checks keep their own copy of this (the program's is
    /// in src/Lab/YourCode.cs): they compile against any lab's src/Lab, and raylab grade builds them in the kit's
    /// namespace beside a student's lab in another, so one file cannot serve both.
    /// </summary>
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
                type = outer; // a lambda's or a local function's class: the class it is written in
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

        return T("poza Twoim kodem", "outside your code");
    }

    /// <summary>Runs <paramref name="work"/> with the time limit, with no position to report.</summary>
    public static TimeSpan Run(ITestOutputHelper output, Action work) => Run(output, () => "—", work);

    /// <summary>The two spheres as the checks pin them (their own copy of scenes/two-spheres.json).</summary>
    public static SceneDescription TwoSpheresFile { get; } = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "two-spheres.json"));

    /// <summary>The lab's perspective camera (3.2), pinned: e = (0, 0.5, 6), target 0, Fov 40.</summary>
    public static LabPerspectiveCamera Perspective() => new()
    {
        Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), Up = new Double3(0, 1, 0), Fov = 40, NearPlane = 0.1, FarPlane = 100,
    };

    /// <summary>The lab's orthographic camera (3.1), pinned: the same eye, a window 4.2 high.</summary>
    public static LabOrthoCamera Orthographic() => new()
    {
        Position = new Double3(0, 0.5, 6), Target = new Double3(0, 0, 0), Up = new Double3(0, 1, 0), ViewHeight = 4.2, NearPlane = 0.1, FarPlane = 100,
    };

    /// <summary>RayLab's camera with the same settings as yours: the oracle.</summary>
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
        _ => throw new ArgumentException($"No RayLab camera for {camera.GetType().Name}.", nameof(camera)),
    };

    /// <summary>A vector with 6 decimals, for messages.</summary>
    public static string V(Double3 v) => F($"({v.X:F6}, {v.Y:F6}, {v.Z:F6})");

    /// <summary>An intensity with 6 decimals, for messages.</summary>
    public static string I(LightIntensity i) => F($"({i.R:F6}, {i.G:F6}, {i.B:F6})");

    /// <summary>An intensity with 6 decimals, for messages.</summary>
    public static string I(Intensity i) => F($"({i.R:F6}, {i.G:F6}, {i.B:F6})");
}
