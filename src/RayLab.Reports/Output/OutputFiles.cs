namespace RayLab.Reports.Output;

/// <summary>
/// The files one command writes, all or none, existing files included. Each is first written under a hidden temporary
/// name in its own folder (<see cref="Write"/>); only when every one is written are they moved into place
/// (<see cref="Commit"/>, <see cref="MoveAll"/>). A file a move replaces is set aside under a hidden name until every
/// move is done and put back if one fails, so a failed run leaves the files it would have replaced as they were.
/// Disposing removes the temporary files of a set that was not committed.
/// </summary>
internal sealed class OutputFiles : IDisposable
{
    private readonly List<FileMove> _staged = [];

    /// <summary>
    /// Writes one output under a hidden temporary name beside <paramref name="path"/>; it replaces nothing until
    /// <see cref="Commit"/>.
    /// </summary>
    /// <param name="path">The output's path, as given.</param>
    /// <param name="option">The option that named it (<c>--stats</c>), for the error.</param>
    /// <param name="write">Writes the file's bytes to the stream.</param>
    /// <exception cref="UsageException">The file cannot be written; the message names the option and the path.</exception>
    public void Write(string path, string option, Action<Stream> write)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        ArgumentNullException.ThrowIfNull(write);
        var move = new FileMove(Hidden(path, "new"), path, option);
        try
        {
            using var stream = new FileStream(move.Temp, FileMode.CreateNew, FileAccess.Write, FileShare.None);
            _staged.Add(move); // from here on the temporary file exists, and Dispose removes it
            write(stream);
            stream.Flush();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw Failed(move, e);
        }
    }

    /// <summary>Moves every file written into place, all or none (<see cref="MoveAll"/>).</summary>
    /// <exception cref="UsageException">A move failed; every file is as it was before the run.</exception>
    public void Commit()
    {
        MoveAll(_staged);
        _staged.Clear();
    }

    /// <summary>Removes the temporary files of outputs not committed (best effort: the error that stopped the run is the one to report).</summary>
    public void Dispose()
    {
        foreach (FileMove move in _staged)
        {
            TryDelete(move.Temp);
        }

        _staged.Clear();
    }

    /// <summary>
    /// Moves each file to its target, in order, all or none: a target that exists is first renamed to a hidden name
    /// beside it; when a move fails, the files already moved are removed and the set-aside files renamed back, and
    /// only when every move is done are the set-aside files deleted. Each step is a rename within one folder. The
    /// sources are left where they were when a move fails (the caller removes them).
    /// </summary>
    /// <param name="moves">The moves, in the order to make them.</param>
    /// <exception cref="UsageException">A move failed (the message names its option and target); every target is as it was.</exception>
    public static void MoveAll(IReadOnlyList<FileMove> moves)
    {
        ArgumentNullException.ThrowIfNull(moves);
        var done = new List<(FileMove Move, string? Old)>();
        try
        {
            foreach (FileMove move in moves)
            {
                string? old = null;
                try
                {
                    if (File.Exists(move.Target))
                    {
                        old = Hidden(move.Target, "old");
                        File.Move(move.Target, old);
                    }

                    File.Move(move.Temp, move.Target);
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    if (old is not null)
                    {
                        TryMove(old, move.Target);
                    }

                    throw Failed(move, e);
                }

                done.Add((move, old));
            }
        }
        catch
        {
            for (int i = done.Count - 1; i >= 0; i--)
            {
                (FileMove move, string? old) = done[i];
                if (TryMove(move.Target, move.Temp) && old is not null)
                {
                    TryMove(old, move.Target);
                }
            }

            throw;
        }

        foreach ((_, string? old) in done)
        {
            if (old is not null)
            {
                TryDelete(old);
            }
        }
    }

    /// <summary>A hidden name beside <paramref name="path"/> that no other file has: <c>.NAME.raylab-KIND-GUID</c>.</summary>
    private static string Hidden(string path, string kind)
    {
        string full = Path.GetFullPath(path);
        return Path.Combine(Path.GetDirectoryName(full) ?? ".", $".{Path.GetFileName(full)}.raylab-{kind}-{Guid.NewGuid():N}");
    }

    // The exception's message may name the temporary file, which the user never asked for: it names the target instead.
    private static UsageException Failed(FileMove move, Exception e) =>
        new($"{move.Option}: cannot write '{move.Target}': {e.Message.Replace(move.Temp, move.Target, StringComparison.Ordinal)}");

    private static bool TryMove(string from, string to)
    {
        try
        {
            File.Move(from, to);
            return true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return false; // best effort: the set-aside file stays under its hidden name rather than being lost
        }
    }

    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // best effort: the error that stopped the run is the one to report
        }
    }
}

/// <summary>One file of an <see cref="OutputFiles"/> set: where it was written, where it goes, and the option that named it.</summary>
/// <param name="Temp">The file as written, under a hidden name (full path).</param>
/// <param name="Target">Where it goes, as given.</param>
/// <param name="Option">The option that named the target (<c>--stats</c>, <c>--out</c>), for errors.</param>
internal readonly record struct FileMove(string Temp, string Target, string Option);
