using RayLab.Scenes;

namespace RayLab.Tests.Scenes;

/// <summary>A prepared scene renders through the image plane <see cref="SceneDescription.Prepare"/> built, and only while that plane is still its camera's.</summary>
public class PreparedSceneTests
{
    private static readonly string LabScene = Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

    private static byte[] Bytes(Image image) => image.PixelBytes.ToArray();

    [Theory]
    [InlineData("jittered")]
    [InlineData("adaptive")]
    [InlineData("exact")]
    public void APreparedRenderIsTheRenderOfItsCamera(string sampler)
    {
        SceneDescription description = SceneFile.Load(LabScene);
        PreparedScene prepared = (description with { Width = 80, Height = 60, Sampler = description.Sampler with { Type = sampler } }).Prepare();
        Assert.NotNull(prepared.Prepared);
        var renderer = new Renderer { MaxDegreeOfParallelism = 2 };
        Image viaPlane = prepared.CreateImage(), viaCamera = prepared.CreateImage();
        prepared.Render(renderer, viaPlane);
        renderer.Render(prepared.Scene, prepared.Camera, prepared.Method, viaCamera);
        Assert.Equal(Bytes(viaCamera), Bytes(viaPlane));
    }

    [Fact]
    public void ACameraSwappedInAfterPreparingIsTheOneThatRenders()
    {
        SceneDescription description = SceneFile.Load(LabScene) with { Width = 80, Height = 60 };
        PreparedScene prepared = description.Prepare();
        Camera other = (description.Camera with { Type = description.Camera.Type == "perspective" ? "orthographic" : "perspective" }).CreateCamera();
        PreparedScene swapped = prepared with { Camera = other };
        var renderer = new Renderer { MaxDegreeOfParallelism = 2 };
        Image viaSwapped = swapped.CreateImage(), viaOther = swapped.CreateImage(), viaPrepared = prepared.CreateImage();
        swapped.Render(renderer, viaSwapped);
        renderer.Render(swapped.Scene, other, swapped.Method, viaOther);
        prepared.Render(renderer, viaPrepared);
        Assert.NotEqual(Bytes(viaPrepared), Bytes(viaOther));
        Assert.Equal(Bytes(viaOther), Bytes(viaSwapped));
    }
}
