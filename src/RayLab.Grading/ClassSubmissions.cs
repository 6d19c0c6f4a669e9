using System.Text.RegularExpressions;

namespace RayLab.Grading;

/// <summary>One student's submission as the class's folder holds it: the row's name, the folder, and Moodle's participant id where there is one.</summary>
public sealed record ClassSubmission
{
    /// <summary>A submission.</summary>
    /// <param name="name">The student's row: the folder's name, or the full name of a Moodle folder.</param>
    /// <param name="folder">The submission's folder: a lab, a folder holding one, or a folder holding the uploaded zip.</param>
    /// <param name="participantId">Moodle's participant id (the worksheet's "Participant 12345"), or null.</param>
    /// <exception cref="ArgumentException">An empty name or folder, or a participant id that is not digits.</exception>
    public ClassSubmission(string name, string folder, string? participantId)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(name);
        ArgumentException.ThrowIfNullOrWhiteSpace(folder);
        if (participantId is not null && (participantId.Length == 0 || !participantId.All(char.IsAsciiDigit)))
        {
            throw new ArgumentException($"expected digits, got '{participantId}'", nameof(participantId));
        }

        Name = name;
        Folder = folder;
        ParticipantId = participantId;
    }

    /// <summary>The student's row: the folder's name, or the full name of a Moodle folder.</summary>
    public string Name { get; }

    /// <summary>The submission's folder.</summary>
    public string Folder { get; }

    /// <summary>Moodle's participant id, or null where the folder is not Moodle's.</summary>
    public string? ParticipantId { get; }
}

/// <summary>
/// The class's submissions as they come, one folder per student: a plain folder of labs or of GitHub Classroom clones
/// (<c>lab2-username</c>; the folder's name is the row), or a Moodle assignment's "Download all submissions" in
/// folders (<c>Full Name_12345_assignsubmission_file_</c>; the full name is the row, 12345 the participant id).
/// </summary>
public static partial class ClassSubmissions
{
    /// <summary>The submissions in <paramref name="folder"/>, in ordinal order of their names; hidden folders are skipped.</summary>
    /// <param name="folder">The class's folder.</param>
    /// <returns>One submission per student. A Moodle student with more than one folder (a file and an online text) has the file's.</returns>
    /// <exception cref="ArgumentException">An empty path.</exception>
    /// <exception cref="DirectoryNotFoundException">No such folder.</exception>
    public static IReadOnlyList<ClassSubmission> Read(string folder)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(folder);
        if (!Directory.Exists(folder))
        {
            throw new DirectoryNotFoundException($"no such folder '{folder}'");
        }

        var plain = new List<ClassSubmission>();
        var moodle = new Dictionary<string, (ClassSubmission Submission, bool File)>(StringComparer.Ordinal);
        foreach (string sub in Directory.EnumerateDirectories(folder).Order(StringComparer.Ordinal))
        {
            string name = Path.GetFileName(sub);
            if (name.StartsWith('.'))
            {
                continue;
            }

            if (TryParseMoodleFolder(name, out string? fullName, out string? id, out string? plugin))
            {
                bool file = plugin == "file";
                if (!moodle.TryGetValue(id, out (ClassSubmission Submission, bool File) known) || (file && !known.File))
                {
                    moodle[id] = (new ClassSubmission(fullName, sub, id), file);
                }
            }
            else
            {
                plain.Add(new ClassSubmission(name, sub, null));
            }
        }

        return [.. plain.Concat(moodle.Values.Select(m => m.Submission)).OrderBy(s => s.Name, StringComparer.Ordinal).ThenBy(s => s.ParticipantId, StringComparer.Ordinal)];
    }

    /// <summary>Reads a Moodle submission folder's name, <c>Full Name_12345_assignsubmission_file_</c>.</summary>
    /// <param name="name">The folder's name.</param>
    /// <param name="fullName">The student's full name, as Moodle wrote it.</param>
    /// <param name="participantId">The participant id.</param>
    /// <param name="plugin">The submission plugin: <c>file</c>, <c>onlinetext</c>, ….</param>
    /// <returns>Whether the name is a Moodle submission folder's.</returns>
    public static bool TryParseMoodleFolder(string name, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out string? fullName,
        [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out string? participantId, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out string? plugin)
    {
        ArgumentNullException.ThrowIfNull(name);
        Match m = MoodleFolder().Match(name);
        fullName = m.Success ? m.Groups["name"].Value.Trim() : null;
        participantId = m.Success ? m.Groups["id"].Value : null;
        plugin = m.Success ? m.Groups["plugin"].Value : null;
        return m.Success && fullName!.Length > 0;
    }

    [GeneratedRegex(@"^(?<name>.+)_(?<id>[0-9]+)_assignsubmission_(?<plugin>[a-z0-9]+)_?$", RegexOptions.CultureInvariant)]
    private static partial Regex MoodleFolder();
}
