using RayLab;
using static MyLab.Tests.Check;

namespace MyLab.Tests;

#if (en)
/// <summary>2.1: LightIntensity against RayLab's Intensity on the same numbers.</summary>
#else
/// <summary>2.1: LightIntensity wobec Intensity z RayLab na tych samych liczbach.</summary>
#endif
public sealed class IntensityChecks(ITestOutputHelper output)
{
    private static readonly double[][] Inputs = [[0.5, 0.25, 0.125], [-0.5, 0.3, 2], [0, 0, 0], [1, 1, 1], [0.9, 0.2, 0.2]];

    [Trait("Section", "2.1")]
    [Fact(DisplayName = English ? "2.1 Intensity: constructors with 3, 2, 1 and 0 components, negative → 0" : "2.1 Natężenie: konstruktory z 3, 2, 1 i 0 składowymi, ujemne → 0")]
    public void Constructors() => Run(output, () =>
    {
        Same("LightIntensity(-0.5, 0.3, 2)", new Intensity(-0.5, 0.3, 2), new LightIntensity(-0.5, 0.3, 2));
        Same("LightIntensity(0.7, -0.1)", new Intensity(0.7, -0.1), new LightIntensity(0.7, -0.1));
        Same("LightIntensity(0.4)", new Intensity(0.4), new LightIntensity(0.4));
        Same("LightIntensity()", new Intensity(), new LightIntensity());
        output.WriteLine(T("5 konstruktorów jak w RayLab", "5 constructors as RayLab's"));
    });

    [Trait("Section", "2.1")]
    [Fact(DisplayName = English ? "2.1 Intensity: +, −, × and ÷ a number, as RayLab's Intensity" : "2.1 Natężenie: +, −, × i ÷ przez skalar, jak Intensity z RayLab")]
    public void Operators() => Run(output, () =>
    {
        int compared = 0;
        foreach (double[] p in Inputs)
        {
            foreach (double[] q in Inputs)
            {
                Intensity a = new(p[0], p[1], p[2]), b = new(q[0], q[1], q[2]);
                LightIntensity la = new(p[0], p[1], p[2]), lb = new(q[0], q[1], q[2]);
                Same($"{I(la)} + {I(lb)}", a + b, la + lb);
                Same($"{I(la)} − {I(lb)} ({T("ujemne → 0", "negative → 0")})", a - b, la - lb);
                Same($"{I(la)} × 3", a * 3, la * 3);
                Same($"3 × {I(la)}", 3 * a, 3 * la);
                Same($"{I(la)} ÷ 4", a / 4, la / 4);
                LightIntensity compound = la;
                compound += lb;
                compound *= 2;
                compound /= 2;
                compound -= lb;
                Same($"(({I(la)} += {I(lb)}) *= 2, /= 2, −= {I(lb)})", ((a + b) * 2 / 2) - b, compound);
                compared += 6;
            }
        }

        output.WriteLine(F($"{compared} {T("działań jak w RayLab", "operations as RayLab's")}"));
    });

    [Trait("Section", "2.1")]
    [Fact(DisplayName = English ? "2.1 Intensity: printing shows R, G and B" : "2.1 Natężenie: wypisanie pokazuje R, G i B")]
    public void Printing() => Run(output, () =>
    {
        string text = new LightIntensity(0.25, 0.5, 0.75).ToString() ?? "";
        foreach (string part in new[] { "0.25", "0.5", "0.75" })
        {
            string local = part.Replace(".", ",", StringComparison.Ordinal);
            Assert.True(text.Contains(part, StringComparison.Ordinal) || text.Contains(local, StringComparison.Ordinal),
                T($"Instrukcja: natężenie da się wypisać (operator <<). LightIntensity(0.25, 0.5, 0.75).ToString() dało \"{text}\", bez {part} ({Source(typeof(LightIntensity), nameof(LightIntensity.ToString))}).",
                  $"The lab: an intensity can be printed (operator <<). LightIntensity(0.25, 0.5, 0.75).ToString() gave \"{text}\", without {part} ({Source(typeof(LightIntensity), nameof(LightIntensity.ToString))})."));
        }

        output.WriteLine($"ToString(): {text}");
    });

    private static void Same(string what, Intensity expected, LightIntensity actual)
    {
        if (expected.R != actual.R || expected.G != actual.G || expected.B != actual.B)
        {
            Assert.Fail(T(
                $"2.1 Natężenie: {what} powinno dać {I(expected)} (każda składowa osobno; ujemna → 0), a dało {I(actual)}.",
                $"2.1 Intensity: {what} should give {I(expected)} (each component on its own; negative → 0), got {I(actual)}."));
        }
    }
}
