using System.Diagnostics;
using System.Text.RegularExpressions;
using SkiaSharp;

namespace RayLab.Templates.Tests;

/// <summary>
/// The exercise lab (<c>dotnet new raylab-lab</c>, <c>--kind exercise</c> by default): the skeletons build with a
/// student's unused variable (a warning, listed by the program with its file and line, not an error); every check of a
/// section still to write is skipped with one line and no stack, and one check, the lab's progress, lists the sections
/// still to write; the checks' names carry numbers written the same under a Polish culture; <c>dotnet run</c> names
/// the classes still to write and says that no picture was made, in each language. The reference solution (the
/// instructor's template, <c>dotnet new raylab-lab-solution</c>) passes every check and writes the pictures; and five
/// sabotages of the solution each fail their own section, a sixth that throws is named by file and line, and an
/// adaptive recursion without its depth limit stops with a message, not a stack overflow. One restored solution lab
/// serves all the sabotages (edit, <c>dotnet test --no-restore</c>, put the file back).
/// </summary>
public sealed partial class LabTemplateTests
{
    /// <summary>The sections every check's display name starts with.</summary>
    private static readonly string[] Sections = ["2.1", "2.2", "3", "3.1", "3.2", "4.1.1", "4.1.2", "4.1.3", "4.1.4", "5"];

    /// <summary>
    /// The words each language's lab uses: a few display names, the words for a section still to write (the skeletons'
    /// message and check's line alike), the README's, the progress check's count on a fresh lab, the program's line
    /// when it made no picture, and its line for a warning (an unused variable) with its start.
    /// </summary>
    private static readonly (string Lang, string[] Names, string ToWrite, string Readme, string Counted, string NoPicture, string Warning)[] Languages =
    [
        ("pl", ["2.1 Natężenie:", "2.2 Obraz:", "3.1 Kamera ortogonalna:", "3.2 Kamera perspektywiczna:", "4.1.4 Próbkowanie adaptacyjne:", "5 Zadanie:"], "jeszcze do napisania", "Zadanie (sekcja 5 instrukcji)",
            "0 z 10 części napisane", "Nie powstał żaden obraz: do obrazów potrzebne są wszystkie części; brakuje: 2.1 Natężenie, 2.2 Obraz,", @"ostrzeżenie\s+src/Lab/LightIntensity\.cs:\d+: zmienna 'licznik'"),
        ("en", ["2.1 Intensity:", "2.2 Image:", "3.1 Orthographic camera:", "3.2 Perspective camera:", "4.1.4 Adaptive sampling:", "5 Task:"], "still to write", "The lab's task (section 5)",
            "0 of 10 parts written", "No picture was made: the pictures need every part; missing: 2.1 Intensity, 2.2 Image,", @"warning\s+src/Lab/LightIntensity\.cs:\d+: the variable 'licznik'"),
    ];

    /// <summary>
    /// The five sabotages: the section that must fail, the file, the line of the solution and what replaces it.
    /// </summary>
    private static readonly (string Section, string File, string Line, string Sabotage)[] Sabotages =
    [
        ("3.2", "src/Lab/LabPerspectiveCamera.cs", "c = (u0 * u) + (v0 * v) - (S * w)", "c = (u0 * u) + (v0 * v) + (S * w)"),     // w with the wrong sign
        ("2.2", "src/Lab/LabImage.cs", "(byte)(int)scaled", "(byte)Math.Round(scaled)"),                                           // rounded, not cut
        ("3", "src/Lab/LabCamera.cs", "=> (x + sx) / nx;", "=> (double)x / nx;"),                                                  // the centre at x/nx
        ("4.1.3", "src/Lab/LabJitteredSampler.cs", "((i + random.NextDouble()) / K", "(((i & ~1) + random.NextDouble()) / K"),     // two samples in one stratum
        ("4.1.4", "src/Lab/LabAdaptiveSampler.cs", ": (tl + centre) / 2;", ": ((3 * tl) + centre) / 4;"),                          // the weights changed
    ];

