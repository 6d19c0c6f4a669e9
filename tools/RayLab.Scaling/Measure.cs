namespace RayLab.Scaling;

/// <summary>Render times measured here: each thread count in turn, round by round, after a warm-up; medians of <see cref="RenderStatistics.RenderTime"/>.</summary>
internal static class Measure
{
    public static Dictionary<int, double> Interleaved(Case c, int[] threads, int rounds)
    {
        Renderer[] renderers = [.. threads.Select(n => new Renderer { MaxDegreeOfParallelism = n })];
        Image image = c.Prepared.CreateImage();
        var times = threads.Select(_ => new List<double>()).ToArray();
        foreach (Renderer r in renderers)
        {
            c.Prepared.Render(r, image);
        }

        for (int round = 0; round < rounds; round++)
        {
            for (int i = 0; i < threads.Length; i++)
            {
                times[i].Add(c.Prepared.Render(renderers[i], image).RenderTime.TotalMilliseconds);
            }
        }

        return threads.Select((n, i) => (n, i)).ToDictionary(p => p.n, p => Profile.Median(times[p.i]));
    }
}
