namespace RayLab.Grading;

/// <summary>
/// Where a submission's lab is once what the student uploaded is unpacked: the folder itself when it holds a lab
/// (<c>src/Lab/*.csproj</c>, there or one folder below), else its one zip unpacked with <see cref="SafeZip"/>.
/// </summary>
public sealed record UploadedLab
{
    private UploadedLab(string? folder, string? refusal, string? polishRefusal)
    {
        Folder = folder;
        Refusal = refusal;
        PolishRefusal = polishRefusal;
    }

    /// <summary>The folder to look for the lab in, or null when the upload was refused.</summary>
    public string? Folder { get; }

    /// <summary>Why the upload was refused, for the student's row (<c>zip refused: lab.zip: entry ../x climbs out of the folder</c>), or null.</summary>
    public string? Refusal { get; }

    /// <summary>The same in Polish, for the student's feedback, or null.</summary>
    public string? PolishRefusal { get; }

    /// <summary>
    /// The lab of <paramref name="submission"/>: the folder as it is when it holds a lab or no zip; its one zip
    /// unpacked into <paramref name="unpacked"/> (which must not exist yet) when it holds no lab; a refusal when the zip
    /// is refused, or when there are several zips and no lab.
    /// </summary>
    /// <param name="submission">The student's folder.</param>
    /// <param name="unpacked">A new folder for the unpacked zip.</param>
    /// <param name="limits">The most entries and bytes the zip may unpack to.</param>
    /// <returns>The folder to look for the lab in, or the refusal.</returns>
    /// <exception cref="ArgumentException">An empty path.</exception>
    public static UploadedLab Unpack(string submission, string unpacked, ZipLimits limits)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(submission);
        ArgumentException.ThrowIfNullOrWhiteSpace(unpacked);
        ArgumentNullException.ThrowIfNull(limits);
        if (HoldsLab(submission))
        {
            return new UploadedLab(submission, null, null);
        }

        string[] zips = [.. Directory.EnumerateFiles(submission)
            .Where(f => f.EndsWith(".zip", StringComparison.OrdinalIgnoreCase) && new FileInfo(f).LinkTarget is null)
            .Order(StringComparer.Ordinal)];
        if (zips.Length == 0)
        {
            return new UploadedLab(submission, null, null);
        }

        if (zips.Length > 1)
        {
            string names = string.Join(", ", zips.Select(Path.GetFileName));
            return new UploadedLab(null, $"zip refused: several zips and no lab: {names}", $"Archiwum odrzucone: kilka archiwów zip i żadnego laboratorium: {names}");
        }

        string name = Path.GetFileName(zips[0]);
        try
        {
            SafeZip.Extract(zips[0], unpacked, limits);
            return new UploadedLab(unpacked, null, null);
        }
        catch (ZipRefusedException e)
        {
            return new UploadedLab(null, $"zip refused: {name}: {e.Message}", $"Archiwum odrzucone: {name}: {e.Polish}");
        }
    }

    /// <summary>Whether a folder holds a lab, there or in one folder below.</summary>
    private static bool HoldsLab(string folder)
    {
        static bool IsLab(string f) =>
            Directory.Exists(Path.Combine(f, "src", "Lab")) && Directory.EnumerateFiles(Path.Combine(f, "src", "Lab"), "*.csproj").Any();
        return IsLab(folder) || Directory.EnumerateDirectories(folder).Any(d => !Path.GetFileName(d).StartsWith('.') && IsLab(d));
    }
}
