using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RayLab.Cli;
using RayLab.Grading;

namespace RayLab.Templates.Tests;

/// <summary>
/// Once for the test run, shared by the test classes that take it: <c>tools/class-kit.sh --feed-only --packed</c> makes a
/// kit from the run's one packing (<see cref="PackedPackages"/>): the feed with every package a lab restores, the
/// instructor's template package beside it and the pinned checks. The kit is then moved to another path
/// (the folder it was made in is deleted); the students' template is installed from the moved kit's feed, and the
/// instructor's from its instructor/ folder, in a temporary DOTNET_CLI_HOME, with an empty NUGET_PACKAGES and a
/// nuget.config above the work folders that clears every package source. Each class works in folders of its own under
/// <see cref="Root"/>; the folder goes when the test process ends.
/// </summary>
public sealed class ClassKit : IAsyncLifetime
{
    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(10);

    /// <summary>The kit of this test process, made by the first class that needs it.</summary>
    private static readonly Lazy<Task<string>> Made = new(MakeAsync, LazyThreadSafetyMode.ExecutionAndPublication);

    /// <summary>One <c>dotnet new</c> at a time in the shared DOTNET_CLI_HOME (classes run side by side).</summary>
    private static readonly SemaphoreSlim NewLab = new(1, 1);

    /// <summary>The test process's one temporary folder for the kit.</summary>
    private static readonly string SharedRoot = Directory.CreateTempSubdirectory("raylab-kit-").FullName;

    /// <summary>The temporary folder everything happens in (one for the test process).</summary>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Performance", "CA1822", Justification = "the kit's folders are read through the fixture the classes take")]
    public string Root => SharedRoot;

    /// <summary>The kit, at the path it was moved to.</summary>
    public string Kit => Path.Combine(Root, "elsewhere", "kit");

    /// <summary>Where the kit was made (deleted once it is moved).</summary>
    public string MadeAt => Path.Combine(Root, "made", "kit");

    /// <summary>The folder the labs are made in: its nuget.config clears every source.</summary>
    public string Work => Path.Combine(Root, "pc");

    /// <summary>The children's NUGET_PACKAGES, empty at the start.</summary>
    public string Packages => Path.Combine(Root, "nuget-packages");

    /// <summary>The version the kit's packages carry.</summary>
    public string Version { get; private set; } = "";

    public async ValueTask InitializeAsync() => Version = await Made.Value;

    /// <summary>Nothing per class: the kit's folder goes when the test process ends.</summary>
    public ValueTask DisposeAsync() => ValueTask.CompletedTask;

    private static async Task<string> MakeAsync()
    {
        AppDomain.CurrentDomain.ProcessExit += (_, _) =>
        {
            try
            {
                Directory.Delete(SharedRoot, recursive: true);
            }
            catch (IOException)
            {
                // a child killed on timeout may still hold a file
            }
        };
        var kit = new ClassKit();
        PackedSet packed = await PackedPackages.LibrariesAsync();
        await ChildProcess.RunCheckedAsync(RepoPaths.Root(), new Dictionary<string, string?>(), ChildTimeout,
            "bash", Path.Combine(RepoPaths.Root(), "tools", "class-kit.sh"), kit.MadeAt, "--feed-only", "--packed", packed.Folder);
        Directory.CreateDirectory(Path.GetDirectoryName(kit.Kit)!);
        Directory.Move(kit.MadeAt, kit.Kit);
        string template = Assert.Single(Directory.GetFiles(Path.Combine(kit.Kit, "feed"), "RayLab.Templates.*.nupkg"));
        string version = Path.GetFileNameWithoutExtension(template)["RayLab.Templates.".Length..];
        Assert.Equal(packed.Version, version);
        Directory.CreateDirectory(kit.Work);
        Directory.CreateDirectory(Path.Combine(SharedRoot, "dotnet-home"));
        File.WriteAllText(Path.Combine(kit.Work, "nuget.config"), """
            <?xml version="1.0" encoding="utf-8"?>
            <configuration>
              <packageSources>
                <clear />
              </packageSources>
            </configuration>
            """);
        await kit.RunAsync(kit.Work, "dotnet", "new", "install", $"RayLab.Templates::{version}", "--add-source", Path.Combine(kit.Kit, "feed"));
        await kit.RunAsync(kit.Work, "dotnet", "new", "install", $"RayLab.Templates.Instructor::{version}", "--add-source", Path.Combine(kit.Kit, "instructor"));
        return version;
    }

    /// <summary>Runs a child in the kit's environment; fails with its command line and output unless it exits 0.</summary>
    /// <returns>What it wrote to stdout.</returns>
    public Task<string> RunAsync(string workingDirectory, string fileName, params string[] args) =>
        ChildProcess.RunCheckedAsync(workingDirectory, Environment(), ChildTimeout, fileName, args);

