using System.Runtime.InteropServices;

namespace RayLab.Tests.Shared;

/// <summary>
/// A folder of this checkout's packages, all of one version, and where each of them is.
/// </summary>
/// <param name="Folder">The folder that holds the .nupkg files (read it; copy from it, never write into it).</param>
/// <param name="Version">The packages' version (MinVer: the commit's).</param>
internal sealed record PackedSet(string Folder, string Version)
{
    /// <summary>The package <paramref name="id"/> at <see cref="Version"/> in <see cref="Folder"/>.</summary>
    /// <returns>Its path.</returns>
    public string Package(string id) => Path.Combine(Folder, $"{id}.{Version}.nupkg");

    /// <summary>Copies the packages <paramref name="ids"/> (and the symbol package of each that has one) into <paramref name="feed"/>.</summary>
    public void CopyTo(string feed, params string[] ids)
    {
        Directory.CreateDirectory(feed);
        foreach (string id in ids)
        {
            foreach (string extension in new[] { "nupkg", "snupkg" })
            {
                string file = Path.Combine(Folder, $"{id}.{Version}.{extension}");
                if (File.Exists(file))
                {
                    File.Copy(file, Path.Combine(feed, Path.GetFileName(file)));
                }
            }
        }
    }
}

/// <summary>
/// This checkout's packages, packed once for every end-to-end fixture of a test process (the package tests' feed, the
/// template tests' feed and the class kit copy what they need into folders of their own). When the environment
/// variable <see cref="SharedVariable"/> names a folder (.ci/run sets it), the packing is shared by every test process
/// of the run as well: the first one packs into that folder, under the commit's id, and the others find it there. A
/// checkout with changes (<c>git status</c> not empty) never shares: a later process may see other sources.
/// Shared packing builds in the checkout's own bin and obj, one pack at a time, so what the run built in Release
/// before is not built again; a process's own packing builds in a folder of its own, so it never races a build of the
/// checkout, and the libraries and the tool pack side by side there.
/// </summary>
internal static class PackedPackages
{
    /// <summary>The environment variable that names the folder shared by the test processes of one run.</summary>
    public const string SharedVariable = "RAYLAB_TEST_PACKAGES";

    /// <summary>The libraries and the template packages: what a lab restores and what installs its templates.</summary>
    public static readonly string[] LibraryIds = ["RayLab", "RayLab.Reports", "RayLab.ImageSharp", "RayLab.Grading.Uses", "RayLab.Grading", "RayLab.Templates", "RayLab.Templates.Instructor"];

    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(10);

    private static readonly Lazy<Task<PackedSet>> Libraries = new(() => PackOnceAsync("libraries", PackLibrariesAsync));

    private static readonly Lazy<Task<PackedSet>> Tool = new(() => PackOnceAsync("tool", PackToolAsync));

    private static readonly Lazy<string> PrivateRoot = new(() =>
    {
        string root = Directory.CreateTempSubdirectory("raylab-packed-").FullName;
        AppDomain.CurrentDomain.ProcessExit += (_, _) =>
        {
            try
            {
                Directory.Delete(root, recursive: true);
            }
            catch (IOException)
            {
                // a child killed on timeout may still hold a file; the temporary folder is not worth failing for
            }
        };
        return root;
    });

    /// <summary>Whether this machine gets the native tool package: RayLab.Tool has one for linux-x64 only.</summary>
    public static bool NativeToolHere => OperatingSystem.IsLinux() && RuntimeInformation.OSArchitecture == System.Runtime.InteropServices.Architecture.X64;

    /// <summary>The libraries and template packages (<see cref="LibraryIds"/>, and RayLab's symbol package), packed once.</summary>
    /// <returns>Their folder and version.</returns>
    public static Task<PackedSet> LibrariesAsync() => Libraries.Value;

    /// <summary>
    /// The tool as .NET 10's RID-specific tool, packed once: the pointer package <c>RayLab.Tool</c>, <c>RayLab.Tool.any</c>
    /// and, where <see cref="NativeToolHere"/>, <c>RayLab.Tool.linux-x64</c> (Native AOT).
    /// </summary>
    /// <returns>Their folder and version.</returns>
    public static Task<PackedSet> ToolAsync() => Tool.Value;

    private static async Task<PackedSet> PackOnceAsync(string set, Func<string, string?, Task<string>> pack)
    {
        string? shared = Environment.GetEnvironmentVariable(SharedVariable);
        string? commit = string.IsNullOrEmpty(shared) ? null : await UnchangedCommitAsync();
        if (commit is null)
        {
            string folder = Path.Combine(PrivateRoot.Value, set);
            return new PackedSet(folder, await pack(folder, Path.Combine(PrivateRoot.Value, set + "-artifacts")));
        }

        // One pack at a time in the checkout's bin and obj, across the run's processes (a lock file), into a scratch
        // folder renamed into place: a process that finds the folder finds it whole, and one that waited for the lock
        // finds what the other packed.
        string target = Path.Combine(shared!, commit, set);
        if (!Directory.Exists(target))
        {
            using FileStream gate = await LockAsync(Path.Combine(shared!, commit, "packing.lock"));
            if (!Directory.Exists(target))
            {
                string scratch = Path.Combine(shared!, commit, $"{set}.{Environment.ProcessId}");
                if (Directory.Exists(scratch))
                {
                    Directory.Delete(scratch, recursive: true);
                }

                await pack(scratch, null);
                Directory.Move(scratch, target);
            }
        }

        return new PackedSet(target, VersionOf(target, set == "libraries" ? "RayLab.Templates.Instructor" : "RayLab.Tool.any"));
    }

