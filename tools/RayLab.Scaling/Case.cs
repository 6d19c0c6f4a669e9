using System.Diagnostics;
using RayLab.Scenes;

namespace RayLab.Scaling;

/// <summary>One row of the table: a scene and a render method, prepared as <c>raylab render</c> prepares them.</summary>
internal sealed record Case(string Name, SceneDescription Description)
{
    /// <summary>The rows run when none is named.</summary>
    public static readonly string[] Defaults =
        ["bench-jittered16", "bench-adaptive", "bench-guard", "bench-exact", "field-jittered16", "field-adaptive", "field-guard", "field-exact"];

    /// <summary>The prepared scene (camera and method).</summary>
    public PreparedScene Prepared { get; } = Description.Prepare();

    /// <summary>The repository folder, from the tool's own location or the current folder.</summary>
    public static string FindRoot()
    {
        for (string? dir = AppContext.BaseDirectory; dir is not null; dir = Path.GetDirectoryName(dir))
        {
            if (File.Exists(Path.Combine(dir, "RayLab.sln")))
            {
                return dir;
            }
        }

        return Directory.GetCurrentDirectory();
    }

    /// <summary>
    /// bench-* is benchmarks/anchors/bench-1080.json; field-* the 960-sphere field at 1920×1080
    /// (<c>tools/sphere-scenes.py field 24 40</c>); the suffix the method: jittered16, jittered256, adaptive (defaults),
    /// guard (adaptive --guard), exact.
    /// </summary>
    public static Case Named(string name, string root)
    {
        string[] parts = name.Split('-', 2);
        if (parts.Length != 2)
        {
            throw new ArgumentException($"{name}: expected SCENE-METHOD, e.g. bench-adaptive");
        }

        SceneDescription scene = parts[0] switch
        {
            "bench" => SceneFile.Load(Path.Combine(root, "benchmarks", "anchors", "bench-1080.json")),
            "field" => SceneFile.Load(Field(root)),
            _ => throw new ArgumentException($"{name}: the scene is bench or field"),
        };
        SamplerSettings s = scene.Sampler;
        s = parts[1] switch
        {
            "jittered16" => s with { Type = "jittered", Samples = 16 },
            "jittered256" => s with { Type = "jittered", Samples = 256 },
            "adaptive" => s with { Type = "adaptive" },
            "guard" => s with { Type = "adaptive", Guard = true },
            "exact" => s with { Type = "exact" },
            _ => throw new ArgumentException($"{name}: the method is jittered16, jittered256, adaptive, guard or exact"),
        };
        return new Case(name, scene with { Sampler = s });
    }

    private static string Field(string root)
    {
        string path = Path.Combine(Path.GetTempPath(), "raylab-scaling-field-24-40.json");
        if (!File.Exists(path))
        {
            using var python = Process.Start("python3", [Path.Combine(root, "tools", "sphere-scenes.py"), "field", "24", "40", path]);
            python.WaitForExit();
            if (python.ExitCode != 0)
            {
                throw new InvalidOperationException("tools/sphere-scenes.py failed");
            }
        }

        return path;
    }
}