    /// <summary>A lab from the installed template, made with the moved kit's feed as its only source.</summary>
    /// <returns>The lab's folder.</returns>
    /// <param name="folder">Where the lab's folder goes.</param>
    /// <param name="name">The lab's name and folder.</param>
    /// <param name="restore">Whether <c>dotnet new</c> restores it.</param>
    /// <param name="kind">The template's <c>--kind</c>: <c>method</c> (the submissions change MyMethod.cs) or <c>exercise</c>.</param>
    /// <param name="template">The template's short name: <c>raylab-lab</c> (the students') or <c>raylab-lab-solution</c> (the instructor's).</param>
    public async Task<string> NewLabAsync(string folder, string name, bool restore, string kind = "method", string template = "raylab-lab")
    {
        string lab = Path.Combine(folder, name);
        List<string> args = ["new", template, "-o", lab, "--kind", kind, "--feed", Path.Combine(Kit, "feed"), "--offline"];
        if (!restore)
        {
            args.Add("--skipRestore");
        }

        await NewLab.WaitAsync();
        try
        {
            await RunAsync(folder, "dotnet", [.. args]);
        }
        finally
        {
            NewLab.Release();
        }

        return lab;
    }

    private Dictionary<string, string?> Environment() => new()
    {
        ["DOTNET_CLI_HOME"] = Path.Combine(Root, "dotnet-home"),
        ["NUGET_PACKAGES"] = Packages,
        ["DOTNET_GENERATE_ASPNET_CERTIFICATE"] = "false",
    };
}

/// <summary>
/// The class kit and <c>raylab grade</c>, end to end: a lab made from a kit that was moved after it was made restores,
/// builds and passes its tests with the kit's feed as its only source; and a class of six labs (a better method, one
/// that breaks the method's section and edits its own test thresholds, the template as created, one that does not
/// compile, one whose method never returns, one whose method and program allocate past the memory limit) graded in
/// bubblewrap against the kit's pinned checks, built and checked two at a time with the programs one after another,
/// gets one right row each, within the limits given.
/// </summary>
[Trait("Category", "Templates")]
public sealed partial class ClassKitTests(ClassKit kit) : IClassFixture<ClassKit>
{
    /// <summary>
    /// The class's limit per submission. The lab that hangs must build and finish one run of its checks, which ends a
    /// check-time-limit after its hung check starts, inside it, or no check has a result: on a 2-core CI machine about
    /// 3.4 times slower than a developer's, that takes about 45 s + 57 s, and this limit leaves 1.7 times that.
    /// </summary>
    private const int SubmissionLimitSeconds = 180;

    /// <summary>
    /// The limit per submission of the exercise labs. The lab whose sampler never returns must build, run its checks
    /// until its hung check ends the run (the lab's 45 s and 5 s more), list the checks and run those left without a
    /// result: about twice what a lab that passes takes, and this limit leaves 1.7 times that on a slow machine.
    /// </summary>
    private const int ExerciseSubmissionLimitSeconds = 480;

    /// <summary>How long stopping a child and its process tree may take beyond a limit.</summary>
    private const int StopSlackSeconds = 30;

    private const string OnePoint = "private static readonly SamplePoint[] Points = [new(0.5, 0.5)];";

    [Fact]
    public async Task ALabFromTheMovedKitRestoresBuildsAndPassesItsTestsWithTheKitsFeedAsItsOnlySource()
    {
        Assert.False(Directory.Exists(kit.MadeAt), "the kit is still where it was made");
        // The solution's package is beside the feed, not in it; the checks (the instructor's) hold the solution.
        Assert.Empty(Directory.GetFiles(Path.Combine(kit.Kit, "feed"), "RayLab.Templates.Instructor.*"));
        Assert.Single(Directory.GetFiles(Path.Combine(kit.Kit, "instructor"), $"RayLab.Templates.Instructor.{kit.Version}.nupkg"));
        Assert.Contains("c = (u0 * u) + (v0 * v) - (S * w)", File.ReadAllText(Path.Combine(kit.Kit, "checks", "exercise", "src", "Lab", "LabPerspectiveCamera.cs")), StringComparison.Ordinal);
        string lab = await kit.NewLabAsync(kit.Work, "Jan_Kowalski", restore: true);
        string config = File.ReadAllText(Path.Combine(lab, "nuget.config"));
        Assert.Contains("<clear />", config, StringComparison.Ordinal);
        Assert.Contains(Path.Combine(kit.Kit, "feed"), config, StringComparison.Ordinal);

        await kit.RunAsync(lab, "dotnet", "build");
        string output = await kit.RunAsync(lab, "dotnet", "test", "--no-build");
        Assert.Matches(@"(?m)^\s+Passed: +\d+\s*$", output); // the lab's detailed summary
        Assert.DoesNotMatch(@"(?m)^\s+Failed: +[1-9]\d*\s*$", output);
        // Everything the lab restored came from the kit: xUnit and the test SDK too.
        string[] feed = [.. Directory.GetFiles(Path.Combine(kit.Kit, "feed"), "*.nupkg").Select(f => Path.GetFileName(f).ToLowerInvariant())];
        foreach (string package in new[] { "xunit.v3.mtp-off", "microsoft.net.test.sdk", "raylab" })
        {
            Assert.True(Directory.Exists(Path.Combine(kit.Packages, package)), $"{package} was not restored");
        }

        foreach (string id in Directory.GetDirectories(kit.Packages))
        {
            foreach (string version in Directory.GetDirectories(id))
            {
                string nupkg = $"{Path.GetFileName(id)}.{Path.GetFileName(version)}.nupkg";
                Assert.Contains(nupkg, feed);
            }
        }
    }

