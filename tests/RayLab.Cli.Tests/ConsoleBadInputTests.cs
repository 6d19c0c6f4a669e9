
namespace RayLab.Cli.Tests;

/// <summary>
/// The bad-input audit through the console, for what ConsoleTests and AdaptiveCliTests did not cover: every
/// option out of range or unparsable, unusable paths for every file the app reads or writes. Each is one line
/// on stderr naming the option or file, exit 1 (bad input) or 2 (a malformed command line), and no file.
/// </summary>
public sealed class ConsoleBadInputTests : IDisposable
{
    private const string Scene = """
        { "image": { "width": 24, "height": 18 },
          "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "fov": 40 },
          "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": [0.5, 0.25, 1] } ] }
        """;

    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Theory]
    // Options out of range: the same limits as the scene file's fields.
    [InlineData(1, "--width", "1048576", "--width", "2000000")]
    [InlineData(1, "--height", "1", "--height", "0")]
    [InlineData(1, "--width/--height", "2,147,483,591", "--width", "1048576", "--height", "1048576")]
    [InlineData(1, "--samples", "65536", "--sampler", "random", "--samples", "100000")]
    [InlineData(1, "--contrast", "finite", "--sampler", "adaptive", "--contrast", "NaN")]
    [InlineData(1, "--contrast", "finite", "--sampler", "adaptive", "--contrast", "Infinity")]
    [InlineData(1, "--min-depth", "0", "--sampler", "adaptive", "--min-depth", "-1")]
    [InlineData(1, "--min-depth", "3", "--sampler", "adaptive", "--min-depth", "4", "--max-depth", "3")]
    [InlineData(1, "--max-depth", "10", "--sampler", "adaptive", "--max-depth", "-1")]
    [InlineData(1, "--threads", "-2", "--threads", "-2")]
    [InlineData(1, "--camera", "''", "--camera", "")]
    // Values that are not numbers of the option's type: a malformed command line.
    [InlineData(2, "", "--seed", "--seed", "-1")]
    [InlineData(2, "", "--width", "--width", "abc")]
    [InlineData(2, "", "--samples", "--samples", "1.5")]
    [InlineData(2, "", "--threads", "--threads")]
    // Output paths that cannot be written.
    [InlineData(1, "--output", "not a usable path", "-o", "{dir}/a\0b.png")]
    [InlineData(1, "--output", "is a folder", "-o", "{dir}/folder.png")]
    [InlineData(1, "--output", "the path is empty", "-o", " ")]
    [InlineData(1, "--stats", "not a usable path", "--stats", "{dir}/a\0b.json")]
    [InlineData(1, "--heatmap", "does not exist", "--heatmap", "{dir}/no-such-folder/heat.png")]
    [InlineData(1, "--heatmap", ".webp", "--heatmap", "{dir}/heat.gif")]
    [InlineData(1, "--quality", "0 to 100", "--quality", "101")]
    [InlineData(1, "--quality", "0 to 100", "--quality", "-1")]
    [InlineData(1, "--heatmap", "same file", "--heatmap", "{out}")]
    public void AnOptionProblemIsOneLineNamingTheOptionAndLeavesNoFile(int code, string option, string mention, params string[] options)
    {
        string scene = WriteScene();
        Directory.CreateDirectory(_dir.File("folder.png"));
        string[] output = options.Contains("-o") ? [] : ["-o", _dir.File("out.png")];
        string[] args = ["render", scene, .. output, .. options];
        AssertFailsCleanly(code, option.Length == 0 ? "raylab: error: " : $"raylab: error: {option}: ", mention, Fill(args));
    }

    [Theory]
    // A folder nobody can create files in (even root): found before the render, and no file is left, not even the
    // picture when only the stats or the heat map cannot be written.
    [InlineData("--output", "-o", "/proc/raylab-out.png")]
    [InlineData("--stats", "--stats", "/proc/raylab-stats.json")]
    [InlineData("--heatmap", "--heatmap", "/proc/raylab-heat.png")]
    public void AnOutputFolderThatCannotBeWrittenIsOneLineNamingTheOptionAndLeavesNoFile(string option, params string[] options)
    {
        Assert.SkipUnless(OperatingSystem.IsLinux(), "/proc is Linux's");
        string scene = WriteScene();
        string[] output = options.Contains("-o") ? [] : ["-o", _dir.File("out.png")];
        AssertFailsCleanly(1, $"raylab: error: {option}: ", "cannot write in the folder '/proc'", ["render", scene, .. output, .. options]);
    }

    [Theory]
    [InlineData("{dir}", "cannot read the file")]
    [InlineData("{dir}/a\0b.json", "cannot read the file")]
    [InlineData("{dir}/missing.json", "cannot read the file")]
    public void AnUnreadableScenePathIsOneLineNamingIt(string scene, string mention)
    {
        string path = Fill([scene])[0];
        AssertFailsCleanly(1, $"raylab: error: {SceneFile(path)}: ", mention, "render", path, "-o", _dir.File("out.png"));
    }

    [Theory]
    [InlineData("")]
    [InlineData(" ")]
    public void AnEmptyScenePathIsOneLine(string scene) =>
        AssertFailsCleanly(1, "raylab: error: scene: the path is empty", "", "render", scene, "-o", _dir.File("out.png"));

    [Fact]
    public void ASceneFileWithoutReadPermissionIsOneLineNamingIt()
    {
        Assert.SkipWhen(OperatingSystem.IsWindows(), "Unix file modes only");
        string scene = WriteScene();
        if (!OperatingSystem.IsWindows())
        {
            File.SetUnixFileMode(scene, UnixFileMode.None);
        }

        try
        {
            using FileStream probe = File.OpenRead(scene); // root reads anything: nothing to test then
            Assert.Skip("running with permission to read any file (root)");
        }
        catch (UnauthorizedAccessException)
        {
        }

        AssertFailsCleanly(1, $"raylab: error: {scene}: ", "cannot read the file", "render", scene, "-o", _dir.File("out.png"));
    }

    private string WriteScene()
    {
        string path = _dir.File("scene.json");
        File.WriteAllText(path, Scene);
        return path;
    }

    private static string SceneFile(string path) => path.Replace("\0", "\\u0000", StringComparison.Ordinal);

    private string[] Fill(string[] args) =>
        [.. args.Select(a => a.Replace("{dir}", _dir.Path, StringComparison.Ordinal).Replace("{out}", _dir.File("out.png"), StringComparison.Ordinal))];

    private void AssertFailsCleanly(int expectedCode, string expectedStart, string mention, params string[] args)
    {
        string[] before = _dir.Entries();
        var stdout = new StringWriter();
        var stderr = new StringWriter();

        int code = Program.Run(args, stdout, stderr);

        string err = stderr.ToString();
        Assert.True(code == expectedCode, $"exit {code}: {err}");
        Assert.Equal("", stdout.ToString());
        Assert.EndsWith(Environment.NewLine, err, StringComparison.Ordinal);
        string line = Assert.Single(err[..^Environment.NewLine.Length].Split('\n'));
        Assert.StartsWith(expectedStart, line, StringComparison.Ordinal);
        Assert.Contains(mention, line, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", err, StringComparison.Ordinal);
        Assert.Equal(before, _dir.Entries());
    }
}
