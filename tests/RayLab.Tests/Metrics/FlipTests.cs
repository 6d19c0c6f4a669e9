using System.Globalization;
using System.Runtime.CompilerServices;
using RayLab.Metrics;

namespace RayLab.Tests.Metrics;

/// <summary>
/// LDR-FLIP against NVIDIA's own FLIP tool (v1.6): its means and error maps for committed render pairs are in
/// Metrics/Data (nvidia-flip.csv, nvidia/*.png; README.md there says how they were made).
/// </summary>
public sealed class FlipTests
{
    /// <summary>The agreement the issue asks for: mean within 10⁻³, each pixel within 0.02.</summary>
    private const double MeanTolerance = 1e-3;
    private const double PixelTolerance = 0.02;

    /// <summary>
    /// What the committed maps allow beyond that: the tool's 8-bit rounding (0.5/255) plus 2·10⁻⁴ of float
    /// difference. On these pairs the largest difference is 0.5/255 + 4·10⁻⁵; dropping the feature exponent q_f
    /// (a wrong model) moves even the low-error pairs' pixels far past it.
    /// </summary>
    private const double StrictPixelTolerance = (0.5 / 255) + 2e-4;

    private readonly ITestOutputHelper _output;

    public FlipTests(ITestOutputHelper output) => _output = output;

    public static TheoryData<string, string, string, double, string> NvidiaPairs()
    {
        var data = new TheoryData<string, string, string, double, string>();
        foreach (string line in File.ReadAllLines(Path.Combine(DataFolder(), "nvidia-flip.csv")).Skip(1))
        {
            string[] f = line.Split(',');
            data.Add(f[0], f[1], f[2], double.Parse(f[3], CultureInfo.InvariantCulture), f[4]);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(NvidiaPairs))]
    public void Matches_NVIDIAs_tool_in_the_mean_and_per_pixel(string reference, string test, string ppd, double nvidiaMean, string nvidiaMap)
    {
        FlipOptions options = ppd == "default"
            ? new FlipOptions()
            : new FlipOptions { PixelsPerDegree = double.Parse(ppd, CultureInfo.InvariantCulture) };
        FlipResult ours = Flip.Compute(Load(reference), Load(test), options);

        // The tool writes its map as 8-bit grey (round(255·e)): a level is within 0.5/255 of its value.
        PngTestDecoder.Result map = PngTestDecoder.Decode(File.ReadAllBytes(Path.Combine(DataFolder(), nvidiaMap)));
        Assert.Equal((ours.Width, ours.Height), (map.Width, map.Height));
        double worst = 0;
        int worstIndex = 0;
        for (int i = 0; i < ours.Map.Length; i++)
        {
            double d = Math.Abs(ours.Map[i] - (map.Rgb[3 * i] / 255.0));
            if (d > worst)
            {
                worst = d;
                worstIndex = i;
            }
        }

        _output.WriteLine($"{test} vs {reference} at {ppd} ppd: ours {ours.Mean:F6}, NVIDIA {nvidiaMean:F6}, |Δ mean| {Math.Abs(ours.Mean - nvidiaMean):E2}; largest |Δ pixel| {worst:F5} at ({worstIndex % ours.Width}, {worstIndex / ours.Width})");
        Assert.InRange(Math.Abs(ours.Mean - nvidiaMean), 0, MeanTolerance);
        Assert.InRange(worst, 0, PixelTolerance);
        Assert.InRange(worst, 0, StrictPixelTolerance);
    }

    [Fact]
    public void Identical_images_give_zero_everywhere()
    {
        Image image = Load("sphere-field-exact.png");
        FlipResult result = Flip.Compute(image, Load("sphere-field-exact.png"));
        Assert.Equal(0, result.Mean);
        Assert.All(result.ToArray(), e => Assert.Equal(0f, e));
    }

    [Theory]
    [InlineData(1, 1)]
    [InlineData(7, 3)]
    [InlineData(33, 17)]
    [InlineData(320, 180)]
    public void The_map_has_the_images_size_and_values_in_0_1(int width, int height)
    {
        FlipResult result = Flip.Compute(TestImages.Varied(width, height, 1), TestImages.Noise(width, height, 2));
        Assert.Equal(width, result.Width);
        Assert.Equal(height, result.Height);
        Assert.Equal(width * height, result.Map.Length);
        Assert.All(result.ToArray(), e => Assert.InRange(e, 0f, 1f));
        Assert.InRange(result.Mean, 0, 1);
        Assert.Equal(result.Map[((height - 1) * width) + width - 1], result[width - 1, height - 1]);
    }

    [Fact]
    public void Mismatched_sizes_throw_naming_the_test_image()
    {
        var e = Assert.Throws<ArgumentException>(() => Flip.Compute(new Image(8, 8), new Image(8, 9)));
        Assert.Equal("test", e.ParamName);
        Assert.Contains("8×9", e.Message, StringComparison.Ordinal);
        Assert.Equal("test", Assert.Throws<ArgumentException>(() => Flip.Compute(new Image(8, 8), new Image(9, 8))).ParamName);
    }

