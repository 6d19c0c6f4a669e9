using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

public class RendererTests
{
    private static readonly Intensity Red = new(0.9, 0.2, 0.2);
    private static readonly Intensity Background = new(0.1, 0.1, 0.15);

    private static Scene TwoSpheres(Intensity? ambient = null) => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, Red), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        Background,
        ambient ?? Intensity.White);

    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    private static byte[] Render(IPixelSampler sampler, int threads, Scene? scene = null, Camera? camera = null, int w = 64, int h = 48)
    {
        var image = new Image(w, h);
        new Renderer { MaxDegreeOfParallelism = threads }.Render(scene ?? TwoSpheres(), camera ?? Camera, sampler, image);
        return image.PixelBytes.ToArray();
    }

    [Theory]
    [InlineData("regular", 4)]
    [InlineData("random", 5)]
    [InlineData("jittered", 9)]
    public void BytesAreIdenticalForOneAndTwoThreads(string name, int samples)
    {
        IPixelSampler sampler = Samplers.Create(name, samples, 3);
        Assert.Equal(Render(sampler, 1), Render(sampler, 2));
        Assert.Equal(Render(sampler, 1), Render(sampler, -1));
    }

    [Theory]
    [InlineData("random")]
    [InlineData("jittered")]
    public void DifferentSeedsGiveDifferentBytes(string name)
    {
        Assert.NotEqual(Render(Samplers.Create(name, 4, 1), 2), Render(Samplers.Create(name, 4, 2), 2));
    }

    [Fact]
    public void ProgressCountsEveryRowOfEachRender()
    {
        var progress = new RenderProgress();
        Assert.Equal(0, progress.Fraction);
        var renderer = new Renderer { MaxDegreeOfParallelism = 2, Progress = progress };
        renderer.Render(TwoSpheres(), Camera, Samplers.Create("jittered", 4, 1), new Image(20, 13));
        Assert.Equal((13, 13, 1.0), (progress.RowsCompleted, progress.TotalRows, progress.Fraction));
        renderer.Render(TwoSpheres(), Camera, new AdaptiveSampler(), new Image(9, 7));
        Assert.Equal((7, 7), (progress.RowsCompleted, progress.TotalRows));
    }

    [Fact]
    public void StatisticsCountEveryPrimaryRay()
    {
        var image = new Image(31, 17);
        RenderStatistics stats = new Renderer().Render(TwoSpheres(), Camera, new RandomSampler(3, 0), image);
        Assert.Equal(31L * 17 * 3, stats.PrimaryRays);
        Assert.True(stats.RenderTime > TimeSpan.Zero);
    }

    [Fact]
    public void ASampleShowsColourTimesAmbientOrTheBackground()
    {
        var ambient = new Intensity(0.5, 1, 0.25);
        var camera = new OrthoCamera { Position = new Double3(0, 0, 10), Target = Double3.Zero, ViewHeight = 8, NearPlane = 0.1 };
        var image = new Image(80, 80);
        new Renderer().Render(TwoSpheres(ambient), camera, new RegularSampler(1), image);
        // Pixel at world (−1.1, 0): the red sphere's centre. Corner: background, not multiplied by ambient.
        int x = (int)((-1.1 + 4) / 8 * 80);
        Assert.Equal(Rgb24.FromIntensity(Red * ambient), image.GetPixel(x, 40));
        Assert.Equal(Rgb24.FromIntensity(Background), image.GetPixel(0, 0));
    }

    [Fact]
    public void EdgePixelsAreAveragedBetweenSphereAndBackground()
    {
        byte[] one = Render(new RegularSampler(1), 2);
        byte[] many = Render(new RegularSampler(16), 2);
        static HashSet<int> Colours(byte[] p) => Enumerable.Range(0, p.Length / 3).Select(i => (p[3 * i] << 16) | (p[(3 * i) + 1] << 8) | p[(3 * i) + 2]).ToHashSet();
        // One sample: only the three flat colours. Sixteen: mixtures along the edges.
        Assert.Equal(3, Colours(one).Count);
        Assert.True(Colours(many).Count > 10);
    }

    [Fact]
    public void NearAndFarPlanesClipByDepthAlongTheGaze()
    {
        // A sphere at depth 6 (its front at 5): visible with far = 100, gone with far = 4.9 or near = 7.5.
        var scene = new Scene([new Sphere(Double3.Zero, 1, Intensity.White)], Intensity.Black, Intensity.White);
        static int Lit(byte[] p) => p.Count(b => b != 0);
        PerspectiveCamera at(double near, double far) => new() { Position = new Double3(0, 0, 6), Target = Double3.Zero, Fov = 30, NearPlane = near, FarPlane = far };
        Assert.True(Lit(Render(new RegularSampler(1), 2, scene, at(0.1, 100))) > 0);
        Assert.Equal(0, Lit(Render(new RegularSampler(1), 2, scene, at(0.1, 4.9))));
        Assert.Equal(0, Lit(Render(new RegularSampler(1), 2, scene, at(7.5, 100))));
        // Near plane inside the sphere: the far wall (depth ≤ 7) shows.
        Assert.True(Lit(Render(new RegularSampler(1), 2, scene, at(6, 100))) > 0);
    }

    [Fact]
    public void ASphereBehindTheCameraIsInvisible()
    {
        var scene = new Scene([new Sphere(new Double3(0, 0, 10), 1, Intensity.White)], Intensity.Black, Intensity.White);
        Assert.All(Render(new RegularSampler(1), 2, scene, new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero, NearPlane = 0 }), b => Assert.Equal(0, b));
    }

    [Fact]
    public void AOneByOneImageRendersItsCentre()
    {
        var scene = new Scene([new Sphere(Double3.Zero, 1, Red)], Background, Intensity.White);
        byte[] pixel = Render(new RegularSampler(1), 1, scene, new PerspectiveCamera { Position = new Double3(0, 0, 5), Target = Double3.Zero }, 1, 1);
        Assert.Equal(new[] { Intensity.ToLevel(0.9), Intensity.ToLevel(0.2), Intensity.ToLevel(0.2) }, pixel);
    }
}
