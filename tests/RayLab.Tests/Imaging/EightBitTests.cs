using RayLab.Simd;

namespace RayLab.Tests.Imaging;

/// <summary>The 8-bit rule's scalar form and its lane form, each against the other and against the rule.</summary>
public class EightBitTests
{
    /// <summary>0, 1, just below 1, above 1, tiny values, every step k/256 and one float ulp either side, and more.</summary>
    private static float[] Values()
    {
        var values = new List<float> { 0f, 1f, MathF.BitDecrement(1f), MathF.BitIncrement(1f), 1.5f, 2f, 1000f, 3e38f, float.PositiveInfinity, float.Epsilon, 1e-30f, 1e-7f, 0.5f / 256 };
        for (int k = 0; k <= 256; k++)
        {
            float step = k / 256f;
            values.AddRange([step, MathF.BitDecrement(step), MathF.BitIncrement(step), (k + 0.5f) / 256f]);
        }

        var random = new Random(256);
        for (int i = 0; i < 2000; i++)
        {
            values.Add((float)(random.NextDouble() * 1.2));
        }

        return [.. values.Where(v => v >= 0)];
    }

    [Fact]
    public void TheScalarFormIsTheLabsTruncationOf256TimesI()
    {
        foreach (float value in Values())
        {
            double scaled = 256.0 * value;
            int expected = scaled >= 255 ? 255 : (int)Math.Floor(scaled);
            Assert.True(expected == EightBit.Level(value), $"I = {value:R}: level {EightBit.Level(value)}, expected {expected}");
        }

        Assert.Equal(0, EightBit.Level(double.NaN));
        Assert.Equal(0, EightBit.Level(-0.5));
        Assert.Equal(255, EightBit.Level(1));
        Assert.Equal(254, EightBit.Level(Math.BitDecrement(255.0 / 256)));
    }

    [Fact]
    public void TheLaneFormGivesTheScalarFormsLevelInEveryLane()
    {
        CheckLanes<Lanes128>();
        CheckLanes<Lanes256>();
        CheckLanes<Lanes512>();
    }

    [Fact]
    public void TheLaneFormWritesOnlyThePixelsItIsGiven()
    {
        var pixels = new Rgb24[5];
        Array.Fill(pixels, new Rgb24(7, 7, 7));
        Lanes256 one = Lanes256.Broadcast(1f);
        EightBit.WriteLanes(one, one, one, Lanes256.Broadcast(256f), pixels.AsSpan(1, 3));
        Assert.Equal([new Rgb24(7, 7, 7), new Rgb24(255, 255, 255), new Rgb24(255, 255, 255), new Rgb24(255, 255, 255), new Rgb24(7, 7, 7)], pixels);
    }

    private static void CheckLanes<TL>()
        where TL : struct, ILanes<TL>
    {
        float[] values = Values();
        int count = TL.Count;
        float[] red = new float[count], green = new float[count], blue = new float[count];
        var pixels = new Rgb24[count];
        for (int start = 0; start < values.Length; start += count)
        {
            for (int lane = 0; lane < count; lane++)
            {
                // Each channel gets a different value, so a swapped channel shows.
                red[lane] = values[(start + lane) % values.Length];
                green[lane] = values[(start + lane + 1) % values.Length];
                blue[lane] = values[(start + lane + 2) % values.Length];
            }

            EightBit.WriteLanes(TL.Load(red), TL.Load(green), TL.Load(blue), TL.Broadcast(256f), pixels);
            for (int lane = 0; lane < count; lane++)
            {
                var expected = new Rgb24(EightBit.Level(red[lane]), EightBit.Level(green[lane]), EightBit.Level(blue[lane]));
                Assert.True(expected == pixels[lane], $"{typeof(TL).Name} lane {lane}: I = ({red[lane]:R}, {green[lane]:R}, {blue[lane]:R}) gave {pixels[lane]}, the scalar form {expected}");
            }
        }
    }
}
