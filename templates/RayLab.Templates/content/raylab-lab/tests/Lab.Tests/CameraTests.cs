using RayLab;

namespace MyLab.Tests;

/// <summary>The camera frame (3.2): w = −g/|g|, u = (up × w)/|up × w|, v = w × u.</summary>
public class CameraTests
{
    private const int Precision = 12;

    [Fact]
    public void ACameraLookingDownMinusZHasTheWorldAxesAsItsFrame()
    {
        var camera = new PerspectiveCamera { Position = new Double3(0, 0, 0), Target = new Double3(0, 0, -1), Up = new Double3(0, 1, 0) };

        var plane = camera.GetImagePlane(800, 600);

        AssertEqual(new Double3(1, 0, 0), plane.U); // right
        AssertEqual(new Double3(0, 1, 0), plane.V); // up
        AssertEqual(new Double3(0, 0, 1), plane.W); // backward, away from what the camera sees
        AssertEqual(new Double3(0, 0, 0), plane.Eye);
    }

    [Fact]
    public void TheLabsCameraLooksDownAtTheSpheres()
    {
        var plane = TwoSpheres.Perspective.GetImagePlane(800, 600);

        double g = Math.Sqrt((0.5 * 0.5) + (6 * 6)); // |g|, g = Target − Position = (0, −0.5, −6)
        AssertEqual(new Double3(0, 0.5 / g, 6 / g), plane.W);
        AssertEqual(new Double3(1, 0, 0), plane.U);
        AssertEqual(new Double3(0, 6 / g, -0.5 / g), plane.V); // w × u: tilted back as the camera looks down
    }

    [Fact]
    public void OrthographicRaysAreParallelToTheGaze()
    {
        var plane = TwoSpheres.Orthographic.GetImagePlane(800, 600);

        Ray corner = plane.GetPixelRay(0, 0, 0.5, 0.5);
        Ray centre = plane.GetPixelRay(400, 300, 0, 0);

        Assert.Equal(corner.Direction.X, centre.Direction.X, Precision);
        Assert.Equal(corner.Direction.Y, centre.Direction.Y, Precision);
        Assert.Equal(corner.Direction.Z, centre.Direction.Z, Precision);
        AssertEqual(plane.Eye, centre.Origin); // the image's centre lies on the ray through the eye
    }

    private static void AssertEqual(Double3 expected, Double3 actual)
    {
        Assert.Equal(expected.X, actual.X, Precision);
        Assert.Equal(expected.Y, actual.Y, Precision);
        Assert.Equal(expected.Z, actual.Z, Precision);
    }
}
