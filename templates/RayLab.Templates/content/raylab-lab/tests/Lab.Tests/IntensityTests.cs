using RayLab;

namespace MyLab.Tests;

/// <summary>The light intensity (2.1): three components, never negative, with the lab's operators.</summary>
public class IntensityTests
{
    private static readonly Intensity A = new(0.5, 0.25, 0.125);
    private static readonly Intensity B = new(0.25, 0.5, 0.125);

    [Fact]
    public void ConstructorsFillTheMissingComponentsWithZero()
    {
        Assert.Equal(new Intensity(0.5, 0, 0), new Intensity(0.5));
        Assert.Equal(new Intensity(0.5, 0.25, 0), new Intensity(0.5, 0.25));
        Assert.Equal(new Intensity(0, 0, 0), new Intensity());
        Assert.Equal(Intensity.Black, new Intensity());
    }

    [Fact]
    public void AddAndSubtractComponentByComponent()
    {
        Assert.Equal(new Intensity(0.75, 0.75, 0.25), A + B);
        Assert.Equal(new Intensity(0.25, 0, 0), A - B); // 0.25 − 0.5 would be negative: 0
    }

    [Fact]
    public void ScaleByANumberOnEitherSideAndDivide()
    {
        Assert.Equal(new Intensity(1, 0.5, 0.25), A * 2);
        Assert.Equal(new Intensity(1, 0.5, 0.25), 2 * A);
        Assert.Equal(new Intensity(0.25, 0.125, 0.0625), A / 2);
    }

    [Fact]
    public void CompoundAssignmentsFollowTheOperators()
    {
        Intensity i = A;
        i += B;
        i -= A;
        i *= 4;
        i /= 2;
        Assert.Equal(new Intensity(0.5, 1, 0.25), i);
    }

    [Fact]
    public void AColourTimesTheAmbientIntensityIsChannelByChannel()
    {
        var ambient = new Intensity(1, 0.5, 0);
        Assert.Equal(new Intensity(0.9, 0.1, 0), new Intensity(0.9, 0.2, 0.2) * ambient);
    }
}
