using RayLab.Sampling;

namespace RayLab.Tests.Cameras;

public class MovingCameraTests
{
    private static readonly Intensity Red = new(0.9, 0.2, 0.2);
    private static readonly Intensity Green = new(0.2, 0.8, 0.3);

    private static readonly Scene TwoSpheres = new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, Red), new Sphere(new Double3(1.2, 0.2, -1), 1.2, Green)],
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    private static Image Render(Camera camera)
    {
        var image = new Image(40, 30);
        new Renderer { MaxDegreeOfParallelism = 2 }.Render(TwoSpheres, camera, new RegularSampler(1), image);
        return image;
    }

    [Fact]
    public void AMovedCameraRendersTheNewViewAndTheOldOneIsUnchanged()
    {
        var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1 };
        Image before = Render(camera);

        // Turn to each sphere in turn, as the lab's snippet sets Target between two renders.
        PerspectiveCamera atRed = camera with { Target = new Double3(-1.1, 0, 0) };
        PerspectiveCamera atGreen = atRed with { Target = new Double3(1.2, 0.2, -1) };
        Image red = Render(atRed);
        Image green = Render(atGreen);

        Assert.Equal(Rgb24.FromIntensity(Red), red.GetPixel(20, 15));
        Assert.Equal(Rgb24.FromIntensity(Green), green.GetPixel(20, 15));
        Assert.NotEqual(red.PixelBytes.ToArray(), green.PixelBytes.ToArray());
        // The same picture as a camera built from scratch with the moved settings.
        var fresh = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = new Double3(1.2, 0.2, -1), Fov = 40, NearPlane = 0.1 };
        Assert.Equal(Render(fresh).PixelBytes.ToArray(), green.PixelBytes.ToArray());
        Assert.Equal(fresh, atGreen);
        // The original camera did not move.
        Assert.Equal(Double3.Zero, camera.Target);
        Assert.Equal(before.PixelBytes.ToArray(), Render(camera).PixelBytes.ToArray());
    }

    [Fact]
    public void AnOrthographicCameraMovesToo()
    {
        var camera = new OrthoCamera { Position = new Double3(-1.1, 0, 6), Target = new Double3(-1.1, 0, 0), ViewHeight = 4.2 };
        OrthoCamera moved = camera with { Position = new Double3(1.2, 0.2, 6), Target = new Double3(1.2, 0.2, -1) };
        Assert.Equal(Rgb24.FromIntensity(Red), Render(camera).GetPixel(20, 15));
        Assert.Equal(Rgb24.FromIntensity(Green), Render(moved).GetPixel(20, 15));
    }

    [Fact]
    public void WithChecksEachPropertyItSetsNamingIt()
    {
        var camera = new PerspectiveCamera();
        Assert.Equal("Fov", Assert.Throws<ArgumentException>(() => camera with { Fov = 180 }).ParamName);
        Assert.Equal("Position", Assert.Throws<ArgumentException>(() => camera with { Position = new Double3(double.NaN, 0, 0) }).ParamName);
        Assert.Equal("NearPlane", Assert.Throws<ArgumentException>(() => camera with { NearPlane = -1 }).ParamName);
        Assert.Equal("Distance", Assert.Throws<ArgumentException>(() => camera with { Distance = 0 }).ParamName);
        Assert.Equal("ViewHeight", Assert.Throws<ArgumentException>(() => new OrthoCamera() with { ViewHeight = double.PositiveInfinity }).ParamName);
    }

    [Fact]
    public void AMoveThatBreaksTheViewIsRejectedWhenRenderedNamingTheProperty()
    {
        var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero };
        Assert.Equal("Target", Assert.Throws<ArgumentException>(() => Render(camera with { Target = camera.Position })).ParamName);
        Assert.Equal("Up", Assert.Throws<ArgumentException>(() => Render(camera with { Up = new Double3(0, -0.5, -6) })).ParamName);
        Assert.Equal("NearPlane", Assert.Throws<ArgumentException>(() => Render(camera with { NearPlane = 2000 })).ParamName);
    }
}