    [Fact]
    public async Task GradingAClassGivesEachLabItsRowWithinTheLimits()
    {
        string submissions = Directory.CreateDirectory(Path.Combine(kit.Root, "submissions")).FullName;
        // A better method: 16 points on a 4×4 grid (16 rays per pixel, the checks' limit), and a test file of its own
        // that always fails, which the grader replaces.
        string correct = await kit.NewLabAsync(submissions, "correct", restore: false);
        Edit(correct, "src/Lab/MyMethod.cs", OnePoint, Grid(4));
        File.WriteAllText(Path.Combine(correct, "tests", "Lab.Tests", "MyOwnCheck.cs"),
            "namespace correct.Tests;\npublic class MyOwnCheck\n{\n    [Fact]\n    public void Fails() => Assert.Fail(\"the student's own failing test\");\n}\n");
        // Sabotaged: 25 points, more rays than the checks allow; its own copy of the checks allows 100, so its own
        // dotnet test would pass.
        string sabotaged = await kit.NewLabAsync(submissions, "sabotaged", restore: false);
        Edit(sabotaged, "src/Lab/MyMethod.cs", OnePoint, Grid(5));
        Edit(sabotaged, "tests/Lab.Tests/MyMethodTests.cs", "MaxRaysPerPixel = 16;", "MaxRaysPerPixel = 100;");
        // The template as created: one ray through each pixel's centre.
        await kit.NewLabAsync(submissions, "template", restore: false);
        string broken = await kit.NewLabAsync(submissions, "broken", restore: false);
        Edit(broken, "src/Lab/MyMethod.cs", "return sum / Points.Length;", "return sum / Points.Length");
        // Its method never returns: an endless loop that sleeps, so that the minutes it runs do not take the CPU from the
        // labs graded beside it.
        string hangs = await kit.NewLabAsync(submissions, "hangs", restore: false);
        Edit(hangs, "src/Lab/MyMethod.cs", "Intensity sum = Intensity.Black;", "while (pixel.X >= 0) { Thread.Sleep(1000); }\n        Intensity sum = Intensity.Black;");
        // Its program keeps every 16 MB it allocates; its method asks for an array of 2 GB at a picture's first pixel
        // (at once, not bit by bit: checks that run side by side in one process and fill the heap together make the
        // collector work so hard near the limit that a check can reach its time limit first).
        string hog = await kit.NewLabAsync(submissions, "hog", restore: false);
        Edit(hog, "src/Lab/MyMethod.cs", "Intensity sum = Intensity.Black;",
            "if (pixel.X == 0 && pixel.Row == 0)\n        {\n            GC.KeepAlive(new byte[Array.MaxLength]);\n        }\n\n        Intensity sum = Intensity.Black;");
        Edit(hog, "src/Lab/Program.cs", "SceneDescription file = TwoSpheres.Load();",
            "var kept = new List<byte[]>();\n        while (kept.Count >= 0) { kept.Add(new byte[1 << 24]); }\n        SceneDescription file = TwoSpheres.Load();");

        string report = Path.Combine(kit.Root, "report");
        using JsonDocument grades = Grade(submissions, "method", report, checkTimeout: 20, runTimeout: 40, jobs: 2);
        Assert.True(grades.RootElement.GetProperty("sandboxed").GetBoolean());
        Assert.Equal(2, grades.RootElement.GetProperty("jobs").GetInt32());
        Assert.Equal(GradeRequest.DefaultMemoryLimitMegabytes, grades.RootElement.GetProperty("memoryLimitMB").GetInt32());
        Dictionary<string, JsonElement> rows = Rows(grades);
        Assert.Equal(["broken", "correct", "hangs", "hog", "sabotaged", "template"], rows.Keys.Order(StringComparer.Ordinal));
        string method = MethodSection(rows["template"]);
        string[] sections = [.. grades.RootElement.GetProperty("sections").EnumerateArray().Select(s => s.GetString()!)];
        Assert.True(sections.Length >= 4, $"sections: {string.Join(", ", sections)}");
        foreach (JsonElement row in rows.Values)
        {
            Assert.InRange(row.GetProperty("seconds").GetDouble(), 0, SubmissionLimitSeconds + StopSlackSeconds);
        }

        // Built and checked two at a time, but the programs, whose times the table compares, one after another.
        (double Start, double Seconds)[] programs = [.. rows.Values.Where(r => r.TryGetProperty("programStart", out _))
            .Select(r => (r.GetProperty("programStart").GetDouble(), r.GetProperty("steps").GetProperty("program").GetDouble())).OrderBy(p => p.Item1)];
        // Every lab that built and had time left ran its program: the four that finish well within the limit always do
        // (the one that hangs may spend its whole limit on its checks).
        foreach (string name in (string[])["correct", "hog", "sabotaged", "template"])
        {
            Assert.True(rows[name].TryGetProperty("programStart", out _), $"{name} ran no program");
        }

        Assert.InRange(programs.Length, 4, 5);
        for (int i = 1; i < programs.Length; i++)
        {
            // (0.2 s: both figures are rounded to 0.1 s)
            Assert.True(programs[i].Start >= programs[i - 1].Start + programs[i - 1].Seconds - 0.2,
                $"a program started at {programs[i].Start} s while the one started at {programs[i - 1].Start} s ran for {programs[i - 1].Seconds} s");
        }

        Assert.False(rows["broken"].GetProperty("steps").TryGetProperty("checks", out _));
        Assert.True(rows["broken"].GetProperty("steps").GetProperty("build").GetDouble() > 0);

        // The better method and the template pass every section (the student's own failing test is not run); the
        // better method's pictures are closer to the exact image.
        foreach (string name in new[] { "correct", "template" })
        {
            Assert.Equal("ok", rows[name].GetProperty("status").GetString());
            Assert.All(sections, s => Assert.Equal("pass", Section(rows[name], s)));
            Assert.DoesNotContain(Checks(rows[name]), c => c.Contains("MyOwnCheck", StringComparison.Ordinal));
        }

        Assert.True(Rmse(rows["correct"]) < Rmse(rows["template"]) / 4, $"RMSE {Rmse(rows["correct"])} against the template's {Rmse(rows["template"])}");
        Assert.Equal(16, rows["correct"].GetProperty("labReport").GetProperty("perspective").GetProperty("raysPerPixel").GetDouble(), 3);

        // Sabotaged: the method's section fails under the instructor's threshold, whatever the student's copy says; the others pass.
        Assert.Equal("ok", rows["sabotaged"].GetProperty("status").GetString());
        Assert.Equal("fail", Section(rows["sabotaged"], method));
        Assert.All(sections.Where(s => s != method), s => Assert.Equal("pass", Section(rows["sabotaged"], s)));

        // Does not compile: the row says so, with the compiler's error, and no check ran.
        Assert.Equal("does not build", rows["broken"].GetProperty("status").GetString());
        Assert.Contains("CS1002", rows["broken"].GetProperty("detail").GetString(), StringComparison.Ordinal);
        Assert.Empty(Checks(rows["broken"]));

        // Never returns: the checks that render with the method time out, the others pass, the program is stopped.
        string hangsStatus = rows["hangs"].GetProperty("status").GetString()!;
        Assert.Contains("time limit", hangsStatus, StringComparison.Ordinal);
        Assert.Equal("timeout", Section(rows["hangs"], method));
        // Every check of the lab has its row, those the runs left out with the one that hung too, and the detail names
        // the one that hung.
        Assert.Equal(Checks(rows["template"]).Order(StringComparer.Ordinal), Checks(rows["hangs"]).Order(StringComparer.Ordinal));
        Assert.Contains("ran past --check-timeout: ", rows["hangs"].GetProperty("detail").GetString(), StringComparison.Ordinal);

        // Past the limit: the checks that render with its method and its program stop at the memory limit (not
        // the machine's), and the row says so; the other checks pass, and the other labs ran under the same limit.
        Assert.Equal("check memory limit; program memory limit; pictures missing", rows["hog"].GetProperty("status").GetString());
        Assert.Contains("--memory-limit", rows["hog"].GetProperty("detail").GetString(), StringComparison.Ordinal);
        Assert.Equal("fail", Section(rows["hog"], method));
        Assert.Contains(sections, s => s != method && Section(rows["hog"], s) == "pass");

        // The page shows each student's pictures and error maps beside the exact ones.
        string html = File.ReadAllText(Path.Combine(report, "index.html"));
        foreach (string file in new[] { "exact/perspective.png", "students/correct/perspective.png", "students/correct/perspective-flip.png" })
        {
            Assert.Contains($"src=\"{file}\"", html, StringComparison.Ordinal);
            Assert.True(File.Exists(Path.Combine(report, file)), $"{file} is missing");
        }

        string[] csv = File.ReadAllLines(Path.Combine(report, "grades.csv"));
        Assert.Equal(7, csv.Length);
        Assert.StartsWith("broken,does not build,", csv[1], StringComparison.Ordinal);
    }

