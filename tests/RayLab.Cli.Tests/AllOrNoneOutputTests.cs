namespace RayLab.Cli.Tests;

/// <summary>
/// <c>raylab render</c> writes its outputs all or none, existing files included: when a later output cannot be
/// written, a file the run would have replaced keeps its bytes and no temporary file is left.
/// </summary>
public sealed class AllOrNoneOutputTests : IDisposable
{
    private const string Scene = """
        { "image": { "width": 16, "height": 12 },
          "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "fov": 40 },
          "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": [0.5, 0.25, 1] } ] }
        """;

    private static readonly byte[] OldPicture = "the picture an earlier run wrote"u8.ToArray();

    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Theory]
    // The stats' folder is gone by the time the stats are written: the write itself fails.
    [InlineData("folder removed")]
    // A folder now stands where the stats go: moving them into place fails, after the picture's move.
    [InlineData("folder in the way")]
    public void AnExistingPictureKeepsItsBytesWhenTheStatsCannotBeWritten(string failure)
    {
        string scene = _dir.File("scene.json");
        File.WriteAllText(scene, Scene);
        string output = _dir.File("out.png");
        File.WriteAllBytes(output, OldPicture);
        string statsFolder = _dir.File("stats");
        Directory.CreateDirectory(statsFolder);
        string stats = Path.Combine(statsFolder, "stats.json");
        // The gate: the sampler's notice is written after the output paths were checked and before any file is.
        var stderr = new GateWriter("raylab: note:", () =>
        {
            if (failure == "folder removed")
            {
                Directory.Delete(statsFolder);
            }
            else
            {
                Directory.CreateDirectory(stats);
            }
        });
        var stdout = new StringWriter();

        int code = Program.Run(["render", scene, "-o", output, "--stats", stats, "--sampler", "adaptive", "--samples", "4"], stdout, stderr, TestContext.Current.CancellationToken);

        string[] lines = stderr.ToString().TrimEnd().Split('\n');
        Assert.True(stderr.Opened, "the gate never opened: the notice is no longer written between the checks and the writes");
        Assert.Equal(1, code);
        Assert.Equal(2, lines.Length);
        Assert.StartsWith($"raylab: error: --stats: cannot write '{stats}'", lines[1], StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", stderr.ToString(), StringComparison.Ordinal);
        Assert.Equal(OldPicture, File.ReadAllBytes(output));
        string[] expected = failure == "folder removed" ? ["out.png", "scene.json"] : ["out.png", "scene.json", "stats", Path.Combine("stats", "stats.json")];
        Assert.Equal(expected, _dir.Entries());
    }

    /// <summary>Captures what is written and runs <paramref name="open"/> once, on the first line that starts with <paramref name="prefix"/>.</summary>
    private sealed class GateWriter(string prefix, Action open) : StringWriter
    {
        public bool Opened { get; private set; }

        public override void WriteLine(string? value)
        {
            base.WriteLine(value);
            if (!Opened && value is not null && value.StartsWith(prefix, StringComparison.Ordinal))
            {
                Opened = true;
                open();
            }
        }
    }
}
