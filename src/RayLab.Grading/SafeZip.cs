using System.IO.Compression;

namespace RayLab.Grading;

/// <summary>What an unpacked zip may hold at most: bytes written in all, and entries.</summary>
public sealed record ZipLimits
{
    /// <summary>The limits for one student's upload: 256 MiB and 20 000 entries.</summary>
    public static ZipLimits Upload { get; } = new(256L << 20, 20_000);

    /// <summary>Limits.</summary>
    /// <param name="maxBytes">The most bytes written in all, ≥ 1.</param>
    /// <param name="maxEntries">The most entries (files and folders), ≥ 1.</param>
    /// <exception cref="ArgumentOutOfRangeException">A limit below 1.</exception>
    public ZipLimits(long maxBytes, int maxEntries)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxBytes, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(maxEntries, 1);
        MaxBytes = maxBytes;
        MaxEntries = maxEntries;
    }

    /// <summary>The most bytes written in all.</summary>
    public long MaxBytes { get; }

    /// <summary>The most entries.</summary>
    public int MaxEntries { get; }
}

/// <summary>Why a zip was refused, in English (the report) and Polish (the student's feedback).</summary>
public sealed class ZipRefusedException : Exception
{
    /// <summary>A refusal.</summary>
    /// <param name="message">Why, in English.</param>
    /// <param name="polish">Why, in Polish.</param>
    public ZipRefusedException(string message, string polish)
        : base(message)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(message);
        ArgumentException.ThrowIfNullOrWhiteSpace(polish);
        Polish = polish;
    }

    /// <summary>A refusal with no Polish text of its own.</summary>
    public ZipRefusedException()
        : this("the zip was refused", "archiwum odrzucone")
    {
    }

    /// <summary>A refusal with the same text in both languages.</summary>
    /// <param name="message">Why.</param>
    public ZipRefusedException(string message)
        : this(message, message)
    {
    }

    /// <summary>A refusal with the same text in both languages, and its cause.</summary>
    /// <param name="message">Why.</param>
    /// <param name="innerException">The cause.</param>
    public ZipRefusedException(string message, Exception innerException)
        : base(message, innerException)
    {
        Polish = message;
    }

    /// <summary>Why, in Polish.</summary>
    public string Polish { get; }
}

/// <summary>
/// Unpacks an uploaded zip into a folder of its own, all or nothing: it refuses an entry whose path climbs out of the
/// folder (<c>..</c>, a rooted path, a drive), a link or any entry that is not a file or folder (its unix mode in the
/// external attributes), and a zip bomb (more entries, or more bytes actually written, than <see cref="ZipLimits"/>
/// allow, whatever the headers claim). A refused zip leaves no folder behind.
/// </summary>
public static class SafeZip
{
    private const int UnixTypeMask = 0xF000;
    private const int UnixFile = 0x8000;
    private const int UnixFolder = 0x4000;
    private const int UnixLink = 0xA000;

    /// <summary>Unpacks <paramref name="zip"/> into <paramref name="folder"/>, which must not exist yet.</summary>
    /// <param name="zip">The zip file.</param>
    /// <param name="folder">The new folder.</param>
    /// <param name="limits">The most entries and bytes.</param>
    /// <exception cref="ZipRefusedException">The zip is refused, or cannot be read as a zip; the folder is not left behind.</exception>
    /// <exception cref="ArgumentException">An empty path, or a folder that already exists.</exception>
    // Long: one loop that checks each entry (path, link, count, bytes actually written) and writes it, with the cleanup of a refused zip around it.
    public static void Extract(string zip, string folder, ZipLimits limits)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(zip);
        ArgumentException.ThrowIfNullOrWhiteSpace(folder);
        ArgumentNullException.ThrowIfNull(limits);
        if (Directory.Exists(folder) || File.Exists(folder))
        {
            throw new ArgumentException($"'{folder}' already exists", nameof(folder));
        }

