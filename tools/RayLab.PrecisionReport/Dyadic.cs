using System.Numerics;

namespace RayLab.PrecisionReport;

/// <summary>
/// An exact dyadic rational <c>M · 2^E</c>. Every finite double is one, and sums, differences and products of
/// them stay exact, so a decision built from them involves no rounding at all.
/// </summary>
/// <param name="M">The integer mantissa.</param>
/// <param name="E">The binary exponent.</param>
public readonly record struct Dyadic(BigInteger M, int E)
{
    /// <summary>The sign: −1, 0 or 1.</summary>
    public int Sign => M.Sign;

    /// <summary>The exact value of a finite double.</summary>
    /// <param name="x">The double.</param>
    /// <exception cref="ArgumentException"><paramref name="x"/> is NaN or infinite.</exception>
    public static Dyadic From(double x)
    {
        if (!double.IsFinite(x))
        {
            throw new ArgumentException($"Only finite doubles are dyadic rationals, got {x}.", nameof(x));
        }

        if (x == 0)
        {
            return new Dyadic(BigInteger.Zero, 0);
        }

        long bits = BitConverter.DoubleToInt64Bits(x);
        int exponent = (int)((bits >> 52) & 0x7FF);
        long mantissa = bits & ((1L << 52) - 1);
        (BigInteger m, int e) = exponent == 0 ? (new BigInteger(mantissa), -1074) : (new BigInteger(mantissa | (1L << 52)), exponent - 1075);
        return new Dyadic(x < 0 ? -m : m, e);
    }

    /// <summary>The exact sum.</summary>
    /// <param name="o">The other term.</param>
    public Dyadic Add(Dyadic o)
    {
        if (M.IsZero)
        {
            return o;
        }

        if (o.M.IsZero)
        {
            return this;
        }

        int e = Math.Min(E, o.E);
        return new Dyadic((M << (E - e)) + (o.M << (o.E - e)), e);
    }

    /// <summary>The exact difference.</summary>
    /// <param name="o">The term to subtract.</param>
    public Dyadic Sub(Dyadic o) => Add(new Dyadic(-o.M, o.E));

    /// <summary>The exact product.</summary>
    /// <param name="o">The other factor.</param>
    public Dyadic Mul(Dyadic o) => new(M * o.M, E + o.E);

    /// <summary>The value as a double (within a few ulps: the mantissa is cut to 60 bits first).</summary>
    public double ToDouble()
    {
        if (M.IsZero)
        {
            return 0;
        }

        BigInteger m = M;
        int e = E;
        long bitLength = BigInteger.Abs(m).GetBitLength();
        if (bitLength > 60)
        {
            int shift = (int)(bitLength - 60);
            m >>= shift;
            e += shift;
        }

        return Math.ScaleB((double)m, e);
    }
}
