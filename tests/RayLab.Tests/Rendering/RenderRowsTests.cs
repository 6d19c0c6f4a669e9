using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>Renderer.RenderRows: bands of rows, rendered one after another, give the bytes and rays per pixel of one render.</summary>
public class RenderRowsTests
{
    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    /// <summary>A pixel method of the test's own: the mean of the pixel's centre and its top-left quarter's centre.</summary>
    private sealed class TwoPoints : IPixelMethod<int>
    {
        public string Name => "two points";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch) => (pixel.Trace(0.5, 0.5) + pixel.Trace(0.25, 0.25)) / 2;
    }

    public static TheoryData<string> Methods => ["jittered", "sobol", "adaptive", "adaptive-min1", "adaptive-quincunx-guard", "exact", "custom"];

    private static RenderMethod Method(string name) => name switch
    {
        "adaptive" => RenderMethod.Adaptive(new AdaptiveSampler(0, 3, 0.05)),
        "adaptive-min1" => RenderMethod.Adaptive(new AdaptiveSampler(1, 3, 0.05)),
        "adaptive-quincunx-guard" => RenderMethod.Adaptive(new AdaptiveSampler(0, 2, 0.05, quincunx: true, guard: true)),
        "exact" => RenderMethod.Exact,
        "custom" => RenderMethod.Custom(new TwoPoints()),
        _ => RenderMethod.Sampled(Samplers.Create(name, 4, 7)),
    };

    [Theory]
    [MemberData(nameof(Methods))]
    public void Bands_rendered_one_after_another_give_the_bytes_of_one_render(string name)
    {
        const int w = 61, h = 37;
        var whole = new Image(w, h);
        var wholeRays = new float[w * h];
        new Renderer().Render(TwoSpheres(), Camera, Method(name), whole, wholeRays);

        var banded = new Image(w, h);
        var bandedRays = new float[w * h];
        var renderer = new Renderer { MaxDegreeOfParallelism = 1 };
        foreach (int[] band in new[] { new[] { 0, 5 }, [5, 0], [5, 11], [16, 1], [17, 20] })
        {
            renderer.RenderRows(TwoSpheres(), Camera, Method(name), banded, band[0], band[1], bandedRays);
        }

        Assert.Equal(whole.PixelBytes.ToArray(), banded.PixelBytes.ToArray());
        Assert.Equal(wholeRays, bandedRays);
    }

    [Fact]
    public void A_band_leaves_the_other_rows_and_counts_its_own_rays()
    {
        var image = new Image(20, 10);
        RenderStatistics stats = new Renderer().RenderRows(TwoSpheres(), Camera, RenderMethod.Sampled(new JitteredSampler(4, 1)), image, 3, 2);
        Assert.Equal(20L * 2 * 4, stats.PrimaryRays);
        Assert.All(image.PixelBytes[..(3 * 20 * 3)].ToArray(), b => Assert.Equal(0, b));
        Assert.All(image.PixelBytes[(5 * 20 * 3)..].ToArray(), b => Assert.Equal(0, b));
        Assert.Contains(image.PixelBytes[(3 * 20 * 3)..(5 * 20 * 3)].ToArray(), b => b != 0);
    }

    [Theory]
    [InlineData(-1, 1, "firstRow")]
    [InlineData(0, -1, "rowCount")]
    [InlineData(5, 6, "rowCount")]
    public void A_band_outside_the_image_names_its_parameter(int first, int count, string parameter)
    {
        ArgumentOutOfRangeException e = Assert.Throws<ArgumentOutOfRangeException>(() =>
            new Renderer().RenderRows(TwoSpheres(), Camera, RenderMethod.Exact, new Image(8, 10), first, count));
        Assert.Equal(parameter, e.ParamName);
    }
}
