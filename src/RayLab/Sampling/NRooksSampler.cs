namespace RayLab.Sampling;

/// <summary>
/// Suffern's n-rooks (Latin hypercube) sampling: the pixel is an N × N grid and the N samples sit like N rooks
/// that cannot take each other, exactly one in each row and each column, jittered inside their cells. Good
/// projections on both axes, though the 2-D distribution can still clump. Any number of samples.
/// </summary>
/// <remarks>
/// Suffern starts from the diagonal and shuffles the x and the y coordinates; here sample i takes row
/// π_y(i) and column π_x(i) of two independent hash permutations (<see cref="Permutation.PermutationElement"/>)
/// keyed on the pixel, which gives the same distribution with no stored table.
/// </remarks>
public sealed class NRooksSampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates an n-rooks sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1.</param>
    /// <param name="seed">The seed; different seeds give different points.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public NRooksSampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed)
    {
    }

    /// <summary>The pixel key's multiplier for the permutation of the columns.</summary>
    internal const uint ColumnSalt = 0xa511e9b3u;

    /// <summary>The pixel key's multiplier for the permutation of the rows.</summary>
    internal const uint RowSalt = 0x63d83595u;

    /// <inheritdoc />
    public override string Name => "nrooks";

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index)
    {
        int count = SamplesPerPixel;
        uint key = CounterHash.PixelKey(x, y, Seed);
        int column = Permutation.PermutationElement(index, count, key * ColumnSalt);
        int row = Permutation.PermutationElement(index, count, key * RowSalt);
        uint h1 = CounterHash.SampleHash(key, index);
        uint h2 = CounterHash.Hash(h1);
        return new SamplePoint((column + CounterHash.ToUnit(h1)) / count, (row + CounterHash.ToUnit(h2)) / count);
    }

    /// <inheritdoc />
    /// <remarks>Above <see cref="PatternLimits.MaxSamples"/> samples the lanes would not be exact: the buffered lanes then ask <see cref="GetSample"/>.</remarks>
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        SamplesPerPixel <= PatternLimits.MaxSamples
            ? user.Run(() => new NRooksLanes<TL>(this))
            : user.Run(() => new BufferedLanes<TL>(this));
}
