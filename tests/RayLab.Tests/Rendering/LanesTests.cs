using RayLab.Rendering.Point.Packets;
using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>
/// The lane wrappers' operations that have a hardware shortcut (vrangeps for <c>MinAbs</c>, blends for <c>Select</c>) or feed the
/// samplers' points (<c>Hash</c>, <c>Top24</c>, <c>ToUnit</c>), lane by lane against the scalar definition, for
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
    public void HashAndUnitsAreTheScalarCounterHashInEveryLane()
    {
        CheckHash<Lanes512>();
        CheckHash<Lanes256>();
        CheckHash<Lanes128>();
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
                Assert.Equal((float)(expected >> 8), top[lane]);
                Assert.Equal(CounterHash.ToUnit(expected), (double)unit[lane]);
            }
        }
    }
}