    [Fact]
    public void Null_images_throw_naming_the_parameter()
    {
        Assert.Equal("reference", Assert.Throws<ArgumentNullException>(() => Flip.Compute(null!, new Image(2, 2))).ParamName);
        Assert.Equal("test", Assert.Throws<ArgumentNullException>(() => Flip.Compute(new Image(2, 2), null!)).ParamName);
    }

    [Fact]
    public void The_result_is_the_same_at_any_thread_count()
    {
        Image reference = Load("sphere-field-exact.png");
        Image test = Load("sphere-field-jittered1.png");
        FlipResult one = Flip.Compute(reference, test, new FlipOptions { MaxDegreeOfParallelism = 1 });
        foreach (int threads in new[] { 2, 3, 8, -1 })
        {
            FlipResult many = Flip.Compute(reference, test, new FlipOptions { MaxDegreeOfParallelism = threads });
            Assert.Equal(one.Mean, many.Mean);
            Assert.True(one.Map.SequenceEqual(many.Map), $"The map at {threads} threads differs from the map at 1.");
        }
    }

    [Fact]
    public void The_vector_and_scalar_paths_agree()
    {
        Image reference = Load("two-spheres-exact.png");
        Image test = Load("two-spheres-jittered1.png");
        FlipResult vector = Flip.Compute(reference, test, null, vectorized: true);
        FlipResult scalar = Flip.Compute(reference, test, null, vectorized: false);
        Assert.InRange(Math.Abs(vector.Mean - scalar.Mean), 0, 1e-6);
        for (int i = 0; i < vector.Map.Length; i++)
        {
            Assert.InRange(Math.Abs(vector.Map[i] - scalar.Map[i]), 0, 1e-4);
        }
    }

    [Fact]
    public void The_default_viewing_conditions_are_the_papers()
    {
        Assert.Equal(0.7 * 3840 / 0.7 * Math.PI / 180, FlipOptions.DefaultPixelsPerDegree, 12);
        Assert.Equal(67.02, new FlipOptions().PixelsPerDegree, 2);
        Assert.Equal(FlipOptions.ComputePixelsPerDegree(0.5, 0.6, 1920), FlipOptions.ForDisplay(0.5, 0.6, 1920).PixelsPerDegree);
        Assert.Equal(-1, new FlipOptions().MaxDegreeOfParallelism);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(0.5)]
    [InlineData(1000.5)]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    public void Pixels_per_degree_out_of_range_throws(double ppd)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => new FlipOptions { PixelsPerDegree = ppd });
        Assert.Equal("PixelsPerDegree", e.ParamName);
    }

    [Fact]
    public void Bad_viewing_conditions_and_thread_counts_throw_naming_the_argument()
    {
        Assert.Equal("distanceMeters", Assert.Throws<ArgumentOutOfRangeException>(() => FlipOptions.ComputePixelsPerDegree(0, 0.7, 3840)).ParamName);
        Assert.Equal("displayWidthMeters", Assert.Throws<ArgumentOutOfRangeException>(() => FlipOptions.ComputePixelsPerDegree(0.7, -1, 3840)).ParamName);
        Assert.Equal("displayWidthPixels", Assert.Throws<ArgumentOutOfRangeException>(() => FlipOptions.ComputePixelsPerDegree(0.7, 0.7, 0)).ParamName);
        Assert.Equal("MaxDegreeOfParallelism", Assert.Throws<ArgumentOutOfRangeException>(() => new FlipOptions { MaxDegreeOfParallelism = 0 }).ParamName);
    }

    [Fact]
    public void The_smallest_and_largest_pixels_per_degree_give_finite_maps()
    {
        Image reference = TestImages.Varied(40, 30, 3);
        Image test = TestImages.Noise(40, 30, 4);
        foreach (double ppd in new[] { FlipOptions.MinPixelsPerDegree, FlipOptions.MaxPixelsPerDegree })
        {
            FlipResult result = Flip.Compute(reference, test, new FlipOptions { PixelsPerDegree = ppd });
            Assert.All(result.ToArray(), e => Assert.InRange(e, 0f, 1f));
        }
    }

    internal static Image Load(string name)
    {
        PngTestDecoder.Result png = PngTestDecoder.Decode(File.ReadAllBytes(Path.Combine(DataFolder(), name)));
        var image = new Image(png.Width, png.Height);
        png.Rgb.CopyTo(image.PixelBytes);
        return image;
    }

    /// <summary>Metrics/Data beside this source file (the data are read from the checkout, not copied to the output).</summary>
    internal static string DataFolder([CallerFilePath] string source = "") =>
        Path.Combine(Path.GetDirectoryName(source)!, "Data");
}
