using System.Numerics;

namespace RayLab.Metrics;

/// <summary>
/// The error spectrum's transform (<see cref="ErrorLocation.Spectrum(Image, Image)"/>): the periodograms of real
/// error planes, averaged, then averaged over rings. Two real planes go through one complex transform, as a + ib:
/// the ring sums need only |A(k)|² + |B(k)|², which is (|Z(k)|² + |Z(−k)|²)/2 for Z = A + iB, and every ring holds
/// −k with k, so a ring's sum of |Z|² is its sum of |A|² + |B|². The rows are transformed in parallel, then the
/// columns (in blocks, each column gathered once); each frequency's power is written by one task and the rings are
/// summed in one fixed order, so the spectrum is the same at any thread count.
/// </summary>
internal static class ErrorSpectrumTransform
{
    /// <summary>Columns a task gathers and transforms at a time.</summary>
    private const int ColumnBlock = 8;

    /// <summary>The spectrum of <paramref name="planes"/> (each width·height, row 0 first), the planes' periodograms averaged.</summary>
    public static ErrorSpectrum Of(IReadOnlyList<double[]> planes, int width, int height, int threads)
    {
        var options = new ParallelOptions { MaxDegreeOfParallelism = threads };
        var power = new double[width * height];
        var data = new Complex[width * height];
        for (int first = 0; first < planes.Count; first += 2)
        {
            double[] re = planes[first];
            double[]? im = first + 1 < planes.Count ? planes[first + 1] : null;
            Parallel.For(0, height, options, () => new Fourier(width), (y, _, fourier) =>
            {
                Span<Complex> row = data.AsSpan(y * width, width);
                for (int x = 0; x < width; x++)
                {
                    int i = (y * width) + x;
                    row[x] = new Complex(re[i], im is null ? 0 : im[i]);
                }

                fourier.Transform(row);
                return fourier;
            }, _ => { });

            int blocks = (width + ColumnBlock - 1) / ColumnBlock;
            Parallel.For(0, blocks, options, () => (new Fourier(height), new Complex[ColumnBlock * height]), (block, _, local) =>
            {
                (Fourier fourier, Complex[] columns) = local;
                int x0 = block * ColumnBlock, count = Math.Min(ColumnBlock, width - x0);
                for (int y = 0; y < height; y++)
                {
                    for (int c = 0; c < count; c++)
                    {
                        columns[(c * height) + y] = data[(y * width) + x0 + c];
                    }
                }

                for (int c = 0; c < count; c++)
                {
                    Span<Complex> column = columns.AsSpan(c * height, height);
                    fourier.Transform(column);
                    for (int y = 0; y < height; y++)
                    {
                        double m = column[y].Magnitude;
                        power[(y * width) + x0 + c] += m * m;
                    }
                }

                return local;
            }, _ => { });
        }

        return Rings(power, width, height, planes.Count);
    }

    /// <summary>The periodogram's ring means, mean and low share from the summed |X|² of <paramref name="planeCount"/> planes.</summary>
    private static ErrorSpectrum Rings(double[] power, int width, int height, int planeCount)
    {
        double scale = (double)width * height * planeCount;
        int rings = (int)Math.Ceiling(Math.Sqrt(0.5) / ErrorLocation.RingWidth) + 1;
        var ringSum = new double[rings];
        var ringCount = new int[rings];
        double total = 0, low = 0;
        for (int v = 0; v < height; v++)
        {
            double fv = (v <= height / 2 ? v : v - height) / (double)height;
            for (int u = 0; u < width; u++)
            {
                double fu = (u <= width / 2 ? u : u - width) / (double)width;
                double f = Math.Sqrt((fu * fu) + (fv * fv));
                double p = power[(v * width) + u] / scale;
                int ring = (int)Math.Round(f / ErrorLocation.RingWidth);
                ringSum[ring] += p;
                ringCount[ring]++;
                total += p;
                low += f <= ErrorLocation.LowFrequencyLimit ? p : 0;
            }
        }

        double[] mean = [.. ringSum.Select((s, r) => ringCount[r] > 0 ? s / ringCount[r] : double.NaN)];
        int n = width * height;
        return new ErrorSpectrum(mean, total / n, total > 0 ? low / total : 0);
    }
}
