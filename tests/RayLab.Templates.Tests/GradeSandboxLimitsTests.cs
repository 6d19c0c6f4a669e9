using System.Text.Json;
using RayLab.Cli;

namespace RayLab.Templates.Tests;

/// <summary>
/// <c>raylab grade</c> against labs that attack the grading machine from their program: one that searches the home
/// folders, the system's temporary folder and the kit for the reference solution, one that allocates native memory
/// past the memory limit, a fork loop, and one that fills its disk. Each gets the row that says which limit stopped
/// it, and the one that searches finds nothing.
/// </summary>
[Trait("Category", "Templates")]
public sealed class GradeSandboxLimitsTests(ClassKit kit) : IClassFixture<ClassKit>
{
    private const string ProgramStart = "SceneDescription file = TwoSpheres.Load();";

    [Fact]
    public async Task LabsThatReadOutsideTheirCopyAllocateNativeMemoryForkOrFillTheDiskEachGetTheRowOfTheLimitThatStoppedThem()
    {
        string submissions = Directory.CreateDirectory(Path.Combine(kit.Root, "limits-submissions")).FullName;

        // Searches the home folders, /tmp and the kit (by its path, as a student who knows where the instructor keeps
        // it would) for the exercise lab's reference camera, and prints what it finds.
        string reader = await kit.NewLabAsync(submissions, "reader", restore: false);
        Edit(reader, "src/Lab/Program.cs", ProgramStart, $$"""
            foreach (string root in new[] { "/root", "/home", "/tmp", "/work", {{JsonSerializer.Serialize(kit.Kit)}} })
                    {
                        try
                        {
                            foreach (string found in Directory.EnumerateFiles(root, "LabOrthoCamera.cs", new EnumerationOptions { RecurseSubdirectories = true, IgnoreInaccessible = true }))
                            {
                                Console.WriteLine("FOUND " + found + ": " + File.ReadAllLines(found).Length + " lines");
                            }
                        }
                        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                        {
                            Console.WriteLine("cannot search " + root + ": " + e.GetType().Name);
                        }
                    }

                    Console.WriteLine("searched");
                    {{ProgramStart}}
            """);

        // Native memory, 64 MB at a time and every page touched, up to 1.5 GB: past the limit of 512 MB.
        string native = await kit.NewLabAsync(submissions, "native", restore: false);
        Edit(native, "src/Lab/Program.cs", ProgramStart, $$"""
            for (int chunk = 0; chunk < 24; chunk++)
                    {
                        IntPtr block = System.Runtime.InteropServices.Marshal.AllocHGlobal(1 << 26);
                        for (int at = 0; at < 1 << 26; at += 4096)
                        {
                            System.Runtime.InteropServices.Marshal.WriteByte(block, at, 1);
                        }
                    }

                    Console.WriteLine("allocated 1536 MB of native memory");
                    {{ProgramStart}}
            """);

        // A fork loop: 3000 processes that sleep, past the process limit of 1024.
        string forks = await kit.NewLabAsync(submissions, "forks", restore: false);
        Edit(forks, "src/Lab/Program.cs", ProgramStart, $$"""
            for (int i = 0; i < 3000; i++)
                    {
                        Process.Start("sleep", "600");
                    }

                    Console.WriteLine("started 3000 processes");
                    {{ProgramStart}}
            """);

        // Fills its copy: 2 GB in one file, past the disk limit of 1024 MB.
        string filler = await kit.NewLabAsync(submissions, "filler", restore: false);
        Edit(filler, "src/Lab/Program.cs", ProgramStart, $$"""
            using (FileStream fill = File.Create("fill.bin"))
                    {
                        byte[] block = new byte[1 << 24];
                        Array.Fill(block, (byte)1);
                        for (int i = 0; i < 128; i++)
                        {
                            fill.Write(block);
                        }
                    }

                    Console.WriteLine("wrote 2048 MB");
                    {{ProgramStart}}
            """);

        string report = Path.Combine(kit.Root, "limits-report");
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int exit = Program.Run(
            ["grade", submissions, "--checks", Path.Combine(kit.Kit, "checks", "method"), "--out", report,
             "--check-timeout", "60", "--run-timeout", "120", "--submission-timeout", "400", "--jobs", "2", "--memory-limit", "512"],
            stdout, stderr, TestContext.Current.CancellationToken);
        TestContext.Current.TestOutputHelper?.WriteLine($"raylab grade:\n{stdout}\n{stderr}");
        Assert.True(exit == 0, $"raylab grade exited {exit}:\n{stdout}\n{stderr}");
        using JsonDocument grades = JsonDocument.Parse(File.ReadAllText(Path.Combine(report, "grades.json")));
        Assert.True(grades.RootElement.GetProperty("sandboxed").GetBoolean());
        Dictionary<string, JsonElement> rows = grades.RootElement.GetProperty("students").EnumerateArray().ToDictionary(r => r.GetProperty("name").GetString()!);
        string Status(string name) => rows[name].GetProperty("status").GetString()!;

        // The search ran, and found nothing: not the kit's reference solution, not anything in a home folder.
        string readerLog = File.ReadAllText(Path.Combine(report, "students", "reader", "log.txt"));
        Assert.Contains("searched", readerLog, StringComparison.Ordinal);
        Assert.DoesNotContain("FOUND ", readerLog, StringComparison.Ordinal);
        Assert.Equal("ok", Status("reader"));

        Assert.StartsWith("program memory limit", Status("native"), StringComparison.Ordinal);
        Assert.DoesNotContain("allocated 1536 MB", File.ReadAllText(Path.Combine(report, "students", "native", "log.txt")), StringComparison.Ordinal);
        Assert.StartsWith("program process limit", Status("forks"), StringComparison.Ordinal);
        Assert.StartsWith("program disk limit", Status("filler"), StringComparison.Ordinal);
        Assert.DoesNotContain("wrote 2048 MB", File.ReadAllText(Path.Combine(report, "students", "filler", "log.txt")), StringComparison.Ordinal);

        // The grader names the mechanism of each limit.
        foreach (string limit in (string[])["memory limit: ", "process limit: ", "disk limit: ", "CPU time limit: "])
        {
            Assert.Contains(limit, stdout.ToString(), StringComparison.Ordinal);
        }

        // Their builds and checks ran within the limits: every section passes for each.
        string[] sections = [.. grades.RootElement.GetProperty("sections").EnumerateArray().Select(s => s.GetString()!)];
        foreach (JsonElement row in rows.Values)
        {
            Assert.All(sections, s => Assert.Equal("pass", row.GetProperty("sections").GetProperty(s).GetString()));
        }
    }

    private static void Edit(string lab, string file, string find, string replace)
    {
        string path = Path.Combine(lab, file);
        string text = File.ReadAllText(path);
        Assert.Contains(find, text, StringComparison.Ordinal);
        File.WriteAllText(path, text.Replace(find, replace, StringComparison.Ordinal));
    }
}
