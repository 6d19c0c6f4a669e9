using System.Numerics;
using RayLab.Metrics;

namespace RayLab.Tests.Metrics;

/// <summary>The low-pass error and the error spectrum against inputs whose answers are known in closed form.</summary>
public class ErrorLocationTests
{
    /// <summary>Gaussian white noise of standard deviation <paramref name="s"/> (Box–Muller on a fixed hash stream).</summary>
    private static double[] WhiteNoise(int width, int height, double s)
    {
        var plane = new double[width * height];
        var random = new Random(12345);
        for (int i = 0; i < plane.Length; i++)
        {
            double u = 1 - random.NextDouble(), v = random.NextDouble();
            plane[i] = s * Math.Sqrt(-2 * Math.Log(u)) * Math.Cos(2 * Math.PI * v);
        }

        return plane;
    }

    private static double[] Plane(int width, int height, Func<int, int, double> f)
    {
        var plane = new double[width * height];
        for (int y = 0; y < height; y++)
        {
            for (int x = 0; x < width; x++)
            {
                plane[(y * width) + x] = f(x, y);
            }
        }

        return plane;
    }

    private static double Rms(double[] plane) => Math.Sqrt(plane.Average(v => v * v));

    [Theory]
    [InlineData(1.0)]
    [InlineData(2.0)]
    public void WhiteNoiseKeepsOneOverTwoSigmaRootPiAfterTheBlur(double sigma)
    {
        double[] noise = WhiteNoise(256, 200, 3);
        double expected = Rms(noise) / (2 * sigma * Math.Sqrt(Math.PI));
        Assert.InRange(ErrorLocation.LowPassRmse(noise, 256, 200, sigma) / expected, 0.95, 1.05);
    }

    [Fact]
    public void WhiteNoiseIsFlatAtItsVarianceWithALowShareOfPiOver64()
    {
        double[] noise = WhiteNoise(256, 200, 3);
        ErrorSpectrum spectrum = ErrorLocation.Spectrum(noise, 256, 200);
        Assert.Equal(noise.Average(v => v * v), spectrum.MeanSquare, 9);
        Assert.InRange(spectrum.LowFrequencyShare, 0.9 * Math.PI / 64, 1.1 * Math.PI / 64);
        for (int ring = 4; ring < 32; ring++)
        {
            Assert.InRange(spectrum.RadialMean[ring] / 9, 0.85, 1.15);
        }
    }

    [Theory]
    [InlineData(128, 8.0)]
    [InlineData(120, 8.0)]
    [InlineData(120, 4.0)]
    public void ASingleFrequencyIsDampedByTheGaussiansTransferAndSitsInItsRing(int width, double period)
    {
        double[] wave = Plane(width, 90, (x, _) => 5 * Math.Cos(2 * Math.PI * x / period));
        double rms = Rms(wave);
        foreach (double sigma in new[] { 1.0, 2.0 })
        {
            // The continuous Gaussian's transfer e^(−2π²σ²f²); where it is below 5% the kernel's renormalised ends
            // at the image's left and right edges, not the wave, set what is left.
            double transfer = Math.Exp(-2 * Math.PI * Math.PI * sigma * sigma / (period * period));
            if (transfer > 0.05)
            {
                Assert.InRange(ErrorLocation.LowPassRmse(wave, width, 90, sigma) / (rms * transfer), 0.9, 1.1);
            }
        }

        ErrorSpectrum spectrum = ErrorLocation.Spectrum(wave, width, 90);
        Assert.Equal(rms * rms, spectrum.MeanSquare, 6);
        int peak = Enumerable.Range(0, spectrum.RadialMean.Count).MaxBy(r => double.IsNaN(spectrum.RadialMean[r]) ? 0 : spectrum.RadialMean[r]);
        Assert.InRange(ErrorSpectrum.Frequency(peak), (1 / period) - ErrorLocation.RingWidth, (1 / period) + ErrorLocation.RingWidth);
        if (width % period == 0)
        {
            // Whole periods: the power sits at ±1/period only, all of it low (8 px) or none of it (4 px).
            Assert.Equal(period >= 8 ? 1 : 0, spectrum.LowFrequencyShare, 6);
        }
    }

    [Fact]
    public void ASmoothRampSurvivesTheBlurAndSitsAtLowFrequencies()
    {
        double[] ramp = Plane(200, 150, (x, y) => (0.04 * (x - 100)) + (0.02 * (y - 75)));
        double rms = Rms(ramp);
        Assert.InRange(ErrorLocation.LowPassRmse(ramp, 200, 150, 1) / rms, 0.99, 1.0);
        Assert.InRange(ErrorLocation.LowPassRmse(ramp, 200, 150, 2) / rms, 0.97, 1.0);
        Assert.InRange(ErrorLocation.Spectrum(ramp, 200, 150).LowFrequencyShare, 0.95, 1.0);
    }

    [Fact]
    public void TheImageFormsAverageTheThreeChannels()
    {
        var exact = new Image(40, 30);
        var image = new Image(40, 30);
        Span<byte> bytes = image.PixelBytes;
        for (int i = 0; i < bytes.Length; i++)
        {
            bytes[i] = (byte)(i % 3 == 0 ? 6 : 0);
        }

        // One channel of three off by 6 everywhere: a constant error, untouched by the blur, all of it at f = 0.
        Assert.Equal(Math.Sqrt(36.0 / 3), ErrorLocation.LowPassRmse(image, exact, 2), 9);
        ErrorSpectrum spectrum = ErrorLocation.Spectrum(image, exact);
        Assert.Equal(12, spectrum.MeanSquare, 9);
        Assert.Equal(1, spectrum.LowFrequencyShare, 9);
        Assert.Equal(0, ErrorLocation.Spectrum(exact, exact).LowFrequencyShare);
    }