        string root = Path.GetFullPath(folder);
        try
        {
            using ZipArchive archive = ZipFile.OpenRead(zip);
            if (archive.Entries.Count > limits.MaxEntries)
            {
                throw new ZipRefusedException($"{archive.Entries.Count} entries, more than the {limits.MaxEntries} allowed",
                    $"{archive.Entries.Count} wpisów, więcej niż dozwolone {limits.MaxEntries}");
            }

            // Every entry's name and kind first, so a refused zip writes nothing.
            var targets = new List<(ZipArchiveEntry Entry, string Target, bool IsFolder)>();
            foreach (ZipArchiveEntry entry in archive.Entries)
            {
                targets.Add((entry, Target(root, entry), IsFolder(entry)));
            }

            Directory.CreateDirectory(root);
            long written = 0;
            foreach ((ZipArchiveEntry entry, string target, bool isFolder) in targets)
            {
                if (isFolder)
                {
                    Directory.CreateDirectory(target);
                    continue;
                }

                Directory.CreateDirectory(Path.GetDirectoryName(target)!);
                using Stream from = entry.Open();
                using var to = new FileStream(target, FileMode.Create, FileAccess.Write, FileShare.None);
                byte[] buffer = new byte[81920];
                int n;
                while ((n = from.Read(buffer, 0, buffer.Length)) > 0)
                {
                    written += n;
                    if (written > limits.MaxBytes)
                    {
                        throw new ZipRefusedException($"unpacks to more than the {limits.MaxBytes} bytes allowed (at {entry.FullName})",
                            $"po rozpakowaniu więcej niż dozwolone {limits.MaxBytes} bajtów (przy {entry.FullName})");
                    }

                    to.Write(buffer, 0, n);
                }
            }
        }
        catch (Exception e) when (e is ZipRefusedException or InvalidDataException or IOException or UnauthorizedAccessException)
        {
            if (Directory.Exists(root))
            {
                Directory.Delete(root, recursive: true);
            }

            if (e is ZipRefusedException)
            {
                throw;
            }

            throw new ZipRefusedException($"not a zip that can be read: {OneLine(e.Message)}",
                $"nie da się odczytać jako zip: {OneLine(e.Message)}");
        }
    }

    /// <summary>Where an entry goes, or a refusal: a path that climbs out, a link, anything that is not a file or folder.</summary>
    private static string Target(string root, ZipArchiveEntry entry)
    {
        string name = entry.FullName;
        int type = (entry.ExternalAttributes >> 16) & UnixTypeMask;
        if (type == UnixLink)
        {
            throw new ZipRefusedException($"entry {name} is a link", $"wpis {name} jest dowiązaniem");
        }

        if (type is not 0 and not UnixFile and not UnixFolder)
        {
            throw new ZipRefusedException($"entry {name} is not a file or folder", $"wpis {name} nie jest plikiem ani folderem");
        }

        string[] parts = name.Replace('\\', '/').Split('/');
        if (name.Length == 0 || name[0] is '/' or '\\' || name.Contains(':', StringComparison.Ordinal) || name.Contains('\0', StringComparison.Ordinal)
            || parts.Any(p => p == ".."))
        {
            throw new ZipRefusedException($"entry {name} climbs out of the folder", $"wpis {name} wychodzi poza folder");
        }

        string target = Path.GetFullPath(Path.Combine([root, .. parts.Where(p => p.Length > 0 && p != ".")]));
        if (!target.StartsWith(root + Path.DirectorySeparatorChar, StringComparison.Ordinal) && target != root)
        {
            throw new ZipRefusedException($"entry {name} climbs out of the folder", $"wpis {name} wychodzi poza folder");
        }

        return target;
    }

    private static bool IsFolder(ZipArchiveEntry entry) =>
        entry.FullName.EndsWith('/') || entry.FullName.EndsWith('\\') || ((entry.ExternalAttributes >> 16) & UnixTypeMask) == UnixFolder;

    private static string OneLine(string text) => string.Join(' ', text.Split(['\r', '\n'], StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries));
}
