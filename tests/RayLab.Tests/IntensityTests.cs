using System.Globalization;

namespace RayLab.Tests;

public class IntensityTests
{
    // ---- Constructors -------------------------------------------------------------------------------

    [Fact]
    public void Constructor_with_three_components_keeps_all_three()
    {
        var i = new Intensity(0.1, 0.2, 0.3);

        Assert.Equal(0.1, i.R);
        Assert.Equal(0.2, i.G);
        Assert.Equal(0.3, i.B);
    }

    [Fact]
    public void Constructor_with_two_components_sets_blue_to_zero()
    {
        var i = new Intensity(0.1, 0.2);

        Assert.Equal(0.1, i.R);
        Assert.Equal(0.2, i.G);
        Assert.Equal(0.0, i.B);
    }

    [Fact]
    public void Constructor_with_one_component_sets_green_and_blue_to_zero()
    {
        var i = new Intensity(0.7);

        Assert.Equal(0.7, i.R);
        Assert.Equal(0.0, i.G);
        Assert.Equal(0.0, i.B);
    }

    [Fact]
    public void Constructor_with_no_components_is_black()
    {
        var i = new Intensity();

        Assert.Equal(0.0, i.R);
        Assert.Equal(0.0, i.G);
        Assert.Equal(0.0, i.B);
        Assert.Equal(Intensity.Black, i);
        Assert.Equal(default, i);
    }

    [Fact]
    public void White_is_one_one_one()
    {
        Assert.Equal(new Intensity(1, 1, 1), Intensity.White);
        Assert.NotEqual(Intensity.Black, Intensity.White);
    }

    [Fact]
    public void Components_above_one_are_kept()
    {
        var i = new Intensity(2.5, 10, 1e300);

        Assert.Equal(2.5, i.R);
        Assert.Equal(10.0, i.G);
        Assert.Equal(1e300, i.B);
    }

    [Theory]
    [InlineData(-0.5)]
    [InlineData(-1e-300)]
    [InlineData(-1e300)]
    [InlineData(double.NegativeInfinity)]
    [InlineData(double.NaN)]
    public void Negative_or_NaN_component_becomes_zero_in_every_position(double bad)
    {
        var r = new Intensity(bad, 0.25, 0.5);
        var g = new Intensity(0.25, bad, 0.5);
        var b = new Intensity(0.25, 0.5, bad);

        Assert.Equal(new Intensity(0, 0.25, 0.5), r);
        Assert.Equal(new Intensity(0.25, 0, 0.5), g);
        Assert.Equal(new Intensity(0.25, 0.5, 0), b);
        Assert.Equal(0.0, r.R);
        Assert.Equal(0.0, g.G);
        Assert.Equal(0.0, b.B);
    }

    [Fact]
    public void Negative_or_NaN_component_becomes_zero_in_short_constructors()
    {
        Assert.Equal(Intensity.Black, new Intensity(-1));
        Assert.Equal(Intensity.Black, new Intensity(double.NaN));
        Assert.Equal(Intensity.Black, new Intensity(-1, double.NaN));
        Assert.False(double.IsNaN(new Intensity(double.NaN).R));
    }

    [Fact]
    public void Negative_zero_becomes_positive_zero()
    {
        var i = new Intensity(-0.0, -0.0, -0.0);

        Assert.False(double.IsNegative(i.R));
        Assert.False(double.IsNegative(i.G));
        Assert.False(double.IsNegative(i.B));
        Assert.Equal("(0, 0, 0)", i.ToString());
        Assert.Equal(Intensity.Black.GetHashCode(), i.GetHashCode());
    }

    // ---- Arithmetic ---------------------------------------------------------------------------------

    [Fact]
    public void Addition_is_component_wise()
    {
        var sum = new Intensity(0.125, 0.25, 0.5) + new Intensity(1, 2, 4);

        Assert.Equal(new Intensity(1.125, 2.25, 4.5), sum);
    }

    [Fact]
    public void Subtraction_is_component_wise()
    {
        var diff = new Intensity(1, 2, 4) - new Intensity(0.5, 0.25, 1);

        Assert.Equal(new Intensity(0.5, 1.75, 3), diff);
    }

    [Fact]
    public void Subtraction_clamps_each_component_at_zero()
    {
        var diff = new Intensity(0.25, 1, 0.5) - new Intensity(0.5, 0.25, 0.5);

        Assert.Equal(0.0, diff.R);
        Assert.Equal(0.75, diff.G);
        Assert.Equal(0.0, diff.B);
        Assert.Equal(Intensity.Black, Intensity.Black - Intensity.White);
    }

