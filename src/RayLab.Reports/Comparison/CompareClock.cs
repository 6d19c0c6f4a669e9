using System.Diagnostics;

namespace RayLab.Reports.Comparison;

/// <summary>
/// Where a comparison's time goes: the wall time of each stage (the renders, the exact image, each measure, the
/// error images, the files, the charts), added up over the stage's calls, and the time since the clock started.
/// The stages run one after another, each on every core it uses, so their times add up to the run's time but for
/// the work between them (reading the scene, the progress display, moving the report into place).
/// </summary>
public sealed class CompareClock
{
    private readonly Stopwatch _since = Stopwatch.StartNew();
    private readonly Lock _lock = new();
    private readonly List<string> _order = [];
    private readonly Dictionary<string, (long Ticks, int Calls)> _stages = new(StringComparer.Ordinal);

    /// <summary>The stage that renders the exact image.</summary>
    internal const string ExactImage = "exact image";

    /// <summary>The stage that renders the settings (every render, counted or not).</summary>
    internal const string Renders = "renders";

    /// <summary>The time since the clock was made.</summary>
    public TimeSpan Elapsed => _since.Elapsed;

    /// <summary>The stages so far, in the order each was first timed.</summary>
    public IReadOnlyList<CompareStage> Stages
    {
        get
        {
            lock (_lock)
            {
                return [.. _order.Select(name => new CompareStage(name, TimeSpan.FromTicks(_stages[name].Ticks), _stages[name].Calls))];
            }
        }
    }

    /// <summary>Runs <paramref name="work"/> and adds its wall time to <paramref name="stage"/>.</summary>
    /// <typeparam name="T">What the work returns.</typeparam>
    /// <param name="stage">The stage's name, e.g. <c>FLIP</c>.</param>
    /// <param name="work">The work.</param>
    /// <returns>What <paramref name="work"/> returned.</returns>
    public T Time<T>(string stage, Func<T> work)
    {
        ArgumentNullException.ThrowIfNull(work);
        long start = Stopwatch.GetTimestamp();
        T result = work();
        Add(stage, Stopwatch.GetElapsedTime(start));
        return result;
    }

    /// <summary>Runs <paramref name="work"/> and adds its wall time to <paramref name="stage"/>.</summary>
    /// <param name="stage">The stage's name.</param>
    /// <param name="work">The work.</param>
    public void Time(string stage, Action work)
    {
        ArgumentNullException.ThrowIfNull(work);
        long start = Stopwatch.GetTimestamp();
        work();
        Add(stage, Stopwatch.GetElapsedTime(start));
    }

    /// <summary>Adds one call of <paramref name="time"/> to <paramref name="stage"/>.</summary>
    /// <param name="stage">The stage's name.</param>
    /// <param name="time">The wall time the call took, ≥ 0.</param>
    public void Add(string stage, TimeSpan time)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(stage);
        ArgumentOutOfRangeException.ThrowIfLessThan(time, TimeSpan.Zero);
        lock (_lock)
        {
            if (!_stages.TryGetValue(stage, out (long Ticks, int Calls) sum))
            {
                _order.Add(stage);
            }

            _stages[stage] = (sum.Ticks + time.Ticks, sum.Calls + 1);
        }
    }
}
