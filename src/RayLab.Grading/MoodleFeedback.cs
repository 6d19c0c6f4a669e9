using System.Text.RegularExpressions;

namespace RayLab.Grading;

/// <summary>A failed section of a submission and the first message of its first check that did not pass.</summary>
/// <param name="Section">The section (<c>3.1</c>, or a check class's name).</param>
/// <param name="Message">The message, or null where the check left none.</param>
public sealed record FailedSection(string Section, string? Message);

/// <summary>
/// The feedback comment a student reads in Moodle, in Polish and on one line: what stopped the grading (the row's
/// problems), then each section that did not pass with its first message, or that every section passed.
/// </summary>
public static partial class MoodleFeedback
{
    /// <summary>The longest a section's message may be in the comment; longer ones end with "…".</summary>
    public const int MaxMessageLength = 200;

    /// <summary>The row's problems as <c>raylab grade</c> writes them, in Polish.</summary>
    private static readonly Dictionary<string, string> Problems = new(StringComparer.Ordinal)
    {
        ["no lab"] = "nie znaleziono laboratorium (src/Lab/*.csproj)",
        ["does not build"] = "projekt się nie kompiluje",
        ["build time limit"] = "kompilacja przekroczyła limit czasu",
        ["submission time limit"] = "ocena przekroczyła limit czasu zgłoszenia",
        ["program time limit"] = "program przekroczył limit czasu",
        ["check time limit"] = "test przekroczył limit czasu",
        ["check memory limit"] = "test przekroczył limit pamięci",
        ["program memory limit"] = "program przekroczył limit pamięci",
        ["pictures missing"] = "brak obrazów",
        ["checks did not run"] = "testy się nie uruchomiły",
    };

    /// <summary>The comment.</summary>
    /// <param name="problems">The row's problems (English, as the report has them); a refused upload's reason is given in Polish by <paramref name="refusal"/>.</param>
    /// <param name="refusal">Why the upload was refused, in Polish, or null.</param>
    /// <param name="failed">The sections that did not pass, in the report's order.</param>
    /// <returns>One line.</returns>
    public static string Polish(IEnumerable<string> problems, string? refusal, IEnumerable<FailedSection> failed)
    {
        ArgumentNullException.ThrowIfNull(problems);
        ArgumentNullException.ThrowIfNull(failed);
        var parts = new List<string>();
        if (refusal is not null)
        {
            parts.Add(OneLine(refusal));
        }
        else
        {
            string[] said = [.. problems.Distinct(StringComparer.Ordinal).Select(Problem)];
            if (said.Length > 0)
            {
                parts.Add(Capital(string.Join("; ", said)));
            }
        }

        FailedSection[] sections = [.. failed];
        if (sections.Length > 0)
        {
            parts.Add("Niezaliczone: " + string.Join("; ", sections.Select(s => s.Message is { Length: > 0 } m ? $"{s.Section}: {Short(OneLine(m))}" : s.Section)));
        }
        else if (refusal is null && parts.Count == 0)
        {
            parts.Add("Wszystkie sekcje zaliczone");
        }

        return string.Join(". ", parts.Select(p => p.TrimEnd('.'))) + ".";
    }

    /// <summary>A problem in Polish: the known ones translated, "program failed (exit N)" too, any other as it is.</summary>
    private static string Problem(string problem)
    {
        if (Problems.TryGetValue(problem, out string? polish))
        {
            return polish;
        }

        Match m = ProgramFailed().Match(problem);
        return m.Success ? $"program zakończył się błędem (kod {m.Groups[1].Value})" : problem;
    }

    private static string Capital(string text) => text.Length == 0 ? text : char.ToUpperInvariant(text[0]) + text[1..];

    private static string Short(string text) => text.Length <= MaxMessageLength ? text : text[..(MaxMessageLength - 1)].TrimEnd() + "…";

    private static string OneLine(string text) => Whitespace().Replace(text, " ").Trim();

    [GeneratedRegex(@"\s+")]
    private static partial Regex Whitespace();

    [GeneratedRegex(@"^program failed \(exit (-?[0-9]+)\)$", RegexOptions.CultureInvariant)]
    private static partial Regex ProgramFailed();
}