    [Fact]
    public void Multiplication_by_scalar_works_with_scalar_on_either_side()
    {
        var i = new Intensity(0.25, 0.5, 1);
        var expected = new Intensity(0.5, 1, 2);

        Assert.Equal(expected, i * 2.0);
        Assert.Equal(expected, 2.0 * i);
    }

    [Fact]
    public void Multiplication_by_negative_scalar_clamps_to_black()
    {
        var i = new Intensity(0.25, 0.5, 1);

        Assert.Equal(Intensity.Black, i * -3.0);
        Assert.Equal(Intensity.Black, -3.0 * i);
    }

    [Fact]
    public void Multiplication_of_two_intensities_is_component_wise_colour_times_ambient()
    {
        var colour = new Intensity(1, 0.5, 0.25);
        var ambient = new Intensity(0.5, 0.5, 2);

        Assert.Equal(new Intensity(0.5, 0.25, 0.5), colour * ambient);
        Assert.Equal(colour * ambient, ambient * colour);
        Assert.Equal(colour, colour * Intensity.White);
        Assert.Equal(Intensity.Black, colour * Intensity.Black);
    }

    [Fact]
    public void Division_by_scalar_divides_every_component()
    {
        var i = new Intensity(1, 2, 3) / 4.0;

        Assert.Equal(new Intensity(0.25, 0.5, 0.75), i);
    }

    [Fact]
    public void Division_by_zero_throws()
    {
        var i = new Intensity(1, 2, 3);

        Assert.Throws<DivideByZeroException>(() => i / 0.0);
        Assert.Throws<DivideByZeroException>(() => Intensity.Black / 0.0);
    }

    [Fact]
    public void Division_by_negative_zero_throws()
    {
        var i = new Intensity(1, 2, 3);

        Assert.Throws<DivideByZeroException>(() => i / -0.0);
    }

    [Fact]
    public void Compound_assignment_operators_work()
    {
        var i = new Intensity(0.5, 0.25, 1);

        i += new Intensity(0.5, 0.25, 1);
        Assert.Equal(new Intensity(1, 0.5, 2), i);

        i -= new Intensity(0.25, 1, 0.5);
        Assert.Equal(new Intensity(0.75, 0, 1.5), i);

        i *= 2.0;
        Assert.Equal(new Intensity(1.5, 0, 3), i);

        i *= new Intensity(2, 5, 0.5);
        Assert.Equal(new Intensity(3, 0, 1.5), i);

        i /= 3.0;
        Assert.Equal(new Intensity(1, 0, 0.5), i);
    }

    [Fact]
    public void Compound_division_by_zero_throws_and_leaves_value_unchanged()
    {
        var i = new Intensity(1, 2, 3);

        Assert.Throws<DivideByZeroException>(() => i /= 0.0);
        Assert.Equal(new Intensity(1, 2, 3), i);
    }

    // ---- Equality -----------------------------------------------------------------------------------

    [Fact]
    public void Equal_intensities_are_equal_by_every_api()
    {
        var a = new Intensity(0.1, 0.2, 0.3);
        var b = new Intensity(0.1, 0.2, 0.3);

        Assert.True(a == b);
        Assert.False(a != b);
        Assert.True(a.Equals(b));
        Assert.True(a.Equals((object)b));
        Assert.Equal(a.GetHashCode(), b.GetHashCode());
    }

    [Theory]
    [InlineData(0.5, 0.2, 0.3)]
    [InlineData(0.1, 0.5, 0.3)]
    [InlineData(0.1, 0.2, 0.5)]
    public void Intensities_differing_in_one_component_are_not_equal(double r, double g, double b)
    {
        var a = new Intensity(0.1, 0.2, 0.3);
        var other = new Intensity(r, g, b);

        Assert.False(a == other);
        Assert.True(a != other);
        Assert.False(a.Equals(other));
        Assert.False(a.Equals((object)other));
    }

    [Fact]
    public void Equals_object_is_false_for_other_types_and_null()
    {
        var a = new Intensity(1, 1, 1);

        Assert.False(a.Equals(null));
        Assert.False(a.Equals("(1, 1, 1)"));
        Assert.False(a.Equals(1.0));
    }

