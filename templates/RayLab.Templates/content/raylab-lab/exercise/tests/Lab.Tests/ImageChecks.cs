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
    [Theory(DisplayName = English ? "2.2 Image: the 8-bit rule i = int(256·I), cut not rounded, 0 … 255" : "2.2 Obraz: reguła 8-bitowa i = int(256·I), obcięcie, a nie zaokrąglenie, 0 … 255")]
    [MemberData(nameof(Edges))]
    public void EightBitRule(Level I) => Run(output, () =>
    {
        double intensity = I.Value;
        byte expected = Intensity.ToLevel(intensity);
        byte actual = LabImage.ToByte(intensity);
        output.WriteLine(F($"I = {intensity:R}: 256·I = {256 * intensity:R}, {T("poziom", "level")} {actual} ({T("oczekiwany", "expected")} {expected})"));
        Assert.True(expected == actual, T(
            F($"2.2 Obraz: dla I = {intensity:R} reguła i = int(256·I) daje {expected} (256·I = {256 * intensity:R}, obcięte; poniżej 0 → 0, od 255/256 w górę → 255, NaN → 0), a ToByte dało {actual} ({Source(typeof(LabImage), nameof(LabImage.ToByte))})."),
            F($"2.2 Image: for I = {intensity:R} the rule i = int(256·I) gives {expected} (256·I = {256 * intensity:R}, cut; below 0 → 0, from 255/256 up → 255, NaN → 0), ToByte gave {actual} ({Source(typeof(LabImage), nameof(LabImage.ToByte))}).")));
    });

    [Trait("Section", "2.2")]
    [Fact(DisplayName = English ? "2.2 Image: SetPixel writes the levels of an intensity into the bitmap, (x, y) with row 0 at the top" : "2.2 Obraz: SetPixel zapisuje poziomy natężenia do bitmapy, (x, y), wiersz 0 na górze")]
    public void SetPixel() => Run(output, () =>
    {
        var image = new LabImage(3, 2);
        Assert.True((image.Width, image.Height) == (3, 2), T($"2.2 Obraz: LabImage(3, 2) ma rozmiar {image.Width}×{image.Height}.", $"2.2 Image: LabImage(3, 2) is {image.Width}×{image.Height}."));
        image.SetPixel(2, 0, new LightIntensity(0.9, 0.2, 2));
        Rgb24 set = image.Bitmap[2, 0], untouched = image.Bitmap[0, 1];
        Rgb24 expected = new(Intensity.ToLevel(0.9), Intensity.ToLevel(0.2), Intensity.ToLevel(2));
        output.WriteLine($"Bitmap[2, 0] = {set}, Bitmap[0, 1] = {untouched}");
        Assert.True(set == expected, T(
            $"2.2 Obraz: po SetPixel(2, 0, (0.9, 0.2, 2)) piksel (2, 0) bitmapy powinien mieć poziomy {expected} (int(256·I), najwyżej 255), a ma {set} ({Source(typeof(LabImage), nameof(LabImage.SetPixel))}).",
            $"2.2 Image: after SetPixel(2, 0, (0.9, 0.2, 2)) the bitmap's pixel (2, 0) should hold {expected} (int(256·I), at most 255), it holds {set} ({Source(typeof(LabImage), nameof(LabImage.SetPixel))})."));
        Assert.True(untouched == new Rgb24(0, 0, 0), T($"2.2 Obraz: nowy obraz jest czarny, a piksel (0, 1) ma {untouched}.", $"2.2 Image: a new image is black, pixel (0, 1) holds {untouched}."));
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
