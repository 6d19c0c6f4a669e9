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

    /// <inheritdoc />
    public override SamplePoint GetSample(int x, int y, int index) =>
        Point(Sets, Pmj02Tables.Pixel(CounterHash.PixelKey(x, y, Seed), scramble: true), index);

    /// <inheritdoc />
    TResult ILaneSampled.WithLanes<TL, TU, TResult>(ref TU user) =>
        user.Run(() => new LaneForm<TL>(Sets, Seed, scramble: true));

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
    /// The points in lanes, pmj02's and pmj02bn's: each lane's pixel reads its own generated set (a gather, one scalar
    /// load per lane), then <see cref="Shift"/> runs in lanes, a block of <see cref="PointBlock.Size"/> samples at a time.
    /// </summary>
    internal struct LaneForm<TL> : ILaneSampler<TL>
        where TL : struct, ILanes<TL>
    {
        private readonly float[] _block = PointBlock.Create<TL>();
        private readonly uint[][] _sets;
        private readonly uint[][] _laneSets = new uint[TL.Count][];
        private readonly float[] _keys = new float[2 * TL.Count];
        private readonly uint _seed;
        private readonly bool _scramble;

        /// <summary>Lanes for the points of <paramref name="sets"/> under <paramref name="seed"/>.</summary>
        /// <param name="sets">The variant's sets.</param>
        /// <param name="seed">The sampler's seed.</param>
        /// <param name="scramble">True for pmj02's digital shift.</param>
        public LaneForm(uint[][] sets, uint seed, bool scramble)
        {
            _sets = sets;
            _seed = seed;
            _scramble = scramble;
        }

        /// <inheritdoc />
        public readonly void BeginPacket(int x0, int row)
        {
            Span<uint> keys = MemoryMarshal.Cast<float, uint>(_keys.AsSpan());
            for (int lane = 0; lane < TL.Count; lane++)
            {
                (int set, uint x, uint y) = Pmj02Tables.Pixel(CounterHash.PixelKey(x0 + lane, row, _seed), _scramble);
                _laneSets[lane] = _sets[set];
                keys[lane] = x;
                keys[TL.Count + lane] = y;
            }
        }

        /// <inheritdoc />
        public readonly int Prepare(int start, int end)
        {
            int count = TL.Count;
            int stop = Math.Min(end, start + PointBlock.Size);
            Span<float> slots = _block.AsSpan(0, 3 * count * (stop - start));
            Span<uint> bits = MemoryMarshal.Cast<float, uint>(slots);
            for (int lane = 0; lane < count; lane++)
            {
                uint[] set = _laneSets[lane];
                for (int index = start, slot = lane; index < stop; index++, slot += 3 * count)
                {
                    bits[slot] = set[2 * index];
                    bits[slot + count] = set[(2 * index) + 1];
                }
            }

            TL kx = TL.Load(_keys), ky = TL.Load(_keys.AsSpan(count));
            for (int index = start; index < stop; index++)
            {
                Shift<TL, LaneMath<TL>>(TL.Load(slots), TL.Load(slots[count..]), kx, ky, out TL sx, out TL sy);
                sx.Store(slots);
                sy.Store(slots[count..]);
                slots = slots[(3 * count)..];
            }

            return stop;
        }

        /// <inheritdoc />
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public readonly void Sample(int index, out TL sx, out TL sy) => PointBlock.Read(_block, index, out sx, out sy);
    }
}
