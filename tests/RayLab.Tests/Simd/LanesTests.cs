using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Tests.Simd;

/// <summary>
/// The lane wrappers' operations that have a hardware shortcut (vrangeps for <c>MinAbs</c>, blends for <c>Select</c>) or feed the
/// samplers' points (<c>Hash</c>, <c>Top24</c>, <c>ToUnit</c>, the integer operations, the conversions and <c>InDouble</c>), lane by lane against the scalar definition, for
/// every width (each runs where the hardware lacks it too, emulated).
/// </summary>
public class LanesTests
{
    private static readonly float[] Values = [0f, -0f, 1f, -1f, 0.5f, -2.5f, 3e-38f, -3e-38f, 1e30f, -1e30f, float.PositiveInfinity, float.NegativeInfinity, 7f, -7.25f, 1e-45f, 123.456f];

    [Fact]
    public void MinAbsIsTheSmallerOfANonNegativeValueAndAnAbsoluteValue()
    {
        CheckMinAbs<Lanes512>();
        CheckMinAbs<Lanes256>();
        CheckMinAbs<Lanes128>();
    }

    [Fact]
    public void SelectTakesEachLaneFromTheSideItsComparisonChose()
    {
        CheckSelect<Lanes512>();
        CheckSelect<Lanes256>();
        CheckSelect<Lanes128>();
    }

    [Fact]
    public void LessThanOrEqualBitsSetsBitIWhereLaneIOfAIsAtMostLaneIOfB()
    {
        CheckLessThanOrEqualBits<Lanes512>();
        CheckLessThanOrEqualBits<Lanes256>();
        CheckLessThanOrEqualBits<Lanes128>();
    }

    [Fact]
    public void HashAndUnitsAreTheScalarCounterHashInEveryLane()
    {
        CheckHash<Lanes512>();
        CheckHash<Lanes256>();
        CheckHash<Lanes128>();
    }

    [Fact]
    public void IntegerOperationsAreTheScalarUintOperationsInEveryLane()
    {
        CheckIntegers<Lanes512>();
        CheckIntegers<Lanes256>();
        CheckIntegers<Lanes128>();
    }

    [Fact]
    public void ConversionsAreTheScalarCastsInEveryLane()
    {
        CheckConversions<Lanes512>();
        CheckConversions<Lanes256>();
        CheckConversions<Lanes128>();
    }

    [Fact]
    public void InDoubleIsTheScalarDoubleExpressionRoundedToFloat()
    {
        CheckInDouble<Lanes512>();
        CheckInDouble<Lanes256>();
        CheckInDouble<Lanes128>();
    }

    private static readonly uint[] Words = [0, 1, 2, 3, 0x7fffffff, 0x80000000, 0x80000001, 0xffffffff, 0xfffffffe, 0x9e3779b9, 0x12345678, 0xdeadbeef, 255, 256, 0x00ffffff, 0x01000001];

    private static float[] AsLanes(int n, int shift) =>
        Enumerable.Range(0, n).Select(lane => BitConverter.UInt32BitsToSingle(Words[(lane + shift) % Words.Length])).ToArray();

    private static uint Bits(float f) => BitConverter.SingleToUInt32Bits(f);

