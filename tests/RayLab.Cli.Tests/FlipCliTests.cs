using System.Globalization;
using System.Text.RegularExpressions;
using RayLab.Reports.Imaging;
using RayLab.Metrics;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Cli.Tests;

/// <summary><c>raylab flip REF TEST [-o MAP]</c>: the library's numbers for a pair of renders, and one line for every bad input.</summary>
public sealed partial class FlipCliTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    /// <summary>The lab's two spheres at 64×48: the exact image and a jittered render at one sample per pixel, as PNG files.</summary>
    private (string Reference, string Test) Renders()
    {
        SceneDescription d = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json")) with { Width = 64, Height = 48 };
        PreparedScene scene = d.Prepare();
        var exact = new Image(64, 48);
        new Renderer().Render(scene.Scene, scene.Camera, RenderMethod.Exact, exact);
        var jittered = new Image(64, 48);
        new Renderer().Render(scene.Scene, scene.Camera, RenderMethod.Sampled(new JitteredSampler(1, seed: 1)), jittered);
        string reference = _dir.File("exact.png"), test = _dir.File("jittered-1.png");
        exact.Save(reference);
        jittered.Save(test);
        return (reference, test);
    }

    [Fact]
    public void PrintsTheLibrarysFlipAndRmseAndWritesTheMagmaMap()
    {
        (string reference, string test) = Renders();
        string map = _dir.File("map.png");

        (int code, string stdout, string stderr) = ConsoleRunner.Run("flip", reference, test, "-o", map);

        Assert.Equal("", stderr);
        Assert.Equal(0, code);
        Image a = Image.Load(reference), b = Image.Load(test);
        FlipResult flip = Flip.Compute(a, b);
        ImageError error = ImageError.Measure(b, a);
        Assert.True(flip.Mean > 0.001 && error.Rmse > 1, "the pair differs enough to measure");
        Match m = Numbers().Match(stdout);
        Assert.True(m.Success, stdout);
        Assert.Equal(flip.Mean, double.Parse(m.Groups["flip"].Value, CultureInfo.InvariantCulture), 6);
        Assert.Equal(error.Rmse, double.Parse(m.Groups["rmse"].Value, CultureInfo.InvariantCulture), 4);
        Assert.Equal(FlipMap.Render(flip).PixelBytes.ToArray(), Image.Load(map).PixelBytes.ToArray());
        Match low = Regex.Match(stdout, @"low-pass RMSE (?<one>[0-9.]+) levels \(Gaussian blur σ = 1 px\), (?<two>[0-9.]+) \(σ = 2 px\); low share (?<share>[0-9.]+)");
        Assert.True(low.Success, stdout);
        Assert.Equal(ErrorLocation.LowPassRmse(b, a, 1), double.Parse(low.Groups["one"].Value, CultureInfo.InvariantCulture), 4);
        Assert.Equal(ErrorLocation.LowPassRmse(b, a, 2), double.Parse(low.Groups["two"].Value, CultureInfo.InvariantCulture), 4);
        Assert.Equal(ErrorLocation.Spectrum(b, a).LowFrequencyShare, double.Parse(low.Groups["share"].Value, CultureInfo.InvariantCulture), 4);
        Assert.Equal(4, stdout.TrimEnd('\n').ReplaceLineEndings("\n").Split('\n').Length);
    }

    [Fact]
    public void WithoutAMapPathItWritesNothingAndAnotherViewingDistanceChangesTheFlip()
    {
        (string reference, string test) = Renders();
        string[] before = _dir.Entries();

        (int code, string stdout, string stderr) = ConsoleRunner.Run("flip", reference, test);
        (int nearCode, string near, _) = ConsoleRunner.Run("flip", reference, test, "--ppd", "20");

        Assert.Equal((0, 0, ""), (code, nearCode, stderr));
        Assert.Equal(before, _dir.Entries());
        Assert.Equal(3, stdout.TrimEnd('\n').ReplaceLineEndings("\n").Split('\n').Length);
        double paper = double.Parse(Numbers().Match(stdout).Groups["flip"].Value, CultureInfo.InvariantCulture);
        double closer = double.Parse(Numbers().Match(near).Groups["flip"].Value, CultureInfo.InvariantCulture);
        Assert.Equal(Flip.Compute(Image.Load(reference), Image.Load(test), new FlipOptions { PixelsPerDegree = 20 }).Mean, closer, 6);
        Assert.NotEqual(paper, closer);
        Assert.Contains("20.00 pixels per degree", near, StringComparison.Ordinal);
    }

    [Fact]
    public void IdenticalPicturesScoreZero()
    {
        (string reference, _) = Renders();

        (int code, string stdout, _) = ConsoleRunner.Run("flip", reference, reference);

        Assert.Equal(0, code);
        Assert.StartsWith("mean FLIP 0.000000 ", stdout, StringComparison.Ordinal);
        Assert.Contains("RMSE 0.0000 levels", stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryBadInputIsOneLineNamingTheFileAndWritesNothing()
    {
        (string reference, string test) = Renders();
        string small = _dir.File("small.png");
        new Image(32, 24).Save(small);
        string text = _dir.File("notes.png");
        File.WriteAllText(text, "these are notes, not a picture");
        string empty = _dir.File("empty.png");
        File.WriteAllBytes(empty, []);
        string cut = _dir.File("cut.png");
        byte[] whole = File.ReadAllBytes(test);
        File.WriteAllBytes(cut, whole[..(whole.Length / 2)]);
        string missing = _dir.File("missing.png");
        string map = _dir.File("map.png");

        AssertFails($"raylab: error: {small}: the picture is 32×24 but the reference {reference} is 64×48", "flip", reference, small, "-o", map);
        AssertFails($"raylab: error: {missing}: no such file", "flip", missing, test, "-o", map);
        AssertFails($"raylab: error: {missing}: no such file", "flip", reference, missing, "-o", map);
        AssertFails($"raylab: error: {text}: not a picture", "flip", reference, text, "-o", map);
        AssertFails($"raylab: error: {empty}: not a picture", "flip", empty, test, "-o", map);
        AssertFails($"raylab: error: {cut}: ", "flip", reference, cut, "-o", map);
        AssertFails($"raylab: error: {_dir.Path}: is a folder, not a picture", "flip", _dir.Path, test, "-o", map);
        AssertFails("raylab: error: --output: No registered image format writes '.txt' files", "flip", reference, test, "-o", _dir.File("map.txt"));
        AssertFails("raylab: error: --output: Cannot tell the image format of ", "flip", reference, test, "-o", _dir.File("map"));
        AssertFails($"raylab: error: --output: the folder '{_dir.File("no")}' does not exist", "flip", reference, test, "-o", _dir.File(Path.Combine("no", "map.png")));
        AssertFails($"raylab: error: --output: '{test}' is one of the pictures compared", "flip", reference, test, "-o", test);
        AssertFails("raylab: error: --ppd: expected 1 to 1000 pixels per degree, got 0", "flip", reference, test, "--ppd", "0");
        AssertFails("raylab: error: ", "flip", reference); // TEST is required: a command-line error
        AssertFails("raylab: error: --ppd: expected a number, got 'far'", "flip", reference, test, "--ppd", "far");
    }

    private void AssertFails(string expectedStart, params string[] args)
    {
        string[] before = _dir.Entries();
        byte[][] contents = [.. before.Select(e => File.Exists(_dir.File(e)) ? File.ReadAllBytes(_dir.File(e)) : [])];

        (int code, string stdout, string stderr) = ConsoleRunner.Run(args);

        Assert.True(code is 1 or 2, $"exit code {code}: {stderr}");
        Assert.Equal("", stdout);
        string line = Assert.Single(stderr.TrimEnd('\n').ReplaceLineEndings("\n").Split('\n'));
        Assert.StartsWith(expectedStart, line, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", stderr, StringComparison.Ordinal);
        Assert.Equal(before, _dir.Entries());
        Assert.Equal(contents, before.Select(e => File.Exists(_dir.File(e)) ? File.ReadAllBytes(_dir.File(e)) : []));
    }

    [GeneratedRegex(@"^mean FLIP (?<flip>\d+\.\d{6}) .*\nRMSE (?<rmse>\d+\.\d{4}) levels", RegexOptions.Multiline)]
    private static partial Regex Numbers();
}
