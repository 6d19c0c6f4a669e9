using System.Globalization;
using System.IO.Compression;
using System.Text;
using System.Text.Json;
using RayLab.Cli;

namespace RayLab.Templates.Tests;

/// <summary>
/// The round through Moodle, end to end: an assignment's "Download all submissions" zip of three students (one folder
/// each, <c>Full Name_ID_assignsubmission_file_</c>, holding the zip of the lab the student uploaded; one of them a zip
/// with an entry that climbs out of its folder) graded by <c>raylab grade</c> in bubblewrap against the kit's method
/// checks with points per section, which fills the assignment's offline grading worksheet.
/// </summary>
[Trait("Category", "Templates")]
public sealed class MoodleGradingTests(ClassKit kit) : IClassFixture<ClassKit>
{
    private const string OnePoint = "private static readonly SamplePoint[] Points = [new(0.5, 0.5)];";

    private const string Grid5 = "private static readonly SamplePoint[] Points = [.. Enumerable.Range(0, 25).Select(i => new SamplePoint(((i % 5) + 0.5) / 5, ((i / 5) + 0.5) / 5))];";

    [Fact]
    public async Task GradingAMoodleDownloadOfThreeStudentsFillsTheGradingWorksheet()
    {
        string root = Directory.CreateDirectory(Path.Combine(kit.Root, "moodle")).FullName;
        string labs = Directory.CreateDirectory(Path.Combine(root, "labs")).FullName;
        string download = Directory.CreateDirectory(Path.Combine(root, "download")).FullName;

        // Zażółć Gęślą: the template as created, every section passes. Jan Kowalski: 25 points a pixel, past the
        // checks' limit, so the method's section fails. Ewa Nowak: a lab whose zip also holds ../../escaped.txt.
        string template = await kit.NewLabAsync(labs, "Lab_Gesla", restore: false);
        string sabotaged = await kit.NewLabAsync(labs, "Lab_Kowalski", restore: false);
        string path = Path.Combine(sabotaged, "src", "Lab", "MyMethod.cs");
        string text = File.ReadAllText(path);
        Assert.Contains(OnePoint, text, StringComparison.Ordinal);
        File.WriteAllText(path, text.Replace(OnePoint, Grid5, StringComparison.Ordinal));
        string climbing = await kit.NewLabAsync(labs, "Lab_Nowak", restore: false);

        // As the students upload them: a zip of the lab's folder.
        Upload(template, Path.Combine(download, "Zażółć Gęślą_101_assignsubmission_file_"), "lab.zip");
        Upload(sabotaged, Path.Combine(download, "Jan Kowalski_102_assignsubmission_file_"), "Lab_Kowalski.zip");
        string nowak = Directory.CreateDirectory(Path.Combine(download, "Ewa Nowak_103_assignsubmission_file_")).FullName;
        Upload(climbing, nowak, "lab.zip");
        using (ZipArchive zip = ZipFile.Open(Path.Combine(nowak, "lab.zip"), ZipArchiveMode.Update))
        {
            using var writer = new StreamWriter(zip.CreateEntry("../../escaped.txt").Open());
            writer.Write("outside");
        }

        // Moodle's own zip of the folders.
        string downloadZip = Path.Combine(root, "Grafika-Lab2-123.zip");
        ZipFile.CreateFromDirectory(download, downloadZip);

        // The checks with points per section: the method's is worth 5, every other 1.
        string checks = Path.Combine(root, "checks", "method");
        CopyFolder(Path.Combine(kit.Kit, "checks", "method"), checks);
        string[] sections = [.. Directory.GetFiles(Path.Combine(checks, "tests", "Lab.Tests"), "*Tests.cs").Select(f => Path.GetFileNameWithoutExtension(f)).Order(StringComparer.Ordinal)];
        Assert.Contains("MyMethodTests", sections);
        string grading = File.ReadAllText(Path.Combine(checks, "grading.json"));
        string points = string.Join(", ", sections.Select(s => $"\"{s}\": {(s == "MyMethodTests" ? 5 : 1)}"));
        File.WriteAllText(Path.Combine(checks, "grading.json"), grading.TrimEnd().TrimEnd('}').TrimEnd() + $",\n  \"points\": {{ {points} }}\n}}\n");
        int full = 5 + sections.Length - 1;

        // Moodle's worksheet: UTF-8 with a BOM, "\n", a student who sent nothing, a quoted cell with a comma and a line break.
        const string Header = "Identifier,Full name,Email address,Status,Grade,Maximum Grade,Grade can be changed,Last modified (submission),Last modified (grade),Feedback comments\n";
        const string Untouched = "Participant 104,Piotr Brak,piotr@example.edu,No submission,,10.00,Yes,-,-,\"Brak pracy, przypomnieć\npo zajęciach\"\n";
        string worksheet = Path.Combine(root, "Grafika-Lab2-123-grades.csv");
        File.WriteAllText(worksheet, Header
            + "Participant 101,Zażółć Gęślą,zg@example.edu,Submitted for grading,,10.00,Yes,\"Friday, 6 November 2026, 10:00 AM\",-,\n"
            + "Participant 102,Jan Kowalski,jk@example.edu,Submitted for grading,,10.00,Yes,\"Friday, 6 November 2026, 11:00 AM\",-,\n"
            + Untouched
            + "Participant 103,Ewa Nowak,en@example.edu,Submitted for grading,,10.00,Yes,\"Friday, 6 November 2026, 12:00 PM\",-,\n",
            new UTF8Encoding(encoderShouldEmitUTF8Identifier: true));

        string report = Path.Combine(root, "report");
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int exit = Program.Run(
            ["grade", downloadZip, "--checks", checks, "--feed", Path.Combine(kit.Kit, "feed"), "--out", report,
             "--moodle-worksheet", worksheet, "--check-timeout", "60", "--run-timeout", "60", "--submission-timeout", "300", "--jobs", "2"],
            stdout, stderr, TestContext.Current.CancellationToken);
        Assert.True(exit == 0, $"raylab grade exited {exit}:\n{stdout}\n{stderr}");
        string filled = Path.Combine(report, "moodle-worksheet.csv");
        TestContext.Current.TestOutputHelper?.WriteLine($"raylab grade:\n{stdout}\n{stderr}\n{filled}:\n{File.ReadAllText(filled)}");
        Assert.Contains($"wrote the Moodle grading worksheet {filled}", stdout.ToString(), StringComparison.Ordinal);
        // The worksheet says 10.00 is the assignment's maximum; the checks' points add up to another figure.
        Assert.Contains($"warning: --moodle-worksheet: the assignment's maximum grade is 10, the checks' full grade {full}", stdout.ToString(), StringComparison.Ordinal);

        // One row per student, by the full name; the refused zip's row says why and nothing of it was graded.
        using JsonDocument grades = JsonDocument.Parse(File.ReadAllText(Path.Combine(report, "grades.json")));
        Dictionary<string, JsonElement> rows = grades.RootElement.GetProperty("students").EnumerateArray().ToDictionary(r => r.GetProperty("name").GetString()!);
        Assert.Equal(["Ewa Nowak", "Jan Kowalski", "Zażółć Gęślą"], rows.Keys.Order(StringComparer.Ordinal));
        Assert.Equal(full, grades.RootElement.GetProperty("maxGrade").GetDouble());
        Assert.Equal("ok", rows["Zażółć Gęślą"].GetProperty("status").GetString());
        Assert.Equal(full, rows["Zażółć Gęślą"].GetProperty("grade").GetDouble());
        Assert.Equal("ok", rows["Jan Kowalski"].GetProperty("status").GetString());
        Assert.Equal("fail", rows["Jan Kowalski"].GetProperty("sections").GetProperty("MyMethodTests").GetString());
        Assert.Equal(full - 5, rows["Jan Kowalski"].GetProperty("grade").GetDouble());
        Assert.Equal("zip refused: lab.zip: entry ../../escaped.txt climbs out of the folder", rows["Ewa Nowak"].GetProperty("status").GetString());
        Assert.Equal(0, rows["Ewa Nowak"].GetProperty("grade").GetDouble());
        Assert.Empty(rows["Ewa Nowak"].GetProperty("checks").EnumerateArray());
        Assert.Equal("103", rows["Ewa Nowak"].GetProperty("moodleParticipant").GetString());
        Assert.False(File.Exists(Path.Combine(root, "escaped.txt")), "the climbing entry was written");

        // The worksheet: the same bytes but the graded rows' Grade and Feedback comments; BOM, header and the untouched row kept.
        byte[] bytes = File.ReadAllBytes(filled);
        Assert.Equal([0xEF, 0xBB, 0xBF], bytes[..3]);
        string written = Encoding.UTF8.GetString(bytes[3..]);
        Assert.StartsWith(Header, written, StringComparison.Ordinal);
        Assert.Contains(Untouched, written, StringComparison.Ordinal);
        Assert.DoesNotContain("\r\n", written, StringComparison.Ordinal);
        string Line(string participant) => written.Split('\n').Single(l => l.StartsWith($"Participant {participant},", StringComparison.Ordinal));
        Assert.StartsWith($"Participant 101,Zażółć Gęślą,zg@example.edu,Submitted for grading,{full.ToString(CultureInfo.InvariantCulture)}.00,10.00,", Line("101"), StringComparison.Ordinal);
        Assert.EndsWith(",-,Wszystkie sekcje zaliczone.", Line("101"), StringComparison.Ordinal);
        Assert.StartsWith($"Participant 102,Jan Kowalski,jk@example.edu,Submitted for grading,{(full - 5).ToString(CultureInfo.InvariantCulture)}.00,10.00,", Line("102"), StringComparison.Ordinal);
        // The failed section with its check's first message.
        Assert.Matches(@"Niezaliczone: MyMethodTests: \S", Line("102"));
        Assert.StartsWith("Participant 103,Ewa Nowak,en@example.edu,Submitted for grading,0.00,10.00,", Line("103"), StringComparison.Ordinal);
        Assert.EndsWith(",-,Archiwum odrzucone: lab.zip: wpis ../../escaped.txt wychodzi poza folder.", Line("103"), StringComparison.Ordinal);
    }

    /// <summary>The lab's folder zipped as a student uploads it (the folder itself at the top), into <paramref name="folder"/>.</summary>
    private static void Upload(string lab, string folder, string name)
    {
        Directory.CreateDirectory(folder);
        ZipFile.CreateFromDirectory(lab, Path.Combine(folder, name), CompressionLevel.Fastest, includeBaseDirectory: true);
    }

    private static void CopyFolder(string from, string to)
    {
        Directory.CreateDirectory(to);
        foreach (string file in Directory.GetFiles(from))
        {
            File.Copy(file, Path.Combine(to, Path.GetFileName(file)));
        }

        foreach (string folder in Directory.GetDirectories(from))
        {
            CopyFolder(folder, Path.Combine(to, Path.GetFileName(folder)));
        }
    }
}
