using System.Numerics;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The real roots θ of a trigonometric polynomial of degree ≤ 2,
/// <c>g(θ) = a0 + a1 cos θ + b1 sin θ + a2 cos 2θ + b2 sin 2θ</c>: where one ellipse, written with its angle θ,
/// crosses another (substituted into the other's equation). With z = e^{iθ}, z² g is a quartic in z whose roots
/// on the unit circle are the answers; they are found together by the Aberth–Ehrlich iteration.
/// </summary>
/// <remarks>
/// Generous on purpose: a root within 1e-6 of the unit circle counts, so two ellipses that nearly touch give
/// their nearly touching points too. The exact reference only uses the roots as places to split a row, and an
/// extra split costs time, never accuracy; a missing one would.
/// </remarks>
internal static class TrigRoots
{
    /// <summary>Writes the roots θ ∈ (−π, π] into <paramref name="roots"/> (room for 4) and returns how many.</summary>
    /// <param name="a0">The constant term.</param>
    /// <param name="a1">The cos θ coefficient.</param>
    /// <param name="b1">The sin θ coefficient.</param>
    /// <param name="a2">The cos 2θ coefficient.</param>
    /// <param name="b2">The sin 2θ coefficient.</param>
    /// <param name="roots">At least 4 entries.</param>
    public static int Solve(double a0, double a1, double b1, double a2, double b2, Span<double> roots)
    {
        double scale = Math.Max(Math.Max(Math.Abs(a0), Math.Abs(a1)), Math.Max(Math.Max(Math.Abs(b1), Math.Abs(a2)), Math.Abs(b2)));
        if (!(scale > 0) || !double.IsFinite(scale))
        {
            return 0; // g ≡ 0: the same ellipse twice, which splits nothing
        }

        a0 /= scale;
        a1 /= scale;
        b1 /= scale;
        a2 /= scale;
        b2 /= scale;
        if (Math.Abs(a2) + Math.Abs(b2) <= 1e-13)
        {
            return SolveFirstOrder(a0, a1, b1, roots);
        }

        // z² g(θ) = c4 z⁴ + c3 z³ + c2 z² + c1 z + c0, made monic.
        var c4 = new Complex(a2 / 2, -b2 / 2);
        var c3 = new Complex(a1 / 2, -b1 / 2);
        Span<Complex> monic = [Complex.Conjugate(c4) / c4, Complex.Conjugate(c3) / c4, a0 / c4, c3 / c4];
        Span<Complex> z = stackalloc Complex[4];
        Aberth(monic, z);
        int count = 0;
        foreach (Complex root in z)
        {
            double modulus = root.Magnitude;
            if (modulus > 0 && Math.Abs(Math.Log(modulus)) < 1e-6)
            {
                roots[count++] = Polish(root.Phase, a0, a1, b1, a2, b2);
            }
        }

        return count;
    }

    private static int SolveFirstOrder(double a0, double a1, double b1, Span<double> roots)
    {
        double r = Math.Sqrt((a1 * a1) + (b1 * b1));
        if (!(r > 0))
        {
            return 0;
        }

        double c = -a0 / r;
        if (Math.Abs(c) > 1 + 1e-9)
        {
            return 0;
        }

        double centre = Math.Atan2(b1, a1), half = Math.Acos(Math.Clamp(c, -1, 1));
        roots[0] = centre - half;
        roots[1] = centre + half;
        return 2;
    }

    // Roots of z⁴ + m3 z³ + m2 z² + m1 z + m0 (coefficients given as m0, m1, m2, m3).
    private static void Aberth(ReadOnlySpan<Complex> m, Span<Complex> z)
    {
        // The roots come in pairs z, 1/z̄ around the unit circle, so start on it at uneven angles.
        for (int k = 0; k < z.Length; k++)
        {
            z[k] = Complex.FromPolarCoordinates(1 + (0.05 * k), 0.4 + (1.6 * k));
        }

        double previousStep = double.PositiveInfinity;
        for (int iteration = 0; iteration < 200; iteration++)
        {
            double largestStep = 0;
            for (int k = 0; k < z.Length; k++)
            {
                Complex x = z[k];
                Complex p = (((x + m[3]) * x + m[2]) * x + m[1]) * x + m[0];
                Complex dp = ((4 * x + (3 * m[3])) * x + (2 * m[2])) * x + m[1];
                if (p == Complex.Zero)
                {
                    continue;
                }

                Complex ratio = dp == Complex.Zero ? new Complex(1e-3, 1e-3) : p / dp;
                Complex repel = Complex.Zero;
                for (int j = 0; j < z.Length; j++)
                {
                    if (j != k && z[j] != x)
                    {
                        repel += 1 / (x - z[j]);
                    }
                }

                Complex step = ratio / (1 - (ratio * repel));
                z[k] = x - step;
                largestStep = Math.Max(largestStep, step.Magnitude / Math.Max(1, z[k].Magnitude));
            }

            // Done when the steps are below double's resolution, or when they have stopped shrinking at the level
            // of rounding (they then wander by an ulp or two for ever: the remaining iterations changed nothing).
            if (largestStep < 1e-16 || (largestStep < 1e-13 && largestStep >= previousStep))
            {
                break;
            }

            previousStep = largestStep;
        }
    }

    // Two Newton steps on the real g(θ), kept only when they stay close (a double root has g' ≈ 0).
    private static double Polish(double theta, double a0, double a1, double b1, double a2, double b2)
    {
        double t = theta;
        for (int i = 0; i < 2; i++)
        {
            double g = a0 + (a1 * Math.Cos(t)) + (b1 * Math.Sin(t)) + (a2 * Math.Cos(2 * t)) + (b2 * Math.Sin(2 * t));
            double dg = (-a1 * Math.Sin(t)) + (b1 * Math.Cos(t)) - (2 * a2 * Math.Sin(2 * t)) + (2 * b2 * Math.Cos(2 * t));
            if (!(Math.Abs(dg) > 1e-6))
            {
                return theta;
            }

            t -= g / dg;
        }

        return Math.Abs(t - theta) < 1e-6 ? t : theta;
    }
}
