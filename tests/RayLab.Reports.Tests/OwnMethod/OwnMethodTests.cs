using RayLab.OwnMethod;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Reports.Tests.OwnMethod;

/// <summary>The README's guide, "Your own antialiasing method": samples/RayLab.OwnMethod measured on the lab's scene.</summary>
public class OwnMethodTests
{
    private static readonly Lazy<IReadOnlyList<MethodResult>> Results = new(() =>
        RayLab.OwnMethod.Comparison.Run(SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json"))));

    private static MethodResult Result(string name) => Results.Value.Single(r => r.Name == name);

    [Fact]
    public void TheRotatedGridBeatsJitteredAtSixteenRays()
    {
        MethodResult rotated = Result("rotated-grid 16"), jittered = Result("jittered 16");
        Assert.Equal(16, rotated.RaysPerPixel);
        Assert.Equal(16, jittered.RaysPerPixel);
        Assert.True(rotated.Error.Rmse < jittered.Error.Rmse, $"{rotated} / {jittered}");
        Assert.True(rotated.Error.MeanAbsolute < jittered.Error.MeanAbsolute, $"{rotated} / {jittered}");
    }

    [Fact]
    public void MitchellBeatsJitteredWithAtLeastItsRays()
    {
        MethodResult mitchell = Result("mitchell"), jittered = Result("jittered 9");
        // 4 rays in a flat pixel, 16 on an edge: a little over 4 per pixel on this scene.
        Assert.InRange(mitchell.RaysPerPixel, 4, 5);
        Assert.True(mitchell.Error.Rmse < jittered.Error.Rmse, $"{mitchell} / {jittered}");
        Assert.True(mitchell.Error.MeanAbsolute < jittered.Error.MeanAbsolute, $"{mitchell} / {jittered}");
    }

    [Fact]
    public void TheRotatedGridHasOneSampleInEachColumnAndRowOfItsCells()
    {
        var sampler = new RotatedGridSampler(16);
        SamplePoint[] points = [.. Enumerable.Range(0, 16).Select(i => sampler.GetSample(3, 5, i))];
        Assert.Equal(16, points.Select(p => (int)(p.X * 16)).Distinct().Count());
        Assert.Equal(16, points.Select(p => (int)(p.Y * 16)).Distinct().Count());
        Assert.Throws<ArgumentOutOfRangeException>(() => new RotatedGridSampler(8));
    }

    [Fact]
    public void MitchellTracesSixteenPointsOnlyWhereTheFirstFourDisagree()
    {
        SceneDescription description = SceneFile.Load(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json")) with { Width = 80, Height = 60 };
        PreparedScene prepared = description.Prepare();
        var rays = new float[80 * 60];
        Image one = prepared.CreateImage(), two = prepared.CreateImage();
        new Renderer { MaxDegreeOfParallelism = 1 }.Render(prepared.Scene, prepared.Camera, RenderMethod.Custom(new MitchellMethod()), one, rays);
        new Renderer { MaxDegreeOfParallelism = 2 }.Render(prepared.Scene, prepared.Camera, RenderMethod.Custom(new MitchellMethod()), two);
        Assert.Equal(one.PixelBytes.ToArray(), two.PixelBytes.ToArray());
        Assert.All(rays, r => Assert.True(r is 4 or 16));
        Assert.Contains(16f, rays);
        Assert.Equal(4, rays[0]); // the top-left corner is background
    }
}
