using System.Reflection;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Tests.Scenes;

/// <summary>
/// The types name their parameters; the scene-file sections turn those names into JSON paths. A renamed
/// property or parameter must fail here, not degrade an error message to the section's name.
/// </summary>
public sealed class SceneSectionTests
{
    public static TheoryData<Type> CameraTypes => [typeof(PerspectiveCamera), typeof(OrthoCamera)];

    [Theory]
    [MemberData(nameof(CameraTypes))]
    public void EveryCameraSettingMapsToACameraField(Type cameraType)
    {
        PropertyInfo[] settable = [.. cameraType.GetProperties(BindingFlags.Public | BindingFlags.Instance).Where(p => p.CanWrite)];

        Assert.NotEmpty(settable);
        foreach (PropertyInfo property in settable)
        {
            string field = SceneSection.Camera.FieldOf(property.Name);
            Assert.True(field.StartsWith("camera.", StringComparison.Ordinal), $"{cameraType.Name}.{property.Name} maps to no camera field (got '{field}')");
            Assert.Contains(field["camera.".Length..], CameraSettings.Fields);
        }
    }

    [Fact]
    public void EverySamplerParameterMapsToASamplerField()
    {
        IEnumerable<ParameterInfo> parameters = typeof(Samplers).GetMethod(nameof(Samplers.Create))!.GetParameters()
            .Concat(typeof(AdaptiveSampler).GetConstructors().SelectMany(c => c.GetParameters()))
            .Concat(typeof(IPixelSampler).Assembly.GetTypes()
                .Where(t => t.IsPublic && !t.IsAbstract && typeof(IPixelSampler).IsAssignableFrom(t))
                .SelectMany(t => t.GetConstructors().SelectMany(c => c.GetParameters())));

        foreach (ParameterInfo parameter in parameters)
        {
            string field = SceneSection.Sampler.FieldOf(parameter.Name);
            Assert.True(field.StartsWith("sampler.", StringComparison.Ordinal), $"{parameter.Member.DeclaringType?.Name}'s parameter {parameter.Name} maps to no sampler field (got '{field}')");
        }
    }

    [Fact]
    public void TheSphereConstructorsParametersMapToSphereFields()
    {
        foreach (ParameterInfo parameter in typeof(Sphere).GetConstructors().SelectMany(c => c.GetParameters()))
        {
            Assert.Equal($"spheres[2].{parameter.Name}", SceneSection.Sphere(2).FieldOf(parameter.Name));
        }
    }

    [Theory]
    [InlineData("Renamed")]
    [InlineData("window2")]
    [InlineData(null)]
    public void AnUnknownNameMapsToTheSectionNotToAGuess(string? name)
    {
        Assert.Equal("camera", SceneSection.Camera.FieldOf(name));
        Assert.Equal("sampler", SceneSection.Sampler.FieldOf(name));
        Assert.Equal("image", SceneSection.Image.FieldOf(name));
    }

    [Fact]
    public void ATypesMessageIsReportedWithTheFieldAndWithoutTheParameterSuffix()
    {
        var e = Assert.Throws<SceneFileException>(() => SceneSection.Camera.Build("s.json", () => new PerspectiveCamera { NearPlane = -2 }));

        Assert.Equal("camera.near", e.Field);
        Assert.Equal("s.json: camera.near: NearPlane must be a finite number ≥ 0, got -2.", e.Message);
        Assert.IsType<ArgumentException>(e.InnerException);
    }
}
