using SixLabors.ImageSharp;
using SixLabors.ImageSharp.PixelFormats;

namespace MyLab;

#if (en)
/// <summary>
/// 2.2 Image: an X×Y array of colours over an ImageSharp bitmap, <see cref="Bitmap"/>, which saves itself
/// (<c>image.Bitmap.SaveAsJpeg("obrazkoncowy.jpg")</c>). An intensity I becomes an 8-bit level by the lab's rule
/// i = int(256·I): cut, not rounded; 0 and below give 0 (black), 1 and above 255 (white) — int(256·1) = 256
/// does not fit in a byte; NaN (0/0, for one) gives 0, where a <c>checked</c> conversion would throw. The checks try
/// each edge: just under and at 1/256, 0.1, 255/256, 1, 1.5, −0.1 and NaN.
/// </summary>
#else
/// <summary>
/// 2.2 Obraz: tablica X×Y kolorów na bitmapie ImageSharp, <see cref="Bitmap"/>, która sama zapisuje się do pliku
/// (<c>obraz.Bitmap.SaveAsJpeg("obrazkoncowy.jpg")</c>). Natężenie I zamienia się na 8-bitowy poziom regułą
/// instrukcji i = int(256·I): obcięcie, nie zaokrąglenie; 0 i mniej daje 0 (czarny), 1 i więcej 255 (biały) —
/// int(256·1) = 256 nie mieści się w bajcie; NaN (np. 0/0) daje 0, a konwersja <c>checked</c> rzuciłaby wyjątek.
/// Testy sprawdzają każdą krawędź: tuż poniżej i równo 1/256, 0.1, 255/256, 1, 1.5, −0.1 i NaN.
/// </summary>
#endif
public sealed class LabImage
{
    public LabImage(int width, int height)
    {
#if (solution)
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        Bitmap = new Image<Rgb24>(width, height);
#else
        throw ToWrite.Section("2.2", "new LabImage(width, height)");
#endif
    }

    /// <summary>X.</summary>
    public int Width => Bitmap.Width;

    /// <summary>Y.</summary>
    public int Height => Bitmap.Height;

    /// <summary>ImageSharp: <c>Bitmap.SaveAsJpeg(path)</c>, <c>Bitmap.SaveAsPng(path)</c>.</summary>
    public Image<Rgb24> Bitmap { get; } = null!;

#if (solution)
#if (en)
    /// <summary>i = int(256·I) (cut, not rounded), kept within 0 … 255; NaN gives 0.</summary>
#else
    /// <summary>i = int(256·I) (obcięcie, nie zaokrąglenie), w granicach 0 … 255; NaN daje 0.</summary>
#endif
    public static byte ToByte(double intensity)
    {
        double scaled = 256 * intensity;
        if (!(scaled > 0))
        {
            return 0; // ujemne i NaN
        }

        return scaled >= 255 ? (byte)255 : (byte)(int)scaled; // int() obcina
    }

#if (en)
    /// <summary>Pixel (x, y), row 0 at the top.</summary>
#else
    /// <summary>Piksel (x, y), wiersz 0 na górze.</summary>
#endif
    public void SetPixel(int x, int y, LightIntensity pixel) =>
        Bitmap[x, y] = new Rgb24(ToByte(pixel.R), ToByte(pixel.G), ToByte(pixel.B));
#else
#if (en)
    /// <summary>i = int(256·I) (cut, not rounded), kept within 0 … 255; NaN gives 0.</summary>
#else
    /// <summary>i = int(256·I) (obcięcie, nie zaokrąglenie), w granicach 0 … 255; NaN daje 0.</summary>
#endif
    public static byte ToByte(double intensity) => throw ToWrite.Section("2.2", "LabImage.ToByte(I)");

#if (en)
    /// <summary>Pixel (x, y), row 0 at the top.</summary>
#else
    /// <summary>Piksel (x, y), wiersz 0 na górze.</summary>
#endif
    public void SetPixel(int x, int y, LightIntensity pixel) => throw ToWrite.Section("2.2", "LabImage.SetPixel(x, y, pixel)");
#endif
}
