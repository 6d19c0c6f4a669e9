namespace RayLab.Cli.Tests;

/// <summary>
/// Every command that writes into a folder says the same thing, in the same words, when nothing can be created there:
/// the option, the folder, and why, checked before any work is done.
/// </summary>
public sealed class OutputFolderMessageTests
{
    [Theory]
    [InlineData("--output", "/proc", "render", "{scene}", "-o", "/proc/raylab-out.png")]
    [InlineData("--stats", "/proc", "render", "{scene}", "-o", "{dir}/out.png", "--stats", "/proc/raylab-stats.json")]
    [InlineData("--out", "/proc/raylab-report", "compare", "{scene}", "--out", "/proc/raylab-report")]
    [InlineData("--out", "/proc/raylab-patterns", "patterns", "--out", "/proc/raylab-patterns", "--sampler", "regular")]
    public void AFolderNothingCanBeCreatedInIsTheSameLineForEveryCommand(string option, string folder, params string[] args)
    {
        Assert.SkipUnless(OperatingSystem.IsLinux(), "/proc is Linux's: nobody can create files or folders in it, not even root");
        using var dir = new RayLab.Tests.Shared.TempDirectory();
        string scene = dir.File("scene.json");
        File.WriteAllText(scene, """
            { "image": { "width": 8, "height": 6 },
              "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "fov": 40 },
              "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": [0.5, 0.25, 1] } ] }
            """);
        string[] filled = [.. args.Select(a => a.Replace("{scene}", scene, StringComparison.Ordinal).Replace("{dir}", dir.Path, StringComparison.Ordinal))];
        var stdout = new StringWriter();
        var stderr = new StringWriter();

        int code = Program.Run(filled, stdout, stderr, TestContext.Current.CancellationToken);

        Assert.Equal(1, code);
        Assert.Equal($"raylab: error: {option}: cannot write in the folder '{folder}': nothing can be created there", stderr.ToString().TrimEnd());
        Assert.Equal(["scene.json"], dir.Entries());
    }
}