    /// <summary>The solution's orthographic GetRay, as the template writes it.</summary>
    private const string OrthoRay = "        Double3 p = Position + c + (alpha * a) + (beta * b);\n        return new Ray(p, -w);";

    /// <summary>The same camera's settings, for RayLab's OrthoCamera.</summary>
    private const string OrthoSettings = "Position = Position, Target = Target, Up = Up, Window = Window, NearPlane = NearPlane, FarPlane = FarPlane, ViewHeight = ViewHeight";

    [Fact]
    public async Task GradingExerciseLabsGivesEachSectionOfTheStudentsClassesItsOwnResult()
    {
        // The exercise lab: the reference solution; and the solution with two mistakes in two sections, each of which
        // must fail only its own: the 8-bit rule rounded instead of cut (2.2), and a regular sampler whose loop never
        // ends for n = 1 and calls nothing of the checks' code (4.1.1; it sleeps, so as not to take a core from the
        // labs graded beside it): its check fails at the lab's limit with its own message and ends the run, and the
        // grader runs the checks left without a result again.
        string submissions = Directory.CreateDirectory(Path.Combine(kit.Root, "exercise-submissions")).FullName;
        await kit.NewLabAsync(submissions, "solution", restore: false, "exercise", "raylab-lab-solution");
        string rounded = await kit.NewLabAsync(submissions, "rounded", restore: false, "exercise", "raylab-lab-solution");
        Edit(rounded, "src/Lab/LabImage.cs", "(byte)(int)scaled", "(byte)Math.Round(scaled)");
        Edit(rounded, "src/Lab/LabRegularSampler.cs", "            for (int i = 0; i < K; i++)",
            "            while (K == 1)\n            {\n                Thread.Sleep(100);\n            }\n\n            for (int i = 0; i < K; i++)");
        // The orthographic camera handed to RayLab's: one line, which gives RayLab's own rays.
        string delegating = await kit.NewLabAsync(submissions, "delegating", restore: false, "exercise", "raylab-lab-solution");
        Edit(delegating, "src/Lab/LabOrthoCamera.cs", OrthoRay,
            $"        return new OrthoCamera {{ {OrthoSettings} }}.GetImagePlane(nx, ny).GetPixelRay(x, y, sx, sy);");
        // The same through reflection, in a helper class, with no RayLab camera named in the code.
        string reflecting = await kit.NewLabAsync(submissions, "reflecting", restore: false, "exercise", "raylab-lab-solution");
        Edit(reflecting, "src/Lab/LabOrthoCamera.cs", OrthoRay,
            "        return Borrowed.Ray(this, x, y, nx, ny, sx, sy);");
        File.WriteAllText(Path.Combine(reflecting, "src", "Lab", "Borrowed.cs"), """
            using RayLab;

            namespace reflecting;

            internal static class Borrowed
            {
                public static Ray Ray(LabOrthoCamera mine, int x, int y, int nx, int ny, double sx, double sy)
                {
                    Type type = Type.GetType("RayLab.Orth" + "oCamera, RayLab.Core")!;
                    object camera = Activator.CreateInstance(type)!;
                    foreach (string name in (string[])["Position", "Target", "Up", "Window", "NearPlane", "FarPlane", "ViewHeight"])
                    {
                        type.GetProperty(name)!.SetValue(camera, typeof(LabOrthoCamera).GetProperty(name)!.GetValue(mine));
                    }

                    object plane = type.GetMethod("GetImagePlane")!.Invoke(camera, [nx, ny])!;
                    return (Ray)plane.GetType().GetMethod("GetPixelRay")!.Invoke(plane, [x, y, sx, sy])!;
                }
            }
            """);
        // The skeleton, nothing written, which attacks the checks two ways. Its project edits the checks at build time so
        // that every check returns at once (ContinueOnError: where the checks are not in its copy, the build goes on).
        // And its intensity writes, while the checks run, a TRX with one passing check per section where the grader
        // reads the run's results, and makes it read-only so that the test platform cannot write its own. Either attack
        // that worked would pass sections.
        string forger = await kit.NewLabAsync(submissions, "forger", restore: false, "exercise");
        Edit(forger, "src/Lab/Lab.csproj", "</Project>", """
              <Target Name="PassEveryCheck" BeforeTargets="CoreCompile">
                <Exec Command="sed -i 's/var clock = Stopwatch.StartNew();/if (work is not null) { return TimeSpan.Zero; } var clock = Stopwatch.StartNew();/' ../../tests/Lab.Tests/Check.cs" ContinueOnError="true" />
              </Target>
            </Project>
            """);

        Edit(forger, "src/Lab/LightIntensity.cs", "public readonly struct LightIntensity\n{", "public readonly struct LightIntensity\n{\n    static LightIntensity() => Forger.Forge();\n");
        File.WriteAllText(Path.Combine(forger, "src", "Lab", "Forger.cs"), ForgerSource);

        using JsonDocument grades = Grade(submissions, "exercise", Path.Combine(kit.Root, "exercise-report"), checkTimeout: 60, runTimeout: 60, jobs: 2, submissionLimit: ExerciseSubmissionLimitSeconds);
        Dictionary<string, JsonElement> rows = Rows(grades);
        string[] sections = [.. grades.RootElement.GetProperty("sections").EnumerateArray().Select(s => s.GetString()!)];
        // Every section of the lab, parsed from the checks' display names.
        Assert.Equal(["2.1", "2.2", "3", "3.1", "3.2", "4.1.1", "4.1.2", "4.1.3", "4.1.4", "5"], sections.Order(StringComparer.Ordinal));
        Assert.Equal("ok", rows["solution"].GetProperty("status").GetString());
        Assert.All(sections, s => Assert.Equal("pass", Section(rows["solution"], s)));
        Assert.Empty(rows["solution"].GetProperty("uses").EnumerateArray());
        Assert.True(Rmse(rows["solution"]) < 1, $"the solution's perspective picture is {Rmse(rows["solution"])} levels RMSE from the exact one");
        // The lab's rule as this lab writes it (each pixel on its own, with its centre): the solution traces what the
        // report puts beside it.
        foreach (string camera in (string[])["orthographic", "perspective"])
        {
            double lab = grades.RootElement.GetProperty("reference").GetProperty(camera).GetProperty("labAdaptiveRaysPerPixel").GetDouble();
            Assert.Equal(lab, rows["solution"].GetProperty("labReport").GetProperty(camera).GetProperty("raysPerPixel").GetDouble(), 0.01);
        }

        // Two mistakes: each fails its own section (and 5, whose pictures go through the same ToByte), the row is still
        // ok, and every other check has its result (as many as the solution's, all passed in the other sections), the
        // checks after the sampler's stopped run too: its check failed with the lab's own result, not the grader's
        // timeout.
        Assert.Equal("ok", rows["rounded"].GetProperty("status").GetString());
        Assert.Equal("fail", Section(rows["rounded"], "2.2"));
        Assert.Equal("fail", Section(rows["rounded"], "4.1.1"));
        Assert.Equal("fail", Section(rows["rounded"], "5"));
        Assert.All(sections.Where(s => s is not "2.2" and not "4.1.1" and not "5"), s => Assert.Equal("pass", Section(rows["rounded"], s)));
        Assert.Equal(Checks(rows["solution"]).Order(StringComparer.Ordinal), Checks(rows["rounded"]).Order(StringComparer.Ordinal));
        Assert.DoesNotContain(rows["rounded"].GetProperty("checks").EnumerateArray(), c => c.GetProperty("outcome").GetString() is "Timeout" or "Crashed" or "NotRun");

        // Handed to RayLab, directly or through reflection: the camera's checks pass (RayLab's rays are right), but the
        // section fails, and the row names what the lab used; every other section passes.
        foreach ((string name, string use) in new[]
        {
            ("delegating", "3.1: LabOrthoCamera.GetRay uses RayLab's Camera.GetImagePlane: the lab asks you to write it"),
            ("reflecting", "3.1: Borrowed.Ray uses reflection (Type.GetType), which the lab does not allow"),
        })
        {
            JsonElement row = rows[name];
            Assert.Equal("not its own code", row.GetProperty("status").GetString());
            Assert.Contains(use, row.GetProperty("uses").EnumerateArray().Select(u => u.GetString()));
            Assert.Equal("fail", Section(row, "3.1"));
            Assert.All(sections.Where(s => s != "3.1"), s => Assert.Equal("pass", Section(row, s)));
        }

        // The lab that attacks the checks: the checks it runs are the instructor's, built where it cannot write, and
        // where they run its code sees their results read-only, so no section passes (each is not written, as the
        // skeleton's are, or fails where its checks meet the intensity's failing static constructor), it earns nothing,
        // and no check the forgery names is in its row.
        Assert.All(sections, s => Assert.Contains(Section(rows["forger"], s), (string[])["not written", "fail"]));
        Assert.Equal(0, rows["forger"].GetProperty("grade").GetDouble());
        Assert.DoesNotContain(rows["forger"].GetProperty("checks").EnumerateArray(), c => c.GetProperty("name").GetString()!.EndsWith(" forged", StringComparison.Ordinal));
    }

