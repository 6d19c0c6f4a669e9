using RayLab.Scenes;

namespace RayLab.Cli.Tests;

/// <summary>The scenes raylab carries: <c>raylab scenes</c>, and <c>raylab render NAME</c> from a folder outside the repository.</summary>
public sealed class CarriedScenesTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    private static readonly string[] Carried = [.. Directory.EnumerateFiles(Path.Combine(AppContext.BaseDirectory, "scenes"), "*.json")
        .Select(f => Path.GetFileNameWithoutExtension(f)).Order(StringComparer.Ordinal)];

    [Fact]
    public void Scenes_lists_every_carried_file_with_its_size_and_sampler()
    {
        var r = ConsoleRunner.Run("scenes");

        Assert.True(r.Code == 0, r.Err);
        Assert.Equal(Carried, CarriedScenes.Names);
        Assert.Contains("two-spheres", Carried);
        string[] lines = r.Out.TrimEnd().Split('\n');
        Assert.Equal(Carried.Length + 1, lines.Length);
        for (int i = 0; i < Carried.Length; i++)
        {
            SceneDescription d = SceneFile.Load(Path.Combine(CarriedScenes.Folder, Carried[i] + ".json"));
            Assert.StartsWith(Carried[i] + " ", lines[i], StringComparison.Ordinal);
            Assert.Contains($"{d.Width}×{d.Height}, {d.Camera.Type} camera, {d.Scene.Spheres.Count} spheres, ", lines[i], StringComparison.Ordinal);
        }

        Assert.Contains("raylab render two-spheres -o out.png", lines[^1], StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("two-spheres")]
    [InlineData("two-spheres.json")]
    [InlineData("off-axis")]
    public async Task A_carried_scene_renders_by_name_from_a_folder_outside_the_repository(string name)
    {
        var r = await ConsoleRunner.RunChildAsync(_dir.Path, "render", name, "-o", "x.png", "--width", "40", "--height", "30");

        Assert.True(r.Code == 0, r.Err);
        PngTestDecoder.Result png = PngTestDecoder.Decode(File.ReadAllBytes(_dir.File("x.png")));
        Assert.Equal((40, 30), (png.Width, png.Height));
        Assert.Contains(png.Rgb, b => b != png.Rgb[0]); // the spheres are in the picture, not only the background
    }

    [Fact]
    public async Task A_file_of_that_name_in_the_current_folder_wins_over_the_carried_scene()
    {
        string own = File.ReadAllText(Path.Combine(CarriedScenes.Folder, "two-spheres.json"))
            .Replace("\"width\": 800", "\"width\": 24", StringComparison.Ordinal);
        Assert.Contains("\"width\": 24", own, StringComparison.Ordinal);
        File.WriteAllText(_dir.File("two-spheres.json"), own);

        var r = await ConsoleRunner.RunChildAsync(_dir.Path, "render", "two-spheres.json", "-o", "x.png", "--height", "10");

        Assert.True(r.Code == 0, r.Err);
        Assert.Equal(24, PngTestDecoder.Decode(File.ReadAllBytes(_dir.File("x.png"))).Width);
    }

    [Fact]
    public void An_unknown_name_is_one_line_with_the_carried_names_and_the_nearest_and_writes_nothing()
    {
        string output = _dir.File("x.png");

        var r = ConsoleRunner.Run("render", "two-sphere", "-o", output);

        Assert.Equal(1, r.Code);
        string line = Assert.Single(r.Err.TrimEnd().Split('\n'));
        Assert.Equal(
            $"raylab: error: scene: 'two-sphere' is neither a file here nor a carried scene; carried scenes: {string.Join(", ", Carried)}; did you mean 'two-spheres'? (see 'raylab scenes')",
            line);
        Assert.False(File.Exists(output));
    }

    [Fact]
    public async Task A_bare_name_that_is_a_folder_here_is_one_line_saying_so()
    {
        Directory.CreateDirectory(_dir.File("shots"));

        var r = await ConsoleRunner.RunChildAsync(_dir.Path, "render", "shots", "-o", "x.png");

        Assert.Equal(1, r.Code);
        Assert.Equal("raylab: error: scene: 'shots' is a folder here, not a scene file (a .json file, or a carried scene: see 'raylab scenes')",
            Assert.Single(r.Err.TrimEnd().Split('\n')));
        Assert.False(File.Exists(_dir.File("x.png")));
    }

    [Fact]
    public void A_path_with_a_folder_is_never_taken_for_a_carried_name()
    {
        var r = ConsoleRunner.Run("render", Path.Combine(_dir.Path, "two-spheres.json"), "-o", _dir.File("x.png"));

        Assert.Equal(1, r.Code);
        Assert.Contains("cannot read the file", r.Err, StringComparison.Ordinal);
    }
}