    [Fact]
    public void BadInputNamesItsParameter()
    {
        Assert.Equal("image", Assert.Throws<ArgumentException>(() => ErrorLocation.LowPassRmse(new Image(4, 4), new Image(5, 4), 1)).ParamName);
        Assert.Equal("sigma", Assert.Throws<ArgumentOutOfRangeException>(() => ErrorLocation.LowPassRmse(new double[4], 2, 2, 0)).ParamName);
        Assert.Equal("error", Assert.Throws<ArgumentException>(() => ErrorLocation.Spectrum(new double[5], 2, 2)).ParamName);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(5)]
    [InlineData(8)]
    [InlineData(12)]
    [InlineData(37)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(6)]
    [InlineData(60)]
    [InlineData(270)]
    [InlineData(480)]
    [InlineData(1080)]
    [InlineData(1920)]
    [InlineData(74)]
    public void TheFourierTransformIsTheSumItDefines(int n)
    {
        var random = new Random(n);
        Complex[] x = [.. Enumerable.Range(0, n).Select(_ => new Complex(random.NextDouble() - 0.5, random.NextDouble() - 0.5))];
        Complex[] fast = [.. x];
        new Fourier(n).Transform(fast);
        for (int k = 0; k < n; k++)
        {
            Complex sum = Complex.Zero;
            for (int j = 0; j < n; j++)
            {
                sum += x[j] * Complex.FromPolarCoordinates(1, -2 * Math.PI * j * k / n);
            }

            Assert.True((fast[k] - sum).Magnitude < 1e-9, $"n = {n}, k = {k}: {fast[k]} against {sum}");
        }
    }

    [Theory]
    [InlineData(1)]
    [InlineData(8)]
    [InlineData(37)]
    [InlineData(60)]
    [InlineData(74)]
    [InlineData(270)]
    [InlineData(1080)]
    [InlineData(1920)]
    public void TheLaneTransformIsEachLanesOwnTransform(int n)
    {
        // Each lane a different sequence: every lane must come out as that sequence's transform, and for the mixed
        // radix lengths that are not powers of two (done by Stockham's stages in both forms) bit for bit the scalar one.
        int lanes = System.Numerics.Vector<double>.Count;
        var random = new Random(n + 1);
        var re = new double[n * lanes];
        var im = new double[n * lanes];
        for (int i = 0; i < re.Length; i++)
        {
            re[i] = random.NextDouble() - 0.5;
            im[i] = random.NextDouble() - 0.5;
        }

        double[] inRe = [.. re], inIm = [.. im];
        var fourier = new Fourier(n);
        fourier.Transform(re, im);
        bool sameOperations = !System.Numerics.BitOperations.IsPow2(n) && n % 7 != 0 && n % 37 != 0;
        for (int l = 0; l < lanes; l++)
        {
            Complex[] scalar = [.. Enumerable.Range(0, n).Select(k => new Complex(inRe[(k * lanes) + l], inIm[(k * lanes) + l]))];
            new Fourier(n).Transform(scalar);
            for (int k = 0; k < n; k++)
            {
                var lane = new Complex(re[(k * lanes) + l], im[(k * lanes) + l]);
                Assert.True((lane - scalar[k]).Magnitude < 1e-9, $"n = {n}, lane {l}, k = {k}: {lane} against {scalar[k]}");
                if (sameOperations)
                {
                    Assert.Equal(scalar[k], lane);
                }
            }
        }
    }

    [Theory]
    [InlineData(61, 37)]
    [InlineData(480, 270)]
    public void TheMeasuresAreTheSameAtAnyThreadCount(int width, int height)
    {
        // Noise-like error with a patch, so every row and column differs; the results must match to the last bit.
        var random = new Random(width);
        var image = new Image(width, height);
        var exact = new Image(width, height);
        for (int y = 0; y < height; y++)
        {
            for (int x = 0; x < width; x++)
            {
                byte level = (byte)random.Next(256);
                exact.GetRowSpan(y)[x] = new Rgb24(level, (byte)(255 - level), 128);
                image.GetRowSpan(y)[x] = x < width / 3 && y < height / 2 ? new Rgb24(level, level, level) : new Rgb24((byte)Math.Min(255, level + random.Next(3)), (byte)(255 - level), 127);
            }
        }

        double[] Lows(int threads) => [ErrorLocation.LowPassRmse(image, exact, 1, threads), ErrorLocation.LowPassRmse(image, exact, 2, threads)];
        double[] Spectrum(int threads)
        {
            ErrorSpectrum s = ErrorLocation.Spectrum(image, exact, threads);
            return [s.MeanSquare, s.LowFrequencyShare, .. s.RadialMean];
        }

        Assert.True(Lows(1)[0] > 0);
        foreach (int threads in new[] { 2, 3, 16, -1 })
        {
            Assert.Equal(Lows(1), Lows(threads));
            Assert.Equal(Spectrum(1), Spectrum(threads));
        }

        // The one-call forms are these on every core.
        Assert.Equal(Lows(1)[1], ErrorLocation.LowPassRmse(image, exact, 2));
        Assert.Equal(Spectrum(1), Spectrum(-1));
    }
}
