using System.Globalization;
using RayLab.Reports.Imaging;

namespace RayLab.Grading;

/// <summary>What a picture read back from a lab's copy comes to (<see cref="GradeJob.ReadPicture"/>).</summary>
/// <param name="Picture">The decoded picture, or null.</param>
/// <param name="Status">The row's problem ("picture is a link", "picture too large"), or null for none.</param>
/// <param name="Problem">The picture's own line in the report (why it has no score), or null.</param>
/// <param name="Missing">Whether there is no picture at the path at all.</param>
internal sealed record PictureRead(Image? Picture, string? Status, string? Problem, bool Missing);

/// <summary>The built program the grader runs, and how its time is taken (<see cref="GradeJob.ProgramCommand"/>).</summary>
/// <param name="Command">The program to start.</param>
/// <param name="Args">Its arguments.</param>
/// <param name="TimedBy">How the program's seconds in the report were taken, one line.</param>
internal sealed record ProgramLaunch(string Command, IReadOnlyList<string> Args, string TimedBy);

public static partial class GradeJob
{
    /// <summary>The row's problem of a picture that is a link, or has a link on its path.</summary>
    internal const string PictureIsALink = "picture is a link";

    /// <summary>The row's problem of a picture larger than the exact image, by its file's size or its header's.</summary>
    internal const string PictureTooLarge = "picture too large";

    /// <summary>
    /// The most bytes a picture file of <paramref name="width"/>×<paramref name="height"/> is read with: 8 bytes a
    /// pixel (16-bit RGBA, stored uncompressed) and 1 MiB for the format's own data, more than any honest encoding of
    /// that size takes.
    /// </summary>
    /// <param name="width">The exact image's width.</param>
    /// <param name="height">The exact image's height.</param>
    /// <returns>The cap in bytes.</returns>
    internal static long PictureByteCap(int width, int height) => (8L * width * height) + (1 << 20);

    /// <summary>
    /// A picture of a lab's copy read as untrusted, after the lab's processes ended: no link followed (the path's
    /// every part below <paramref name="lab"/> must be no link, and the file opened must be the one at that path),
    /// a regular file of at most <see cref="PictureByteCap"/> bytes, read once, and decoded only when its header
    /// claims at most <paramref name="width"/>×<paramref name="height"/> pixels (a larger one is refused before
    /// anything is allocated for its pixels).
    /// </summary>
    /// <param name="lab">The lab's copy.</param>
    /// <param name="file">The picture's path relative to it, '/' between folders.</param>
    /// <param name="width">The exact image's width.</param>
    /// <param name="height">The exact image's height.</param>
    /// <returns>The picture, or why there is none.</returns>
    // Long: each check of an untrusted picture in the order it must run: path, links, size, opened file, header, decode.
    internal static PictureRead ReadPicture(string lab, string file, int width, int height)
    {
        ArgumentException.ThrowIfNullOrEmpty(lab);
        ArgumentException.ThrowIfNullOrEmpty(file);
        string copy = RealPath(lab);
        string path = copy;
        foreach (string part in file.Split('/', '\\'))
        {
            if (part is "" or "." or "..")
            {
                return new PictureRead(null, PictureIsALink, $"{file}: leaves the lab's copy", false);
            }

            path = Path.Combine(path, part);
            var entry = new FileInfo(path);
            if (entry.LinkTarget is not null)
            {
                return new PictureRead(null, PictureIsALink, $"{file} is a link, or a folder on its path is: the grader follows no link out of a lab's copy", false);
            }

            if (!entry.Exists && !Directory.Exists(path))
            {
                return new PictureRead(null, null, null, true);
            }
        }

        var info = new FileInfo(path);
        long cap = PictureByteCap(width, height);
        if (Directory.Exists(path) || info.Length == 0)
        {
            // a folder, an empty file, or no regular file at all (a pipe or a device has no length): nothing opened
            return new PictureRead(null, null, $"{file} does not decode ({(Directory.Exists(path) ? "a folder" : "empty, or not a regular file")})", false);
        }

        if (info.Length > cap)
        {
            return new PictureRead(null, PictureTooLarge, TooManyBytes(file, info.Length, cap, width, height), false);
        }

        byte[] bytes;
        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, bufferSize: 0);
            if (OpenedPath(stream) is { } opened && opened != path)
            {
                return new PictureRead(null, PictureIsALink, $"{file} is a link, or a folder on its path is: the grader follows no link out of a lab's copy", false);
            }

