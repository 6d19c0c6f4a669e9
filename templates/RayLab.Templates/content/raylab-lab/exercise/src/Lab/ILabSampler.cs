namespace MyLab;

#if (en)
/// <summary>
/// 4.1 Sampling methods: the points of one pixel, (x, y) in the unit square [0, 1) × [0, 1), x to the right and y
/// downward from the pixel's top-left corner. The render loop (<see cref="LabRenderer"/>) shoots a ray through each
/// and takes the mean. <paramref name="random"/> is the render loop's generator for this row (the same seed gives
/// the same picture).
/// </summary>
#else
/// <summary>
/// 4.1 Metody próbkowania: punkty jednego piksela, (x, y) w kwadracie jednostkowym [0, 1) × [0, 1), x w prawo, y w
/// dół od lewego górnego rogu piksela. Pętla renderowania (<see cref="LabRenderer"/>) wysyła promień przez każdy z
/// nich i bierze średnią. Generator losowy daje pętla, jeden na wiersz (to samo ziarno daje ten sam obraz).
/// </summary>
#endif
public interface ILabSampler
{
    /// <summary>n.</summary>
    int SamplesPerPixel { get; }

#if (en)
    /// <summary>The n points of one pixel.</summary>
#else
    /// <summary>n punktów jednego piksela.</summary>
#endif
    (double X, double Y)[] GetSamples(Random random);
}
