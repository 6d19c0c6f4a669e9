
namespace RayLab.Tests.Geometry;

public class SphereTests
{
    private static readonly Sphere Unit = new(Double3.Zero, 1, Intensity.White);

    [Fact]
    public void AHeadOnRayHitsTheNearSide()
    {
        Assert.True(Unit.TryIntersect(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)), 0, 100, out double t));
        Assert.Equal(4, t, 1e-15);
        // An unnormalised direction scales t.
        Assert.True(Unit.TryIntersect(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -2)), 0, 100, out t));
        Assert.Equal(2, t, 1e-15);
    }

    [Fact]
    public void AnExactlyTangentRayCountsAsAHit()
    {
        // Discriminant exactly 0: x = 1 touches the unit sphere at (1, 0, 0).
        Assert.True(Unit.TryIntersect(new Ray(new Double3(1, 0, 5), new Double3(0, 0, -1)), 0, 100, out double t));
        Assert.Equal(5, t, 1e-15);
        Assert.False(Unit.TryIntersect(new Ray(new Double3(Math.BitIncrement(1.0), 0, 5), new Double3(0, 0, -1)), 0, 100, out _));
    }

    [Fact]
    public void WhenTheNearRootIsClippedTheFarRootIsSeen()
    {
        // From the centre, or with the near plane inside the sphere, the inside of the far wall shows.
        Assert.True(Unit.TryIntersect(new Ray(Double3.Zero, new Double3(0, 0, -1)), 0, 100, out double t));
        Assert.Equal(1, t, 1e-15);
        Assert.True(Unit.TryIntersect(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)), 4.5, 100, out t));
        Assert.Equal(6, t, 1e-15);
    }

    [Fact]
    public void TheVisibleIntervalIsClosed()
    {
        var ray = new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1));
        Assert.True(Unit.TryIntersect(ray, 4, 4, out double t));
        Assert.Equal(4, t);
        Assert.False(Unit.TryIntersect(ray, 0, Math.BitDecrement(4.0), out _));
    }

    [Fact]
    public void SpheresBehindTheRayAreNotHit()
    {
        Assert.False(Unit.TryIntersect(new Ray(new Double3(0, 0, 5), new Double3(0, 0, 1)), 0, 100, out _));
    }

    [Fact]
    public void DegenerateInputsMissWithoutNaN()
    {
        var zero = new Sphere(Double3.Zero, 0, Intensity.White);
        Assert.False(zero.TryIntersect(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)), 0, 100, out _));
        Assert.False(Unit.TryIntersect(new Ray(new Double3(0, 0, 5), Double3.Zero), 0, 100, out _));
        Assert.False(Unit.TryIntersect(new Ray(new Double3(0, 0, 5), new Double3(double.NaN, 0, -1)), 0, 100, out _));
        // Origin on the surface, tangent: t = 0, not NaN.
        Assert.True(Unit.TryIntersect(new Ray(new Double3(1, 0, 0), new Double3(0, 0, 1)), 0, 100, out double t));
        Assert.Equal(0, t);
    }

    [Fact]
    public void ConstructionRejectsNegativeOrNonFiniteRadiusAndCentre()
    {
        Assert.Equal("radius", Assert.Throws<ArgumentException>(() => new Sphere(Double3.Zero, -1, Intensity.White)).ParamName);
        Assert.Equal("radius", Assert.Throws<ArgumentException>(() => new Sphere(Double3.Zero, double.NaN, Intensity.White)).ParamName);
        Assert.Equal("center", Assert.Throws<ArgumentException>(() => new Sphere(new Double3(0, double.PositiveInfinity, 0), 1, Intensity.White)).ParamName);
    }
}
