using System.Numerics;
using RayLab.Cameras;
using RayLab.Sampling;

namespace RayLab.Tests.Cameras;

public class CameraTests
{
    private static Camera Make(string type, Double3 position, Double3 target, Double3? up = null) => type == "perspective"
        ? new PerspectiveCamera { Position = position, Target = target, Up = up ?? Double3.UnitY, Fov = 50, NearPlane = 0.1 }
        : new OrthoCamera { Position = position, Target = target, Up = up ?? Double3.UnitY, ViewHeight = 6, NearPlane = 0.1 };

    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void FrameIsOrthonormalAndRightHandedForAGenericGaze(string type)
    {
        Camera camera = Make(type, new Double3(1.3, -2.1, 7.7), new Double3(-0.4, 0.9, 0.2), new Double3(0.1, 1, 0.3));
        ImagePlane plane = camera.GetImagePlane(64, 48);
        Assert.Equal(1, plane.U.Length, 1e-12);
        Assert.Equal(1, plane.V.Length, 1e-12);
        Assert.Equal(1, plane.W.Length, 1e-12);
        Assert.Equal(0, Double3.Dot(plane.U, plane.V), 1e-12);
        Assert.Equal(0, Double3.Dot(plane.U, plane.W), 1e-12);
        Assert.Equal(0, Double3.Dot(plane.V, plane.W), 1e-12);
        Double3 uxv = Double3.Cross(plane.U, plane.V);
        Assert.Equal(0, (uxv - plane.W).Length, 1e-12);
        Double3 gaze = Double3.Normalize(camera.Target - camera.Position);
        Assert.Equal(-1, Double3.Dot(plane.W, gaze), 1e-12);
    }

    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void ASphereRightOfAndAboveTheGazeRendersInTheUpperRight(string type)
    {
        // Camera looking down −z from +z; world +x is camera right, +y camera up.
        Camera camera = Make(type, new Double3(0, 0, 10), Double3.Zero);
        var red = new Intensity(1, 0, 0);
        var scene = new Scene([new Sphere(new Double3(1.5, 1.5, 0), 0.5, red)], Intensity.Black, Intensity.White);
        var image = new Image(40, 40);
        new Renderer().Render(scene, camera, new RegularSampler(1), image);

        (double cx, double cy) = Centroid(image);
        Assert.True(cx > 20, $"sphere centroid x = {cx}: expected right half (not mirrored)");
        Assert.True(cy < 20, $"sphere centroid row = {cy}: expected upper half (not flipped)");
    }

    [Fact]
    public void OrthographicPixelCentresFollowTheLabFormula()
    {
        // The lab: plane [−1, 1], pixel size 2/resolution per axis, cx = −1 + (x + 0.5)·pw, cy = 1 − (y + 0.5)·ph.
        var camera = new OrthoCamera { Position = new Double3(0, 0, 1), Target = Double3.Zero, ViewHeight = 2 };
        const int N = 8;
        ImagePlane plane = camera.GetImagePlane(N, N);
        for (int y = 0; y < N; y++)
        {
            for (int x = 0; x < N; x++)
            {
                Ray ray = plane.GetPixelRay(x, y, 0.5, 0.5);
                Assert.Equal(-1 + ((x + 0.5) * 2.0 / N), ray.Origin.X, 1e-12);
                Assert.Equal(1 - ((y + 0.5) * 2.0 / N), ray.Origin.Y, 1e-12);
                Assert.Equal(1, ray.Origin.Z, 1e-12);
                Assert.Equal(new Double3(0, 0, -1), ray.Direction);
            }
        }
    }

    [Fact]
    public void OrthographicPixelsAreSquareForANonSquareImage()
    {
        // The lab swaps the resolutions in its pixel size; RayLab must not.
        var camera = new OrthoCamera { Position = new Double3(0, 0, 1), Target = Double3.Zero, ViewHeight = 2 };
        ImagePlane plane = camera.GetImagePlane(300, 100);
        double pixelWidth = (plane.GetPixelRay(1, 0, 0.5, 0.5).Origin - plane.GetPixelRay(0, 0, 0.5, 0.5).Origin).Length;
        double pixelHeight = (plane.GetPixelRay(0, 1, 0.5, 0.5).Origin - plane.GetPixelRay(0, 0, 0.5, 0.5).Origin).Length;
        Assert.Equal(2.0 / 100, pixelHeight, 1e-12);
        Assert.Equal(pixelHeight, pixelWidth, 1e-12);
    }