    private static async Task<string> PackLibrariesAsync(string folder, string? artifacts)
    {
        string repo = RepoPaths.Root();
        foreach (string project in new[] { "src/RayLab/RayLab.csproj", "src/RayLab.Reports/RayLab.Reports.csproj", "src/RayLab.ImageSharp/RayLab.ImageSharp.csproj", "src/RayLab.Grading.Uses/RayLab.Grading.Uses.csproj", "src/RayLab.Grading/RayLab.Grading.csproj", "templates/RayLab.Templates/RayLab.Templates.csproj", "templates/RayLab.Templates.Instructor/RayLab.Templates.Instructor.csproj" })
        {
            await PackAsync(Path.Combine(repo, project), folder, artifacts);
        }

        string version = VersionOf(folder, "RayLab.Templates.Instructor");
        AssertAll(folder, version, [.. LibraryIds.Select(id => $"{id}.{version}.nupkg"), $"RayLab.{version}.snupkg"]);
        return version;
    }

    private static async Task<string> PackToolAsync(string folder, string? artifacts)
    {
        string console = Path.Combine(RepoPaths.Root(), "samples", "RayLab.Console", "RayLab.Console.csproj");
        // The native package first: the packs share the project's restore output, which each rewrites for its own
        // runtime identifiers, and a pack after one for another identifier compiles the linux-x64 assembly again. First,
        // it restores as `dotnet publish -r linux-x64` did (CI's native step), and takes that publish's native code (the
        // x86-64-v3 build it carries) as up to date instead of compiling it once more (42 s of CPU).
        if (NativeToolHere)
        {
            await PackAsync(console, folder, artifacts, "-r", "linux-x64");
        }

        await PackAsync(console, folder, artifacts);
        await PackAsync(console, folder, artifacts, "-r", "any");

        string version = VersionOf(folder, "RayLab.Tool.any");
        AssertAll(folder, version, NativeToolHere
            ? [$"RayLab.Tool.{version}.nupkg", $"RayLab.Tool.linux-x64.{version}.nupkg"]
            : [$"RayLab.Tool.{version}.nupkg"]);
        return version;
    }

    /// <summary>
    /// <c>dotnet pack</c> in Release into <paramref name="folder"/>, with bin/obj under <paramref name="artifacts"/> (null:
    /// the checkout's own); the packing uses the machine's NuGet cache (what the packed packages are used with is the
    /// fixtures' own empty one).
    /// </summary>
    private static Task<string> PackAsync(string project, string folder, string? artifacts, params string[] more) =>
        ChildProcess.RunCheckedAsync(RepoPaths.Root(), new Dictionary<string, string?>(), ChildTimeout,
            "dotnet", ["pack", project, "-c", "Release", "-o", folder, .. (artifacts is null ? Array.Empty<string>() : ["--artifacts-path", artifacts]), .. more]);

    /// <summary>
    /// The file <paramref name="path"/> held open alone (an exclusive lock on Unix and Windows alike, also against another
    /// open of this process), once whoever holds it closes it; at most <see cref="ChildTimeout"/> × 3, a whole packing.
    /// </summary>
    private static async Task<FileStream> LockAsync(string path)
    {
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        DateTime giveUp = DateTime.UtcNow + (ChildTimeout * 3);
        while (true)
        {
            try
            {
                return new FileStream(path, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.None);
            }
            catch (IOException) when (DateTime.UtcNow < giveUp)
            {
                await Task.Delay(250);
            }
        }
    }

    /// <summary>The checkout's commit, or null where the checkout has changes or is no git checkout.</summary>
    private static async Task<string?> UnchangedCommitAsync()
    {
        var none = new Dictionary<string, string?>();
        ChildResult head = await ChildProcess.RunAsync(RepoPaths.Root(), none, ChildTimeout, "git", "rev-parse", "HEAD");
        ChildResult status = await ChildProcess.RunAsync(RepoPaths.Root(), none, ChildTimeout, "git", "status", "--porcelain");
        return head.ExitCode == 0 && status.ExitCode == 0 && status.Output.Trim().Length == 0 ? head.Output.Trim() : null;
    }

    /// <summary>The version in the one package <paramref name="id"/>.*.nupkg of <paramref name="folder"/>.</summary>
    private static string VersionOf(string folder, string id)
    {
        string[] found = Directory.GetFiles(folder, $"{id}.*.nupkg")
            .Where(f => char.IsAsciiDigit(Path.GetFileName(f)[(id.Length + 1)..][0])).ToArray();
        Assert.True(found.Length == 1, $"not one {id}.<version>.nupkg in {folder}: {string.Join(", ", Directory.GetFiles(folder).Select(Path.GetFileName))}");
        return Path.GetFileNameWithoutExtension(found[0])[(id.Length + 1)..];
    }

    private static void AssertAll(string folder, string version, string[] files)
    {
        foreach (string file in files)
        {
            Assert.True(File.Exists(Path.Combine(folder, file)),
                $"{folder} lacks {file} (version {version}; a commit during the packing?): {string.Join(", ", Directory.GetFiles(folder).Select(Path.GetFileName))}");
        }
    }
}
