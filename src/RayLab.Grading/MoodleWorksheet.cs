using System.Globalization;
using System.Text;
using System.Text.RegularExpressions;

namespace RayLab.Grading;

/// <summary>A Moodle grading worksheet that cannot be read: the file and what is wrong, in one line.</summary>
public sealed class MoodleWorksheetException : Exception
{
    /// <summary>A bad worksheet.</summary>
    public MoodleWorksheetException()
        : base("not a Moodle grading worksheet")
    {
    }

    /// <summary>A bad worksheet.</summary>
    /// <param name="message">The file and what is wrong.</param>
    public MoodleWorksheetException(string message)
        : base(message)
    {
    }

    /// <summary>A bad worksheet, with the cause.</summary>
    /// <param name="message">The file and what is wrong.</param>
    /// <param name="innerException">The cause.</param>
    public MoodleWorksheetException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}

/// <summary>One student's grade and feedback for the worksheet.</summary>
/// <param name="Grade">The grade.</param>
/// <param name="Feedback">The feedback comment, one line.</param>
public sealed record WorksheetGrade(double Grade, string Feedback);

/// <summary>
/// A Moodle assignment's offline grading worksheet ("Download grading worksheet"): a CSV file in UTF-8, with or without
/// a byte order mark, whose header names the columns (<c>Identifier</c> with "Participant 12345", <c>Full name</c>,
/// <c>Grade</c>, <c>Feedback comments</c>, …) and whose quoted cells may hold commas, quotes and line breaks.
/// <see cref="Fill"/> writes the same bytes with the graded students' Grade and Feedback comments cells replaced, so
/// that "Upload grading worksheet" takes it unchanged.
/// </summary>
public sealed partial class MoodleWorksheet
{
    private static readonly string[] IdentifierNames = ["Identifier", "Identyfikator"];
    private static readonly string[] FullNameNames = ["Full name", "Imię i nazwisko", "Pełna nazwa"];
    private static readonly string[] GradeNames = ["Grade", "Ocena"];
    private static readonly string[] MaximumGradeNames = ["Maximum Grade", "Maksymalna ocena", "Ocena maksymalna"];
    private static readonly string[] FeedbackNames = ["Feedback comments", "Komentarz zwrotny", "Komentarze zwrotne", "Informacja zwrotna"];

    private readonly string _file;
    private readonly bool _bom;
    private readonly List<List<Cell>> _records;
    private readonly List<string> _ends;
    private readonly int _identifier;
    private readonly int _fullName;
    private readonly int _grade;
    private readonly int _feedback;
    private readonly string _newLine;
    private readonly char _decimal;

    private MoodleWorksheet(string file, bool bom, List<List<Cell>> records, List<string> ends)
    {
        _file = file;
        _bom = bom;
        _records = records;
        _ends = ends;
        string[] header = [.. records[0].Select(c => c.Value.Trim())];
        _identifier = Column(header, IdentifierNames, required: true);
        _fullName = Column(header, FullNameNames, required: false);
        _grade = Column(header, GradeNames, required: true);
        _feedback = Column(header, FeedbackNames, required: true);
        int maximum = Column(header, MaximumGradeNames, required: false);
        _newLine = ends.FirstOrDefault(e => e.Length > 0) ?? "\n";
        _decimal = maximum >= 0 && records.Skip(1).Any(r => maximum < r.Count && DecimalComma().IsMatch(r[maximum].Value)) ? ',' : '.';
        MaximumGrade = maximum < 0 ? null : records.Skip(1)
            .Select(r => maximum < r.Count && double.TryParse(r[maximum].Value.Trim().Replace(',', '.'), NumberStyles.Float, CultureInfo.InvariantCulture, out double m) ? m : (double?)null)
            .FirstOrDefault(m => m is not null);
    }

    /// <summary>The assignment's maximum grade, from the first row's <c>Maximum Grade</c> cell that holds a number, or null.</summary>
    public double? MaximumGrade { get; }

