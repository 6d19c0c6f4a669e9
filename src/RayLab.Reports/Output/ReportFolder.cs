namespace RayLab.Reports.Output;

/// <summary>
/// Moves a report built in a hidden staging folder into its output folder, <c>index.html</c> last, so a page never
/// points at files that are not there yet; shared by <c>raylab compare</c>, <c>raylab patterns</c> and <c>raylab grade</c>.
/// </summary>
internal static class ReportFolder
{
    /// <summary>
    /// Moves every file under <paramref name="staging"/> to the same relative path under <paramref name="folder"/>,
    /// after checking that no file or folder is in the way of any of them (so a clash stops the run before anything
    /// is moved). The moves are all or none: when one fails, every file already replaced is put back.
    /// </summary>
    /// <returns>How many files were moved, <c>index.html</c> included.</returns>
    // Long: the checks before any move, then the moves all or none, in one place.
    public static int Publish(string staging, string folder)
    {
        string[] files = [.. Directory.EnumerateFiles(staging, "*", SearchOption.AllDirectories)
            .OrderBy(f => Path.GetFileName(f) == "index.html").ThenBy(f => f, StringComparer.Ordinal)];
        // Check every target first, so a file or folder in the way stops the run before anything is moved.
        foreach (string file in files)
        {
            string target = Path.Combine(folder, Path.GetRelativePath(staging, file));
            string parent = Path.GetDirectoryName(target)!;
            if (File.Exists(parent))
            {
                throw new UsageException($"--out: '{parent}' is a file where the report needs a folder");
            }

            if (Directory.Exists(target))
            {
                throw new UsageException($"--out: '{target}' is a folder where the report writes a file");
            }
        }

        // All or none (OutputFiles.MoveAll): a failed move puts back the files already replaced, and the folders made
        // for the report are removed again.
        var made = new List<string>();
        try
        {
            var moves = new List<FileMove>();
            foreach (string file in files)
            {
                string target = Path.Combine(folder, Path.GetRelativePath(staging, file));
                for (string? parent = Path.GetDirectoryName(Path.GetFullPath(target)); parent is not null && !Directory.Exists(parent); parent = Path.GetDirectoryName(parent))
                {
                    made.Add(parent);
                }

                Directory.CreateDirectory(Path.GetDirectoryName(target)!);
                moves.Add(new FileMove(file, target, "--out"));
            }

            OutputFiles.MoveAll(moves);
        }
        catch
        {
            foreach (string empty in made.Distinct().OrderByDescending(f => f.Length))
            {
                try
                {
                    if (Directory.Exists(empty) && !Directory.EnumerateFileSystemEntries(empty).Any())
                    {
                        Directory.Delete(empty);
                    }
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    // best effort: the failed move is the error to report
                }
            }

            throw;
        }

        return files.Length;
    }
}
