using System.Globalization;
using RayLab.Rendering.Exact;

namespace RayLab.Cli.Tests;

/// <summary>
/// A scene file of 1 000 000 spheres through <c>raylab render</c>: the point and adaptive samplers render
/// it through the hierarchy, the exact one refuses it with one line naming its limit and leaves no file. The file
/// (about 80 MB) is written into the test's temporary folder, never into the repository. About 40 s on 2 cores: in the
/// Slow category, which .ci/run runs as its own step and the README's <c>dotnet test</c> leaves out.
/// </summary>
[Trait("Category", "Slow")]
public sealed class ManySpheresCliTests : IDisposable
{
    private const int Count = 1_000_000;

    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-million-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    /// <summary>Writes a scene of <see cref="Count"/> small white spheres in front of the camera, right of its axis (the left half of the picture is background).</summary>
    private string WriteScene()
    {
        string path = Path.Combine(_dir, "million.json");
        var random = new Random(1);
        using var writer = new StreamWriter(path);
        writer.Write("""
            { "image": { "width": 32, "height": 24 },
              "camera": { "type": "perspective", "position": [0, 1, 6], "target": [0, 0, -4], "fov": 55, "near": 1, "far": 1000 },
              "spheres": [
            """);
        for (int i = 0; i < Count; i++)
        {
            double x = random.NextDouble() * 100, y = (random.NextDouble() * 200) - 100, z = -10 - (random.NextDouble() * 200);
            writer.Write(string.Create(CultureInfo.InvariantCulture, $"{(i == 0 ? "" : ",")}{{\"center\":[{x:F4},{y:F4},{z:F4}],\"radius\":0.3,\"color\":[1,1,1]}}\n"));
        }

        writer.Write("] }\n");
        return path;
    }

    [Fact]
    public void AMillionSpheresRenderThroughTheConsoleAndTheExactSamplerRefusesThemInOneLine()
    {
        string scene = WriteScene();
        foreach (string[] sampler in new[] { new[] { "--sampler", "jittered", "--samples", "4" }, ["--sampler", "adaptive"] })
        {
            string image = Path.Combine(_dir, $"{sampler[1]}.png");
            var r = Run(["render", scene, "-o", image, "--threads", "2", .. sampler]);
            Assert.True(r.Code == 0, r.Err);
            Assert.Equal("", r.Err);
            Assert.Contains("32×24", Assert.Single(r.Out.TrimEnd().Split('\n')), StringComparison.Ordinal);
            SkiaDecode.Result png = SkiaDecode.Load(image);
            Assert.Equal((32, 24), (png.Width, png.Height));
            Assert.Contains(png.Rgb, b => b > 200);   // white spheres are hit
            Assert.Contains(png.Rgb, b => b == 0);    // and the black background is seen
        }

        string exact = Path.Combine(_dir, "exact.png");
        var refused = Run("render", scene, "-o", exact, "--sampler", "exact", "--threads", "2");
        Assert.Equal(1, refused.Code);
        string line = Assert.Single(refused.Err.TrimEnd().Split('\n'));
        Assert.StartsWith("raylab: error: ", line, StringComparison.Ordinal);
        Assert.Contains($"at most {OutlineSet.MaxSpheresInView}", line, StringComparison.Ordinal);
        Assert.Empty(Directory.GetFiles(_dir, "exact*"));
    }
}
