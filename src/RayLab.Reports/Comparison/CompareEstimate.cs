namespace RayLab.Reports.Comparison;

/// <summary>
/// The time a comparison has left, from the work it has measured so far: each setting still to come costs the mean
/// time the measures and files have taken per setting so far, plus its renders. A point sampler's render is its
/// samples times the render time per sample and pixel measured so far (of its own line once it has one, else of every
/// point sampler), a setting without samples (adaptive, your own methods) the mean of such settings so far (else one
/// sample per pixel); a render of <see cref="CompareRunner.LongRender"/> or more is counted once, a shorter one as
/// many times as the timing rule renders it. Nothing is assumed that was not measured in this run.
/// </summary>
internal sealed class CompareEstimate(IReadOnlyList<CompareCase> cases, int repeats)
{
    private readonly Dictionary<string, (double Seconds, double SamplePixels)> _lines = new(StringComparer.Ordinal);
    private double _pointSeconds, _pointSamplePixels, _otherSeconds, _measureSeconds;
    private int _others, _done;

    /// <summary>Records setting <paramref name="index"/>: the wall time of one of its renders, and of its measures and files.</summary>
    public void Done(int index, TimeSpan oneRender, TimeSpan measures, long pixels)
    {
        CompareCase c = cases[index];
        _done++;
        _measureSeconds += measures.TotalSeconds;
        if (c.SamplesPerPixel is { } spp)
        {
            double samplePixels = (double)spp * pixels;
            _pointSeconds += oneRender.TotalSeconds;
            _pointSamplePixels += samplePixels;
            _lines[c.Series] = _lines.TryGetValue(c.Series, out var line)
                ? (line.Seconds + oneRender.TotalSeconds, line.SamplePixels + samplePixels)
                : (oneRender.TotalSeconds, samplePixels);
        }
        else
        {
            _otherSeconds += oneRender.TotalSeconds;
            _others++;
        }
    }

    /// <summary>The seconds left for the settings after <paramref name="index"/>, or null before any setting is done.</summary>
    public double? SecondsLeft(int index, long pixels)
    {
        if (_done == 0)
        {
            return null;
        }

        double perPointSample = _pointSamplePixels > 0 ? _pointSeconds / _pointSamplePixels : double.NaN;
        double left = 0;
        for (int i = index + 1; i < cases.Count; i++)
        {
            CompareCase c = cases[i];
            double render = c.SamplesPerPixel is { } spp
                ? (_lines.TryGetValue(c.Series, out var line) ? line.Seconds / line.SamplePixels : perPointSample) * spp * pixels
                : _others > 0 ? _otherSeconds / _others : perPointSample * pixels;
            if (double.IsNaN(render))
            {
                render = _otherSeconds / Math.Max(1, _others);
            }

            left += Renders(render) + (_measureSeconds / _done);
        }

        return left;
    }

    /// <summary>The render time a setting whose one render takes <paramref name="render"/> seconds costs under the timing rule.</summary>
    private double Renders(double render)
    {
        if (render >= CompareRunner.LongRender.TotalSeconds)
        {
            return render;
        }

        // the repeats, and at least three for the median where they add up to less than the floor; more only
        // where renders disagree, which an estimate cannot know
        double floor = CompareRunner.MinimumMeasured.TotalSeconds;
        int count = Math.Max(repeats, render > 0 ? (int)Math.Min(3, Math.Ceiling(floor / render)) : 3);
        return render * count;
    }
}
