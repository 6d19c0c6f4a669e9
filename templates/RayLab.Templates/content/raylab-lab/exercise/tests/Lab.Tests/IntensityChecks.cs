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
    [Fact(DisplayName = Msg.Constructors)]
    public void Constructors() => Run(output, () =>
    {
        Same("LightIntensity(-0.5, 0.3, 2)", new Intensity(-0.5, 0.3, 2), new LightIntensity(-0.5, 0.3, 2), Constructor("r, g, b", typeof(double), typeof(double), typeof(double)));
        Same("LightIntensity(0.7, -0.1)", new Intensity(0.7, -0.1), new LightIntensity(0.7, -0.1), Constructor("r, g", typeof(double), typeof(double)));
        Same("LightIntensity(0.4)", new Intensity(0.4), new LightIntensity(0.4), Constructor("r", typeof(double)));
        Same("LightIntensity()", new Intensity(), new LightIntensity(), Constructor(""));
        output.WriteLine(Msg.ConstructorsAsRayLab);
    });

    [Trait("Section", "2.1")]
    [Fact(DisplayName = Msg.Operators)]
    public void Operators() => Run(output, () =>
    {
        int compared = 0;
        foreach (double[] p in Inputs)
        {
            foreach (double[] q in Inputs)
            {
                Intensity a = new(p[0], p[1], p[2]), b = new(q[0], q[1], q[2]);
                LightIntensity la = new(p[0], p[1], p[2]), lb = new(q[0], q[1], q[2]);
                Same($"{I(la)} + {I(lb)}", a + b, la + lb, Operator("op_Addition", "+", typeof(LightIntensity), typeof(LightIntensity)));
                Same($"{I(la)} − {I(lb)} ({Msg.NegativeToZero})", a - b, la - lb, Operator("op_Subtraction", "−", typeof(LightIntensity), typeof(LightIntensity)));
                Same($"{I(la)} × 3", a * 3, la * 3, Operator("op_Multiply", "* (I × s)", typeof(LightIntensity), typeof(double)));
                Same($"3 × {I(la)}", 3 * a, 3 * la, Operator("op_Multiply", "* (s × I)", typeof(double), typeof(LightIntensity)));
                Same($"{I(la)} ÷ 4", a / 4, la / 4, Operator("op_Division", "/", typeof(LightIntensity), typeof(double)));
                LightIntensity compound = la;
                compound += lb;
                compound *= 2;
                compound /= 2;
                compound -= lb;
                Same($"(({I(la)} += {I(lb)}) *= 2, /= 2, −= {I(lb)})", ((a + b) * 2 / 2) - b, compound, null);
                compared += 6;
            }
        }

        output.WriteLine(Msg.OperationsAsRayLab(compared));
    });

    [Trait("Section", "2.1")]
    [Fact(DisplayName = Msg.Printing)]
    public void Printing() => Run(output, () =>
    {
        string text = new LightIntensity(0.25, 0.5, 0.75).ToString() ?? "";
        foreach (string part in new[] { "0.25", "0.5", "0.75" })
        {
            string local = part.Replace(".", ",", StringComparison.Ordinal);
            Assert.True(text.Contains(part, StringComparison.Ordinal) || text.Contains(local, StringComparison.Ordinal),
                Msg.PrintingMisses(text, part, Source(typeof(LightIntensity), nameof(LightIntensity.ToString))));
        }

        output.WriteLine($"ToString(): {text}");
    });

#if (en)
    /// <summary>
    /// Fails unless <paramref name="actual"/> is <paramref name="expected"/> bit for bit; the message names
    /// <paramref name="source"/>, where your constructor or operator that gave the value is written (read only then), when there is one.
    /// </summary>
#else
    /// <summary>
    /// Nie przechodzi, jeśli <paramref name="actual"/> nie jest co do bitu <paramref name="expected"/>; komunikat podaje
    /// <paramref name="source"/>, gdzie jest napisany Twój konstruktor albo operator, który dał tę wartość (odczytywane dopiero wtedy), jeśli jest jeden.
    /// </summary>
#endif
    private static void Same(string what, Intensity expected, LightIntensity actual, Func<string>? source)
    {
        if (expected.R != actual.R || expected.G != actual.G || expected.B != actual.B)
        {
            string at = source is null ? "" : $" ({source()})";
            Assert.Fail(Msg.IntensityShouldGive(what, expected, actual, at));
        }
    }

#if (en)
    /// <summary>Where your constructor of LightIntensity with these parameters is written (<see cref="Check.Source(System.Reflection.MethodBase?, string)"/>).</summary>
#else
    /// <summary>Gdzie jest napisany Twój konstruktor LightIntensity z tymi parametrami (<see cref="Check.Source(System.Reflection.MethodBase?, string)"/>).</summary>
#endif
    private static Func<string> Constructor(string parameters, params Type[] types) => () =>
        Source(typeof(LightIntensity).GetConstructor(types), $"new LightIntensity({parameters})");

#if (en)
    /// <summary>Where your operator <paramref name="shown"/> of LightIntensity (the method <paramref name="name"/>, with these operands) is written.</summary>
#else
    /// <summary>Gdzie jest napisany Twój operator <paramref name="shown"/> LightIntensity (metoda <paramref name="name"/> z tymi argumentami).</summary>
#endif
    private static Func<string> Operator(string name, string shown, params Type[] types) => () =>
        Source(typeof(LightIntensity).GetMethod(name, types), $"LightIntensity.operator {shown}");
}
