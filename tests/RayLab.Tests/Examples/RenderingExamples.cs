// Example tests to start from. Copy this folder (Examples/) into your own xUnit project that references the RayLab
// package; the README's quick start ("Tests") shows the project file. These tests use only RayLab's public API and
// ImageAssert from this folder: render a small scene in memory, then assert on pixels, on the rays traced and on
// the difference from another render. Run them here with: dotnet test --filter "FullyQualifiedName~Examples"
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Tests.Examples;

public sealed class RenderingExamples
{
    private const int Width = 64, Height = 48;

    private static readonly Intensity Red = new(0.9, 0.2, 0.2);
    private static readonly Intensity Green = new(0.2, 0.8, 0.3);
    private static readonly Intensity Background = new(0.1, 0.1, 0.15);

    // Two unit spheres at x = ∓1.5 seen from 8 units away with a 40° vertical field of view. Where they land in the
    // 64×48 image: the window at distance 1 is 2·tan 20° = 0.728 high and 0.971 wide, so a centre at x = ±1.5,
    // depth 8, is at u = ±1.5/8 = ±0.1875, i.e. column 32 ± 0.1875/0.971·64 = 19.6 and 44.4, on the middle row
    // (24). Each sphere's radius is about tan(asin(1/8))/0.971·64 = 8.3 pixels.
    private static readonly Scene TwoSpheres = new(
        [new Sphere(new Double3(-1.5, 0, 0), 1, Red), new Sphere(new Double3(1.5, 0, 0), 1, Green)],
        background: Background, ambient: Intensity.White);

    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0, 8), Target = Double3.Zero, Fov = 40 };

    private static (Image Image, RenderStatistics Stats) Render(IPixelSampler sampler, int threads = -1)
    {
        var image = new Image(Width, Height);
        RenderStatistics stats = new Renderer { MaxDegreeOfParallelism = threads }.Render(TwoSpheres, Camera, sampler, image);
        return (image, stats);
    }

    [Fact]
    public void APixelInsideASphereHasTheSpheresColour()
    {
        (Image image, _) = Render(new RegularSampler(1));

        // Colour × ambient (white), stored by the lab's rule int(256·I): red (0.9, 0.2, 0.2) is RGB (230, 51, 51).
        ImageAssert.PixelEqual(Red, image, 19, 24);
        ImageAssert.PixelEqual(new Rgb24(230, 51, 51), image, 20, 23);
        ImageAssert.PixelEqual(Green, image, 44, 24);
    }

    [Fact]
    public void TheCornersAreBackground()
    {
        (Image image, _) = Render(new JitteredSampler(4, seed: 1));

        // Antialiasing blends only where a pixel straddles an edge: a corner pixel sees background alone.
        ImageAssert.PixelEqual(Background, image, 0, 0);
        ImageAssert.PixelEqual(Background, image, Width - 1, 0);
        ImageAssert.PixelEqual(Background, image, 0, Height - 1);
        ImageAssert.PixelEqual(Background, image, Width - 1, Height - 1);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(4)]
    [InlineData(16)]
    public void APointSamplerTracesWidthTimesHeightTimesSamplesRays(int samplesPerPixel)
    {
        (_, RenderStatistics stats) = Render(new JitteredSampler(samplesPerPixel, seed: 1));

        Assert.Equal((long)Width * Height * samplesPerPixel, stats.PrimaryRays);
    }

    [Fact]
    public void TheSameSeedGivesTheSameImageOnOneThreadOrMany()
    {
        (Image one, _) = Render(new JitteredSampler(16, seed: 7), threads: 1);
        (Image many, _) = Render(new JitteredSampler(16, seed: 7), threads: 4);

        ImageAssert.Equal(one, many);
    }

    [Fact]
    public void ASceneFileDescribesTheSameRender()
    {
        // The same scene as JSON (as in samples/scenes/*.json): SceneFile.Parse, then Prepare() for camera and sampler.
        PreparedScene fromFile = SceneFile.Parse("""
            { "image": { "width": 64, "height": 48 },
              "background": [0.1, 0.1, 0.15],
              "camera": { "type": "perspective", "position": [0, 0, 8], "target": [0, 0, 0], "fov": 40 },
              "spheres": [ { "center": [-1.5, 0, 0], "radius": 1, "color": [0.9, 0.2, 0.2] },
                           { "center": [1.5, 0, 0], "radius": 1, "color": [0.2, 0.8, 0.3] } ],
              "sampler": { "type": "jittered", "samples": 16, "seed": 7 } }
            """).Prepare();
        Image image = fromFile.CreateImage();
        fromFile.Render(new Renderer(), image);

        (Image fromCode, _) = Render(new JitteredSampler(16, seed: 7));
        ImageAssert.Equal(fromCode, image);
    }

    [Fact]
    public void AntialiasingBringsThePictureCloseToTheExactOne()
    {
        // The exact reference: each pixel's area-weighted colour, computed analytically (the lab's "method of
        // our own", `--sampler exact`). Jaggies (one ray per pixel centre) are far from it; 16 jittered samples
        // per pixel are close; the error left is noise along the two outlines (about 2·2π·8.3 ≈ 105 edge pixels
        // of 3072). Measured: 0.62 levels per channel for one sample, 0.13 for 16 jittered; the bounds keep a margin.
        var exact = new Image(Width, Height);
        new Renderer().Render(TwoSpheres, Camera, RenderMethod.Exact, exact);

        (Image jaggies, _) = Render(new RegularSampler(1));
        (Image jittered, _) = Render(new JitteredSampler(16, seed: 1));

        double jaggyError = ImageAssert.MeanErrorAtMost(exact, jaggies, maxMean: 1.0);
        double antialiasedError = ImageAssert.MeanErrorAtMost(exact, jittered, maxMean: 0.2);
        Assert.True(antialiasedError < jaggyError / 3, $"16 jittered samples: {antialiasedError:F3} levels, one sample: {jaggyError:F3}");
    }
}
