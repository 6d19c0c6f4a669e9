using RayLab;
using Rgb24 = SixLabors.ImageSharp.PixelFormats.Rgb24;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>2.2: the 8-bit rule i = int(256·I) at its edges, against RayLab's, and the image's pixels.</summary>
#else
/// <summary>2.2: reguła 8-bitowa i = int(256·I) na jej krańcach, wobec reguły RayLab, i piksele obrazu.</summary>
#endif
public sealed class ImageChecks(ITestOutputHelper output)
{
    public static TheoryData<Level> Edges => new()
    {
        0.0, 1.0 / 256 - 1e-12, 1.0 / 256, 0.1, 0.5, 127.5 / 256, 0.999 / 256 * 255, 255.0 / 256 - 1e-9, 255.0 / 256, 0.999999, 1.0, 1.5, -0.1, double.NaN,
    };

    [Trait("Section", "2.2")]
    [Theory(DisplayName = Msg.EightBitRule)]
    [MemberData(nameof(Edges))]
    public void EightBitRule(Level I) => Run(output, () =>
    {
        double intensity = I.Value;
        byte expected = Intensity.ToLevel(intensity);
        byte actual = LabImage.ToByte(intensity);
        output.WriteLine(Msg.EightBitLine(intensity, actual, expected));
        Assert.True(expected == actual, Msg.EightBitWrong(intensity, expected, actual, Source(typeof(LabImage), nameof(LabImage.ToByte))));
    });

    [Trait("Section", "2.2")]
    [Fact(DisplayName = Msg.SetPixel)]
    public void SetPixel() => Run(output, () =>
    {
        var image = new LabImage(3, 2);
        Assert.True((image.Width, image.Height) == (3, 2), Msg.ImageSize(image.Width, image.Height));
        image.SetPixel(2, 0, new LightIntensity(0.9, 0.2, 2));
        Rgb24 set = image.Bitmap[2, 0], untouched = image.Bitmap[0, 1];
        Rgb24 expected = new(Intensity.ToLevel(0.9), Intensity.ToLevel(0.2), Intensity.ToLevel(2));
        output.WriteLine($"Bitmap[2, 0] = {set}, Bitmap[0, 1] = {untouched}");
        Assert.True(set == expected, Msg.SetPixelWrong(expected, set, Source(typeof(LabImage), nameof(LabImage.SetPixel))));
        Assert.True(untouched == new Rgb24(0, 0, 0), Msg.NewImageNotBlack(untouched));
    });
}

#if (en)
/// <summary>
/// An intensity as a theory's argument, named the same on every machine: 0.1, not 0,1 under a Polish culture, and in
/// its shortest exact form (0.996093749, not 0.99609374900000003).
/// </summary>
#else
/// <summary>
/// Natężenie jako argument testu z danymi, nazwane tak samo na każdym komputerze: 0.1, a nie 0,1 przy polskich
/// ustawieniach regionalnych, i w najkrótszej dokładnej postaci (0.996093749, a nie 0.99609374900000003).
/// </summary>
#endif
public sealed class Level : Xunit.Sdk.IXunitSerializable
{
    public Level()
    {
    }

    public Level(double value) => Value = value;

    public double Value { get; private set; }

    public static implicit operator Level(double value) => new(value);

    public void Deserialize(Xunit.Sdk.IXunitSerializationInfo info) => Value = (double)info.GetValue("I")!;

    public void Serialize(Xunit.Sdk.IXunitSerializationInfo info) => info.AddValue("I", Value, typeof(double));

    public override string ToString() => Value.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
}
