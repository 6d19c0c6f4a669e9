namespace MyLab;

#if (en)
/// <summary>4.1.3 Jittered (stratified) sampling: the pixel split into a k×k grid, one random point in each cell: ((i + rand())/k, (j + rand())/k).</summary>
#else
/// <summary>4.1.3 Próbkowanie jittered (losowe nieregularne): piksel podzielony na siatkę k×k, jeden losowy punkt w każdej komórce: ((i + rand())/k, (j + rand())/k).</summary>
#endif
public sealed class LabJitteredSampler : ILabSampler
{
    public LabJitteredSampler(int samplesPerPixel)
    {
        int k = (int)Math.Round(Math.Sqrt(samplesPerPixel));
        if (samplesPerPixel < 1 || k * k != samplesPerPixel)
        {
#if (en)
            throw new ArgumentException($"Jittered sampling needs a k×k grid: n must be a square (1, 4, 9, 16, 25, …), got {samplesPerPixel}.", nameof(samplesPerPixel));
#else
            throw new ArgumentException($"Próbkowanie jittered potrzebuje siatki k×k: n musi być kwadratem (1, 4, 9, 16, 25, …), a jest {samplesPerPixel}.", nameof(samplesPerPixel));
#endif
        }

        SamplesPerPixel = samplesPerPixel;
        K = k;
    }

    /// <inheritdoc/>
    public int SamplesPerPixel { get; }

    /// <summary>k = √n.</summary>
    public int K { get; }

#if (solution)
    /// <inheritdoc/>
    public (double X, double Y)[] GetSamples(Random random)
    {
        var points = new (double X, double Y)[SamplesPerPixel];
        for (int j = 0; j < K; j++)
        {
            for (int i = 0; i < K; i++)
            {
                points[(j * K) + i] = ((i + random.NextDouble()) / K, (j + random.NextDouble()) / K);
            }
        }

        return points;
    }
#else
    /// <inheritdoc/>
    public (double X, double Y)[] GetSamples(Random random) => throw ToWrite.Section("4.1.3", "LabJitteredSampler.GetSamples(random)");
#endif
}
