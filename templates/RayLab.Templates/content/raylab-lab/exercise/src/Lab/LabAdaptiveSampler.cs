namespace MyLab;

#if (en)
/// <summary>
/// 4.1.4 Adaptive sampling (as in mental ray), the lab's rule. Trace the pixel's corners A, B, C, D and its centre E
/// (quincunx). A square (the pixel is depth 0) splits into four quadrants; quadrant q is refined when its corner and
/// the square's centre differ by more than <see cref="Contrast"/> in some channel (all four when the corners differ
/// among themselves while each agrees with the centre), never below <see cref="MaxDepth"/>. A refined quadrant has
/// two of its corners already (a corner of the square and the centre): trace its missing corners and its centre
/// (F, G, H, …), each point once. Value (the lab's weights): square = ¼ Σ v(q), v(q) = (corner_q + X)/2 for a quadrant
/// that is not refined, v(q) = the quadrant's own value for a refined one.
/// </summary>
#else
/// <summary>
/// 4.1.4 Próbkowanie adaptacyjne (jak w Mental Ray), reguła z instrukcji. Wyślij promienie w rogi piksela A, B, C, D i
/// w jego środek E (kwinkunks). Kwadrat (piksel to głębokość 0) dzieli się na cztery podobszary; podobszar q jest
/// dzielony dalej, gdy jego róg i środek kwadratu różnią się o więcej niż <see cref="Contrast"/> w którejś
/// składowej (wszystkie cztery, gdy rogi różnią się między sobą, a każdy zgadza się ze środkiem), nigdy głębiej niż
/// <see cref="MaxDepth"/>. Dzielony podobszar ma już dwa rogi (róg kwadratu i środek): wyślij promienie w brakujące
/// rogi i jego środek (F, G, H, …), każdy punkt raz. Wartość (wagi z instrukcji): kwadrat = ¼ Σ v(q),
/// v(q) = (róg_q + X)/2 dla podobszaru niedzielonego, v(q) = wartość podobszaru dla dzielonego.
/// </summary>
#endif
public sealed class LabAdaptiveSampler
{
    public LabAdaptiveSampler(int maxDepth = 3, double contrast = 0.05)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(maxDepth);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(maxDepth, 10);
        ArgumentOutOfRangeException.ThrowIfNegative(contrast);
        MaxDepth = maxDepth;
        Contrast = contrast;
    }

#if (en)
    /// <summary>The deepest square: 0 is the pixel, 3 squares of ⅛ pixel.</summary>
#else
    /// <summary>Najgłębszy kwadrat: 0 to cały piksel, 3 to kwadraty o boku ⅛ piksela.</summary>
#endif
    public int MaxDepth { get; }

#if (en)
    /// <summary>The spatial contrast: two values differ when some channel differs by more than this.</summary>
#else
    /// <summary>Kontrast przestrzenny: dwie wartości się różnią, gdy któraś składowa różni się o więcej niż on.</summary>
#endif
    public double Contrast { get; }

#if (solution)
#if (en)
    /// <summary>True when some channel of a and b differs by more than the contrast.</summary>
#else
    /// <summary>Prawda, gdy któraś składowa a i b różni się o więcej niż kontrast.</summary>
#endif
    public bool Differ(LightIntensity a, LightIntensity b) =>
        Math.Abs(a.R - b.R) > Contrast || Math.Abs(a.G - b.G) > Contrast || Math.Abs(a.B - b.B) > Contrast;

#if (en)
    /// <summary>The pixel's value; trace(x, y) shoots the ray through (x, y) in the pixel, x right and y down, 0 … 1.</summary>
#else
    /// <summary>Wartość piksela; trace(x, y) wysyła promień przez punkt (x, y) piksela, x w prawo, y w dół, od 0 do 1.</summary>
#endif
    public LightIntensity Pixel(Func<double, double, LightIntensity> trace)
    {
        var traced = new Dictionary<(double, double), LightIntensity>(); // każdy punkt tylko raz
        LightIntensity At(double x, double y)
        {
            if (!traced.TryGetValue((x, y), out LightIntensity value))
            {
                value = trace(x, y);
                traced.Add((x, y), value);
            }

            return value;
        }

        // A, B, C, D: rogi; E: środek.
        return Square(At, 0, 0, 1, 0, At(0, 0), At(1, 0), At(0, 1), At(1, 1), At(0.5, 0.5));
    }

    private LightIntensity Square(Func<double, double, LightIntensity> at, double x0, double y0, double size, int depth,
        LightIntensity tl, LightIntensity tr, LightIntensity bl, LightIntensity br, LightIntensity centre)
    {
        bool refineTl = false, refineTr = false, refineBl = false, refineBr = false;
        if (depth < MaxDepth)
        {
            refineTl = Differ(tl, centre);
            refineTr = Differ(tr, centre);
            refineBl = Differ(bl, centre);
            refineBr = Differ(br, centre);
            if (!(refineTl || refineTr || refineBl || refineBr)
                && (Differ(tl, tr) || Differ(tl, bl) || Differ(tl, br) || Differ(tr, bl) || Differ(tr, br) || Differ(bl, br)))
            {
                refineTl = refineTr = refineBl = refineBr = true;
            }
        }

        double h = size / 2, q = size / 4;
        LightIntensity vTl = refineTl
            ? Square(at, x0, y0, h, depth + 1, tl, at(x0 + h, y0), at(x0, y0 + h), centre, at(x0 + q, y0 + q))
            : (tl + centre) / 2;
        LightIntensity vTr = refineTr
            ? Square(at, x0 + h, y0, h, depth + 1, at(x0 + h, y0), tr, centre, at(x0 + size, y0 + h), at(x0 + h + q, y0 + q))
            : (tr + centre) / 2;
        LightIntensity vBl = refineBl
            ? Square(at, x0, y0 + h, h, depth + 1, at(x0, y0 + h), centre, bl, at(x0 + h, y0 + size), at(x0 + q, y0 + h + q))
            : (bl + centre) / 2;
        LightIntensity vBr = refineBr
            ? Square(at, x0 + h, y0 + h, h, depth + 1, centre, at(x0 + size, y0 + h), at(x0 + h, y0 + size), br, at(x0 + h + q, y0 + h + q))
            : (br + centre) / 2;
        return (vTl + vTr + vBl + vBr) / 4;
    }
#else
#if (en)
    /// <summary>True when some channel of a and b differs by more than the contrast.</summary>
#else
    /// <summary>Prawda, gdy któraś składowa a i b różni się o więcej niż kontrast.</summary>
#endif
    public bool Differ(LightIntensity a, LightIntensity b) => throw ToWrite.Section("4.1.4", "LabAdaptiveSampler.Differ(a, b)");

#if (en)
    /// <summary>The pixel's value; trace(x, y) shoots the ray through (x, y) in the pixel, x right and y down, 0 … 1.</summary>
#else
    /// <summary>Wartość piksela; trace(x, y) wysyła promień przez punkt (x, y) piksela, x w prawo, y w dół, od 0 do 1.</summary>
#endif
    public LightIntensity Pixel(Func<double, double, LightIntensity> trace) => throw ToWrite.Section("4.1.4", "LabAdaptiveSampler.Pixel(trace)");
#endif
}