    /// <summary>
    /// A helper of the forging lab: finds the folder of every run's results, from the test platform's command lines
    /// and from the grader's temporary folders, and writes a TRX there with one passing check per section.
    /// </summary>
    private const string ForgerSource = """
        namespace forger;

        internal static class Forger
        {
            public static void Forge()
            {
                if (!OperatingSystem.IsLinux())
                {
                    return;
                }

                string trx = "<?xml version=\"1.0\" encoding=\"utf-8\"?><TestRun xmlns=\"http://microsoft.com/schemas/VisualStudio/TeamTest/2010\"><Results>"
                    + string.Concat(((string[])["2.1", "2.2", "3", "3.1", "3.2", "4.1.1", "4.1.2", "4.1.3", "4.1.4", "5"]).Select(s => $"<UnitTestResult testName=\"{s} forged\" outcome=\"Passed\" />"))
                    + "</Results></TestRun>";
                var folders = new List<string>();
                foreach (string process in Directory.GetDirectories("/proc"))
                {
                    string[] args;
                    try
                    {
                        args = File.ReadAllText(Path.Combine(process, "cmdline")).Split('\0');
                    }
                    catch (Exception)
                    {
                        continue;
                    }

                    int at = Array.IndexOf(args, "--results-directory");
                    if (at >= 0 && at + 1 < args.Length)
                    {
                        folders.Add(args[at + 1]);
                    }
                }

                foreach (string work in Directory.GetDirectories(Path.GetTempPath(), "raylab-grade-*"))
                {
                    string of = Path.Combine(work, "results-of");
                    if (Directory.Exists(of))
                    {
                        folders.AddRange(Directory.GetDirectories(of).SelectMany(d => Enumerable.Range(1, 3).Select(n => Path.Combine(d, $"results-{n}"))));
                    }
                }

                foreach (string folder in folders.Distinct())
                {
                    Directory.CreateDirectory(folder);
                    string file = Path.Combine(folder, "checks.trx");
                    File.WriteAllText(file, trx);
                    File.SetUnixFileMode(file, UnixFileMode.UserRead | UnixFileMode.GroupRead | UnixFileMode.OtherRead);
                    File.SetUnixFileMode(folder, UnixFileMode.UserRead | UnixFileMode.UserExecute | UnixFileMode.GroupRead | UnixFileMode.GroupExecute | UnixFileMode.OtherRead | UnixFileMode.OtherExecute);
                }
            }
        }
        """;

