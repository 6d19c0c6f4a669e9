
namespace RayLab.Cli.Tests;

/// <summary>
/// Mistyped commands, options and choice values: one line naming what was typed and the nearest valid name, exit 2
/// for the command line and 1 for a bad value, and nothing written.
/// </summary>
public sealed class TypoTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-typos-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    private string Output => Path.Combine(_dir, "out.png");

    private (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        Assert.Empty(Directory.GetFileSystemEntries(_dir));
        return (code, stdout.ToString(), stderr.ToString());
    }

    [Fact]
    public void AnUnknownCommandSuggestsTheNearestOne()
    {
        var r = Run("rendr", Scene, "-o", Output);

        Assert.Equal(2, r.Code);
        Assert.Equal("", r.Out);
        Assert.Equal("raylab: error: unknown command 'rendr'; did you mean 'render'? (see 'raylab --help')" + Environment.NewLine, r.Err);
    }

    [Theory]
    [InlineData("--sampels", "4", "'--samples'")]
    [InlineData("--sample", "4", "'--sampler' or '--samples'")]
    [InlineData("--heigth", "40", "'--height'")]
    [InlineData("--maxdepth", "2", "'--max-depth'")]
    public void AnUnknownOptionSuggestsTheNearestOne(string typed, string value, string suggestion)
    {
        var r = Run("render", Scene, "-o", Output, typed, value);

        Assert.Equal(2, r.Code);
        Assert.Equal("", r.Out);
        Assert.Equal($"raylab: error: unknown option '{typed}'; did you mean {suggestion}? (see 'raylab render --help')" + Environment.NewLine, r.Err);
    }

    [Fact]
    public void AMistypedRequiredOptionIsReportedAsTheTypoNotAsMissing()
    {
        var r = Run("render", Scene, "--ouput", Output);

        Assert.Equal(2, r.Code);
        Assert.StartsWith("raylab: error: unknown option '--ouput'; did you mean '--output'?", r.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void AnUnknownOptionOfTheTopCommandSuggestsFromItsOptions()
    {
        var r = Run("--verison");

        Assert.Equal(2, r.Code);
        Assert.Equal("raylab: error: unknown option '--verison'; did you mean '--version'? (see 'raylab --help')" + Environment.NewLine, r.Err);
    }

    [Fact]
    public void AnUnexpectedArgumentWithNothingCloseHasNoSuggestion()
    {
        var r = Run("render", Scene, "extra", "-o", Output);

        Assert.Equal(2, r.Code);
        Assert.Equal("raylab: error: unexpected argument 'extra' (see 'raylab render --help')" + Environment.NewLine, r.Err);
    }

    [Theory]
    [InlineData("--sampler", "jitterd", "sampler", "jittered")]
    [InlineData("--sampler", "Sobol", "sampler", "sobol")]
    [InlineData("--camera", "persp", "camera", "perspective")]
    [InlineData("--camera", "orthograhpic", "camera", "orthographic")]
    public void AMistypedChoiceSuggestsTheNearestValueAndIsBadInput(string option, string typed, string what, string meant)
    {
        var r = Run("render", Scene, "-o", Output, option, typed);

        Assert.Equal(1, r.Code);
        Assert.Equal("", r.Out);
        string line = Assert.Single(r.Err.ReplaceLineEndings("\n").TrimEnd('\n').Split('\n'));
        Assert.StartsWith($"raylab: error: {option}: unknown {what} '{typed}'; expected one of: ", line, StringComparison.Ordinal);
        Assert.EndsWith($"; did you mean '{meant}'?", line, StringComparison.Ordinal);
    }

    [Fact]
    public void AChoiceWithNothingCloseListsTheChoicesOnly()
    {
        var r = Run("render", Scene, "-o", Output, "--camera", "fisheye");

        Assert.Equal(1, r.Code);
        Assert.Equal("raylab: error: --camera: unknown camera 'fisheye'; expected one of: perspective, orthographic" + Environment.NewLine, r.Err);
    }

    [Theory]
    [InlineData("--samples", "abc", "a whole number")]
    [InlineData("--width", "4.5", "a whole number")]
    [InlineData("--seed", "-1", "a whole number from 0 to 4294967295")]
    [InlineData("--contrast", "high", "a number")]
    public void ANumberThatDoesNotParseNamesTheOptionAndWhatItTakes(string option, string value, string expected)
    {
        var r = Run("render", Scene, "-o", Output, option, value);

        Assert.Equal(2, r.Code);
        Assert.Equal($"raylab: error: {option}: expected {expected}, got '{value}' (see 'raylab render --help')" + Environment.NewLine, r.Err);
    }
}
