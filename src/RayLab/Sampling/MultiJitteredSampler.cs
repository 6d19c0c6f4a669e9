namespace RayLab.Sampling;

/// <summary>
/// Multi-jittered sampling (Chiu, Shirley and Wang 1994; Suffern's <c>MultiJittered</c>): n × n jittered
/// sampling that is also an n-rooks pattern on the N = n² fine grid, so each coarse cell, each fine column and each
/// fine row holds exactly one sample.
/// </summary>
/// <remarks>
/// Sample i sits in coarse cell (i mod n, i div n). In the canonical arrangement cell (c, r) uses fine column r
/// of its coarse column and fine row c of its coarse row; the shuffle permutes the fine columns independently in
/// every coarse column and the fine rows independently in every coarse row (unlike Kensler's correlated variant,
/// which shares one permutation). Each permutation is a stateless hash permutation
/// (<see cref="Permutation.PermutationElement"/>) keyed on the pixel, so no table is stored.
/// </remarks>
public sealed class MultiJitteredSampler : GridSampler, ILaneSampled
{
    /// <summary>Xored into the pixel key for the shuffles of the fine columns (the lanes use the same).</summary>
    internal const uint ColumnSalt = 0x2f5a1c37u;

    /// <summary>Xored into the pixel key for the shuffles of the fine rows.</summary>
    internal const uint RowSalt = 0xc13fa9a9u;

    /// <summary>Creates an n×n multi-jittered sampler.</summary>
    /// <param name="samplesPerPixel">n², a perfect square ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentException">Not a positive perfect square.</exception>
    public MultiJitteredSampler(int samplesPerPixel, uint seed) : base(samplesPerPixel, seed) { }

    /// <inheritdoc />
    public override string Name => "multijittered";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        int n = GridSize;
        int column = index % n, row = index / n;
        uint key = CounterHash.PixelKey(x, y, Seed);

        // Fine column of this sample inside its coarse column: a permutation (over rows) of that column.
        int subColumn = Permutation.PermutationElement(row, n, CounterHash.SampleHash(key ^ ColumnSalt, column));

        // Fine row of this sample inside its coarse row: a permutation (over columns) of that row.
        int subRow = Permutation.PermutationElement(column, n, CounterHash.SampleHash(key ^ RowSalt, row));

        uint h1 = CounterHash.SampleHash(key, index);
        uint h2 = CounterHash.Hash(h1);
        return new SamplePoint(
            (column + ((subColumn + CounterHash.ToUnit(h1)) / n)) / n,
            (row + ((subRow + CounterHash.ToUnit(h2)) / n)) / n);
    }

    /// <inheritdoc />
    /// <remarks>Above <see cref="PatternLimits.MaxSamples"/> samples the lanes would not be exact: the buffered lanes then ask <see cref="GetSample"/>.</remarks>
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        SamplesPerPixel <= PatternLimits.MaxSamples
            ? user.Run(() => new MultiJitteredLanes<TL>(this))
            : user.Run(() => new BufferedLanes<TL>(this));
}
