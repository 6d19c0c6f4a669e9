using RayLab.Rendering;

namespace RayLab.Comparison;

/// <summary>Watches a comparison's renders one by one: a progress bar, a line per render, or nothing.</summary>
public interface ICompareProgress
{
    /// <summary>Runs one render of the comparison, showing <paramref name="label"/> while it runs.</summary>
    /// <param name="label">What is being rendered, e.g. <c>jittered, 16 spp (1/3)</c>.</param>
    /// <param name="render">The render; call it once and return what it returns.</param>
    /// <returns>The render's statistics.</returns>
    RenderStatistics Render(string label, Func<RenderStatistics> render);
}
