using RayLab.Rendering;

namespace RayLab.Scaling;

/// <summary>
/// The render time on N threads predicted from a one-thread <see cref="Profile"/>: the serial set-up and the work
/// after the rows as measured, the parallel part of the set-up divided by N, and the row loop simulated as
/// <see cref="BandSchedule"/> runs it. With ranges (<paramref name="inOrder"/> false: the adaptive renderer) each
/// thread starts with an equal range of bands, and whenever a thread is free it takes the front of its range or, when
/// that is empty, steals the back half of the fullest range; in order, the thread free first takes the next band. A
/// band costs its in-order time when the same thread rendered the band above (the same piece of the row above) last
/// among that piece's bands, else its scattered time.
/// Thread start-up and memory bandwidth are not modelled.
/// </summary>
internal class Model(Profile profile, bool inOrder = false)
{
    protected Profile Profile => profile;

    public double Predict(int threads) =>
        Math.Max(0, profile.PreparationMs - profile.ParallelPreparationMs) + (profile.ParallelPreparationMs / threads) + Rows(threads) + profile.AfterMs;

    /// <summary>The row loop's time on <paramref name="threads"/> threads.</summary>
    protected virtual double Rows(int threads)
    {
        if (inOrder)
        {
            return InGroups(threads, 1, followOn: true);
        }

        int bands = profile.BandMs.Length;
        int workers = BandSchedule.Workers(bands, threads);
        var free = new double[workers];
        int[][] last = LastRows(workers);
        var lo = new int[workers];
        var hi = new int[workers];
        for (int w = 0; w < workers; w++)
        {
            lo[w] = (int)((long)bands * w / workers);
            hi[w] = (int)((long)bands * (w + 1) / workers);
        }

        var done = new bool[workers];
        while (true)
        {
            // The worker free first takes its next band, or steals the back half of the fullest range.
            int w = -1;
            for (int i = 0; i < workers; i++)
            {
                if (!done[i] && (w < 0 || free[i] < free[w]))
                {
                    w = i;
                }
            }

            if (w < 0)
            {
                break;
            }

            int band;
            if (lo[w] < hi[w])
            {
                band = lo[w]++;
            }
            else
            {
                int victim = -1;
                for (int v = 0; v < workers; v++)
                {
                    if (hi[v] - lo[v] > 0 && (victim < 0 || hi[v] - lo[v] > hi[victim] - lo[victim]))
                    {
                        victim = v;
                    }
                }

                if (victim < 0)
                {
                    done[w] = true;
                    continue;
                }

                int mid = lo[victim] + ((hi[victim] - lo[victim]) / 2);
                (lo[w], hi[w]) = (mid + 1, hi[victim]);
                hi[victim] = mid;
                band = mid;
            }

            free[w] += Follows(last[w], band) ? profile.BandMs[band] : profile.ScatteredBandMs[band];
        }

        return free.Max();
    }

    /// <summary>For each of <paramref name="workers"/> workers, the row it rendered each piece in last (none yet).</summary>
    private int[][] LastRows(int workers) => [.. Enumerable.Range(0, workers).Select(_ => Enumerable.Repeat(-2, profile.Pieces).ToArray())];

    /// <summary>Whether <paramref name="band"/> follows the same piece of the row above on a worker whose pieces' last rows are <paramref name="lastRow"/>; notes the band.</summary>
    private bool Follows(int[] lastRow, int band)
    {
        int row = band / profile.Pieces, piece = band % profile.Pieces;
        bool follows = lastRow[piece] == row - 1;
        lastRow[piece] = row;
        return follows;
    }

    /// <summary>
    /// The bands handed out in order, <paramref name="merge"/> at a time, each group to the thread free first: a
    /// group's first band costs its scattered time, or its in-order time where <paramref name="followOn"/> and the same
    /// thread rendered the band above last; the group's other bands their in-order time.
    /// </summary>
    protected double InGroups(int threads, int merge, bool followOn)
    {
        int bands = profile.BandMs.Length;
        var free = new double[BandSchedule.Workers((bands + merge - 1) / merge, threads)];
        int[][] last = LastRows(free.Length);
        for (int b = 0; b < bands; b += merge)
        {
            int w = Array.IndexOf(free, free.Min());
            int end = Math.Min(bands, b + merge);
            free[w] += Follows(last[w], b) && followOn ? profile.BandMs[b] : profile.ScatteredBandMs[b];
            for (int k = b + 1; k < end; k++)
            {
                // A group's other bands follow on within the group.
                _ = Follows(last[w], k);
                free[w] += profile.BandMs[k];
            }
        }

        return free.Max();
    }

    /// <summary>
    /// The loop before this schedule, as an optimistic model: Parallel.For handing the bands out one at a time, in
    /// order, to whichever thread is free first, <paramref name="merge"/> of today's bands to one of its bands (whose
    /// first row always starts afresh).
    /// </summary>
    public static Model Old(Profile profile, int merge) => new OldModel(profile, merge);

    private sealed class OldModel(Profile profile, int merge) : Model(profile)
    {
        protected override double Rows(int threads) => InGroups(threads, merge, followOn: false);
    }
}
