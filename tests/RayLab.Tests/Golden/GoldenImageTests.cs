using System.Security.Cryptography;
using RayLab.Sampling;

namespace RayLab.Tests.Golden;

/// <summary>
/// The golden set: every sampler × both cameras (and an off-axis window) × every kernel, the adaptive
/// sampler and the exact reference, on small scenes, each image's SHA-256 pinned in <c>golden.txt</c>.
/// A refactoring must keep every byte; a change that means to change pictures regenerates the file with
/// <c>RAYLAB_UPDATE_GOLDEN=1 dotnet test --filter FullyQualifiedName~GoldenImageTests</c> and says why.
/// </summary>
public class GoldenImageTests
{
    private const int Width = 37;
    private const int Height = 23;

    private static readonly string GoldenFile = Path.Combine(AppContext.BaseDirectory, "Golden", "golden.txt");

    private static Scene TwoSpheres() => new(
        [
            new Sphere(new Double3(-0.9, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)),
            new Sphere(new Double3(1.1, 0.3, -1), 1.2, new Intensity(0.2, 0.8, 0.3)),
            new Sphere(new Double3(0.2, -0.6, 1.5), 0.05, new Intensity(0.3, 0.3, 0.95)),
        ],
        new Intensity(0.1, 0.1, 0.15),
        new Intensity(0.9, 0.95, 1));

    private static readonly (string Name, Camera Camera)[] Cameras =
    [
        ("ortho", new OrthoCamera { Position = new Double3(0, 0.2, 6), Target = Double3.Zero, ViewHeight = 4.5, NearPlane = 0.1, FarPlane = 100 }),
        ("persp", new PerspectiveCamera { Position = new Double3(0.3, 0.5, 6), Target = Double3.Zero, Fov = 45, NearPlane = 0.1, FarPlane = 100 }),
        ("offaxis", new PerspectiveCamera { Position = new Double3(0, 0, 6), Target = new Double3(0, 0.1, 0), Up = new Double3(0.1, 1, 0), Distance = 2, Window = new Window(-1.5, -0.4, 0.9, 1.1), NearPlane = 0.1, FarPlane = 100 }),
        ("ortho-offaxis", new OrthoCamera { Position = new Double3(0, 0, 6), Target = Double3.Zero, Window = new Window(-2.5, -1.2, 1.5, 2.1), NearPlane = 0.1, FarPlane = 100 }),
    ];

    private static readonly RenderKernel[] Kernels = [RenderKernel.Scalar, RenderKernel.Vector128, RenderKernel.Vector256, RenderKernel.Vector512];

    /// <summary>Every case of the set: a name and how to render it into an image.</summary>
    public static IEnumerable<(string Name, Func<Image> Render)> Cases()
    {
        Scene scene = TwoSpheres();
        foreach ((string cameraName, Camera camera) in Cameras)
        {
            foreach (string sampler in Samplers.Names)
            {
                foreach (int samples in Counts(sampler))
                {
                    foreach (RenderKernel kernel in Kernels)
                    {
                        yield return ($"{cameraName} {sampler} {samples} {kernel}", () => Render(scene, camera, Samplers.Create(sampler, samples, 7), kernel));
                    }
                }
            }

            foreach ((string label, AdaptiveSampler adaptive) in new[]
            {
                ("default", new AdaptiveSampler()),
                ("min1-max4-c0.05", new AdaptiveSampler(1, 4, 0.05)),
                ("quincunx", new AdaptiveSampler(0, 3, 0.1, quincunx: true)),
                ("max0", new AdaptiveSampler(0, 0, 0.1)),
            })
            {
                yield return ($"{cameraName} adaptive {label}", () =>
                {
                    var image = new Image(Width, Height);
                    new Renderer { MaxDegreeOfParallelism = 2 }.Render(scene, camera, adaptive, image);
                    return image;
                });
            }

            yield return ($"{cameraName} exact", () =>
            {
                var image = new Image(Width, Height);
                new Renderer { MaxDegreeOfParallelism = 2 }.Render(scene, camera, RenderMethod.Exact, image);
                return image;
            });
        }
    }

    // The grid samplers take squares only; the others also get a count that is neither a square nor a power of two.
    private static int[] Counts(string sampler) => sampler is "regular" or "jittered" or "multijittered" ? [1, 9, 16] : [1, 6, 16];

    private static Image Render(Scene scene, Camera camera, IPixelSampler sampler, RenderKernel kernel)
    {
        var image = new Image(Width, Height);
        new Renderer { MaxDegreeOfParallelism = 2, Kernel = kernel }.Render(scene, camera, sampler, image);
        return image;
    }

    private static string Hash(Image image) => Convert.ToHexStringLower(SHA256.HashData(image.PixelBytes));

    [Fact]
    public void EveryImageKeepsItsBytes()
    {
        var actual = Cases().Select(c => (c.Name, Hash: Hash(c.Render()))).ToList();
        if (Environment.GetEnvironmentVariable("RAYLAB_UPDATE_GOLDEN") == "1")
        {
            string source = Path.Combine(FindSourceDirectory(), "golden.txt");
            File.WriteAllLines(source, actual.Select(a => $"{a.Name}\t{a.Hash}"));
            return;
        }

        Dictionary<string, string> expected = File.ReadAllLines(GoldenFile)
            .Select(line => line.Split('\t'))
            .ToDictionary(parts => parts[0], parts => parts[1]);
        Assert.Equal(expected.Count, actual.Count);
        var changed = actual.Where(a => !expected.TryGetValue(a.Name, out string? hash) || hash != a.Hash).Select(a => a.Name).ToList();
        Assert.True(changed.Count == 0, $"{changed.Count} of {actual.Count} golden images changed: {string.Join("; ", changed.Take(20))}");
    }

    [Fact]
    public void TheSetCoversEveryKernelSamplerAndCamera()
    {
        // The set distinguishes what it pins: pictures of different samplers and cameras differ.
        var cases = Cases().ToList();
        Assert.Equal(Cameras.Length * ((Samplers.Names.Count * 3 * Kernels.Length) + 5), cases.Count);
        string a = Hash(cases.First(c => c.Name == "persp jittered 16 Vector512").Render());
        string b = Hash(cases.First(c => c.Name == "ortho jittered 16 Vector512").Render());
        string c = Hash(cases.First(c => c.Name == "persp sobol 16 Vector512").Render());
        Assert.Equal(3, new[] { a, b, c }.Distinct().Count());
    }

    private static string FindSourceDirectory([System.Runtime.CompilerServices.CallerFilePath] string path = "") =>
        Path.GetDirectoryName(path)!;
}
