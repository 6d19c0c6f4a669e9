using System.Globalization;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Cli.Tests;

/// <summary>
/// <c>raylab --help</c> and <c>raylab render --help</c>: every option with its default (what the scene file says, and
/// what a scene that omits the field gets) and its range or choices, wrapped at 80 columns when not on a terminal.
/// </summary>
public sealed class HelpTests
{
    private static (int Code, string Out, string Err) Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return (code, stdout.ToString(), stderr.ToString());
    }

    private static string RenderHelp()
    {
        var r = Run("render", "--help");
        Assert.Equal(0, r.Code);
        Assert.Equal("", r.Err);
        return r.Out;
    }

    [Theory]
    [InlineData("--help")]
    [InlineData("-h")]
    [InlineData("render", "--help")]
    public void HelpFitsIn80Columns(params string[] args)
    {
        var r = Run(args);

        Assert.Equal(0, r.Code);
        string[] lines = r.Out.ReplaceLineEndings("\n").Split('\n');
        Assert.True(lines.Length > 5, r.Out);
        Assert.All(lines, line => Assert.True(line.TrimEnd().Length <= 80, $"{line.TrimEnd().Length} columns: {line}"));
    }

    [Fact]
    public void TheTopHelpNamesTheRenderCommandAndWhereItsOptionsAre()
    {
        var r = Run("--help");

        Assert.Equal(0, r.Code);
        string text = Unwrap(r.Out);
        Assert.Contains("render <scene>", text, StringComparison.Ordinal);
        Assert.Contains("With no command, renders the two-sphere scene", text, StringComparison.Ordinal);
        Assert.Contains("'raylab render --help' lists the options", text, StringComparison.Ordinal);
        Assert.Contains("--version", text, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--output", "(REQUIRED)", ".png, .bmp, .jpg/.jpeg or .webp")]
    [InlineData("--camera", "Default: the scene's camera.type.", "perspective or orthographic")]
    [InlineData("--sampler", "Default: the scene's sampler.type;", "regular, random, jittered, cmj, multijittered, nrooks, hammersley, sobol, pmj02, pmj02bn, zsobol, adaptive or exact")]
    [InlineData("--samples", "Default: the scene's sampler.samples;", "1 to 65536; a perfect square (1, 4, 9, …) for regular, jittered and multijittered")]
    [InlineData("--seed", "Default: the scene's sampler.seed;", "0 to 4294967295")]
    [InlineData("--min-depth", "Default: the scene's sampler.minDepth;", "0 to the maximum depth")]
    [InlineData("--max-depth", "Default: the scene's sampler.maxDepth;", "0 to 10")]
    [InlineData("--contrast", "Default: the scene's sampler.contrast;", "≥ 0")]
    [InlineData("--quincunx", "Default: the scene's sampler.quincunx;", "every pixel's centre")]
    [InlineData("--kernel", "Default: auto.", "auto, scalar, vector128, vector256 or vector512")]
    [InlineData("--device", "Default: cpu.", "cpu, gpu or auto")]
    [InlineData("--width", "Default: the scene's image.width.", "1 to 1048576, with W·H·3 ≤ 2,147,483,591 bytes")]
    [InlineData("--height", "Default: the scene's image.height.", "1 to 1048576, with W·H·3 ≤ 2,147,483,591 bytes")]
    [InlineData("--threads", "Default: all cores", "≥ 1")]
    [InlineData("--stats", "Default: none.", "JSON")]
    [InlineData("--warmup", "Default: off", "leaves out JIT compilation")]
    [InlineData("--heatmap", "Default: none.", ".png, .bmp, .jpg/.jpeg or .webp")]
    [InlineData("--quality", "Default: 90.", "0 to 100")]
    public void EachRenderOptionStatesItsDefaultAndRange(string option, string defaultText, string rangeText)
    {
        string entry = OptionEntry(RenderHelp(), option);

        Assert.Contains(defaultText, entry, StringComparison.Ordinal);
        Assert.Contains(rangeText, entry, StringComparison.Ordinal);
    }

    [Fact]
    public void EveryRenderOptionInTheHelpHasADefaultOrIsRequired()
    {
        string[] entries = OptionEntries(RenderHelp());

        Assert.Equal(20, entries.Length); // --output, 18 other options and --help
        Assert.All(entries.Where(e => !e.Contains("--help", StringComparison.Ordinal)), e =>
            Assert.True(e.Contains("Default:", StringComparison.Ordinal) || e.Contains("(REQUIRED)", StringComparison.Ordinal), e));
    }

    [Fact]
    public void TheSamplerChoicesInTheHelpAreTheOnesTheSceneFileAccepts()
    {
        string entry = OptionEntry(RenderHelp(), "--sampler");

        Assert.All(SamplerSettings.Types, name => Assert.Contains(name, entry, StringComparison.Ordinal));
        Assert.Contains($"0 to {AdaptiveSampler.MaxSupportedDepth}", OptionEntry(RenderHelp(), "--max-depth"), StringComparison.Ordinal);
    }

    [Fact]
    public void TheDefaultsInTheHelpAreWhatASceneFileWithoutThoseFieldsGets()
    {
        const string Scene = """
            { "image": { "width": 4, "height": 3 }, "spheres": [],
              "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0] } %SAMPLER% }
            """;
        SamplerSettings none = SceneFile.Parse(Scene.Replace("%SAMPLER%", "", StringComparison.Ordinal)).Sampler;
        SamplerSettings random = SceneFile.Parse(Scene.Replace("%SAMPLER%", ", \"sampler\": { \"type\": \"random\" }", StringComparison.Ordinal)).Sampler;
        SamplerSettings adaptive = SceneFile.Parse(Scene.Replace("%SAMPLER%", ", \"sampler\": { \"type\": \"adaptive\" }", StringComparison.Ordinal)).Sampler;
        string help = RenderHelp();

        Assert.Contains($"; {none.Type} if omitted", OptionEntry(help, "--sampler"), StringComparison.Ordinal);
        Assert.Contains($"; {random.Samples} if omitted", OptionEntry(help, "--samples"), StringComparison.Ordinal);
        Assert.Contains($"; {random.Seed} if omitted", OptionEntry(help, "--seed"), StringComparison.Ordinal);
        Assert.Contains($"; {adaptive.MinDepth} if omitted", OptionEntry(help, "--min-depth"), StringComparison.Ordinal);
        Assert.Contains($"; {adaptive.MaxDepth} if omitted", OptionEntry(help, "--max-depth"), StringComparison.Ordinal);
        Assert.Contains($"; {adaptive.Contrast.ToString(CultureInfo.InvariantCulture)} if omitted", OptionEntry(help, "--contrast"), StringComparison.Ordinal);
        Assert.Contains($"; {(adaptive.Quincunx ? "true" : "false")} if omitted", OptionEntry(help, "--quincunx"), StringComparison.Ordinal);
    }

    [Fact]
    public void TheSceneArgumentIsDescribed()
    {
        string text = Unwrap(RenderHelp());

        Assert.Contains("<scene>  The scene file: JSON", text, StringComparison.Ordinal);
        Assert.Contains("raylab render <scene> [options]", text, StringComparison.Ordinal);
    }

    // ---- reading the help ------------------------------------------------------------------------------

    /// <summary>The help with its wrapped lines joined: runs of spaces (the indentation of a continuation) become one.</summary>
    private static string Unwrap(string help) =>
        string.Join(' ', help.ReplaceLineEndings("\n").Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0));

    /// <summary>The option entries of the help, each unwrapped to one line: "--seed &lt;S&gt; The sampler's seed, …".</summary>
    private static string[] OptionEntries(string help)
    {
        string[] lines = help.ReplaceLineEndings("\n").Split('\n');
        int start = Array.IndexOf(lines, "Options:");
        Assert.True(start >= 0, help);
        var entries = new List<string>();
        foreach (string line in lines.Skip(start + 1).TakeWhile(l => l.Length > 0))
        {
            if (line.StartsWith("  -", StringComparison.Ordinal))
            {
                entries.Add(line.Trim());
            }
            else
            {
                Assert.NotEmpty(entries);
                entries[^1] += " " + line.Trim();
            }
        }

        return [.. entries];
    }

    private static string OptionEntry(string help, string option) =>
        Assert.Single(OptionEntries(help), e => e.Split(' ', ',').Contains(option));
}
