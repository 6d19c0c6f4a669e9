using System.Globalization;

namespace RayLab.Grading;

/// <summary>
/// <c>raylab grade</c>'s marks: a refused upload's row, the failed checks' messages, each row's grade from grading.json's
/// points (<see cref="GradingScheme"/>), and Moodle's grading worksheet filled with the grades and Polish feedback.
/// </summary>
internal static class GradeMarks
{
    /// <summary>The name of the filled worksheet in the report folder.</summary>
    public const string WorksheetFile = "moodle-worksheet.csv";

    /// <summary>The row of a submission whose upload was refused: its status says why, its log too; nothing of it is built.</summary>
    public static GradedLab Refused(UploadedLab upload, StudentRow row, string staging)
    {
        string folder = Path.Combine(staging, "students", row.Folder);
        Directory.CreateDirectory(folder);
        string log = Path.Combine(folder, "log.txt");
        row.Problems.Add(upload.Refusal!);
        row.PolishRefusal = upload.PolishRefusal;
        File.WriteAllText(log, upload.Refusal + "\n");
        return new GradedLab(row, "", log, folder);
    }

    /// <summary>The row's grade: the points of its sections that pass and of its pictures within the thresholds.</summary>
    public static double Grade(GradeSetup setup, StudentRow row, IEnumerable<string> sections, IEnumerable<string> cameras) =>
        setup.Scheme.Grade(
            sections.Distinct(StringComparer.Ordinal).ToDictionary(s => s, row.Section, StringComparer.Ordinal),
            cameras.Select(c => row.Pictures.TryGetValue(c, out PictureScore? p) && p.Problem is null ? (p.Rmse, p.Flip) : (double.NaN, double.NaN)));

    /// <summary>The full grade: every section's points and every picture's.</summary>
    public static double MaxGrade(GradeSetup setup, IEnumerable<string> sections, IReadOnlyCollection<string> cameras) =>
        setup.Scheme.MaxGrade(sections, cameras.Count);

    /// <summary>A warning for each section grading.json's points name that no check of any submission has (a typo, or a section the checks lack).</summary>
    public static IEnumerable<string> UnknownSections(GradeSetup setup, IReadOnlyList<StudentRow> rows)
    {
        if (setup.Scheme.SectionPoints is not { } points || rows.All(r => r.Checks.Count == 0))
        {
            yield break;
        }

        var sections = rows.SelectMany(r => r.Checks.Keys).Select(GradeJob.SectionOf).ToHashSet(StringComparer.Ordinal);
        foreach (string section in points.Keys.Where(s => !sections.Contains(s)))
        {
            yield return $"warning: grading.json: points.{section}: no check has this section; its points count in the full grade only";
        }
    }

    /// <summary>The student's feedback in Polish: what stopped the grading, then each section that did not pass with its first message.</summary>
    public static string Feedback(StudentRow row, IEnumerable<string> sections)
    {
        var failed = new List<FailedSection>();
        foreach (string section in sections)
        {
            string result = row.Section(section);
            if (result is "" or "pass")
            {
                continue;
            }

            if (result == "not written")
            {
                failed.Add(new FailedSection(section, "jeszcze do napisania"));
                continue;
            }

            // A section refused for what it uses may have every check passed: its message is the use, in the row.
            (string display, string outcome) = row.Checks.FirstOrDefault(c => GradeJob.SectionOf(c.Key) == section && c.Value is not "Passed" and not "Skipped");
            failed.Add(new FailedSection(section, display is null ? null : row.Messages.GetValueOrDefault(display) ?? outcome switch
            {
                "Timeout" => "test przekroczył limit czasu",
                "Crashed" => "test przerwał proces testów",
                "NotRun" => "test nie został uruchomiony",
                _ => null,
            }));
        }

        return MoodleFeedback.Polish(row.Problems, row.PolishRefusal, failed);
    }

    /// <summary>
    /// Fills the worksheet of <c>--moodle-worksheet</c>, when given, into the staging folder: each graded student's Grade
    /// and Feedback comments, found by participant id (a Moodle download) or by full name; a student it lacks gets a
    /// warning line.
    /// </summary>
    /// <returns>The file's name in the report, or null without a worksheet.</returns>
    public static string? WriteWorksheet(string staging, GradeSetup setup, IReadOnlyList<StudentRow> rows, TextWriter stdout)
    {
        if (setup.Worksheet is not { } worksheet)
        {
            return null;
        }

        string[] sections = [.. rows.SelectMany(r => r.Checks.Keys).Select(GradeJob.SectionOf).Distinct().Order(GradeReport.SectionOrder.Instance)];
        var known = worksheet.Participants.Select(p => p.ParticipantId).ToHashSet(StringComparer.Ordinal);
        var grades = new Dictionary<string, WorksheetGrade>(StringComparer.Ordinal);
        foreach (StudentRow row in rows)
        {
            string? id = row.ParticipantId ?? worksheet.ParticipantOf(row.Name);
            if (id is null || !known.Contains(id))
            {
                stdout.WriteLine($"warning: --moodle-worksheet: {row.Name}{(row.ParticipantId is null ? "" : $" (participant {row.ParticipantId})")} is not in the worksheet; their grade is only in the report");
                continue;
            }

            grades[id] = new WorksheetGrade(row.Grade, Feedback(row, sections));
        }

        double full = MaxGrade(setup, sections, setup.Pictures.Keys);
        if (worksheet.MaximumGrade is double maximum && Math.Abs(maximum - full) > 1e-9)
        {
            stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"warning: --moodle-worksheet: the assignment's maximum grade is {maximum:0.##}, the checks' full grade {full:0.##}; make them agree in Moodle or in grading.json's points"));
        }

        File.WriteAllBytes(Path.Combine(staging, WorksheetFile), worksheet.Fill(grades));
        return WorksheetFile;
    }
}