    [Fact]
    public async Task CtrlCWhileTwoLabsAreGradedSideBySideStopsBothSandboxesAndWritesNoReport()
    {
        // Two labs whose builds never end by themselves: only Ctrl+C can stop them.
        string submissions = Directory.CreateDirectory(Path.Combine(kit.Root, "interrupted-submissions")).FullName;
        foreach (string name in (string[])["first", "second"])
        {
            string lab = await kit.NewLabAsync(submissions, name, restore: false);
            Edit(lab, "src/Lab/Lab.csproj", "</Project>", "  <Target Name=\"NeverEnds\" BeforeTargets=\"CoreCompile\">\n    <Exec Command=\"sleep 100000\" />\n  </Target>\n</Project>");
        }

        string report = Path.Combine(kit.Root, "interrupted-report");
        string[] workBefore = GradeWorkFolders();

        // raylab grade as its own process, as a terminal runs it, so that SIGINT reaches it as Ctrl+C does.
        using Process grade = ConsoleChild.Start(kit.Root, "grade", submissions, "--checks", Path.Combine(kit.Kit, "checks", "method"), "--out", report, "--jobs", "2");
        Task<string> stdout = grade.StandardOutput.ReadToEndAsync(TestContext.Current.CancellationToken);
        Task<string> stderr = grade.StandardError.ReadToEndAsync(TestContext.Current.CancellationToken);
        using var _ = ConsoleChild.EndOnFailure(grade);

        // The gate: both labs' builds stuck in their sandboxes at once (two sleeps below raylab).
        var guard = Stopwatch.StartNew();
        while (Descendants(grade.Id).Count(p => Command(p) == "sleep") < 2)
        {
            Assert.False(grade.HasExited || guard.Elapsed > TimeSpan.FromMinutes(5),
                $"raylab grade never had both labs building at once:\n{(grade.HasExited ? await stdout + "\n" + await stderr : "")}");
            await Task.Delay(50, TestContext.Current.CancellationToken);
        }

        int[] children = Descendants(grade.Id);
        await ConsoleChild.InterruptAndWaitAsync(grade, TimeSpan.FromMinutes(2));

        // Cancelled: the exit code a shell gives Ctrl+C, one line, no report, no process of either sandbox left, and
        // the grader's temporary folder gone.
        string said = await stderr;
        Assert.True(grade.ExitCode == Program.CancelledExitCode, $"raylab grade exited {grade.ExitCode}:\n{await stdout}\n{said}");
        Assert.Equal("raylab: grading cancelled; no report written", said.Trim());
        Assert.False(File.Exists(Path.Combine(report, "index.html")) || File.Exists(Path.Combine(report, "grades.json")), "a report was written");
        int[] alive = [.. children.Where(Alive)];
        Assert.True(alive.Length == 0, $"still running after raylab grade ended: {string.Join("; ", alive.Select(p => $"{p} {Command(p)}"))}");
        Assert.Equal(workBefore, GradeWorkFolders());
    }