    [Fact]
    public void PerspectiveRaysAreTheLabsEPlusTTimesPMinusE()
    {
        var camera = new PerspectiveCamera
        {
            Position = new Double3(0.5, 1, 3), Target = new Double3(0.5, 1, 0), Distance = 2,
            Window = new Window(-0.3, -0.1, 0.9, 0.5),
        };
        ImagePlane plane = camera.GetImagePlane(20, 10);
        // a = (u1 − u0) u, b = (v1 − v0) v, c = u0 u + v0 v − s w; here u = x, v = y, w = z.
        Assert.Equal(new Double3(1.2, 0, 0).X, plane.A.X, 1e-12);
        Assert.Equal(0.6, plane.B.Y, 1e-12);
        Assert.Equal(-0.3, plane.C.X, 1e-12);
        Assert.Equal(-0.1, plane.C.Y, 1e-12);
        Assert.Equal(-2, plane.C.Z, 1e-12);
        for (int row = 0; row < 10; row++)
        {
            for (int x = 0; x < 20; x++)
            {
                double alpha = (x + 0.5) / 20, beta = 1 - ((row + 0.5) / 10);
                Ray ray = plane.GetPixelRay(x, row, 0.5, 0.5);
                Double3 p = camera.Position + plane.C + (alpha * plane.A) + (beta * plane.B);
                Assert.Equal(camera.Position, ray.Origin);
                Assert.Equal(0, (ray.Direction - (p - camera.Position)).Length, 1e-12);
            }
        }
    }

    [Fact]
    public void AnOffAxisWindowShiftsThePictureAsTheFormulaSays()
    {
        // A small sphere on the axis at depth 10 sits at window point (0, 0). With window [u0, u1] the
        // point u = 0 is at α = −u0/(u1 − u0): the picture moves when the window moves.
        var sphere = new Sphere(new Double3(0, 0, -10), 0.3, Intensity.White);
        var scene = new Scene([sphere], Intensity.Black, Intensity.White);
        foreach (Window window in new[] { new Window(-0.5, -0.5, 0.5, 0.5), new Window(-0.2, -0.6, 0.8, 0.4), new Window(-0.9, -0.1, 0.1, 0.9) })
        {
            var camera = new PerspectiveCamera { Position = Double3.Zero, Target = new Double3(0, 0, -1), Window = window };
            var image = new Image(100, 100);
            new Renderer().Render(scene, camera, new RegularSampler(1), image);
            (double cx, double cy) = Centroid(image);
            double expectedX = (-window.U0 / window.Width * 100) - 0.5;
            double expectedRow = ((1 - (-window.V0 / window.Height)) * 100) - 0.5;
            Assert.Equal(expectedX, cx, 0.6);
            Assert.Equal(expectedRow, cy, 0.6);
        }
    }

    [Theory]
    [InlineData(10.0)]
    [InlineData(45.0)]
    [InlineData(90.0)]
    [InlineData(170.0)]
    public void TheVerticalFieldOfViewSpansTheImageHeight(double fov)
    {
        var camera = new PerspectiveCamera { Position = new Double3(1, 2, 3), Target = new Double3(4, 0, -2), Fov = fov };
        ImagePlane plane = camera.GetImagePlane(320, 200);
        Double3 gaze = Double3.Normalize(camera.Target - camera.Position);
        Double3 top = Double3.Normalize(plane.GetRay(0.5, 1).Direction);
        Double3 bottom = Double3.Normalize(plane.GetRay(0.5, 0).Direction);
        Double3 right = Double3.Normalize(plane.GetRay(1, 0.5).Direction);
        Assert.Equal(fov, Math.Acos(Double3.Dot(top, bottom)) * 180 / Math.PI, 1e-9);
        Assert.Equal(fov / 2, Math.Acos(Double3.Dot(top, gaze)) * 180 / Math.PI, 1e-9);
        // Square pixels: the half-width on the plane is the half-height times W/H.
        double halfHeight = Math.Tan(fov * Math.PI / 360);
        Assert.Equal(halfHeight * 320 / 200, Math.Tan(Math.Acos(Double3.Dot(right, gaze))), 1e-9);
    }

