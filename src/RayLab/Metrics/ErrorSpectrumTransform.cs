using System.Buffers;
using System.Numerics;

namespace RayLab.Metrics;

/// <summary>
/// The error spectrum's transform (<see cref="ErrorLocation.Spectrum(Image, Image)"/>): the periodograms of real
/// error planes, averaged, then averaged over rings. Two real planes go through one complex transform, as a + ib:
/// the ring sums need only |A(k)|² + |B(k)|², which is (|Z(k)|² + |Z(−k)|²)/2 for Z = A + iB, and every ring holds
/// −k with k, so a ring's sum of |Z|² is its sum of |A|² + |B|². The rows are transformed in parallel, then the
/// columns, each task a vector's lanes of them at a time (<see cref="Fourier.Transform(Span{double}, Span{double})"/>:
/// a lane's result does not depend on its neighbours); each frequency's power is written by one task and the rings are
/// summed in one fixed order, so the spectrum is the same at any thread count.
/// </summary>
internal static class ErrorSpectrumTransform
{
    /// <summary>The spectrum of <paramref name="planes"/> (each width·height, row 0 first), the planes' periodograms averaged.</summary>
    public static ErrorSpectrum Of(IReadOnlyList<double[]> planes, int width, int height, int threads)
    {
        var options = new ParallelOptions { MaxDegreeOfParallelism = threads };
        int pixels = width * height;
        double[] power = ArrayPool<double>.Shared.Rent(pixels);
        double[] dataRe = ArrayPool<double>.Shared.Rent(pixels);
        double[] dataIm = ArrayPool<double>.Shared.Rent(pixels);
        try
        {
            Array.Clear(power, 0, pixels);
            for (int first = 0; first < planes.Count; first += 2)
            {
                TransformRows(planes[first], first + 1 < planes.Count ? planes[first + 1] : null, dataRe, dataIm, width, height, options);
                PowerOfColumns(dataRe, dataIm, power, width, height, options);
            }

            return Rings(power, width, height, planes.Count, options);
        }
        finally
        {
            ArrayPool<double>.Shared.Return(power);
            ArrayPool<double>.Shared.Return(dataRe);
            ArrayPool<double>.Shared.Return(dataIm);
        }
    }

    /// <summary>The rows' transforms of <paramref name="re"/> + i·<paramref name="im"/>, a vector's lanes of rows at a time (lane l holds row y0 + l), into the data planes.</summary>
    private static void TransformRows(double[] re, double[]? im, double[] dataRe, double[] dataIm, int width, int height, ParallelOptions options)
    {
        int lanes = Vector<double>.Count;
        Parallel.For(0, (height + lanes - 1) / lanes, options, () => new LaneBuffers(width), (block, _, buffers) =>
        {
            int y0 = block * lanes, count = Math.Min(lanes, height - y0);
            Span<double> bufferRe = buffers.Re, bufferIm = buffers.Im;
            if (count < lanes)
            {
                bufferRe.Clear();
                bufferIm.Clear();
            }

            for (int l = 0; l < count; l++)
            {
                int row = (y0 + l) * width;
                for (int x = 0; x < width; x++)
                {
                    bufferRe[(x * lanes) + l] = re[row + x];
                    bufferIm[(x * lanes) + l] = im is null ? 0 : im[row + x];
                }
            }

            buffers.Fourier.Transform(bufferRe, bufferIm);
            for (int l = 0; l < count; l++)
            {
                int row = (y0 + l) * width;
                for (int x = 0; x < width; x++)
                {
                    dataRe[row + x] = bufferRe[(x * lanes) + l];
                    dataIm[row + x] = bufferIm[(x * lanes) + l];
                }
            }

            return buffers;
        }, _ => { });
    }

