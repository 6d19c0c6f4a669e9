namespace MyLab;

#if (en)
/// <summary>4.1.2 Random sampling: n uniform random points in the pixel (the lab's code: pp.x = s·(c − 0.5·hres + rand())); they may clump.</summary>
#else
/// <summary>4.1.2 Próbkowanie losowe: n punktów losowych, równomiernie w pikselu (kod z instrukcji: pp.x = s·(c − 0.5·hres + rand())); mogą się skupiać.</summary>
#endif
public sealed class LabRandomSampler : ILabSampler
{
    public LabRandomSampler(int samplesPerPixel)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(samplesPerPixel, 1);
        SamplesPerPixel = samplesPerPixel;
    }

    /// <inheritdoc/>
    public int SamplesPerPixel { get; }

#if (solution)
    /// <inheritdoc/>
    public (double X, double Y)[] GetSamples(Random random)
    {
        var points = new (double X, double Y)[SamplesPerPixel];
        for (int p = 0; p < points.Length; p++)
        {
            points[p] = (random.NextDouble(), random.NextDouble());
        }

        return points;
    }
#else
    /// <inheritdoc/>
    public (double X, double Y)[] GetSamples(Random random) => throw ToWrite.Section("4.1.2", "LabRandomSampler.GetSamples(random)");
#endif
}
