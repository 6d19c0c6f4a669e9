using System.Text.Json;
using RayLab.Scenes;

namespace RayLab.Cli.Tests;

/// <summary><c>raylab render … --sampler exact</c>: the exact reference from the console.</summary>
public sealed class ExactCliTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-exact-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string LabScene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void ExactRendersTheLibrarysPictureAndReportsNoRays()
    {
        string image = Path.Combine(_dir, "exact.bmp"), stats = Path.Combine(_dir, "s.json"), heat = Path.Combine(_dir, "heat.png");

        var r = Run("render", LabScene, "-o", image, "--sampler", "exact", "--width", "80", "--height", "60", "--threads", "2", "--stats", stats, "--heatmap", heat);

        Assert.True(r.Code == 0, r.Err);
        Assert.Equal("", r.Err);
        string line = Assert.Single(r.Out.TrimEnd().Split('\n'));
        Assert.Contains("exact (area-weighted), 0 rays", line, StringComparison.Ordinal);
        using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
        JsonElement root = json.RootElement;
        Assert.Equal("exact", root.GetProperty("sampler").GetString());
        Assert.Equal(0, root.GetProperty("rays").GetInt64());
        Assert.Equal(0, root.GetProperty("samplesPerPixel").GetInt32());
        Assert.Equal(2, root.GetProperty("threads").GetInt32());
        Assert.True(root.GetProperty("renderMs").GetDouble() > 0);
        Assert.True(File.Exists(heat));

        SceneDescription scene = SceneFile.Load(LabScene);
        var expected = new Image(80, 60);
        new Renderer().Render(scene.Scene, scene.Camera.CreateCamera(), RenderMethod.Exact, expected);
        Assert.Equal(expected.PixelBytes.ToArray(), SkiaDecode.Load(image).Rgb);
    }

    [Fact]
    public void ASphereTheExactReferenceCannotOutlineIsAOneLineErrorAndNoFile()
    {
        string scene = Path.Combine(_dir, "behind.json");
        File.WriteAllText(scene, """
            {
              "image": { "width": 40, "height": 30 },
              "camera": { "type": "perspective", "position": [0, 0, 6], "target": [0, 0, 0], "fov": 40, "near": 0.1 },
              "spheres": [ { "center": [-1.1, 0, 0], "radius": 1, "color": [0.9, 0.2, 0.2] },
                           { "center": [0.3, 0.4, 5.5], "radius": 1, "color": [0.2, 0.8, 0.3] } ]
            }
            """);
        string image = Path.Combine(_dir, "never.png");

        var point = Run("render", scene, "-o", Path.Combine(_dir, "point.png"));
        var exact = Run("render", scene, "-o", image, "--sampler", "exact", "--stats", Path.Combine(_dir, "s.json"));

        Assert.Equal(0, point.Code);
        Assert.Equal(1, exact.Code);
        string error = Assert.Single(exact.Err.TrimEnd().Split('\n'));
        Assert.StartsWith($"raylab: error: {scene}: spheres[1]: reaches behind the perspective camera", error);
        Assert.Equal(["point.png"], Directory.GetFiles(_dir).Select(Path.GetFileName).Where(n => n != "behind.json"));
    }
}