    [Fact]
    public async Task TheExerciseLabInEachLanguageBuildsWithAWarningSkipsWhatIsStillToWriteAndRunNamesTheClassesToWrite()
    {
        // One folder for both languages (the second made over the first with --force): one restore, as the files differ
        // only in their text.
        string lab = Path.Combine(TrappedFolder("exercise"), "Lab2");
        foreach ((string lang, string[] names, string toWrite, string readme, string counted, string noPicture, string warning) in Languages)
        {
            await feed.RunAsync(feed.Root, "dotnet", "new", "raylab-lab", "-o", lab, "--lang", lang, "--feed", feed.Feed, "--force", "--skipRestore");
            AssertNoTemplateLeftovers(lab);
            Assert.Contains(readme, File.ReadAllText(Path.Combine(lab, "README.md")), StringComparison.Ordinal);

            // A variable left unused in a section, as students leave them while they work: a warning, shown, not fatal.
            string intensity = Path.Combine(lab, "src", "Lab", "LightIntensity.cs");
            string constructor = "        throw ToWrite.Section(\"2.1\", \"new LightIntensity(r, g, b)\");";
            Assert.Contains(constructor, File.ReadAllText(intensity), StringComparison.Ordinal);
            File.WriteAllText(intensity, File.ReadAllText(intensity).Replace(constructor, "        int licznik = 0;\n" + constructor, StringComparison.Ordinal));
            string build = await feed.RunAsync(lab, "dotnet", "build");
            Assert.Contains("warning CS0219", build, StringComparison.Ordinal);

            // dotnet run: every section listed as still to write, by class; the warning with its file and line; no
            // picture, and why; no stack trace; a non-zero exit.
            (int runExit, string run) = await feed.RunUncheckedAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"));
            Assert.True(runExit == 1, $"dotnet run with the skeletons ({lang}) exited {runExit}:\n{run}");
            foreach (string section in Sections)
            {
                Assert.Matches($@"(?m)^\s+{toWrite}\s+{Regex.Escape(section)}\s", run);
            }

            foreach (string type in new[] { "LightIntensity", "LabImage", "LabCamera", "LabOrthoCamera", "LabPerspectiveCamera", "LabJitteredSampler", "LabAdaptiveSampler", "LabRenderer" })
            {
                Assert.Contains(type, run, StringComparison.Ordinal);
            }

            Assert.Contains(noPicture, run, StringComparison.Ordinal);
            Assert.Matches($"(?m)^\\s+{warning}", run);
            Assert.DoesNotMatch(@"(?m)^\s+at \S+\(", run);
            (int checkExit, string check) = await feed.RunUncheckedAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"), "--", "check");
            Assert.Equal(1, checkExit);
            Assert.Matches($"(?m)^\\s+{warning}", check);

            // dotnet test, under a Polish culture: it builds and runs despite the warning. A section still to write is
            // not wrong: its checks are skipped, each with one line and no stack; one check fails, the lab's progress,
            // with the sections still to write. Each section's own-code check passes (the skeletons use nothing the lab
            // does not allow). Numbers in the checks' names are written the same whatever the culture.
            (int testExit, string test) = await feed.RunUncheckedAsync(lab, new Dictionary<string, string?> { ["LC_ALL"] = "pl_PL.UTF-8", ["LANG"] = "pl_PL.UTF-8", ["DOTNET_CLI_UI_LANGUAGE"] = "en" },
                "dotnet", "test", "--no-build");
            Assert.NotEqual(0, testExit);
            (int passed, int failed) = DetailedCounts(test);
            int skipped = DetailedSkipped().Match(test) is { Success: true } m ? int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) : 0;
            Assert.True(passed == Sections.Length && failed == 1 && skipped >= 30, $"the skeletons ({lang}): {passed} passed, {failed} failed, {skipped} skipped:\n{test}");
            Assert.Equal(Sections.Order(), SkippedSections(test).Order());
            Assert.Empty(FailedSections(test));
            foreach (string name in names)
            {
                Assert.Contains("Skipped " + name, test, StringComparison.Ordinal);
            }

            Assert.Contains(counted, test, StringComparison.Ordinal);
            foreach (string section in Sections)
            {
                Assert.Matches($@"(?m)^\s+{Regex.Escape(section)} \S.*\((Lab\w+|LightIntensity)\): ", test);
            }

            string window = $"{names[2]} {toWrite} — LabOrthoCamera.GetWindow(nx, ny)";
            Assert.True(Regex.Count(test, Regex.Escape(window)) == 1, $"\"{window}\" is not in the output ({lang}) once:\n{test}");
            Assert.DoesNotMatch(@"(?m)^\s+at \S", test);
            Assert.DoesNotContain("Stack Trace:", test, StringComparison.Ordinal);
            Assert.DoesNotMatch(@"(?m)^\s+(Passed|Failed|Skipped) .*\d,\d", test);
            Assert.Contains("(I: 0.1)", test, StringComparison.Ordinal);
            if (lang == "pl")
            {
                string[] english = [.. EnglishLines(test + "\n" + run + "\n" + check)];
                Assert.True(english.Length == 0, $"the Polish lab's output holds English:\n{string.Join("\n", english)}");
            }
        }
    }

    [Fact]
    public async Task ThePolishExerciseLabHasNoEnglishSentenceInWhatTheStudentWritesInOrReadsAndDotnetNewListsItInPolish()
    {
        string list = await feed.RunAsync(feed.Root, "dotnet", "new", "list", "raylab-lab");
        Assert.Contains("Laboratorium RayLab (kamera, próbkowanie, obraz, natężenie)", list, StringComparison.Ordinal);
        Assert.DoesNotContain("RayLab lab (camera", list, StringComparison.Ordinal);

        string root = TrappedFolder("polish");
        string pl = Path.Combine(root, "pl"), en = Path.Combine(root, "en");
        await feed.RunAsync(feed.Root, "dotnet", "new", "raylab-lab", "-o", pl, "--feed", feed.Feed, "--skipRestore");
        await feed.RunAsync(feed.Root, "dotnet", "new", "raylab-lab", "-o", en, "--lang", "en", "--feed", feed.Feed, "--skipRestore");
        string[] english = [.. EnglishSentences(pl)];
        Assert.True(english.Length == 0, $"the Polish exercise lab holds {english.Length} English sentences:\n{string.Join("\n", english)}");

        // The heuristic finds English where it is: the English lab's files are full of it.
        Assert.True(EnglishSentences(en).Count() > 20, "the heuristic finds no English in the English lab");
    }

    [Fact]
    public async Task TheEnglishExerciseLabHasNoPolishLetterInAnyFile()
    {
        string root = TrappedFolder("english");
        string en = Path.Combine(root, "en"), pl = Path.Combine(root, "pl");
        await feed.RunAsync(feed.Root, "dotnet", "new", "raylab-lab", "-o", en, "--lang", "en", "--feed", feed.Feed, "--skipRestore");
        await feed.RunAsync(feed.Root, "dotnet", "new", "raylab-lab", "-o", pl, "--feed", feed.Feed, "--skipRestore");
        string[] polish = [.. PolishLines(en)];
        Assert.True(polish.Length == 0, $"the English exercise lab holds {polish.Length} lines with a Polish letter:\n{string.Join("\n", polish)}");

        // The search finds Polish where it is: the Polish lab's files are full of it.
        Assert.True(PolishLines(pl).Count() > 20, "no Polish letter found in the Polish lab");
    }

    [Fact]
    public async Task TheSolutionPassesEveryCheckRendersThePicturesAndEachSabotageFailsItsOwnSection()
    {
        string lab = Path.Combine(TrappedFolder("solution"), "Lab2");
        await feed.RunAsync(feed.Root, "dotnet", "new", "raylab-lab-solution", "-o", lab, "--feed", feed.Feed);
        AssertNoTemplateLeftovers(lab);

        // Every check passes.
        (int testExit, string test) = await feed.RunUncheckedAsync(lab, "dotnet", "test");
        Assert.True(testExit == 0, $"dotnet test failed in the solution lab:\n{test}");
        (int passed, int failed) = DetailedCounts(test);
        Assert.True(failed == 0 && passed >= 35, $"the solution: {passed} passed, {failed} failed:\n{test}");
        Assert.Equal(Sections.Order(), PassedSections(test).Order());
        Assert.Matches(@"RMSE [\d.,]+ poziomu, max \d+, FLIP [\d.,]+", test); // the figures are in dotnet test's output

        // check: every section listed as written (not "done": it only knows that nothing throws NotImplementedException).
        string check = await feed.RunAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"), "--", "check");
        foreach (string section in Sections)
        {
            Assert.Matches($@"(?m)^\s+napisane\s+{Regex.Escape(section)}\s", check);
        }

        Assert.Contains("Wszystkie części są napisane; sprawdzenie: dotnet test", check, StringComparison.Ordinal);

        // dotnet run: both pictures and obrazkoncowy.jpg, one line per render.
        string output = await feed.RunAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"));
        foreach (string camera in new[] { "orthographic", "perspective" })
        {
            Assert.Matches($@"(?m)^{camera} +adaptive +[\d,]+ promieni \( *[\d.]+ na piksel\) +[\d.]+ ms", output);
            AssertPicture(Path.Combine(lab, "out", $"two-spheres-{camera}.png"), SKEncodedImageFormat.Png);
        }

        Assert.Matches(@"(?m)^rozgrzewka .* ms", output);
        double difference = MeanDifference(AssertPicture(Path.Combine(lab, "out", "obrazkoncowy.jpg"), SKEncodedImageFormat.Jpeg),
            AssertPicture(Path.Combine(lab, "out", "two-spheres-perspective.png"), SKEncodedImageFormat.Png));
        Assert.True(difference < 2, $"obrazkoncowy.jpg differs from the perspective picture by {difference:F2} levels on average");

        // The sabotages, one at a time in the same lab.
        var clock = Stopwatch.StartNew();
        foreach ((string section, string file, string line, string sabotage) in Sabotages)
        {
            string path = Path.Combine(lab, file);
            string source = File.ReadAllText(path);
            Assert.Contains(line, source, StringComparison.Ordinal);
            File.WriteAllText(path, source.Replace(line, sabotage, StringComparison.Ordinal));
            // The sabotaged section's checks and 2.1's (which must still pass), by their Section trait.
            (int exit, string result) = await feed.RunUncheckedAsync(lab, "dotnet", "test", "--no-restore", "--filter", $"Section={section}|Section=2.1");
            File.WriteAllText(path, source);

            Assert.True(exit != 0, $"the sabotage of {section} ({sabotage}) passed every check:\n{result}");
            string[] failing = FailedSections(result);
            Assert.True(failing.Contains(section), $"the sabotage of {section} ({sabotage}) failed sections {string.Join(", ", failing)}, not {section}:\n{result}");
            Assert.DoesNotContain("2.1", failing); // the intensity is not sabotaged: its checks still pass
            Assert.Contains("2.1", PassedSections(result));
            if (section == "2.2")
            {
                // A wrong value names the method that gave it, at its first line of code in the student's file.
                int first = Array.FindIndex(source.Split('\n'), l => l.Contains("double scaled = 256 * intensity;", StringComparison.Ordinal)) + 1;
                Assert.Contains($"a ToByte dało 26 (src/Lab/LabImage.cs:{first}, LabImage.ToByte).", result, StringComparison.Ordinal);
            }
        }

        TestContext.Current.TestOutputHelper?.WriteLine($"five sabotages: {clock.Elapsed.TotalSeconds:F0} s");

        // A loop that never ends: past the lab's limit the check fails with its own message, and the loop is stopped at
        // its next call into the checks' camera or sampler. The limit is 45 s, below the grader's default 60 s
        // (--check-timeout); here LAB_TIME_LIMIT_S makes it 10 s, so that each of the two endless loops takes 10 s.
        Assert.Contains("TimeSpan.FromSeconds(45)", File.ReadAllText(Path.Combine(lab, "tests", "Lab.Tests", "Check.cs")), StringComparison.Ordinal);
        Assert.Contains("DefaultValueFactory = _ => 60,", File.ReadAllText(Path.Combine(RepoPaths.Root(), "samples", "RayLab.Console", "GradeCommand.cs")), StringComparison.Ordinal);
        var shortLimit = new Dictionary<string, string?> { ["LAB_TIME_LIMIT_S"] = "10" };
        string renderer = Path.Combine(lab, "src", "Lab", "LabRenderer.cs");
        string rendererSource = File.ReadAllText(renderer);
        const string row = "for (int x = 0; x < nx; x++)\n            {\n                (double X, double Y)[] points";
        Assert.Contains(row, rendererSource, StringComparison.Ordinal);
        File.WriteAllText(renderer, rendererSource.Replace(row, row.Replace("x++", "x = x * 1", StringComparison.Ordinal), StringComparison.Ordinal));
        (int hangExit, string hang) = await feed.RunUncheckedAsync(lab, shortLimit, "dotnet", "test", "--no-restore", "--filter", "FullyQualifiedName~SameSeedSamePicture");
        File.WriteAllText(renderer, rendererSource);
        Assert.True(hangExit != 0, $"5 passed with a render loop that never ends:\n{hang}");
        Assert.Matches(@"Przekroczony limit czasu 10 s: metoda się nie skończyła \(zapętlenie\?\)\. Ostatnio: piksel \(0, \d+\)\. Twoja metoda została zatrzymana\.", hang);

        // A loop that calls nothing of the checks' code (an endless for in the regular sampler, for every n): nothing
        // inside the process can stop it, so its check fails at the limit with its own message and ends the run after
        // its result. The grid's other cases, which would each hang as long, do not start, and when dotnet test
        // returns no test process is left running the loop.
        string regular = Path.Combine(lab, "src", "Lab", "LabRegularSampler.cs");
        string regularSource = File.ReadAllText(regular);
        const string step = "for (int i = 0; i < K; i++)";
        Assert.Contains(step, regularSource, StringComparison.Ordinal);
        File.WriteAllText(regular, regularSource.Replace(step, "for (int i = 0; i < K; i *= 1)", StringComparison.Ordinal));
        (int spinExit, string spin) = await feed.RunUncheckedAsync(lab, shortLimit, "dotnet", "test", "--no-restore", "--filter", "Section=4.1.1");
        File.WriteAllText(regular, regularSource);
        Assert.True(spinExit != 0, $"4.1.1 passed with a sampler that never returns:\n{spin}");
        Assert.Matches(@"Przekroczony limit czasu 10 s: metoda się nie skończyła \(zapętlenie\?\)\. Ostatnio: —\. Twojej metody nie dało się zatrzymać \(jej pętla nie woła niczego z kodu sprawdzeń\), więc dotnet test kończy się na tym sprawdzeniu razem z nią \(Check\.StopRun\)", spin);
        Assert.True(Regex.Count(spin, @"(?m)^\s+Failed 4\.1\.1 ") == 1, $"not one 4.1.1 check failed, and the run ended:\n{spin}");
        Assert.Empty(TestProcesses(lab));

        // Code that throws: the checks and check name the exception and where in the student's code it came from.
        string image = Path.Combine(lab, "src", "Lab", "LabImage.cs");
        string imageSource = File.ReadAllText(image);
        const string cut = "(byte)(int)scaled";
        int cutLine = Array.FindIndex(imageSource.Split('\n'), l => l.Contains(cut, StringComparison.Ordinal)) + 1;
        Assert.True(cutLine > 0, $"LabImage.cs has no line with {cut}");
        File.WriteAllText(image, imageSource.Replace(cut, "(byte)(new int[2])[(int)scaled]", StringComparison.Ordinal));
        (int throwExit, string thrown) = await feed.RunUncheckedAsync(lab, "dotnet", "test", "--no-restore", "--filter", "Section=2.2");
        (int checkExit, string listed) = await feed.RunUncheckedAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"), "--", "check");
        File.WriteAllText(image, imageSource);
        string at = $"src/Lab/LabImage.cs:{cutLine}, LabImage.ToByte";
        Assert.True(throwExit != 0, $"2.2 passed with a ToByte that indexes past an array:\n{thrown}");
        Assert.Contains($"Twój kod rzucił IndexOutOfRangeException: Index was outside the bounds of the array. ({at}", thrown, StringComparison.Ordinal);
        Assert.Matches($@"(?m)^\s+at \S+\.LabImage\.ToByte\(.*\) in .*src[/\\]Lab[/\\]LabImage\.cs:line {cutLine}\s*$", thrown);
        Assert.DoesNotMatch(FrameworkFrame(), thrown);
        Assert.Equal(1, checkExit);
        Assert.Matches($@"(?m)^\s+rzuca wyjątek\s+2\.2\s.*IndexOutOfRangeException: .*\({Regex.Escape(at)}\)", listed);
        Assert.Matches(@"(?m)^\s+napisane\s+2\.1\s", listed);
        Assert.Contains("Sekcje, które rzucają wyjątek: 2.2", listed, StringComparison.Ordinal);

        // An adaptive recursion without its depth limit: on an edge it splits for ever, and overflows the stack. The
        // checks and check stop it at its first point past depth 3 and say so, with the place in the student's code;
        // the program stops before it renders.
        string adaptive = Path.Combine(lab, "src", "Lab", "LabAdaptiveSampler.cs");
        string adaptiveSource = File.ReadAllText(adaptive);
        const string limit = "if (depth < MaxDepth)";
        Assert.Contains(limit, adaptiveSource, StringComparison.Ordinal);
        File.WriteAllText(adaptive, adaptiveSource.Replace(limit, "if (depth >= 0)", StringComparison.Ordinal));
        (int endlessExit, string endless) = await feed.RunUncheckedAsync(lab, "dotnet", "test", "--no-restore", "--filter", "Section=4.1.4");
        (int endlessCheckExit, string endlessListed) = await feed.RunUncheckedAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"), "--", "check");
        (int endlessRunExit, string endlessRun) = await feed.RunUncheckedAsync(lab, "dotnet", "run", "--no-build", "--project", Path.Combine("src", "Lab"));
        File.WriteAllText(adaptive, adaptiveSource);
        foreach (string said in new[] { endless, endlessListed, endlessRun })
        {
            Assert.DoesNotContain("Stack overflow", said, StringComparison.OrdinalIgnoreCase);
        }

        Assert.True(endlessExit != 0, $"4.1.4 passed with no depth limit:\n{endless}");
        Assert.Matches(@"Twój kod rzucił InvalidOperationException: punkt .* leży poza siatką co 1/16 piksela, więc w kwadracie głębszym niż 3: rekurencja nie zatrzymuje się na MaxDepth = 3 \(src/Lab/LabAdaptiveSampler\.cs:\d+, LabAdaptiveSampler\.", endless);
        Assert.Equal(1, endlessCheckExit);
        Assert.Matches(@"(?m)^\s+rzuca wyjątek\s+4\.1\.4\s.*InvalidOperationException: punkt \([\d.E-]+, [\d.E-]+\) leży poza siatką co 1/16 piksela, więc w kwadracie głębszym niż 3: rekurencja nie zatrzymuje się na MaxDepth = 3 \(src/Lab/LabAdaptiveSampler\.cs:\d+, LabAdaptiveSampler\.\w+\)", endlessListed);
        Assert.Contains("Sekcje, które rzucają wyjątek: 4.1.4", endlessListed, StringComparison.Ordinal);
        Assert.Equal(1, endlessRunExit);
        Assert.Contains("Sekcje, które rzucają wyjątek: 4.1.4", endlessRun, StringComparison.Ordinal);
        Assert.DoesNotContain("rozgrzewka", endlessRun, StringComparison.Ordinal); // no render began
    }

    /// <summary>The running processes whose command line names the lab's folder and its checks (Linux's /proc; none elsewhere).</summary>
    private static string[] TestProcesses(string lab) => !OperatingSystem.IsLinux() ? [] :
        [.. Directory.GetDirectories("/proc").Select(p =>
        {
            try
            {
                return File.ReadAllText(Path.Combine(p, "cmdline")).Replace('\0', ' ');
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                return "";
            }
        }).Where(c => c.Contains(lab, StringComparison.Ordinal) && c.Contains("Lab.Tests", StringComparison.Ordinal))];

    /// <summary>
    /// The passed and failed counts of dotnet test's summary at the exercise lab's detailed verbosity ("Total tests: 37",
    /// "Passed: 37", "Failed: 0" on lines of their own).
    /// </summary>
    private static (int Passed, int Failed) DetailedCounts(string output)
    {
        Assert.True(DetailedTotal().IsMatch(output), $"dotnet test printed no summary (did the lab build?):\n{output}");
        Match passed = DetailedPassed().Match(output), failed = DetailedFailed().Match(output);
        return (passed.Success ? int.Parse(passed.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) : 0,
            failed.Success ? int.Parse(failed.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) : 0);
    }

    [GeneratedRegex(@"(?m)^\s*Total tests: +\d+")]
    private static partial Regex DetailedTotal();

    [GeneratedRegex(@"(?m)^\s+Passed: +(\d+)\s*$")]
    private static partial Regex DetailedPassed();

    [GeneratedRegex(@"(?m)^\s+Failed: +(\d+)\s*$")]
    private static partial Regex DetailedFailed();

    [GeneratedRegex(@"(?m)^\s+Skipped: +(\d+)\s*$")]
    private static partial Regex DetailedSkipped();

    /// <summary>A stack frame of .NET's or xUnit's own code (reflection, threads, the runner) in dotnet test's output.</summary>
    [GeneratedRegex(@"(?m)\bat (System\.|Xunit\.|InvokeStub_)")]
    private static partial Regex FrameworkFrame();

    /// <summary>The sections with a failed check in dotnet test's output.</summary>
    private static string[] FailedSections(string output) =>
        [.. SectionLine().Matches(output).Where(m => m.Groups["result"].Value == "Failed").Select(m => m.Groups["section"].Value).Distinct()];

    /// <summary>The sections with a skipped check (still to write) in dotnet test's output.</summary>
    private static string[] SkippedSections(string output) =>
        [.. SectionLine().Matches(output).Where(m => m.Groups["result"].Value == "Skipped").Select(m => m.Groups["section"].Value).Distinct()];

    /// <summary>The sections with a passed check in dotnet test's output.</summary>
    private static string[] PassedSections(string output) =>
        [.. SectionLine().Matches(output).Where(m => m.Groups["result"].Value == "Passed").Select(m => m.Groups["section"].Value).Distinct()];

    [GeneratedRegex(@"(?m)^\s+(?<result>Passed|Failed|Skipped) (?<section>\d+(\.\d+)*) ")]
    private static partial Regex SectionLine();

    /// <summary>
    /// The English sentences in what the student writes in and reads in a lab: the comments and string literals of
    /// src/Lab's sources and of the checks' sources, the comments of the project and configuration files,
    /// and the README's prose (outside code). A sentence is English when it holds two of a few common English words
    /// ("the", "is", "of", …), none of them Polish; code identifiers, <c>&lt;c&gt;</c> and <c>&lt;see/&gt;</c>
    /// elements, interpolation holes and backticks are left out first. The checks' string literals are searched as
    /// src/Lab's are: each lab holds its own language's messages only (tests/Lab.Tests/Messages.cs).
    /// </summary>
    private static IEnumerable<string> EnglishSentences(string lab)
    {
        foreach (string file in Directory.GetFiles(lab, "*", SearchOption.AllDirectories).Where(f => !IsBuildOutput(lab, f)))
        {
            string relative = Path.GetRelativePath(lab, file).Replace('\\', '/');
            string name = Path.GetFileName(file);
            if (name.EndsWith(".json", StringComparison.Ordinal))
            {
                continue;
            }

            string text = File.ReadAllText(file);
            IEnumerable<string> parts = name.EndsWith(".md", StringComparison.Ordinal)
                ? Regex.Split(Regex.Replace(text, "(?s)```.*?```", ""), @"\n\s*\n").Select(p => Regex.Replace(p, "`[^`]*`", ""))
                : Regex.Matches(text, @"(?s)//[^\n]*|/\*.*?\*/|<!--.*?-->|""(?:[^""\\\n]|\\.)*""").Select(m => m.Value);
            foreach (string part in parts)
            {
                if (IsEnglish(Regex.Replace(part, @"(?s)<c>.*?</c>|<see [^>]*/>|\{[^{}]*\}", "")))
                {
                    yield return $"{relative}: {Regex.Replace(part.Trim(), @"\s+", " ")}";
                }
            }
        }
    }

    /// <summary>The lines of a lab's files (its build output left out) that hold a Polish letter (ą, ć, ę, ł, ń, ó, ś, ź, ż).</summary>
    private static IEnumerable<string> PolishLines(string lab) =>
        Directory.GetFiles(lab, "*", SearchOption.AllDirectories).Where(f => !IsBuildOutput(lab, f)).SelectMany(f =>
            File.ReadLines(f).Where(l => PolishLetter().IsMatch(l)).Select(l => $"{Path.GetRelativePath(lab, f).Replace('\\', '/')}: {l.Trim()}"));

    [GeneratedRegex("[ąćęłńóśźżĄĆĘŁŃÓŚŹŻ]")]
    private static partial Regex PolishLetter();

    /// <summary>The lines of a lab's output, other than the test platform's and the build's own, that read as English.</summary>
    private static IEnumerable<string> EnglishLines(string output) =>
        output.Split('\n').Where(l => !RunnerLine().IsMatch(l)).Where(l => IsEnglish(Regex.Replace(l, @"^\s*(Passed|Failed|Skipped) ", ""))).Select(l => l.Trim());

    private static bool IsEnglish(string text) =>
        EnglishWord().Matches(text).Select(m => m.Value.ToLowerInvariant()).Distinct().Count() >= 2;

    /// <summary>Common English words that are not Polish words ("to", "do", "one" are).</summary>
    [GeneratedRegex(@"\b(the|is|of|and|with|your|this|that|are|for|from|its|which|when|what|each|every|not|was|has)\b", RegexOptions.IgnoreCase)]
    private static partial Regex EnglishWord();

    /// <summary>The test platform's and the build's own lines (in English whatever the lab's language).</summary>
    [GeneratedRegex(@"^\s*(Total tests|Total time|Test Run|A total of|Starting test execution|Results File|Error Message|Stack Trace|Standard Output Messages|Test run for|VSTest version|Microsoft \(R\)|Copyright|Determining projects|Restored |Build succeeded|Time Elapsed|\d+ Warning|\d+ Error|.* -> /)")]
    private static partial Regex RunnerLine();

    /// <summary>A new folder under the feed's root whose Directory.Build.props and Directory.Packages.props break any project that inherits them.</summary>
    private string TrappedFolder(string name)
    {
        string work = Directory.CreateDirectory(Path.Combine(feed.Root, "work-" + name)).FullName;
        File.WriteAllText(Path.Combine(work, "Directory.Build.props"), """
            <Project>
              <Target Name="NotTheLabs" BeforeTargets="Restore;CollectPackageReferences;Build">
                <Error Text="The lab inherited a Directory.Build.props from a folder above it." />
              </Target>
            </Project>
            """);
        File.WriteAllText(Path.Combine(work, "Directory.Packages.props"), """
            <Project>
              <PropertyGroup><ManagePackageVersionsCentrally>true</ManagePackageVersionsCentrally></PropertyGroup>
            </Project>
            """);
        return work;
    }

    /// <summary>No template symbol, conditional or unstamped version is left in the lab's files.</summary>
    private void AssertNoTemplateLeftovers(string lab)
    {
        Assert.Contains($"<RayLabVersion>{feed.Version}</RayLabVersion>", File.ReadAllText(Path.Combine(lab, "Directory.Build.props")), StringComparison.Ordinal);
        Assert.True(File.Exists(Path.Combine(lab, "tests", "Lab.Tests", "two-spheres.json")), "the checks' own scene is missing");
        Assert.False(Directory.Exists(Path.Combine(lab, "exercise")), "the template's exercise folder was copied as it is");
        foreach (string file in Directory.GetFiles(lab, "*", SearchOption.AllDirectories).Where(f => !IsBuildOutput(lab, f)))
        {
            string text = File.ReadAllText(file);
            Assert.DoesNotContain("0.0.0-raylab-version", text, StringComparison.Ordinal);
            Assert.DoesNotContain("RAYLAB_", text, StringComparison.Ordinal);
            Assert.DoesNotContain("#if (", text, StringComparison.Ordinal);
            Assert.DoesNotContain("MyMethod", text, StringComparison.Ordinal);
        }
    }
}
