
namespace RayLab.Reports.Comparison;

/// <summary>Watches a comparison's renders one by one: a progress bar, a line per render, or nothing.</summary>
public interface ICompareProgress
{
    /// <summary>Runs one render of the comparison, showing <paramref name="label"/> while it runs.</summary>
    /// <param name="label">What is being rendered, e.g. <c>jittered, 16 spp (1/3)</c>.</param>
    /// <param name="render">The render; call it once and return what it returns.</param>
    /// <returns>The render's statistics.</returns>
    RenderStatistics Render(string label, Func<RenderStatistics> render);

    /// <summary>
    /// Tells that <paramref name="renders"/> of the repeats planned for a setting were not needed (its first render
    /// was long enough to be its time, <see cref="CompareRunner.LongRender"/>), so a count of renders can move on.
    /// </summary>
    /// <param name="renders">How many planned renders were left out.</param>
    void Skipped(int renders)
    {
    }

    /// <summary>
    /// Tells that <paramref name="done"/> of <paramref name="settings"/> settings are rendered, measured and saved,
    /// <paramref name="elapsed"/> into the run, and the time the rest will take at the pace measured so far (each
    /// setting's renders scaled by its samples from the render times so far, plus the measures' mean time per setting).
    /// </summary>
    /// <param name="done">Settings finished.</param>
    /// <param name="settings">Settings in all.</param>
    /// <param name="elapsed">The run's time so far.</param>
    /// <param name="left">The estimate of the time left; null where nothing has been measured yet.</param>
    void Setting(int done, int settings, TimeSpan elapsed, TimeSpan? left)
    {
    }
}