    /// <summary>The columns' transforms of the data planes, a vector's lanes of columns at a time (a vector load per row), their |X|² added into <paramref name="power"/>.</summary>
    private static void PowerOfColumns(double[] dataRe, double[] dataIm, double[] power, int width, int height, ParallelOptions options)
    {
        int lanes = Vector<double>.Count;
        Parallel.For(0, (width + lanes - 1) / lanes, options, () => new LaneBuffers(height), (block, _, buffers) =>
        {
            int x0 = block * lanes, count = Math.Min(lanes, width - x0);
            Span<double> bufferRe = buffers.Re, bufferIm = buffers.Im;
            if (count == lanes)
            {
                // A whole vector of columns: one load and one store a row each way (the same sums, lane by lane).
                for (int y = 0; y < height; y++)
                {
                    new Vector<double>(dataRe, (y * width) + x0).CopyTo(bufferRe.Slice(y * lanes, lanes));
                    new Vector<double>(dataIm, (y * width) + x0).CopyTo(bufferIm.Slice(y * lanes, lanes));
                }

                buffers.Fourier.Transform(bufferRe, bufferIm);
                for (int y = 0; y < height; y++)
                {
                    var a = new Vector<double>(bufferRe.Slice(y * lanes, lanes));
                    var b = new Vector<double>(bufferIm.Slice(y * lanes, lanes));
                    Span<double> target = power.AsSpan((y * width) + x0, lanes);
                    (new Vector<double>(target) + ((a * a) + (b * b))).CopyTo(target);
                }

                return buffers;
            }

            // The last, partial block: the lanes past the image's columns transform zeros.
            bufferRe.Clear();
            bufferIm.Clear();
            for (int y = 0; y < height; y++)
            {
                dataRe.AsSpan((y * width) + x0, count).CopyTo(bufferRe.Slice(y * lanes, count));
                dataIm.AsSpan((y * width) + x0, count).CopyTo(bufferIm.Slice(y * lanes, count));
            }

            buffers.Fourier.Transform(bufferRe, bufferIm);
            for (int y = 0; y < height; y++)
            {
                Span<double> target = power.AsSpan((y * width) + x0, count);
                for (int l = 0; l < count; l++)
                {
                    double a = bufferRe[(y * lanes) + l], b = bufferIm[(y * lanes) + l];
                    target[l] += (a * a) + (b * b);
                }
            }

            return buffers;
        }, _ => { });
    }

    /// <summary>A task's transform of one length and its lanes' buffers (length · <see cref="Vector{T}.Count"/> values each).</summary>
    private sealed class LaneBuffers(int length)
    {
        public Fourier Fourier { get; } = new(length);

        public double[] Re { get; } = new double[length * Vector<double>.Count];

        public double[] Im { get; } = new double[length * Vector<double>.Count];
    }

    /// <summary>
    /// The periodogram's ring means, mean and low share from the summed |X|² of <paramref name="planeCount"/> planes:
    /// each row's sums taken by one task, then the rows' added in order, so the result does not depend on the threads.
    /// </summary>
    private static ErrorSpectrum Rings(double[] power, int width, int height, int planeCount, ParallelOptions options)
    {
        double scale = (double)width * height * planeCount;
        int rings = (int)Math.Ceiling(Math.Sqrt(0.5) / ErrorLocation.RingWidth) + 1;
        var rowRings = new double[height * rings];
        var rowCounts = new int[height * rings];
        var rowTotals = new double[height];
        var rowLows = new double[height];
        Parallel.For(0, height, options, v =>
        {
            Span<double> ringSum = rowRings.AsSpan(v * rings, rings);
            Span<int> ringCount = rowCounts.AsSpan(v * rings, rings);
            double fv = (v <= height / 2 ? v : v - height) / (double)height;
            double total = 0, low = 0;
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

            rowTotals[v] = total;
            rowLows[v] = low;
        });

        var sums = new double[rings];
        var counts = new long[rings];
        double all = 0, lowAll = 0;
        for (int v = 0; v < height; v++)
        {
            for (int r = 0; r < rings; r++)
            {
                sums[r] += rowRings[(v * rings) + r];
                counts[r] += rowCounts[(v * rings) + r];
            }

            all += rowTotals[v];
            lowAll += rowLows[v];
        }

        double[] mean = [.. sums.Select((s, r) => counts[r] > 0 ? s / counts[r] : double.NaN)];
        int n = width * height;
        return new ErrorSpectrum(mean, all / n, all > 0 ? lowAll / all : 0);
    }
}
