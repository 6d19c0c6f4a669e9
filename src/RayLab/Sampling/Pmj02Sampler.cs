using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Simd;

namespace RayLab.Sampling;

/// <summary>
/// Progressive multi-jittered (0, 2) samples (Christensen, Kensler and Kilpatrick, EGSR 2018): every prefix of 2ᵐ
/// samples of a pixel is a (0, m, 2)-net in base 2, so it has exactly one point in each elementary interval
/// [a/2ʲ, (a+1)/2ʲ) × [b/2ᵏ, (b+1)/2ᵏ) with j + k = m, and the first N of a 4N-sample pixel are themselves such a
/// set. Any number of samples works; at a count between two powers of two the samples are the first of the next
/// power's set, so the largest power-of-two prefix keeps the guarantee.
/// </summary>
/// <remarks>
/// The sets are generated once by the library (64 of them, each as long as the sample count rounded up to a power of
/// two; see docs/samplers.md for their size). A pixel takes the set its <see cref="CounterHash.PixelKey"/> picks,
/// and XORs each coordinate with a key hashed from it (a random digital shift, which keeps every net a net).
/// </remarks>
public sealed class Pmj02Sampler : PixelSampler, ILaneSampled
{
    /// <summary>Creates a pmj02 sampler.</summary>
    /// <param name="samplesPerPixel">Samples per pixel, ≥ 1 (a power of two for the full net property).</param>
    /// <param name="seed">The seed; different seeds give pixels other sets and shifts.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="samplesPerPixel"/> is less than 1.</exception>
    public Pmj02Sampler(int samplesPerPixel, uint seed)
        : base(samplesPerPixel, seed) => Sets = Pmj02Tables.Sets(blueNoise: false, samplesPerPixel);

    /// <inheritdoc />
    public override string Name => "pmj02";

    /// <summary>The generated sets this sampler reads.</summary>
    internal uint[][] Sets { get; }

    /// <summary>The first <see cref="IPixelSampler.SamplesPerPixel"/> points of each set laid end to end (<see cref="Pmj02Tables.Flat"/>), made at the first render in lanes.</summary>
    internal uint[] FlatSets => LazyInitializer.EnsureInitialized(ref _flatSets, () => Pmj02Tables.Flat(Sets, SamplesPerPixel));

    private uint[]? _flatSets;

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index) =>
        Point(Sets, Pmj02Tables.Pixel(CounterHash.PixelKey(x, y, Seed), scramble: true), index);

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new LaneForm<TL>(FlatSets, SamplesPerPixel, Seed, scramble: true));

    /// <summary>
    /// Point <paramref name="index"/> of a pixel whose set and keys <see cref="Pmj02Tables.Pixel"/> gave (pmj02's and
    /// pmj02bn's, each with its own sets).
    /// </summary>
    /// <param name="sets">The variant's sets.</param>
    /// <param name="pixel">The pixel's set and scramble keys.</param>
    /// <param name="index">The sample index.</param>
    internal static SamplePoint Point(uint[][] sets, (int Set, uint X, uint Y) pixel, int index)
    {
        uint[] set = sets[pixel.Set];
        Shift<ScalarLane, ScalarMath>(
            new ScalarLane(set[2 * index], 0), new ScalarLane(set[(2 * index) + 1], 0), new ScalarLane(pixel.X, 0), new ScalarLane(pixel.Y, 0), out ScalarLane sx, out ScalarLane sy);
        return new SamplePoint(sx.Value, sy.Value);
    }

    /// <summary>
    /// A stored point (x, y) of the pixel's set under its keys: (<see cref="CounterHash.ToUnit"/>(x ⊕ kx),
    /// <see cref="CounterHash.ToUnit"/>(y ⊕ ky)), the digital shift (keys 0 for pmj02bn) and the conversion.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static void Shift<TV, TM>(TV x, TV y, TV kx, TV ky, out TV sx, out TV sy)
        where TV : struct
        where TM : IPointMath<TV>
    {
        sx = TM.ToUnit(TM.Xor(x, kx));
        sy = TM.ToUnit(TM.Xor(y, ky));
    }

    /// <summary>
    /// The points in lanes, pmj02's and pmj02bn's: each lane's set and keys are hashed in lanes once per packet
    /// (<see cref="Pmj02Tables.Pixel"/>), each sample's stored point is gathered from the sets laid end to end
    /// (<see cref="Pmj02Tables.Flat"/>: each point's x and y, side by side, as one 64-bit gathered element, a load
    /// per lane where the hardware has no gather), then <see cref="Shift"/> runs in lanes.
    /// </summary>
    internal unsafe struct LaneForm<TL> : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly uint* _table;
        private readonly uint _salt;
        private readonly int _stride;
        private readonly bool _scramble;
        private TL _first, _kx, _ky;

        /// <summary>Lanes for the points of <paramref name="sets"/> under <paramref name="seed"/>.</summary>
        /// <param name="sets">The variant's sets laid end to end (<see cref="Pmj02Tables.Flat"/>), pinned.</param>
        /// <param name="count">The samples per pixel: each set's first <paramref name="count"/> points are in the table.</param>
        /// <param name="seed">The sampler's seed.</param>
        /// <param name="scramble">True for pmj02's digital shift.</param>
        public LaneForm(uint[] sets, int count, uint seed, bool scramble)
        {
            _table = (uint*)Unsafe.AsPointer(ref MemoryMarshal.GetArrayDataReference(sets));   // pinned, and the sampler keeps it
            _stride = 2 * count;
            _salt = PointHash.Salt(seed);
            _scramble = scramble;
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void BeginPacket(int x0, int row)
        {
            TL keys = PointHash.PixelKeys<TL, LaneMath<TL>>(x0, row, _salt);
            Pmj02Tables.Pixel<TL, LaneMath<TL>>(keys, _scramble, out TL set, out _kx, out _ky);
            _first = TL.MultiplyBits(set, TL.BroadcastBits((uint)_stride));
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly int Prepare(int start, int end) => end;

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy)
        {
            TL.GatherPairs(_table, TL.AddBits(_first, TL.BroadcastBits(2u * (uint)index)), out TL x, out TL y);
            Shift<TL, LaneMath<TL>>(x, y, _kx, _ky, out sx, out sy);
        }
    }
}
