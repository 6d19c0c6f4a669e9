using RayLab.Reports.Comparison;
using Spectre.Console;

namespace RayLab.Cli;

/// <summary>
/// Shows how far <c>raylab compare</c> has got: a Spectre.Console progress bar when the app writes to a
/// terminal, one plain line per render when the console's output is redirected, and nothing when the app runs
/// with other writers (tests call <see cref="Program.Run"/> with string writers, which get only the results).
/// </summary>
public abstract class CompareProgress : ICompareProgress
{
    /// <summary>Counts finished rows of the current render; give it to the renderer.</summary>
    public RenderProgress Rows { get; } = new();

    /// <summary>Runs <paramref name="work"/> with the progress display that suits <paramref name="stdout"/>.</summary>
    /// <param name="stdout">The app's output writer.</param>
    /// <param name="renders">How many renders the work will do.</param>
    /// <param name="work">The work; it calls <see cref="Render"/> for each render.</param>
    public static void Run(TextWriter stdout, int renders, Action<CompareProgress> work)
    {
        ArgumentNullException.ThrowIfNull(work);
        if (!ReferenceEquals(stdout, Console.Out))
        {
            work(new Silent());
        }
        else if (Console.IsOutputRedirected || !AnsiConsole.Profile.Capabilities.Interactive)
        {
            work(Lines(stdout, renders));
        }
        else
        {
            AnsiConsole.Progress()
                .AutoClear(true)
                .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn())
                .Start(context => work(new Bars(context, renders)));
        }
    }

    /// <summary>The plain display: one line per finished render, <c>[3/70] jittered 16 spp: 41.2 ms</c>.</summary>
    /// <param name="writer">Where the lines go.</param>
    /// <param name="renders">How many renders there will be.</param>
    public static CompareProgress Lines(TextWriter writer, int renders) => new PlainLines(writer, renders);

    /// <summary>Runs one render, showing <paramref name="label"/> while it runs.</summary>
    /// <param name="label">What is being rendered.</param>
    /// <param name="render">The render; it should report rows to <see cref="Rows"/>.</param>
    /// <returns>The render's statistics.</returns>
    public abstract RenderStatistics Render(string label, Func<RenderStatistics> render);

    /// <summary>Moves the count of renders past <paramref name="renders"/> planned repeats that were not needed.</summary>
    /// <param name="renders">How many.</param>
    public virtual void Skipped(int renders)
    {
    }

    /// <summary>Tells that a setting is finished, with the estimate of the time left (<see cref="ICompareProgress.Setting"/>).</summary>
    /// <param name="done">Settings finished.</param>
    /// <param name="settings">Settings in all.</param>
    /// <param name="elapsed">The run's time so far.</param>
    /// <param name="left">The time left at the pace measured so far; null where nothing has been measured yet.</param>
    public virtual void Setting(int done, int settings, TimeSpan elapsed, TimeSpan? left)
    {
    }

    /// <summary>", about 73 s left (at the pace measured so far)", or nothing without an estimate.</summary>
    private static string LeftText(TimeSpan? left) => left is { } l
        ? FormattableString.Invariant($", about {l.TotalSeconds:F0} s left (at the pace measured so far)")
        : "";

    private sealed class Silent : CompareProgress
    {
        public override RenderStatistics Render(string label, Func<RenderStatistics> render) => render();
    }

    private sealed class PlainLines(TextWriter writer, int renders) : CompareProgress
    {
        private int _done;

        public override void Skipped(int renders) => _done += renders;

        public override void Setting(int done, int settings, TimeSpan elapsed, TimeSpan? left) =>
            writer.WriteLine(FormattableString.Invariant($"[{done}/{settings} settings] {elapsed.TotalSeconds:F1} s so far{LeftText(left)}"));

        public override RenderStatistics Render(string label, Func<RenderStatistics> render)
        {
            RenderStatistics stats = render();
            writer.WriteLine(FormattableString.Invariant($"[{++_done}/{renders}] {label}: {stats.RenderTime.TotalMilliseconds:F1} ms"));
            return stats;
        }
    }

    private sealed class Bars(ProgressContext context, int renders) : CompareProgress
    {
        private readonly ProgressTask _all = context.AddTask("compare", maxValue: renders);
        private readonly ProgressTask _current = context.AddTask("starting", maxValue: 1);

        public override RenderStatistics Render(string label, Func<RenderStatistics> render)
        {
            _current.Description = Markup.Escape(label);
            _current.Value = 0;
            Task<RenderStatistics> task = Task.Run(render);
            // Poll the row counter while the render runs on the thread pool (no callbacks on render threads).
            while (!((IAsyncResult)task).AsyncWaitHandle.WaitOne(100))
            {
                _current.Value = Rows.Fraction;
            }

            RenderStatistics stats = task.GetAwaiter().GetResult();
            _current.Value = 1;
            _all.Increment(1);
            return stats;
        }

        public override void Skipped(int renders) => _all.Increment(renders);

        public override void Setting(int done, int settings, TimeSpan elapsed, TimeSpan? left) =>
            _all.Description = Markup.Escape(FormattableString.Invariant($"{done}/{settings} settings{LeftText(left)}"));
    }
}