            bytes = new byte[(int)Math.Min(info.Length, cap) + 1];
            int read = stream.ReadAtLeast(bytes, bytes.Length, throwOnEndOfStream: false);
            if (read > cap)
            {
                return new PictureRead(null, PictureTooLarge, TooManyBytes(file, read, cap, width, height), false);
            }

            Array.Resize(ref bytes, read);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return new PictureRead(null, null, $"{file} cannot be read", false);
        }

        // The header's size first: a picture larger than the exact image is refused before anything is allocated for it.
        if (SkiaBitmaps.ReadSize(bytes) is not (int claimedWidth, int claimedHeight))
        {
            return new PictureRead(null, null, $"{file} does not decode", false);
        }

        if (claimedWidth > width || claimedHeight > height)
        {
            return new PictureRead(null, PictureTooLarge, string.Create(CultureInfo.InvariantCulture,
                $"{file} claims {claimedWidth}×{claimedHeight} pixels, more than the exact image's {width}×{height}; not decoded"), false);
        }

        try
        {
            return new PictureRead(Image.Load(bytes, file, width, height), null, null, false);
        }
        catch (InvalidDataException)
        {
            return new PictureRead(null, null, $"{file} does not decode", false);
        }
    }

    private static string TooManyBytes(string file, long bytes, long cap, int width, int height) => string.Create(CultureInfo.InvariantCulture,
        $"{file}: {bytes:N0} bytes, more than the {cap:N0} a {width}×{height} picture takes; not read");

    /// <summary>The path of the file a stream has open, as the kernel resolved it (Linux's /proc/self/fd), or null where there is none to ask.</summary>
    private static string? OpenedPath(FileStream stream)
    {
        if (!OperatingSystem.IsLinux())
        {
            return null;
        }

        string fd = string.Create(CultureInfo.InvariantCulture, $"/proc/self/fd/{stream.SafeFileHandle.DangerousGetHandle()}");
        try
        {
            return new FileInfo(fd).LinkTarget;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    /// <summary>
    /// A folder's path with every link on it resolved (the grader's own folders: a lab's copy may be below a
    /// temporary folder that is itself a link).
    /// </summary>
    private static string RealPath(string path, int depth = 0)
    {
        string full = Path.GetFullPath(path);
        string root = Path.GetPathRoot(full) ?? "/";
        string real = root;
        foreach (string part in full[root.Length..].Split(Path.DirectorySeparatorChar, StringSplitOptions.RemoveEmptyEntries))
        {
            string next = Path.Combine(real, part);
            string? link = new FileInfo(next).LinkTarget;
            real = link is null || depth > 40 ? next : RealPath(Path.Combine(real, link), depth + 1);
        }

        return real;
    }

    /// <summary>
    /// How the grader starts a built lab's program and times it: the assembly the grader scanned and built the checks
    /// against (<see cref="GradeChecks.BuiltAssembly"/>), started as <c>dotnet src/Lab/bin/Debug/net10.0/NAME.dll</c>
    /// in the lab's root (as <c>dotnet run</c> starts it) where its <c>.runtimeconfig.json</c> is beside it, so that
    /// the grader's clock holds the program and not <c>dotnet run</c>'s reading of the project; else <c>dotnet run
    /// --no-build</c>, and the report says that its start is counted.
    /// </summary>
    /// <param name="lab">The lab's copy, built.</param>
    /// <returns>The command and how its time is taken.</returns>
    internal static ProgramLaunch ProgramCommand(string lab)
    {
        ArgumentException.ThrowIfNullOrEmpty(lab);
        string? assembly = Directory.Exists(Path.Combine(lab, "src", "Lab")) ? GradeChecks.BuiltAssembly(lab) : null;
        string? config = assembly is null ? null : Path.ChangeExtension(assembly, ".runtimeconfig.json");
        if (assembly is not null && File.Exists(config) && new FileInfo(config).LinkTarget is null)
        {
            string dll = Path.GetRelativePath(lab, assembly).Replace(Path.DirectorySeparatorChar, '/');
            return new ProgramLaunch("dotnet", [dll], $"the grader's clock around the built program (dotnet {dll}), in the sandbox, one program at a time");
        }

        return new ProgramLaunch("dotnet", ["run", "--project", Path.Combine("src", "Lab"), "--no-build"],
            "the grader's clock around dotnet run --no-build (its start counted: no built program with its runtimeconfig.json in src/Lab/bin/Debug/net10.0), in the sandbox, one program at a time");
    }
}
