namespace MyLab;

#if (en)
/// <summary>4.1.1 Regular sampling: a k×k grid in the pixel (the lab's example: 5×5, n = 25), the same for every pixel; the point of cell (i, j) is its centre, ((i + 0.5)/k, (j + 0.5)/k).</summary>
#else
/// <summary>4.1.1 Próbkowanie regularne: siatka k×k w pikselu (przykład z instrukcji: 5×5, n = 25), ta sama dla każdego piksela; punkt komórki (i, j) to jej środek, ((i + 0.5)/k, (j + 0.5)/k).</summary>
#endif
public sealed class LabRegularSampler : ILabSampler
{
    public LabRegularSampler(int samplesPerPixel)
    {
        int k = (int)Math.Round(Math.Sqrt(samplesPerPixel));
        if (samplesPerPixel < 1 || k * k != samplesPerPixel)
        {
#if (en)
            throw new ArgumentException($"Regular sampling needs a k×k grid: n must be a square (1, 4, 9, 16, 25, …), got {samplesPerPixel}.", nameof(samplesPerPixel));
#else
            throw new ArgumentException($"Próbkowanie regularne potrzebuje siatki k×k: n musi być kwadratem (1, 4, 9, 16, 25, …), a jest {samplesPerPixel}.", nameof(samplesPerPixel));
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
                points[(j * K) + i] = ((i + 0.5) / K, (j + 0.5) / K);
            }
        }

        return points;
    }
#else
    /// <inheritdoc/>
    public (double X, double Y)[] GetSamples(Random random) => throw ToWrite.Section("4.1.1", "LabRegularSampler.GetSamples(random)");
#endif
}