    /// <summary>Each row's participant id (the number of "Participant 12345") and full name, in the file's order.</summary>
    public IReadOnlyList<(string ParticipantId, string FullName)> Participants =>
        [.. _records.Skip(1).Where(r => _identifier < r.Count && ParticipantNumber().IsMatch(r[_identifier].Value))
            .Select(r => (ParticipantNumber().Match(r[_identifier].Value).Groups[1].Value, _fullName >= 0 && _fullName < r.Count ? r[_fullName].Value : ""))];

    /// <summary>Reads a worksheet.</summary>
    /// <param name="file">The CSV file.</param>
    /// <returns>The worksheet.</returns>
    /// <exception cref="ArgumentException">An empty path.</exception>
    /// <exception cref="MoodleWorksheetException">Not UTF-8, a quote left open, or a header without Identifier, Grade or Feedback comments.</exception>
    /// <exception cref="IOException">The file cannot be read.</exception>
    public static MoodleWorksheet Read(string file)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(file);
        return Parse(File.ReadAllBytes(file), file);
    }

    /// <summary>Reads a worksheet's bytes.</summary>
    /// <param name="bytes">The file's bytes.</param>
    /// <param name="file">The file's name, for the errors.</param>
    /// <returns>The worksheet.</returns>
    /// <exception cref="MoodleWorksheetException">Not UTF-8, a quote left open, or a header without Identifier, Grade or Feedback comments.</exception>
    // Long: one RFC 4180 reader that keeps each row's exact bytes (quotes, line ends, BOM) beside its cells, so unchanged rows are written back as read.
    public static MoodleWorksheet Parse(byte[] bytes, string file)
    {
        ArgumentNullException.ThrowIfNull(bytes);
        ArgumentException.ThrowIfNullOrWhiteSpace(file);
        bool bom = bytes.Length >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF;
        string text;
        try
        {
            text = new UTF8Encoding(false, throwOnInvalidBytes: true).GetString(bytes, bom ? 3 : 0, bytes.Length - (bom ? 3 : 0));
        }
        catch (DecoderFallbackException)
        {
            throw new MoodleWorksheetException($"{file}: not UTF-8; download the worksheet from Moodle again, unchanged");
        }

        var records = new List<List<Cell>>();
        var ends = new List<string>();
        int i = 0;
        int line = 1;
        while (i < text.Length)
        {
            var record = new List<Cell>();
            while (true)
            {
                int start = i;
                var value = new StringBuilder();
                if (i < text.Length && text[i] == '"')
                {
                    int opened = line;
                    i++;
                    while (true)
                    {
                        if (i >= text.Length)
                        {
                            throw new MoodleWorksheetException($"{file}: line {opened}: a quoted cell is never closed");
                        }

                        if (text[i] == '"')
                        {
                            if (i + 1 < text.Length && text[i + 1] == '"')
                            {
                                value.Append('"');
                                i += 2;
                                continue;
                            }

                            i++;
                            break;
                        }

                        line += text[i] == '\n' ? 1 : 0;
                        value.Append(text[i++]);
                    }

                    // Anything up to the separator after a closing quote belongs to the cell, as spreadsheets read it.
                    while (i < text.Length && text[i] is not ',' and not '\r' and not '\n')
                    {
                        value.Append(text[i++]);
                    }
                }
                else
                {
                    while (i < text.Length && text[i] is not ',' and not '\r' and not '\n')
                    {
                        value.Append(text[i++]);
                    }
                }

                record.Add(new Cell(value.ToString(), text[start..i]));
                if (i < text.Length && text[i] == ',')
                {
                    i++;
                    continue;
                }

                break;
            }

            string end = i >= text.Length ? "" : text[i] == '\r' && i + 1 < text.Length && text[i + 1] == '\n' ? "\r\n" : text[i].ToString();
            i += end.Length;
            line++;
            records.Add(record);
            ends.Add(end);
        }

        if (records.Count == 0)
        {
            throw new MoodleWorksheetException($"{file}: the file is empty; download the grading worksheet from Moodle");
        }

        return new MoodleWorksheet(file, bom, records, ends);
    }

    /// <summary>
    /// The worksheet with the Grade and Feedback comments cells of the students in <paramref name="grades"/> replaced
    /// (by participant id), every other byte as read: the byte order mark or its absence, the line endings, the other
    /// rows and cells. A grade is written with two decimals, with the decimal comma where the file's maximum grades use one.
    /// </summary>
    /// <param name="grades">Each graded student's grade and feedback, by participant id.</param>
    /// <returns>The new file's bytes.</returns>
    public byte[] Fill(IReadOnlyDictionary<string, WorksheetGrade> grades)
    {
        ArgumentNullException.ThrowIfNull(grades);
        var text = new StringBuilder();
        for (int r = 0; r < _records.Count; r++)
        {
            List<Cell> record = _records[r];
            WorksheetGrade? grade = null;
            if (r > 0 && _identifier < record.Count && ParticipantNumber().Match(record[_identifier].Value) is { Success: true } m)
            {
                grades.TryGetValue(m.Groups[1].Value, out grade);
            }

            for (int c = 0; c < Math.Max(record.Count, grade is null ? 0 : Math.Max(_grade, _feedback) + 1); c++)
            {
                if (c > 0)
                {
                    text.Append(',');
                }

                text.Append(grade is not null && c == _grade ? Quote(FormatGrade(grade.Grade))
                    : grade is not null && c == _feedback ? Quote(grade.Feedback)
                    : c < record.Count ? record[c].Raw : "");
            }

            text.Append(_ends[r].Length > 0 || r == _records.Count - 1 ? _ends[r] : _newLine);
        }

        byte[] body = new UTF8Encoding(false).GetBytes(text.ToString());
        return _bom ? [0xEF, 0xBB, 0xBF, .. body] : body;
    }

    /// <summary>The participant id of the row whose full name is <paramref name="fullName"/>, where exactly one row has it.</summary>
    /// <param name="fullName">The student's full name.</param>
    /// <returns>The participant id, or null.</returns>
    public string? ParticipantOf(string fullName)
    {
        ArgumentNullException.ThrowIfNull(fullName);
        string[] ids = [.. Participants.Where(p => p.FullName == fullName).Select(p => p.ParticipantId)];
        return ids.Length == 1 ? ids[0] : null;
    }

    private string FormatGrade(double grade)
    {
        string text = grade.ToString("F2", CultureInfo.InvariantCulture);
        return _decimal == ',' ? text.Replace('.', ',') : text;
    }

    private int Column(string[] header, string[] names, bool required)
    {
        int index = Array.FindIndex(header, h => names.Contains(h, StringComparer.OrdinalIgnoreCase));
        if (index < 0 && required)
        {
            throw new MoodleWorksheetException($"{_file}: no column '{names[0]}' in the header ({string.Join(", ", header)}); give the assignment's grading worksheet as Moodle writes it");
        }

        return index;
    }

    private static string Quote(string cell)
    {
        string one = string.Join(' ', cell.Split(['\r', '\n'], StringSplitOptions.RemoveEmptyEntries));
        return one.IndexOfAny([',', '"']) >= 0 || one.StartsWith(' ') || one.EndsWith(' ')
            ? $"\"{one.Replace("\"", "\"\"", StringComparison.Ordinal)}\""
            : one;
    }

    [GeneratedRegex(@"^\s*\D*?([0-9]+)\s*$", RegexOptions.CultureInvariant)]
    private static partial Regex ParticipantNumber();

    [GeneratedRegex(@"^\s*[0-9]+,[0-9]+\s*$", RegexOptions.CultureInvariant)]
    private static partial Regex DecimalComma();

    /// <summary>A cell: its value, and its text as the file has it (quotes and all).</summary>
    private readonly record struct Cell(string Value, string Raw);
}