    [Fact]
    public void PositionEqualToTargetIsRejectedNamingTarget()
    {
        var camera = new PerspectiveCamera { Position = new Double3(1, 1, 1), Target = new Double3(1, 1, 1) };
        ArgumentException e = Assert.Throws<ArgumentException>(() => camera.GetImagePlane(10, 10));
        Assert.Equal("Target", e.ParamName);
    }

    [Theory]
    [InlineData(0, 1, 0)]
    [InlineData(0, -3, 0)]
    [InlineData(0, 0, 0)]
    public void AnUpVectorParallelToTheGazeOrZeroIsRejectedNamingUp(double x, double y, double z)
    {
        var camera = new OrthoCamera { Position = new Double3(0, 5, 0), Target = Double3.Zero, Up = new Double3(x, y, z) };
        ArgumentException e = Assert.Throws<ArgumentException>(() => camera.GetImagePlane(10, 10));
        Assert.Equal("Up", e.ParamName);
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(-10.0)]
    [InlineData(180.0)]
    [InlineData(200.0)]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    public void FovOutsideTheOpenIntervalIsRejected(double fov)
    {
        ArgumentException e = Assert.Throws<ArgumentException>(() => new PerspectiveCamera { Fov = fov });
        Assert.Equal("Fov", e.ParamName);
    }

    [Fact]
    public void NearNotBelowFarIsRejected()
    {
        var camera = new PerspectiveCamera { Target = new Double3(0, 0, -1), NearPlane = 5, FarPlane = 5 };
        ArgumentException e = Assert.Throws<ArgumentException>(() => camera.GetImagePlane(4, 4));
        Assert.Equal("NearPlane", e.ParamName);
        Assert.Throws<ArgumentException>(() => new PerspectiveCamera { NearPlane = -1 });
        Assert.Throws<ArgumentException>(() => new PerspectiveCamera { FarPlane = double.NaN });
        Assert.Throws<ArgumentException>(() => new PerspectiveCamera { Position = new Double3(double.NaN, 0, 0) });
        Assert.Throws<ArgumentException>(() => new PerspectiveCamera { Distance = 0 });
        Assert.Throws<ArgumentException>(() => new OrthoCamera { ViewHeight = -2 });
        Assert.Throws<ArgumentException>(() => new PerspectiveCamera { Window = new Window(1, 0, 0, 1) });
    }

    [Fact]
    public void TheLabDefaultsHold()
    {
        var camera = new PerspectiveCamera();
        Assert.Equal(Double3.Zero, camera.Position);
        Assert.Equal(new Double3(0, 0, 1), camera.Target);
        Assert.Equal(Double3.UnitY, camera.Up);
        Assert.Equal(1, camera.NearPlane);
        Assert.Equal(1000, camera.FarPlane);
        // The System.Numerics vector converts implicitly.
        var fromNumerics = new OrthoCamera { Position = new Vector3(1, 2, 3) };
        Assert.Equal(new Double3(1, 2, 3), fromNumerics.Position);
    }

    [Fact]
    public void PixelCentresDoNotAccumulateErrorOnAVeryWideImage()
    {
        const int W = 100_000;
        var camera = new OrthoCamera { Position = Double3.Zero, Target = new Double3(0, 0, -1), Window = new Window(0, 0, 1, 1) };
        ImagePlane plane = camera.GetImagePlane(W, 1);
        foreach (int x in new[] { 0, 1, 12_345, 50_000, 99_998, 99_999 })
        {
            double u = plane.GetPixelRay(x, 0, 0.5, 0.5).Origin.X;
            Assert.Equal((x + 0.5) / W, u, 1e-3 / W);
        }
    }

    internal static (double X, double Row) Centroid(Image image)
    {
        double sx = 0, sy = 0, n = 0;
        for (int y = 0; y < image.Height; y++)
        {
            Span<Rgb24> row = image.GetRowSpan(y);
            for (int x = 0; x < row.Length; x++)
            {
                double weight = row[x].R + row[x].G + row[x].B;
                sx += weight * x;
                sy += weight * y;
                n += weight;
            }
        }

        Assert.True(n > 0, "the image is empty");
        return (sx / n, sy / n);
    }
}