    private static void CheckIntegers<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] result = new float[n];
        for (int shift = 0; shift < Words.Length; shift++)
        {
            float[] a = AsLanes(n, 0), b = AsLanes(n, shift);
            TL x = TL.Load(a), y = TL.Load(b);
            void Expect(TL actual, Func<uint, uint, uint> scalar, string what)
            {
                actual.Store(result);
                for (int lane = 0; lane < n; lane++)
                {
                    uint expected = scalar(Bits(a[lane]), Bits(b[lane]));
                    Assert.True(expected == Bits(result[lane]), $"{typeof(TL).Name} {what}({Bits(a[lane]):x8}, {Bits(b[lane]):x8}) gave {Bits(result[lane]):x8}, expected {expected:x8}");
                }
            }

            Expect(TL.AddBits(x, y), (p, q) => unchecked(p + q), "AddBits");
            Expect(TL.SubtractBits(x, y), (p, q) => unchecked(p - q), "SubtractBits");
            Expect(TL.MultiplyBits(x, y), (p, q) => unchecked(p * q), "MultiplyBits");
            Expect(TL.ReverseBits(y), (_, q) => LowDiscrepancy.ReverseBits(q), "ReverseBits");
            Expect(TL.LessThanBits(x, y), (p, q) => (int)p < (int)q ? uint.MaxValue : 0, "LessThanBits");
            Expect(TL.ShiftLeftBits(x, shift), (p, _) => p << shift, "ShiftLeftBits");
            Expect(TL.ShiftRightBits(x, shift), (p, _) => p >> shift, "ShiftRightBits");
            Expect(TL.ShiftLeftBits(x, 31 - shift), (p, _) => p << (31 - shift), "ShiftLeftBits");
            Expect(TL.ShiftRightBits(x, 31 - shift), (p, _) => p >> (31 - shift), "ShiftRightBits");
            Expect(TL.MultiplyHalves(x, y), (p, q) => (ushort)(p * q) | ((uint)(ushort)((p >> 16) * (q >> 16)) << 16), "MultiplyHalves");
            Expect(TL.ShiftRightHalves(x, shift % 16), (p, _) => (uint)((ushort)p >> (shift % 16)) | ((p >> 16 >> (shift % 16)) << 16), "ShiftRightHalves");
            Expect(Gather<TL>(y), (_, q) => Table[q % (uint)Table.Length], "GatherBits");
            GatherPairs(y, out TL first, out TL second);
            Expect(first, (_, q) => Table[q % (uint)(Table.Length - 1)], "GatherPairs (first)");
            Expect(second, (_, q) => Table[(q % (uint)(Table.Length - 1)) + 1], "GatherPairs (second)");
        }
    }

    /// <summary>A pinned table for <see cref="ILanes{TSelf}.GatherBits"/>, each entry unlike its index.</summary>
    private static readonly uint[] Table = MakeTable();

    private static uint[] MakeTable()
    {
        uint[] table = GC.AllocateUninitializedArray<uint>(61, pinned: true);
        for (int i = 0; i < table.Length; i++)
        {
            table[i] = CounterHash.Hash((uint)i);
        }

        return table;
    }

    /// <summary>The table's entries at each lane's bits mod its length.</summary>
    private static unsafe TL Gather<TL>(TL bits)
        where TL : struct, ILanes<TL>
    {
        float[] lanes = new float[TL.Count];
        bits.Store(lanes);
        for (int lane = 0; lane < lanes.Length; lane++)
        {
            lanes[lane] = BitConverter.UInt32BitsToSingle(Bits(lanes[lane]) % (uint)Table.Length);
        }

        fixed (uint* table = Table)
        {
            return TL.GatherBits(table, TL.Load(lanes));
        }
    }

    /// <summary>The table's entries at each lane's bits mod its length less one, and the entries after them.</summary>
    private static unsafe void GatherPairs<TL>(TL bits, out TL first, out TL second)
        where TL : struct, ILanes<TL>
    {
        float[] lanes = new float[TL.Count];
        bits.Store(lanes);
        for (int lane = 0; lane < lanes.Length; lane++)
        {
            lanes[lane] = BitConverter.UInt32BitsToSingle(Bits(lanes[lane]) % (uint)(Table.Length - 1));
        }

        fixed (uint* table = Table)
        {
            TL.GatherPairs(table, TL.Load(lanes), out first, out second);
        }
    }

    [Fact]
    public void PermutationPairsInHalvesAreTheScalarPermutations()
    {
        CheckPermutationPairs<Lanes512>();
        CheckPermutationPairs<Lanes256>();
        CheckPermutationPairs<Lanes128>();
    }

    /// <summary>Every element of two permutations per lane, side by side in the lanes' halves, against the scalar permutations, at each length that fits.</summary>
    private static void CheckPermutationPairs<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] low = new float[n], high = new float[n];
        for (int length = 1; length <= 1 << 15; length *= 2)
        {
            Assert.True(LanePermutationPair<TL>.Fits(length));
            for (int shift = 0; shift < Words.Length; shift++)
            {
                float[] p = AsLanes(n, shift), q = AsLanes(n, shift + 5);
                var pair = default(LanePermutationPair<TL>);
                pair.Set(TL.Load(p), TL.Load(q), length);
                for (int i = 0; i < Math.Min(length, 64); i++)
                {
                    int at = (int)((uint)(i * 2654435761u) % (uint)length), other = (at + 1) % length;
                    TL indices = TL.Xor(LanePermutationPair<TL>.Both((uint)at), LanePermutationPair<TL>.Both((uint)(at ^ other)) & TL.BroadcastBits(0xffff0000u));
                    TL both = pair.Elements(indices, LanePermutationPair<TL>.Mask(length));
                    LanePermutationPair<TL>.Low(both).Store(low);
                    LanePermutationPair<TL>.High(both).Store(high);
                    for (int lane = 0; lane < n; lane++)
                    {
                        Assert.Equal(Permutation.PermutationElement(at, length, Bits(p[lane])), (int)Bits(low[lane]));
                        Assert.Equal(Permutation.PermutationElement(other, length, Bits(q[lane])), (int)Bits(high[lane]));
                    }
                }
            }
        }

        Assert.False(LanePermutationPair<TL>.Fits(1 << 16));
        Assert.False(LanePermutationPair<TL>.Fits(12));
    }

    private static void CheckConversions<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] result = new float[n];
        for (int shift = 0; shift < Words.Length; shift++)
        {
            float[] a = AsLanes(n, shift);
            TL.BitsToFloat(TL.Load(a)).Store(result);
            for (int lane = 0; lane < n; lane++)
            {
                Assert.Equal((int)Bits(a[lane]), result[lane]);
            }

            float[] values = Enumerable.Range(0, n).Select(lane => ((lane + shift) * 1234.567f) - 9000f).ToArray();
            TL.TruncateToBits(TL.Load(values)).Store(result);
            for (int lane = 0; lane < n; lane++)
            {
                Assert.Equal((int)values[lane], (int)Bits(result[lane]));
            }
        }
    }

    private static void CheckInDouble<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] result = new float[n], shifted = new float[n];
        const double Kensler = 1.0 / 4294967808.0;
        foreach ((double scale, int inner, int outer) in new[] { (CellFormula.UnitScale, 7, 1), (Kensler, 3, 5), (Kensler, 17, 1), (CellFormula.UnitScale, 16, 16), (Kensler, 4, 8), (Kensler, 8, 3), (CellFormula.UnitScale, 1, 256) })
        {
            var formula = new CellFormula(scale, inner, outer);
            for (int shift = 0; shift < Words.Length; shift++)
            {
                float[] a = Enumerable.Range(0, n).Select(lane => (float)((lane + shift) % inner)).ToArray();
                float[] c = Enumerable.Range(0, n).Select(lane => (float)((lane * 3) % 5)).ToArray();
                uint[] hashes = Enumerable.Range(0, n).Select(lane => CounterHash.Hash((uint)(lane + (17 * shift)))).ToArray();
                float[] high = hashes.Select(h => (float)(h >> 8)).ToArray(), low = hashes.Select(h => (float)(h & 0xff)).ToArray();
                TL.InDouble(formula, TL.Load(a), TL.Load(high), TL.Load(c), TL.Load(low)).Store(result);
                TL.InDouble(new ShiftFormula((double)shift / 17), TL.Load(high), default, default, default).Store(shifted);
                for (int lane = 0; lane < n; lane++)
                {
                    double jitter = hashes[lane] * scale;
                    float expected = (float)((c[lane] + ((a[lane] + jitter) / inner)) / outer);
                    Assert.Equal(BitConverter.SingleToInt32Bits(expected), BitConverter.SingleToInt32Bits(result[lane]));
                    double wrapped = ((double)shift / 17) + CounterHash.ToUnit(hashes[lane]);
                    float expectedShift = (float)(wrapped >= 1 ? wrapped - 1 : wrapped);
                    Assert.Equal(BitConverter.SingleToInt32Bits(expectedShift), BitConverter.SingleToInt32Bits(shifted[lane]));
                }
            }
        }
    }

    private static void CheckSelect<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] a = new float[n], b = new float[n], result = new float[n];
        for (int lane = 0; lane < n; lane++)
        {
            a[lane] = Values[lane % Values.Length];
            b[lane] = lane - 3.5f;
        }

        TL.Select(TL.LessThan(TL.Load(a), TL.Load(b)), TL.Load(a), TL.Load(b)).Store(result);
        for (int lane = 0; lane < n; lane++)
        {
            Assert.Equal(a[lane] < b[lane] ? a[lane] : b[lane], result[lane]);
        }

        // SelectWhereLess: the same choice in one step, NaN on either side choosing whenFalse.
        float[] values = [.. Values, float.NaN];
        for (int shift = 0; shift < values.Length; shift++)
        {
            float[] x = new float[n], y = new float[n], whenTrue = new float[n], whenFalse = new float[n];
            for (int lane = 0; lane < n; lane++)
            {
                x[lane] = values[lane % values.Length];
                y[lane] = values[(lane + shift) % values.Length];
                (whenTrue[lane], whenFalse[lane]) = (lane + 0.25f, -lane - 0.75f);
            }

            TL.SelectWhereLess(TL.Load(x), TL.Load(y), TL.Load(whenTrue), TL.Load(whenFalse)).Store(result);
            for (int lane = 0; lane < n; lane++)
            {
                Assert.Equal(x[lane] < y[lane] ? whenTrue[lane] : whenFalse[lane], result[lane]);
            }
        }
    }

    private static void CheckLessThanOrEqualBits<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] values = [.. Values, float.NaN];
        for (int shift = 0; shift < values.Length; shift++)
        {
            float[] a = new float[n], b = new float[n];
            uint expected = 0;
            for (int lane = 0; lane < n; lane++)
            {
                a[lane] = values[lane % values.Length];
                b[lane] = values[(lane + shift) % values.Length];
                expected |= a[lane] <= b[lane] ? 1u << lane : 0;   // false where either is NaN
            }

            Assert.Equal(expected, TL.LessThanOrEqualBits(TL.Load(a), TL.Load(b)));
            Assert.Equal(expected, TL.MaskBits(TL.LessThanOrEqual(TL.Load(a), TL.Load(b))));
        }
    }

    private static void CheckMinAbs<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        for (int shift = 0; shift < Values.Length; shift++)
        {
            float[] a = new float[n], b = new float[n], result = new float[n];
            for (int lane = 0; lane < n; lane++)
            {
                a[lane] = Math.Abs(Values[lane % Values.Length]);
                b[lane] = Values[(lane + shift) % Values.Length];
            }

            TL.MinAbs(TL.Load(a), TL.Load(b)).Store(result);
            for (int lane = 0; lane < n; lane++)
            {
                float expected = Math.Min(a[lane], Math.Abs(b[lane]));
                Assert.True(BitConverter.SingleToInt32Bits(expected) == BitConverter.SingleToInt32Bits(result[lane]), $"{typeof(TL).Name}: {a[lane]} min |{b[lane]}| gave {result[lane]}");
            }
        }
    }

    private static void CheckHash<TL>()
        where TL : struct, ILanes<TL>
    {
        int n = TL.Count;
        float[] bits = new float[n], hashed = new float[n], top = new float[n], unit = new float[n];
        foreach (uint start in new uint[] { 0, 1, 0x7fffffff, 0xfffffff0, 0x9e3779b9 })
        {
            TL keys = TL.SequenceBits(start);
            keys.Store(bits);
            TL h = TL.Hash(keys);
            h.Store(hashed);
            TL.Top24(h).Store(top);
            TL.ToUnit(h).Store(unit);
            for (int lane = 0; lane < n; lane++)
            {
                uint key = unchecked(start + (uint)lane);
                Assert.Equal(key, BitConverter.SingleToUInt32Bits(bits[lane]));
                uint expected = CounterHash.Hash(key);
                Assert.Equal(expected, BitConverter.SingleToUInt32Bits(hashed[lane]));
                Assert.Equal(expected >> 8, top[lane]);
                Assert.Equal(CounterHash.ToUnit(expected), unit[lane]);
            }
        }
    }
}