    [Fact]
    public void Hash_code_depends_on_every_component()
    {
        // Not a contract that hashes differ, but a hash that ignored a component would give one value per group.
        var reds = Enumerable.Range(1, 10).Select(i => new Intensity(i / 10.0, 0.5, 0.5).GetHashCode()).Distinct().Count();
        var greens = Enumerable.Range(1, 10).Select(i => new Intensity(0.5, i / 10.0, 0.5).GetHashCode()).Distinct().Count();
        var blues = Enumerable.Range(1, 10).Select(i => new Intensity(0.5, 0.5, i / 10.0).GetHashCode()).Distinct().Count();

        Assert.True(reds > 1, "hash ignores R");
        Assert.True(greens > 1, "hash ignores G");
        Assert.True(blues > 1, "hash ignores B");
    }

    [Fact]
    public void Intensities_work_as_dictionary_keys()
    {
        var set = new HashSet<Intensity> { new(1, 0, 0), new(1, 0, 0), new(0, 1, 0), new(-1, 1, 0) };

        Assert.Equal(2, set.Count);
        Assert.Contains(new Intensity(0, 1, 0), set);
    }

    // ---- ToString -----------------------------------------------------------------------------------

    [Theory]
    [InlineData(0.0, 0.0, 0.0, "(0, 0, 0)")]
    [InlineData(1.0, 0.5, 0.25, "(1, 0.5, 0.25)")]
    [InlineData(2.0, 10.0, 0.125, "(2, 10, 0.125)")]
    public void ToString_formats_as_R_G_B(double r, double g, double b, string expected)
    {
        Assert.Equal(expected, new Intensity(r, g, b).ToString());
    }

    [Fact]
    public void ToString_uses_invariant_culture_even_when_current_culture_uses_a_decimal_comma()
    {
        CultureInfo saved = CultureInfo.CurrentCulture;
        var commaCulture = (CultureInfo)CultureInfo.InvariantCulture.Clone();
        commaCulture.NumberFormat.NumberDecimalSeparator = ",";
        commaCulture.NumberFormat.NegativeSign = "~";
        try
        {
            CultureInfo.CurrentCulture = commaCulture;
            Assert.Equal("1,5", 1.5.ToString()); // sanity: the culture really is in effect

            Assert.Equal("(1.5, 0.25, 0)", new Intensity(1.5, 0.25).ToString());
        }
        finally
        {
            CultureInfo.CurrentCulture = saved;
        }
    }

    // ---- ToLevel: level = int(256 · I), clamped to 0..255, NaN → 0 ------------------------------

    [Theory]
    [InlineData(0.0, 0)]
    [InlineData(1.0, 255)]
    [InlineData(2.0, 255)]
    [InlineData(double.PositiveInfinity, 255)]
    [InlineData(double.MaxValue, 255)]
    [InlineData(-0.5, 0)]
    [InlineData(double.NegativeInfinity, 0)]
    [InlineData(double.NaN, 0)]
    [InlineData(0.5, 128)]
    [InlineData(0.25, 64)]
    [InlineData(1.0 / 256.0, 1)]
    [InlineData(2.0 / 256.0, 2)]
    [InlineData(254.5 / 256.0, 254)]
    [InlineData(255.0 / 256.0, 255)]
    [InlineData(0.999, 255)]
    [InlineData(double.Epsilon, 0)]
    public void ToLevel_follows_the_lab_rule(double component, int expected)
    {
        Assert.Equal(expected, Intensity.ToLevel(component));
    }

    public static TheoryData<double, int> BoundaryLevels => new()
    {
        { Math.BitDecrement(1.0), 255 },
        { Math.BitIncrement(1.0), 255 },
        { Math.BitDecrement(1.0 / 256.0), 0 },
        { Math.BitDecrement(0.5), 127 },
        { -0.0, 0 },
        { Math.BitDecrement(255.0 / 256.0), 254 },
    };

    [Theory]
    [MemberData(nameof(BoundaryLevels))]
    public void ToLevel_truncates_just_below_each_step(double component, int expected)
    {
        Assert.Equal(expected, Intensity.ToLevel(component));
    }

    [Fact]
    public void ToLevel_matches_truncation_of_256_times_I_for_every_level()
    {
        for (int level = 0; level < 256; level++)
        {
            double low = level / 256.0;
            Assert.Equal(level, Intensity.ToLevel(low));
            Assert.Equal(level, Intensity.ToLevel((level + 0.5) / 256.0));
            if (level > 0)
            {
                Assert.Equal(level - 1, Intensity.ToLevel(Math.BitDecrement(low)));
            }
        }
    }
}