    /// <summary>The grader's temporary folders (raylab-grade-*) in the machine's temporary folder.</summary>
    private static string[] GradeWorkFolders() => [.. Directory.GetDirectories(Path.GetTempPath(), "raylab-grade-*").Order(StringComparer.Ordinal)];

    /// <summary>Every process below <paramref name="root"/>, from the parent ids in /proc/PID/stat.</summary>
    private static int[] Descendants(int root)
    {
        var children = new Dictionary<int, List<int>>();
        foreach (string folder in Directory.GetDirectories("/proc"))
        {
            if (!int.TryParse(Path.GetFileName(folder), CultureInfo.InvariantCulture, out int pid))
            {
                continue;
            }

            try
            {
                string stat = File.ReadAllText(Path.Combine(folder, "stat"));
                // "pid (comm) state ppid …": the command may hold spaces and parentheses, so read after the last ')'.
                string[] rest = stat[(stat.LastIndexOf(')') + 2)..].Split(' ');
                int parent = int.Parse(rest[1], CultureInfo.InvariantCulture);
                if (!children.TryGetValue(parent, out List<int>? list))
                {
                    children[parent] = list = [];
                }

                list.Add(pid);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // the process ended while it was read
            }
        }

        var found = new List<int>();
        var next = new Queue<int>([root]);
        while (next.TryDequeue(out int pid))
        {
            foreach (int child in children.GetValueOrDefault(pid) ?? [])
            {
                found.Add(child);
                next.Enqueue(child);
            }
        }

        return [.. found];
    }

