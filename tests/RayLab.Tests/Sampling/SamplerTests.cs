using RayLab.Sampling;

namespace RayLab.Tests.Sampling;

public class SamplerTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(4)]
    [InlineData(25)]
    public void RegularSamplesSitOnTheCellCentres(int count)
    {
        var sampler = new RegularSampler(count);
        int n = (int)Math.Sqrt(count);
        for (int i = 0; i < count; i++)
        {
            SamplePoint s = sampler.GetSample(7, 3, i);
            Assert.Equal(((i % n) + 0.5) / n, s.X, 1e-15);
            Assert.Equal(((i / n) + 0.5) / n, s.Y, 1e-15);
        }

        Assert.Equal(new SamplePoint(0.5, 0.5), new RegularSampler(1).GetSample(0, 0, 0));
    }

    [Fact]
    public void JitteredPutsExactlyOneSampleInEachCell()
    {
        var sampler = new JitteredSampler(16, 42);
        for (int px = 0; px < 20; px++)
        {
            var seen = new bool[16];
            for (int i = 0; i < 16; i++)
            {
                SamplePoint s = sampler.GetSample(px, px * 3, i);
                Assert.InRange(s.X, 0, Math.BitDecrement(1.0));
                Assert.InRange(s.Y, 0, Math.BitDecrement(1.0));
                int cell = ((int)(s.Y * 4) * 4) + (int)(s.X * 4);
                Assert.Equal(i, cell);
                seen[cell] = true;
            }

            Assert.All(seen, Assert.True);
        }
    }

    [Fact]
    public void RandomSamplesAreUniformAndInTheUnitSquare()
    {
        var sampler = new RandomSampler(1000, 7);
        double meanX = 0, meanY = 0;
        for (int i = 0; i < 1000; i++)
        {
            SamplePoint s = sampler.GetSample(5, 9, i);
            Assert.InRange(s.X, 0, Math.BitDecrement(1.0));
            Assert.InRange(s.Y, 0, Math.BitDecrement(1.0));
            meanX += s.X / 1000;
            meanY += s.Y / 1000;
        }

        // Mean of 1000 uniforms: standard deviation 0.009; 0.05 is over five sigma.
        Assert.Equal(0.5, meanX, 0.05);
        Assert.Equal(0.5, meanY, 0.05);
    }

    [Theory]
    [InlineData("random")]
    [InlineData("jittered")]
    public void SamplesAreAFunctionOfPixelIndexAndSeed(string name)
    {
        IPixelSampler a = Samplers.Create(name, 4, 1), again = Samplers.Create(name, 4, 1), other = Samplers.Create(name, 4, 2);
        Assert.Equal(a.GetSample(3, 4, 2), again.GetSample(3, 4, 2));
        Assert.NotEqual(a.GetSample(3, 4, 2), other.GetSample(3, 4, 2));
        Assert.NotEqual(a.GetSample(3, 4, 2), a.GetSample(4, 3, 2));
        Assert.NotEqual(a.GetSample(3, 4, 2), a.GetSample(3, 4, 3));
    }

    [Theory]
    [InlineData("regular", 5)]
    [InlineData("jittered", 8)]
    [InlineData("regular", 0)]
    [InlineData("random", 0)]
    [InlineData("jittered", -4)]
    public void UnusableSampleCountsAreRejectedNamingTheParameter(string name, int samples)
    {
        ArgumentException e = Assert.ThrowsAny<ArgumentException>(() => Samplers.Create(name, samples, 0));
        Assert.Equal("samplesPerPixel", e.ParamName);
    }

    [Fact]
    public void UnknownSamplerNamesAreRejectedListingTheKnownOnes()
    {
        ArgumentException e = Assert.Throws<ArgumentException>(() => Samplers.Create("stochastic", 4, 0));
        Assert.Contains("jittered", e.Message);
        Assert.IsType<JitteredSampler>(Samplers.Create("Jittered", 4, 0));
    }

    [Fact]
    public void TheCounterHashIsLowbias32()
    {
        // Reference values of Wellons' lowbias32 (as in benchmarks/anchors/native_ref.cpp).
        Assert.Equal(0u, CounterHash.Hash(0));
        Assert.NotEqual(CounterHash.Hash(1), CounterHash.Hash(2));
        uint x = 1;
        x ^= x >> 16; x *= 0x7feb352d; x ^= x >> 15; x *= 0x846ca68b; x ^= x >> 16;
        Assert.Equal(x, CounterHash.Hash(1));
        Assert.Equal(0.0, CounterHash.ToUnit(0));
        Assert.Equal(1 - Math.Pow(2, -24), CounterHash.ToUnit(uint.MaxValue));
    }
}
