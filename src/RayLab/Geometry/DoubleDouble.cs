namespace RayLab.Geometry;

/// <summary>
/// An unevaluated sum <c>Hi + Lo</c> of two doubles with |Lo| ≤ ulp(Hi)/2: about 106 significant bits
/// (Dekker 1971; Hida, Li and Bailey's double-double). Used off the render path, where a hit point must be
/// placed on the surface to the last ulp.
/// </summary>
/// <param name="Hi">The leading part, the value rounded to a double.</param>
/// <param name="Lo">The rounding error of <paramref name="Hi"/>.</param>
internal readonly record struct DoubleDouble(double Hi, double Lo)
{
    /// <summary>The sign of the value: −1, 0 or 1.</summary>
    public int Sign => Hi != 0 ? Math.Sign(Hi) : Math.Sign(Lo);

    /// <summary>a + b exactly (Knuth's TwoSum, no ordering needed).</summary>
    public static DoubleDouble TwoSum(double a, double b)
    {
        double s = a + b;
        double bb = s - a;
        double e = (a - (s - bb)) + (b - bb);
        return new(s, e);
    }

    /// <summary>a − b exactly.</summary>
    public static DoubleDouble TwoDiff(double a, double b) => TwoSum(a, -b);

    /// <summary>a · b exactly (the error term from a fused multiply-add).</summary>
    public static DoubleDouble TwoProduct(double a, double b)
    {
        double p = a * b;
        return new(p, Math.FusedMultiplyAdd(a, b, -p));
    }

    /// <summary>The sum, to about 106 bits.</summary>
    public static DoubleDouble operator +(DoubleDouble x, DoubleDouble y)
    {
        DoubleDouble s = TwoSum(x.Hi, y.Hi);
        DoubleDouble t = TwoSum(x.Lo, y.Lo);
        DoubleDouble u = FastTwoSum(s.Hi, s.Lo + t.Hi);
        return FastTwoSum(u.Hi, u.Lo + t.Lo);
    }

    /// <summary>The negation (exact).</summary>
    public static DoubleDouble operator -(DoubleDouble x) => new(-x.Hi, -x.Lo);

    /// <summary>The difference, to about 106 bits.</summary>
    public static DoubleDouble operator -(DoubleDouble x, DoubleDouble y) => x + (-y);

    /// <summary>The product, to about 106 bits.</summary>
    public static DoubleDouble operator *(DoubleDouble x, DoubleDouble y)
    {
        DoubleDouble p = TwoProduct(x.Hi, y.Hi);
        return FastTwoSum(p.Hi, p.Lo + ((x.Hi * y.Lo) + (x.Lo * y.Hi)));
    }

    /// <summary>The product with a double, to about 106 bits.</summary>
    public static DoubleDouble operator *(DoubleDouble x, double y)
    {
        DoubleDouble p = TwoProduct(x.Hi, y);
        return FastTwoSum(p.Hi, p.Lo + (x.Lo * y));
    }

    // a + b exactly when |a| ≥ |b| (or a = 0).
    private static DoubleDouble FastTwoSum(double a, double b)
    {
        double s = a + b;
        return new(s, b - (s - a));
    }
}
