using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>
/// A sphere too far from the camera for double (its offset from a ray's origin, or its radius, squares past
/// double's range) is refused by every method, naming it, where it used to vanish from the picture without a word;
/// up to the limit, and wherever the camera and the spheres lie together, the picture is drawn.
/// </summary>
public class DoubleReachTests
{
    private static readonly Intensity Red = new(1, 0, 0);

    private static Scene Spheres(params (Double3 Centre, double Radius)[] spheres) =>
        new([.. spheres.Select(s => new Sphere(s.Centre, s.Radius, Red))], Intensity.Black, Intensity.White);

    private static PerspectiveCamera LookingDown(Double3 eye) =>
        new() { Position = eye, Target = eye - new Double3(0, 0, 1), Fov = 40, NearPlane = 0, FarPlane = 1e308 };

    public static TheoryData<string> Methods => ["regular", "adaptive", "exact", "trace"];

    private static void Render(string method, Scene scene, Camera camera)
    {
        var image = new Image(8, 6);
        switch (method)
        {
            case "regular": new Renderer().Render(scene, camera, RenderMethod.Sampled(new RegularSampler(4)), image); break;
            case "adaptive": new Renderer().Render(scene, camera, new AdaptiveSampler(), image); break;
            case "exact": new Renderer().Render(scene, camera, RenderMethod.Exact, image); break;
            default: Renderer.TracePixel(scene, camera, 8, 6, RenderMethod.Sampled(new RegularSampler(1)), 4, 3); break;
        }
    }

    [Theory]
    [MemberData(nameof(Methods))]
    public void ASphereBeyondDoublesReachIsRefusedByIndexNotDrawnAway(string method)
    {
        // Sphere 1 fills the view, 3e154 away with radius 2e154: r² and |c − e|² overflow double.
        Scene scene = Spheres((new Double3(0, 0, -5), 1), (new Double3(0, 0, -3e154), 2e154));

        var e = Assert.Throws<UnsupportedSceneException>(() => Render(method, scene, LookingDown(Double3.Zero)));

        Assert.Equal(1, e.SphereIndex);
        Assert.StartsWith("Sphere 1 (centre ", e.Message, StringComparison.Ordinal);
        Assert.Contains("overflows double", e.Reason, StringComparison.Ordinal);
        Assert.Throws<UnsupportedSceneException>(() => RenderMethod.Sampled(new RegularSampler(1)).Check(scene, LookingDown(Double3.Zero), 8, 6));
    }

    [Theory]
    [InlineData(0, 3e15, 2e15)]         // the same scene scaled down
    [InlineData(0, 3e152, 2e152)]       // its far side at the limit, 5e152
    [InlineData(1e160, 3e150, 2e150)]   // far from the origin, but near the camera: only the offsets count
    public void WithinReachTheSphereFillsThePictureWithEveryKernel(double x, double distance, double radius)
    {
        var eye = new Double3(x, 0, 0);
        Scene scene = Spheres((eye - new Double3(0, 0, distance), radius));

        foreach (RenderKernel kernel in Enum.GetValues<RenderKernel>().Where(k => k != RenderKernel.Auto))
        {
            var image = new Image(8, 6);
            new Renderer { Kernel = kernel }.Render(scene, LookingDown(eye), RenderMethod.Sampled(new RegularSampler(4)), image);
            for (int y = 0; y < image.Height; y++)
            {
                Assert.All(image.GetRowSpan(y).ToArray(), p => Assert.Equal(new Rgb24(255, 0, 0), p));
            }
        }
    }
}
