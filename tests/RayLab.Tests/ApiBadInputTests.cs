using RayLab.Cameras;
using RayLab.Scenes;

namespace RayLab.Tests;

/// <summary>
/// The bad-input audit through the library: every setting that can be wrong throws an ArgumentException naming
/// the parameter (or property) to change — including finite numbers whose combination overflows, which used to
/// give a silently blank image.
/// </summary>
public class ApiBadInputTests
{
    private static readonly Double3 Nan3 = new(double.NaN, 0, 0);
    private static readonly Double3 Inf3 = new(0, double.PositiveInfinity, 0);

    public static TheoryData<string, Func<object>> Setters() => new()
    {
        { "Position", () => new PerspectiveCamera { Position = Nan3 } },
        { "Target", () => new OrthoCamera { Target = Inf3 } },
        { "Up", () => new PerspectiveCamera { Up = Nan3 } },
        { "NearPlane", () => new PerspectiveCamera { NearPlane = -1 } },
        { "NearPlane", () => new PerspectiveCamera { NearPlane = double.NaN } },
        { "NearPlane", () => new PerspectiveCamera { NearPlane = double.PositiveInfinity } },
        { "FarPlane", () => new PerspectiveCamera { FarPlane = 0 } },
        { "FarPlane", () => new PerspectiveCamera { FarPlane = double.NaN } },
        { "FarPlane", () => new OrthoCamera { FarPlane = double.PositiveInfinity } },
        { "Distance", () => new PerspectiveCamera { Distance = 0 } },
        { "Distance", () => new PerspectiveCamera { Distance = double.PositiveInfinity } },
        { "ViewHeight", () => new OrthoCamera { ViewHeight = -2 } },
        { "ViewHeight", () => new OrthoCamera { ViewHeight = double.NaN } },
        { "Window", () => new PerspectiveCamera { Window = new Window(double.NaN, 0, 1, 1) } },
        { "Window", () => new PerspectiveCamera { Window = new Window(0, 0, 0, 1) } },
        { "Window", () => new OrthoCamera { Window = new Window(0, 1, 1, -1) } },
        { "Window", () => new OrthoCamera { Window = new Window(-1e308, -1, 1e308, 1) } }, // u1 − u0 overflows
        { "radius", () => new Sphere(Double3.Zero, double.PositiveInfinity, Intensity.White) },
        { "spheres", () => new Scene(null!, Intensity.Black, Intensity.White) },
        { "spheres", () => new Scene([null!], Intensity.Black, Intensity.White) },
        { "MaxDegreeOfParallelism", () => new Renderer { MaxDegreeOfParallelism = 0 } },
        { "MaxDegreeOfParallelism", () => new Renderer { MaxDegreeOfParallelism = -2 } },
        { "path", () => SceneFile.Load(null!) },
        { "path", () => SceneFile.Load(" ") },
        { "json", () => SceneFile.Parse(null!) },
    };

    [Theory]
    [MemberData(nameof(Setters))]
    public void ASettingOutOfRangeThrowsNamingIt(string parameter, Func<object> create) =>
        Assert.Equal(parameter, Assert.ThrowsAny<ArgumentException>(create).ParamName);

    public static TheoryData<string, Camera, int, int> Views() => new()
    {
        { "width", new PerspectiveCamera(), 0, 4 },
        { "height", new OrthoCamera(), 4, -1 },
        { "Target", new PerspectiveCamera { Position = new Double3(1e308, 0, 0), Target = new Double3(-1e308, 0, 0) }, 4, 4 },
        { "Up", new PerspectiveCamera { Up = Double3.Zero }, 4, 4 },
        // The window from Fov and Distance, or from ViewHeight, overflows.
        { "Distance", new PerspectiveCamera { Distance = 1e308, Fov = 170 }, 4, 4 },
        { "ViewHeight", new OrthoCamera { ViewHeight = 1.7e308 }, 4, 2 },
        // Finite windows whose rays cannot be squared: before, every ray missed and the image was blank.
        { "Distance", new PerspectiveCamera { Distance = 1e308 }, 4, 4 },
        { "Distance", new PerspectiveCamera { Distance = 1e-160 }, 4, 4 },
        { "Window", new PerspectiveCamera { Window = new Window(-1e200, -1, 1e200, 1) }, 4, 4 },
        { "Position", new OrthoCamera { Position = new Double3(1.7e308, 0, 0), Target = new Double3(1.7e308, 0, -1), ViewHeight = 1e308 }, 4, 4 },
    };

    [Theory]
    [MemberData(nameof(Views))]
    public void AViewThatCannotBeRenderedThrowsNamingTheSettingToChange(string parameter, Camera camera, int width, int height)
    {
        Assert.Equal(parameter, Assert.ThrowsAny<ArgumentException>(() => camera.GetImagePlane(width, height)).ParamName);
    }

    [Fact]
    public void HugeAndTinyGazeAndUpVectorsGiveTheSameFrameAsOrdinaryOnes()
    {
        // Only direction matters: gaze and up are scaled by powers of two before squaring, exactly, so the frame
        // is bit for bit the one an ordinary-sized vector gives (and 1e-200 is not "the same point").
        var gaze = new Double3(-0.4, 0.9, -7.5);
        var up = new Double3(0.1, 1, 0.2);
        ImagePlane ordinary = new PerspectiveCamera { Position = Double3.Zero, Target = gaze, Up = up }.GetImagePlane(8, 8);
        foreach (double scale in new[] { Math.ScaleB(1.0, 600), Math.ScaleB(1.0, -600) })
        {
            ImagePlane scaled = new PerspectiveCamera { Position = Double3.Zero, Target = scale * gaze, Up = scale * up }.GetImagePlane(8, 8);
            Assert.Equal((ordinary.U, ordinary.V, ordinary.W), (scaled.U, scaled.V, scaled.W));
        }
    }

    [Fact]
    public void SavingIntoAMissingFolderNamesTheFolderNotATemporaryFile()
    {
        using var dir = new TempDirectory();
        string path = dir.File("no-such-folder/out.png");

        DirectoryNotFoundException e = Assert.Throws<DirectoryNotFoundException>(() => new Image(2, 2).Save(path));

        Assert.Contains(dir.File("no-such-folder"), e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain(".tmp", e.Message, StringComparison.Ordinal);
        Assert.Empty(dir.Entries());
    }
}
