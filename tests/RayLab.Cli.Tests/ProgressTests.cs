using System.Text.RegularExpressions;
using RayLab.Scenes;
using Spectre.Console;

namespace RayLab.Cli.Tests;

/// <summary>
/// The render progress bar: drawn (with escape codes) on an interactive ANSI console, never on redirected output,
/// and the rays-per-second figure in the summary line either way.
/// </summary>
public sealed partial class ProgressTests : IDisposable
{
    private const char Escape = '\x1b';

    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-progress-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    private static string Scene => Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    [GeneratedRegex(@", render \d+\.\d ms \((\d+\.\d) Mrays/s; JIT build: includes compiling what this run had not run before\), encode \d+\.\d ms$")]
    private static partial Regex RaysPerSecond();

    [Fact]
    public void ARenderIntoWritersThatAreNotTheTerminalPrintsNoEscapeCodesAndOneSummaryWithRaysPerSecond()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();

        int code = Program.Run(["render", Scene, "-o", Path.Combine(_dir, "a.png"), "--width", "160", "--height", "120",
            "--sampler", "jittered", "--samples", "4"], stdout, stderr, TestContext.Current.CancellationToken);

        Assert.Equal(0, code);
        Assert.DoesNotContain(Escape, stdout.ToString());
        Assert.Equal("", stderr.ToString());
        string line = Assert.Single(stdout.ToString().ReplaceLineEndings("\n").TrimEnd('\n').Split('\n'));
        Assert.Matches(RaysPerSecond(), line);
        Assert.Contains("76,800 rays", line, StringComparison.Ordinal); // 160·120·4
        Assert.False(ProgressDisplay.IsTerminal(stdout));
    }

    [Fact]
    public async Task TheAppWithRedirectedOutputPrintsNoEscapeCodes()
    {
        // A child process whose stdout is a pipe: Console.Out is the real standard output here, and it is redirected.
        (int code, string output, string error) = await ConsoleRunner.RunChildAsync(
            _dir, "render", Scene, "-o", "b.png", "--width", "320", "--height", "240", "--sampler", "jittered", "--samples", "16");

        Assert.Equal(0, code);
        Assert.Equal("", error);
        Assert.DoesNotContain(Escape, output);
        Assert.Matches(RaysPerSecond(), Assert.Single(output.ReplaceLineEndings("\n").TrimEnd('\n').Split('\n')));
    }

    [Fact]
    public void OnAnInteractiveAnsiConsoleTheBarIsDrawnAndTheCursorGivenBack()
    {
        // The control for the tests above: the same display on a console that is a terminal does write escape codes.
        var terminal = new StringWriter();
        IAnsiConsole console = InteractiveConsole(terminal);
        var progress = new RenderProgress();

        using (new ProgressDisplay(console, progress, "picture.png", TimeSpan.Zero))
        {
            Render(progress, 64, 48);
        }

        string drawn = terminal.ToString();
        Assert.Contains(Escape, drawn);
        Assert.Contains("picture.png", drawn, StringComparison.Ordinal);
        Assert.Contains("\x1b[?25l", drawn, StringComparison.Ordinal); // cursor hidden while drawing …
        Assert.EndsWith("\x1b[?25h", drawn.TrimEnd(), StringComparison.Ordinal); // … and shown again at the end
        Assert.Equal(48, progress.RowsCompleted);
    }

    [Fact]
    public void ARenderThatEndsBeforeTheDisplaysThreadStartsIsStillShownOnceTheDelayHasPassed()
    {
        // The delay is judged by the clock, not by which thread runs first: with no delay, a display disposed
        // at once (often before its thread has started) still draws and clears its bar; 200 tries catch the race.
        for (int attempt = 0; attempt < 200; attempt++)
        {
            var terminal = new StringWriter();
            using (new ProgressDisplay(InteractiveConsole(terminal), new RenderProgress(), "instant.png", TimeSpan.Zero))
            {
            }

            Assert.Contains("\x1b[?25h", terminal.ToString(), StringComparison.Ordinal);
        }
    }

    [Fact]
    public void ARenderShorterThanTheDelayDrawsNothing()
    {
        var terminal = new StringWriter();
        var progress = new RenderProgress();

        using (new ProgressDisplay(InteractiveConsole(terminal), progress, "quick.png", TimeSpan.FromHours(1)))
        {
            Render(progress, 16, 12);
        }

        Assert.Equal("", terminal.ToString());
    }

    [Fact]
    public void ANegativeDelayIsRejected()
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() =>
            new ProgressDisplay(InteractiveConsole(new StringWriter()), new RenderProgress(), "x", TimeSpan.FromSeconds(-1)));
        Assert.Equal("delay", e.ParamName);
    }

    private static IAnsiConsole InteractiveConsole(TextWriter writer) => AnsiConsole.Create(new AnsiConsoleSettings
    {
        Ansi = AnsiSupport.Yes,
        ColorSystem = ColorSystemSupport.Standard,
        Interactive = InteractionSupport.Yes,
        Out = new AnsiConsoleOutput(writer),
    });

    private static void Render(RenderProgress progress, int width, int height)
    {
        PreparedScene scene = (SceneFile.Load(Scene) with { Width = width, Height = height }).Prepare();
        var image = new Image(width, height);
        scene.Render(new Renderer { Progress = progress }, image);
    }
}