    /// <summary>A process's command name (/proc/PID/comm), or "" once it has ended.</summary>
    private static string Command(int pid)
    {
        try
        {
            return File.ReadAllText($"/proc/{pid}/comm").Trim();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return "";
        }
    }

    /// <summary>Whether a process still runs: it is in /proc and not a zombie waiting for its parent.</summary>
    private static bool Alive(int pid)
    {
        try
        {
            string stat = File.ReadAllText($"/proc/{pid}/stat");
            return stat[stat.LastIndexOf(')')..] is not [_, _, 'Z', ..];
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false;
        }
    }

    /// <summary>
    /// <c>raylab grade</c>, in-process, of the labs in <paramref name="submissions"/> against the kit's pinned checks of
    /// <paramref name="kind"/>, with the class's limit per submission; fails with both outputs unless it exits 0.
    /// </summary>
    /// <returns>The report's grades.json.</returns>
    private JsonDocument Grade(string submissions, string kind, string report, int checkTimeout, int runTimeout, int jobs, int submissionLimit = SubmissionLimitSeconds)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int exit = Program.Run(
            ["grade", submissions, "--checks", Path.Combine(kit.Kit, "checks", kind), "--out", report,
             "--check-timeout", checkTimeout.ToString(CultureInfo.InvariantCulture), "--run-timeout", runTimeout.ToString(CultureInfo.InvariantCulture),
             "--submission-timeout", submissionLimit.ToString(CultureInfo.InvariantCulture), "--jobs", jobs.ToString(CultureInfo.InvariantCulture)],
            stdout, stderr, TestContext.Current.CancellationToken);
        Assert.True(exit == 0, $"raylab grade exited {exit}:\n{stdout}\n{stderr}");
        TestContext.Current.TestOutputHelper?.WriteLine($"raylab grade {kind}:\n{stdout}\n{stderr}");
        return JsonDocument.Parse(File.ReadAllText(Path.Combine(report, "grades.json")));
    }

    /// <summary>The report's rows, by the student's name.</summary>
    private static Dictionary<string, JsonElement> Rows(JsonDocument grades) =>
        grades.RootElement.GetProperty("students").EnumerateArray().ToDictionary(r => r.GetProperty("name").GetString()!);

    private static string Grid(int n) =>
        $"private static readonly SamplePoint[] Points = [.. Enumerable.Range(0, {n * n}).Select(i => new SamplePoint(((i % {n}) + 0.5) / {n}, ((i / {n}) + 0.5) / {n}))];";

    private static void Edit(string lab, string file, string find, string replace)
    {
        string path = Path.Combine(lab, file);
        string text = File.ReadAllText(path);
        Assert.Contains(find, text, StringComparison.Ordinal);
        File.WriteAllText(path, text.Replace(find, replace, StringComparison.Ordinal));
    }

    /// <summary>The section of the checks that measure the student's method against the exact image.</summary>
    private static string MethodSection(JsonElement row) =>
        row.GetProperty("checks").EnumerateArray()
            .First(c => c.GetProperty("name").GetString()!.Contains("MyMethodIsCloseToTheExactImage", StringComparison.Ordinal))
            .GetProperty("section").GetString()!;

    private static string? Section(JsonElement row, string section) =>
        row.GetProperty("sections").GetProperty(section).GetString();

    private static string[] Checks(JsonElement row, string? section = null) =>
        [.. row.GetProperty("checks").EnumerateArray()
            .Where(c => section is null || c.GetProperty("section").GetString() == section)
            .Select(c => c.GetProperty("name").GetString()!)];

    private static double Rmse(JsonElement row) => row.GetProperty("pictures").GetProperty("perspective").GetProperty("rmse").GetDouble();
}
