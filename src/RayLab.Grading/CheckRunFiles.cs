using System.Xml;
using System.Xml.Linq;

namespace RayLab.Grading;

/// <summary>A check's result in a TRX file: its display name, its outcome, and its failure message's first line.</summary>
/// <param name="Display">The check's display name (the TRX's <c>testName</c>).</param>
/// <param name="Outcome">The TRX's outcome: <c>Passed</c>, <c>Failed</c>, <c>NotExecuted</c> (a skipped check), …; <c>Failed</c> where none is given.</param>
/// <param name="Message">The first non-empty line of its error message, or null for none.</param>
public sealed record CheckResult(string Display, string Outcome, string? Message)
{
    /// <summary>
    /// What the outcome counts as: <c>Passed</c>; <c>Skipped</c> for the TRX's <c>NotExecuted</c> (a check skipped, as
    /// the exercise lab's checks skip a section still to write); <c>Failed</c> for any other outcome.
    /// </summary>
    public string Result => Outcome switch
    {
        "Passed" => "Passed",
        "NotExecuted" => "Skipped",
        _ => "Failed",
    };
}

/// <summary>A check the test platform's blame data collector saw start and not finish: the test host hung or crashed in it.</summary>
/// <param name="FullName">Its fully qualified name, for a <c>--filter</c> that leaves it out of the next run.</param>
/// <param name="Display">Its display name.</param>
public sealed record UnfinishedCheck(string FullName, string Display);

/// <summary>
/// What a run of the checks leaves in its results folder, read as untrusted: the TRX file the test platform writes
/// (<c>--logger trx</c>) and the blame data collector's <c>Sequence_*.xml</c> files. A file larger than
/// <see cref="MaxBytes"/>, a link, or one that is not XML reads as holding nothing; no DTD is processed.
/// </summary>
public static class CheckRunFiles
{
    /// <summary>The largest file read: 64 MiB (a TRX holds each check's output, which the lab's code can fill).</summary>
    public const long MaxBytes = 64L << 20;

    /// <summary>The checks' results in a TRX file, in the file's order.</summary>
    /// <param name="trx">The TRX file.</param>
    /// <returns>Each result; none where the file is missing, a link, too large or not XML.</returns>
    public static IReadOnlyList<CheckResult> Results(string trx)
    {
        ArgumentException.ThrowIfNullOrEmpty(trx);
        var results = new List<CheckResult>();
        foreach (XElement result in Elements(trx).Where(e => e.Name.LocalName == "UnitTestResult"))
        {
            if (result.Attribute("testName")?.Value is { } display)
            {
                string? message = result.Descendants().FirstOrDefault(e => e.Name.LocalName == "Message")?.Value;
                string? first = message?.Split('\n').Select(l => l.Trim()).FirstOrDefault(l => l.Length > 0);
                results.Add(new CheckResult(display, result.Attribute("outcome")?.Value ?? "Failed", first));
            }
        }

        return results;
    }

    /// <summary>The checks a blame sequence file lists as started and not finished.</summary>
    /// <param name="sequence">The <c>Sequence_*.xml</c> file.</param>
    /// <returns>Each unfinished check; none where the file is missing, a link, too large or not XML.</returns>
    public static IReadOnlyList<UnfinishedCheck> Unfinished(string sequence)
    {
        ArgumentException.ThrowIfNullOrEmpty(sequence);
        return [.. Elements(sequence)
            .Where(e => e.Name.LocalName == "Test" && e.Attribute("Completed")?.Value == "False" && e.Attribute("Name") is not null)
            .Select(e => new UnfinishedCheck(e.Attribute("Name")!.Value, e.Attribute("DisplayName")?.Value ?? e.Attribute("Name")!.Value))];
    }

    private static List<XElement> Elements(string path)
    {
        var file = new FileInfo(path);
        if (!file.Exists || file.LinkTarget is not null || file.Length > MaxBytes)
        {
            return [];
        }

        try
        {
            using XmlReader reader = XmlReader.Create(path, new XmlReaderSettings { DtdProcessing = DtdProcessing.Prohibit, XmlResolver = null });
            return XDocument.Load(reader).Descendants().ToList();
        }
        catch (Exception e) when (e is XmlException or IOException or UnauthorizedAccessException)
        {
            return [];
        }
    }
}
