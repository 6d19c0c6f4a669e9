using System.Diagnostics;
using System.Globalization;
using Spectre.Console;
using Spectre.Console.Rendering;

namespace RayLab.Cli;

/// <summary>
/// A progress bar for one render, drawn by Spectre.Console from a thread of its own that polls
/// <see cref="RenderProgress"/> (the render threads never wait for the terminal). It appears only after a delay,
/// so a render shorter than that draws nothing at all rather than flashing a bar, and it is cleared when the
/// render ends, leaving the summary line alone on the screen. Dispose it when the render returns.
/// </summary>
public sealed class ProgressDisplay : IDisposable
{
    /// <summary>How long a render runs before the console shows its bar: 1 second.</summary>
    public static TimeSpan Delay { get; } = TimeSpan.FromSeconds(1);

    private static readonly TimeSpan Refresh = TimeSpan.FromMilliseconds(100);

    private readonly ManualResetEventSlim _done = new();
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private readonly Task _display;
    private TimeSpan _endedAt = TimeSpan.MaxValue;

    /// <summary>Starts waiting; after <paramref name="delay"/>, unless disposed first, draws the bar on <paramref name="console"/>.</summary>
    /// <param name="console">Where to draw: an interactive console that understands ANSI escapes.</param>
    /// <param name="progress">The counter the renderer advances (<see cref="Renderer.Progress"/>).</param>
    /// <param name="label">What is being rendered (the output file's name).</param>
    /// <param name="delay">How long to wait before drawing anything.</param>
    public ProgressDisplay(IAnsiConsole console, RenderProgress progress, string label, TimeSpan delay)
    {
        ArgumentNullException.ThrowIfNull(console);
        ArgumentNullException.ThrowIfNull(progress);
        ArgumentNullException.ThrowIfNull(label);
        ArgumentOutOfRangeException.ThrowIfLessThan(delay, TimeSpan.Zero);
        _display = Task.Factory.StartNew(() => Show(console, progress, label, delay), CancellationToken.None,
            TaskCreationOptions.LongRunning, TaskScheduler.Default);
    }

    /// <summary>
    /// True when <paramref name="stdout"/> is the process's own standard output and that is a terminal: not a
    /// file, a pipe or a test's <see cref="StringWriter"/>, which must never receive escape codes.
    /// </summary>
    /// <param name="stdout">The writer the console app prints its results to.</param>
    public static bool IsTerminal(TextWriter stdout) => ReferenceEquals(stdout, Console.Out) && !Console.IsOutputRedirected;

    /// <summary>
    /// The bar for a render whose results go to <paramref name="stdout"/>, after <see cref="Delay"/>; null (nothing
    /// to show, nothing to dispose) unless that is an interactive terminal with ANSI support.
    /// </summary>
    /// <param name="stdout">The writer the console app prints its results to.</param>
    /// <param name="progress">The counter the renderer advances.</param>
    /// <param name="label">What is being rendered.</param>
    public static ProgressDisplay? ForTerminal(TextWriter stdout, RenderProgress progress, string label)
    {
        if (!IsTerminal(stdout))
        {
            return null;
        }

        IAnsiConsole console = AnsiConsole.Console;
        return console.Profile.Capabilities is { Ansi: true, Interactive: true }
            ? new ProgressDisplay(console, progress, label, Delay)
            : null;
    }

    /// <summary>Ends the display: clears the bar if it was drawn and returns once the terminal is left clean.</summary>
    public void Dispose()
    {
        _endedAt = _clock.Elapsed;
        _done.Set();
        _display.Wait();
        _done.Dispose();
    }

    private void Show(IAnsiConsole console, RenderProgress progress, string label, TimeSpan delay)
    {
        // Nothing is drawn for a render that ended within the delay (by the clock, not by whether this thread got
        // to run first: a render that ends after the delay is shown even if it ended before this thread woke).
        if (_done.Wait(delay) && _endedAt < delay)
        {
            return;
        }

        // Spectre hides the cursor while it draws; a Ctrl+C that ends the process (the second: the first cancels the
        // render, and the bar is cleared as the render returns) would not give it back, so do that here.
        ConsoleCancelEventHandler showCursor = (_, _) => console.Cursor.Show(true);
        Console.CancelKeyPress += showCursor;
        try
        {
            console.Progress()
                .AutoClear(true)
                .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(),
                    new TimeColumn(_clock), new SpinnerColumn())
                .Start(context =>
                {
                    ProgressTask task = context.AddTask(Markup.Escape(label), maxValue: Math.Max(1, progress.TotalRows));
                    do
                    {
                        task.MaxValue = Math.Max(1, progress.TotalRows);
                        task.Value = progress.RowsCompleted;
                    }
                    while (!_done.Wait(Refresh));

                    task.Value = task.MaxValue;
                });
        }
        catch (Exception e) when (e is IOException or InvalidOperationException)
        {
            // The bar is a courtesy: a terminal that went away, or another live display, must not fail the render.
        }
        finally
        {
            Console.CancelKeyPress -= showCursor;
        }
    }

    /// <summary>
    /// Time since the render started (the bar appears a second late) and the time left at the rate so far: rows are
    /// about equally costly, so elapsed × (1 − f)/f. Spectre's own columns time the bar, not the render.
    /// </summary>
    private sealed class TimeColumn(Stopwatch clock) : ProgressColumn
    {
        public override IRenderable Render(RenderOptions options, ProgressTask task, TimeSpan deltaTime)
        {
            TimeSpan elapsed = clock.Elapsed;
            double done = task.Value / task.MaxValue;
            string left = done > 0 ? Format(elapsed * ((1 - done) / done)) : "?";
            return new Text($"{Format(elapsed)} elapsed, {left} left", new Style(Color.Grey));
        }

        private static string Format(TimeSpan t) =>
            t.ToString(t.TotalHours >= 1 ? @"h\:mm\:ss" : @"m\:ss", CultureInfo.InvariantCulture);
    }
}
