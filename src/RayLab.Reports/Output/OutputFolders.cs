namespace RayLab.Reports.Output;

/// <summary>
/// The console's one message for an output folder a command cannot write in, whichever command found it (render's
/// <c>-o</c>, <c>--stats</c> and <c>--heatmap</c>, the <c>--out</c> of compare, patterns and grade):
/// <c>OPTION: cannot write in the folder 'FOLDER': WHY</c>.
/// </summary>
internal static class OutputFolders
{
    /// <summary>Why a file or folder could not be created in a folder, in a few words, for the end of an error line.</summary>
    /// <param name="e">What creating it threw.</param>
    /// <param name="hidden">The hidden name the command tried (a probe file, a staging folder), which the user never asked for: a message naming it says "a new file" instead.</param>
    /// <returns>"permission denied", "nothing can be created there" (no such folder, as in /proc), or the exception's message.</returns>
    public static string Why(Exception e, string? hidden = null)
    {
        ArgumentNullException.ThrowIfNull(e);
        return e switch
        {
            UnauthorizedAccessException => "permission denied",
            FileNotFoundException or DirectoryNotFoundException => "nothing can be created there",
            _ when hidden is not null => e.Message.Replace(hidden, "a new file", StringComparison.Ordinal),
            _ => e.Message,
        };
    }

    /// <summary>
    /// Checks, before any work, that files can be created in <paramref name="folder"/>, or, where it does not exist yet,
    /// in the nearest folder above it that does (where the command will create it): a hidden file is created there
    /// and deleted on close, so nothing is left.
    /// </summary>
    /// <param name="option">The option that named the folder or a file in it, for the error.</param>
    /// <param name="folder">The folder, as given.</param>
    /// <exception cref="UsageException">Nothing can be created there (<see cref="CannotWrite"/>).</exception>
    public static void Probe(string option, string folder)
    {
        string? existing = Path.GetFullPath(folder);
        while (existing is not null && !Directory.Exists(existing))
        {
            existing = Path.GetDirectoryName(existing);
        }

        string probe = Path.Combine(existing ?? ".", $".raylab-probe.{Guid.NewGuid():N}.tmp");
        try
        {
            using (new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose))
            {
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw CannotWrite(option, folder, e, probe);
        }
    }

    /// <summary>The error for an output folder that cannot be written in: the option, the folder, and <see cref="Why"/>.</summary>
    /// <param name="option">The option that named the folder or a file in it (<c>--out</c>, <c>--stats</c>).</param>
    /// <param name="folder">The folder.</param>
    /// <param name="e">What creating a file or folder there threw.</param>
    /// <param name="hidden">The hidden name the command tried, left out of the message.</param>
    /// <returns>The exception to throw.</returns>
    public static UsageException CannotWrite(string option, string folder, Exception e, string? hidden = null) =>
        new($"{option}: cannot write in the folder '{folder}': {Why(e, hidden)}");
}
