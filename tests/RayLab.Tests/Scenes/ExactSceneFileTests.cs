using RayLab.Scenes;

namespace RayLab.Tests.Scenes;

/// <summary>The exact reference in scene files: <c>"sampler": { "type": "exact" }</c>, its dispatch and its errors.</summary>
public class ExactSceneFileTests
{
    private const string Source = "exact-scene.json";

    // Sphere 1 sits around the perspective eye's plane (depth −0.5 to 1.5), inside the view: the exact reference
    // cannot outline it; an orthographic camera can (the near plane at depth 0 cuts it).
    private static string Scene(string camera, string sampler) => $$"""
        {
          "image": { "width": 40, "height": 30 },
          "background": [0.1, 0.1, 0.15],
          "camera": { "type": "{{camera}}", "position": [0, 0, 6], "target": [0, 0, 0], "fov": 40, "height": 5, "near": 0 },
          "spheres": [ { "center": [-1.1, 0, 0], "radius": 1, "color": [0.9, 0.2, 0.2] },
                       { "center": [0.3, 0.4, 5.5], "radius": 1, "color": [0.2, 0.8, 0.3] } ],
          "sampler": {{sampler}}
        }
        """;

    private static readonly string LabScene = Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    [Fact]
    public void TheExactSamplerIsASamplerTypeAndRendersThroughTheExactRenderer()
    {
        SceneDescription description = SceneFile.Load(LabScene);
        description = description with { Sampler = description.Sampler with { Type = "exact" }, Width = 64, Height = 48 };

        PreparedScene prepared = description.Prepare();
        var image = prepared.CreateImage();
        float[] rays = [.. Enumerable.Repeat(7f, 64 * 48)];
        RenderStatistics stats = prepared.Render(new Renderer { MaxDegreeOfParallelism = 2 }, image, rays);

        Assert.Contains("exact", SamplerSettings.Types);
        Assert.True(description.Sampler.IsExact);
        Assert.True(prepared.IsExact);
        Assert.Equal(("exact", 0), (prepared.SamplerName, prepared.SamplesPerPixel));
        Assert.Equal(0, stats.PrimaryRays);
        Assert.All(rays, r => Assert.Equal(0f, r));
        var direct = new Image(64, 48);
        new Renderer().Render(prepared.Scene, prepared.Camera, RenderMethod.Exact, direct);
        Assert.Equal(direct.PixelBytes.ToArray(), image.PixelBytes.ToArray());
    }

    [Fact]
    public void AFileAskingForExactLoadsWithItsOtherSamplerFieldsIgnored()
    {
        SceneDescription scene = SceneFile.Parse(Scene("orthographic", """{ "type": "exact", "samples": 16, "seed": 3 }"""), Source);

        Assert.Equal("exact", scene.Sampler.Type);
        Assert.True(scene.Prepare().IsExact);
    }

    [Fact]
    public void ASphereTheExactReferenceCannotOutlineIsAnErrorNamingItsField()
    {
        var e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(Scene("perspective", """{ "type": "exact" }"""), Source));

        Assert.Equal("spheres[1]", e.Field);
        Assert.StartsWith($"{Source}: spheres[1]: reaches behind the perspective camera (its depth along the gaze runs from -0.5 to 1.5)", e.Message);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void TheSameSphereIsFineForAPointSamplerUntilTheSamplerIsSwitchedToExact()
    {
        SceneDescription scene = SceneFile.Parse(Scene("perspective", """{ "type": "jittered", "samples": 4 }"""), Source);

        var e = Assert.Throws<SceneFileException>(() => (scene with { Sampler = scene.Sampler with { Type = "exact" } }).Prepare());

        Assert.Equal("spheres[1]", e.Field);
    }
}
