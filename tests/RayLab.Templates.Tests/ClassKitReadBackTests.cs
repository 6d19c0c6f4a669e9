using System.Text;
using System.Text.Json;
using RayLab.Reports.Imaging;
using RayLab.Scenes;

namespace RayLab.Templates.Tests;

/// <summary>
/// What <c>raylab grade</c> reads back from a lab's copy after the lab's program ran (its pictures, its lines, its
/// output), read as the lab's own and untrusted: graded in one run against the kit's method checks.
/// </summary>
public sealed partial class ClassKitTests
{
    private const string LastLine = "Console.WriteLine(\"wrote out/obrazkoncowy.jpg\");";

    [Fact]
    public async Task WhatTheGraderReadsBackFromALabIsTheLabsOwnAndUntrusted()
    {
        string submissions = Directory.CreateDirectory(Path.Combine(kit.Root, "readback-submissions")).FullName;
        SceneDescription scene = SceneFile.Load(Path.Combine(kit.Kit, "checks", "method", "scenes", "two-spheres.json"));

        // A file beside the submissions, outside every lab: a picture of the scene's size, which a grader that follows
        // links would score and copy into the report.
        string outside = Path.Combine(kit.Root, "readback-outside.png");
        var secret = new Image(scene.Width, scene.Height);
        for (int y = 0; y < scene.Height; y++)
        {
            for (int x = 0; x < scene.Width; x++)
            {
                secret.GetRowSpan(y)[x] = new Rgb24((byte)x, (byte)y, 77);
            }
        }

        secret.Save(outside);

        // Its program renders, then makes its pictures links out of its copy: the perspective one to the file outside,
        // the orthographic one (relative) to where today's grader keeps its own exact picture.
        string linked = await kit.NewLabAsync(submissions, "linked", restore: false);
        Edit(linked, "src/Lab/Program.cs", LastLine, LastLine + $$"""

                    File.Delete("out/two-spheres-perspective-mymethod.png");
                    File.CreateSymbolicLink("out/two-spheres-perspective-mymethod.png", @"{{outside}}");
                    File.Delete("out/two-spheres-orthographic-mymethod.png");
                    File.CreateSymbolicLink("out/two-spheres-orthographic-mymethod.png", "../../../report/exact/orthographic.png");
            """);

        // Its pictures are PNG files of a few bytes that claim 100000×100000 and 20000×20000 pixels (the second within
        // what RayLab's reader takes, 1.6 GB of pixels).
        string huge = await kit.NewLabAsync(submissions, "huge", restore: false);
        File.WriteAllBytes(Path.Combine(huge, "claim-100000.png"), ClaimingPng.Of(100_000, 100_000));
        File.WriteAllBytes(Path.Combine(huge, "claim-20000.png"), ClaimingPng.Of(20_000, 20_000));
        Edit(huge, "src/Lab/Program.cs", LastLine, LastLine + """

                    bool? optimised = !System.Reflection.CustomAttributeExtensions.GetCustomAttribute<System.Diagnostics.DebuggableAttribute>(typeof(Program).Assembly)?.IsJITOptimizerDisabled;
                    Console.WriteLine($"JIT-optimised: {optimised ?? true}");
                    File.Copy("claim-100000.png", "out/two-spheres-perspective-mymethod.png", overwrite: true);
                    File.Copy("claim-20000.png", "out/two-spheres-orthographic-mymethod.png", overwrite: true);
            """);

        // A name that is a spreadsheet formula; its program starts with an error line that is a formula too (the first
        // error line, the row's detail), renders, waits 2 s, prints render lines that claim 0.001 ms, and fails.
        const string formula = "=HYPERLINK(\"https:evil.example\",\"click\")"; // a folder's name: no slash
        string liar = await kit.NewLabAsync(submissions, "liar", restore: false);
        Edit(liar, "src/Lab/Program.cs", LastLine, LastLine + """

                    Thread.Sleep(2000);
                    Console.WriteLine("orthographic mymethod    480,000 rays ( 1.00 per pixel)      0.001 ms");
                    Console.WriteLine("perspective  mymethod    480,000 rays ( 1.00 per pixel)      0.001 ms");
                    Environment.Exit(3);
            """);
        Edit(liar, "src/Lab/Program.cs", "SceneDescription file = TwoSpheres.Load();", """
            Console.Error.WriteLine("=HYPERLINK(\"https:evil.example\",\"click\") error: the lab's own words");
                    SceneDescription file = TwoSpheres.Load();
            """);
        Directory.Move(liar, Path.Combine(submissions, formula));

        string report = Path.Combine(kit.Root, "readback-report");
        using JsonDocument grades = Grade(submissions, "method", report, checkTimeout: 60, runTimeout: 60, jobs: 2);
        Dictionary<string, JsonElement> rows = Rows(grades);
        Assert.Equal([formula, "huge", "linked"], rows.Keys.Order(StringComparer.Ordinal));

        // The links: refused, whatever they point at, and nothing of the file outside is in the report.
        Assert.Equal("picture is a link", rows["linked"].GetProperty("status").GetString());
        foreach (string camera in (string[])["orthographic", "perspective"])
        {
            Assert.Contains("link", rows["linked"].GetProperty("pictures").GetProperty(camera).GetProperty("problem").GetString(), StringComparison.Ordinal);
        }

        byte[] outsideBytes = File.ReadAllBytes(outside);
        foreach (string file in Directory.EnumerateFiles(report, "*", SearchOption.AllDirectories))
        {
            byte[] bytes = File.ReadAllBytes(file);
            Assert.False(bytes.AsSpan().SequenceEqual(outsideBytes), $"{file} is a copy of the file outside the lab");
            if (file.EndsWith(".png", StringComparison.Ordinal))
            {
                Assert.False(Image.Load(file).PixelBytes.SequenceEqual(secret.PixelBytes), $"{file} holds the pixels of the file outside the lab");
            }
        }

        // The claims: refused from the header, before any pixel, with the size they claim.
        Assert.Equal("picture too large", rows["huge"].GetProperty("status").GetString());
        Assert.Contains("100000×100000", rows["huge"].GetProperty("pictures").GetProperty("perspective").GetProperty("problem").GetString(), StringComparison.Ordinal);
        Assert.Contains("20000×20000", rows["huge"].GetProperty("pictures").GetProperty("orthographic").GetProperty("problem").GetString(), StringComparison.Ordinal);

        // The grader built the lab's program with optimisations (a debug build's program says False).
        Assert.Contains("JIT-optimised: True", File.ReadAllText(Path.Combine(report, "students", "huge", "log.txt")), StringComparison.Ordinal);

        // The times are the grader's: its clock around the program, which waited 2 s; none of the lab's "0.001 ms".
        JsonElement program = rows[formula].GetProperty("program");
        Assert.Equal($"program failed (exit 3)", rows[formula].GetProperty("status").GetString());
        Assert.True(program.GetProperty("seconds").GetDouble() >= 2, $"the program, which waited 2 s, took {program.GetProperty("seconds").GetDouble()} s by the grader's clock");
        Assert.Contains("grader", program.GetProperty("timedBy").GetString(), StringComparison.Ordinal);
        Assert.DoesNotContain("0.001", File.ReadAllText(Path.Combine(report, "grades.json")), StringComparison.Ordinal);
        Assert.DoesNotContain("0.001", File.ReadAllText(Path.Combine(report, "grades.csv")), StringComparison.Ordinal);
        Assert.StartsWith(formula, rows[formula].GetProperty("detail").GetString(), StringComparison.Ordinal);

        // The CSV: every cell the lab wrote that a spreadsheet would take for a formula starts with ' instead.
        string[][] csv = [.. ReadCsv(File.ReadAllText(Path.Combine(report, "grades.csv")))];
        string[] formulaCells = [.. csv.SelectMany(r => r).Where(c => c.Contains("HYPERLINK", StringComparison.Ordinal))];
        Assert.Equal(["'" + formula, "'" + rows[formula].GetProperty("detail").GetString()], formulaCells);
        Assert.All(csv.SelectMany(r => r), c => Assert.False(c.Length > 0 && "=+-@\t\r".Contains(c[0], StringComparison.Ordinal), $"a cell starts with a formula's character: {c}"));
    }

    /// <summary>The cells of a CSV text (RFC 4180: quoted cells may hold commas, quotes doubled, line breaks).</summary>
    private static IEnumerable<string[]> ReadCsv(string text)
    {
        var row = new List<string>();
        var cell = new StringBuilder();
        bool quoted = false;
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            if (quoted)
            {
                if (c == '"' && i + 1 < text.Length && text[i + 1] == '"')
                {
                    cell.Append('"');
                    i++;
                }
                else if (c == '"')
                {
                    quoted = false;
                }
                else
                {
                    cell.Append(c);
                }
            }
            else if (c == '"')
            {
                quoted = true;
            }
            else if (c == ',')
            {
                row.Add(cell.ToString());
                cell.Clear();
            }
            else if (c == '\n')
            {
                row.Add(cell.ToString().TrimEnd('\r'));
                cell.Clear();
                yield return [.. row];
                row.Clear();
            }
            else
            {
                cell.Append(c);
            }
        }

        if (cell.Length > 0 || row.Count > 0)
        {
            row.Add(cell.ToString());
            yield return [.. row];
        }
    }
}
