using System.Globalization;
using RayLab.Scenes;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// The scene files <c>raylab</c> carries in <c>scenes/</c> beside itself (the build output, the native build's
/// folder and the .NET tool), reachable by name from any folder: <c>raylab render two-spheres -o x.png</c>.
/// A file of that name in the current folder wins; <c>raylab scenes</c> lists them.
/// </summary>
public static class CarriedScenes
{
    /// <summary>The folder of the carried scenes: <c>scenes/</c> beside the app.</summary>
    public static string Folder => Path.Combine(AppContext.BaseDirectory, "scenes");

    /// <summary>The carried scenes' names (file names without <c>.json</c>), in ordinal order.</summary>
    public static IReadOnlyList<string> Names =>
        Directory.Exists(Folder)
            ? [.. Directory.EnumerateFiles(Folder, "*.json").Select(f => Path.GetFileNameWithoutExtension(f)).Order(StringComparer.Ordinal)]
            : [];

    /// <summary>
    /// The file a scene argument stands for: the path itself when that file exists or the argument names a folder;
    /// else, for a bare name (<c>two-spheres</c> or <c>two-spheres.json</c>), the carried scene of that name.
    /// </summary>
    /// <param name="scene">The scene argument as typed.</param>
    /// <returns>The path to load.</returns>
    /// <exception cref="UsageException">A bare name that is a folder here, or neither a file here nor a carried scene (with the names that are).</exception>
    public static string Resolve(string scene)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(scene);
        if (File.Exists(scene) || scene.IndexOfAny(['/', Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar]) >= 0)
        {
            return scene;
        }

        string name = scene.EndsWith(".json", StringComparison.OrdinalIgnoreCase) ? scene[..^".json".Length] : scene;
        IReadOnlyList<string> names = Names;
        if (names.Contains(name, StringComparer.Ordinal))
        {
            return Path.Combine(Folder, name + ".json");
        }

        if (Directory.Exists(scene))
        {
            throw new UsageException($"scene: '{scene}' is a folder here, not a scene file (a .json file, or a carried scene: see 'raylab scenes')");
        }

        throw new UsageException(
            $"scene: '{scene}' is neither a file here nor a carried scene; carried scenes: {string.Join(", ", names)}{Suggestions.DidYouMean(name, names)} (see 'raylab scenes')");
    }

    /// <summary><c>raylab scenes</c>: one line per carried scene, its name, size, camera, spheres and sampler.</summary>
    /// <param name="stdout">Where the list goes.</param>
    /// <param name="stderr">Where a broken scene file is reported.</param>
    /// <returns>0, or 1 when a carried file does not load.</returns>
    public static int List(TextWriter stdout, TextWriter stderr)
    {
        ArgumentNullException.ThrowIfNull(stdout);
        ArgumentNullException.ThrowIfNull(stderr);
        IReadOnlyList<string> names = Names;
        int width = names.Count == 0 ? 0 : names.Max(n => n.Length);
        return CommandExit.Run(
            stderr,
            () =>
            {
                foreach (string name in names)
                {
                    SceneDescription d = SceneFile.Load(Path.Combine(Folder, name + ".json"));
                    PreparedScene p = d.Prepare();
                    stdout.WriteLine(string.Create(CultureInfo.InvariantCulture,
                        $"{name.PadRight(width)}  {d.Width}×{d.Height}, {d.Camera.Type} camera, {d.Scene.Spheres.Count} spheres, {p.SamplerDescription}"));
                }

                stdout.WriteLine($"Render one by name from any folder: raylab render {(names.Contains("two-spheres") ? "two-spheres" : names.Count > 0 ? names[0] : "NAME")} -o out.png ({Folder})");
                return CommandExit.Done;
            },
            cancelled: "the list is not complete",
            tooLarge: "list the scenes",
            CancellationToken.None);
    }
}
