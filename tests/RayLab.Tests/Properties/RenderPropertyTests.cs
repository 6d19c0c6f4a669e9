namespace RayLab.Tests.Properties;

/// <summary>Random valid scenes (<see cref="RandomScene"/>, fixed FsCheck seed): rendering is total and deterministic.</summary>
public class RenderPropertyTests
{
    private readonly ITestOutputHelper _output;

    public RenderPropertyTests(ITestOutputHelper output) => _output = output;

    [Fact]
    public void EveryPixelsLinearValueIsFiniteAndBetweenTheSmallestAndLargestSampleValue()
    {
        // A pixel is the mean of its samples, each the background or a colour × ambient, so it lies in their
        // [min, max] per channel — up to the rounding of the sum and the division: n + 1 roundings of 2^−53.
        // (Intensities are generated up to 2^150 so that colour × ambient is finite; beyond ~1e154 each, the
        // product overflows to ∞, the 8-bit pixel is still 255, and no NaN can arise since Intensity maps NaN to 0.)
        int scenesWithASphere = 0;
        PropertyCheck.ForAll(RandomScene.WithPointSampler, 300, s =>
        {
            var values = new Intensity[s.Width * s.Height];
            new Renderer { Kernel = RenderKernel.Scalar }.Render(s.Scene, s.Camera, RenderMethod.Sampled(s.Sampler!), values, s.Width, s.Height);
            bool sphereSeen = false;
            (Intensity low, Intensity high) = s.Range;
            double slack = Math.ScaleB(s.Sampler!.SamplesPerPixel + 1, -53);
            for (int row = 0; row < s.Height; row++)
            {
                for (int x = 0; x < s.Width; x++)
                {
                    Intensity v = values[(row * s.Width) + x];
                    sphereSeen |= v != s.Scene.Background;
                    foreach ((double value, double lo, double hi) in new[] { (v.R, low.R, high.R), (v.G, low.G, high.G), (v.B, low.B, high.B) })
                    {
                        Assert.True(double.IsFinite(value), $"pixel ({x}, {row}): {v}");
                        Assert.True(value >= lo * (1 - slack) && value <= hi * (1 + slack), $"pixel ({x}, {row}): {v} outside [{low}, {high}]");
                    }
                }
            }

            scenesWithASphere += sphereSeen ? 1 : 0;
        });
        _output.WriteLine($"{scenesWithASphere} of 300 scenes show a sphere in some pixel");
        Assert.True(scenesWithASphere >= 60, $"only {scenesWithASphere} of 300 scenes show a sphere: the generator must aim better");
    }

    [Fact]
    public void TheBytesAreTheSameForOneTwoAndFourThreads()
    {
        PropertyCheck.ForAll(RandomScene.Any, 150, s =>
        {
            byte[] one = Render(s, 1);
            Assert.Equal(one, Render(s, 2));
            Assert.Equal(one, Render(s, 4));
            // The 8-bit levels stay within those of the smallest and largest sample value (±1 for rounding at a
            // level boundary), for the adaptive combination rule as for the mean.
            (Intensity low, Intensity high) = s.Range;
            for (int i = 0; i < one.Length; i++)
            {
                (double lo, double hi) = (i % 3) switch { 0 => (low.R, high.R), 1 => (low.G, high.G), _ => (low.B, high.B) };
                Assert.InRange(one[i], Intensity.ToLevel(lo) - 1, Intensity.ToLevel(hi) + 1);
            }
        });
    }

    private static byte[] Render(RandomScene s, int threads)
    {
        var image = new Image(s.Width, s.Height);
        var renderer = new Renderer { MaxDegreeOfParallelism = threads };
        if (s.Adaptive is { } adaptive)
        {
            renderer.Render(s.Scene, s.Camera, adaptive, image);
        }
        else
        {
            renderer.Render(s.Scene, s.Camera, s.Sampler!, image);
        }

        return image.PixelBytes.ToArray();
    }
}
