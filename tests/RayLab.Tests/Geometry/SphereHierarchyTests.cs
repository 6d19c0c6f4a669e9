using RayLab.Geometry;
using RayLab.Rendering.Exact;
using RayLab.Sampling;

namespace RayLab.Tests.Geometry;

/// <summary>
/// The bounding volume hierarchy changes only the time, never a byte: every renderer gives the same picture
/// with <see cref="SceneAcceleration.None"/> and <see cref="SceneAcceleration.Hierarchy"/> on scenes of 1 to 2000
/// spheres (both cameras, an off-axis window, spheres crossing the near plane, nested and touching spheres), and
/// the scalar query returns what testing every sphere in index order returns, ties included.
/// </summary>
public class SphereHierarchyTests
{
    private static readonly PerspectiveCamera Perspective = new() { Position = new Double3(0, 1, 6), Target = new Double3(0, 0, -4), Fov = 55, NearPlane = 1, FarPlane = 60 };

    private static readonly PerspectiveCamera OffAxis = Perspective with { Window = new Window(-0.2, -0.25, 0.6, 0.3), Distance = 1 };

    private static readonly OrthoCamera Orthographic = new() { Position = new Double3(0.3, 1, 6), Target = new Double3(0.1, 0, -4), ViewHeight = 9, NearPlane = 1, FarPlane = 60 };

    /// <summary>
    /// Random spheres in front of the camera, plus (from 4 spheres on) a sphere nested in another, two touching
    /// spheres, a pair that intersect, a duplicate (the same t: the higher index must win) and, when asked, a
    /// sphere the near plane cuts.
    /// </summary>
    private static Sphere[] Spheres(int count, int seed, bool crossNear)
    {
        var random = new Random(seed);
        var spheres = new List<Sphere>();
        Intensity Colour() => new(random.NextDouble(), random.NextDouble(), random.NextDouble());
        if (count >= 4)
        {
            spheres.Add(new Sphere(new Double3(-1, 0, -3), 1.2, Colour()));
            spheres.Add(new Sphere(new Double3(-1, 0, -3), 0.6, Colour()));        // nested
            spheres.Add(new Sphere(new Double3(1.5, 0, -3), 0.8, Colour()));
            spheres.Add(new Sphere(new Double3(3.1, 0, -3), 0.8, Colour()));        // touching the one before
        }

        if (count >= 8)
        {
            spheres.Add(new Sphere(new Double3(0, 2, -6), 1, Colour()));
            spheres.Add(new Sphere(new Double3(0.8, 2.3, -6.2), 0.9, Colour()));    // intersecting
            spheres.Add(new Sphere(new Double3(0, 2, -6), 1, Colour()));            // a duplicate
        }

        if (crossNear && spheres.Count < count)
        {
            spheres.Add(new Sphere(new Double3(0.4, 0.7, 4.6), 0.6, Colour()));    // the near plane (depth 1) cuts it
        }

        double radius = 0.15 + (2.0 / Math.Cbrt(count));
        while (spheres.Count < count)
        {
            var centre = new Double3((random.NextDouble() * 14) - 7, (random.NextDouble() * 8) - 4, -2 - (random.NextDouble() * 20));
            spheres.Add(new Sphere(centre, radius * (0.3 + random.NextDouble()), Colour()));
        }

        return [.. spheres];
    }

    private static Scene SceneOf(Sphere[] spheres, SceneAcceleration acceleration) =>
        new(spheres, new Intensity(0.1, 0.1, 0.15), Intensity.White) { Acceleration = acceleration };

    private static byte[] Render(Scene scene, Camera camera, RenderMethod method, RenderKernel kernel, int threads = 2)
    {
        var image = new Image(53, 37);
        new Renderer { Kernel = kernel, MaxDegreeOfParallelism = threads }.Render(scene, camera, method, image);
        return image.PixelBytes.ToArray();
    }

    public static TheoryData<int, string, bool> Cases() => CasesOf(1, 2, 9, 60, 400);

    /// <summary>2 000 spheres: the deepest trees, and the flat reference renders every sphere for every ray (minutes on 2 cores).</summary>
    public static TheoryData<int, string, bool> ManyCases() => CasesOf(2000);

    private static TheoryData<int, string, bool> CasesOf(params int[] counts)
    {
        var data = new TheoryData<int, string, bool>();
        foreach (int count in counts)
        {
            foreach (string camera in new[] { "perspective", "off-axis", "orthographic" })
            {
                data.Add(count, camera, false);
                data.Add(count, camera, true);
            }
        }

        return data;
    }

    private static Camera CameraOf(string name) => name switch
    {
        "perspective" => Perspective,
        "off-axis" => OffAxis,
        _ => Orthographic,
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void EveryRendererGivesTheSameBytesWithAndWithoutTheHierarchy(int count, string cameraName, bool crossNear) =>
        AssertSameBytesWithAndWithoutTheHierarchy(count, cameraName, crossNear);

    [Theory]
    [Trait("Category", "Slow")]
    [MemberData(nameof(ManyCases))]
    public void EveryRendererGivesTheSameBytesWithAndWithoutTheHierarchyOfManySpheres(int count, string cameraName, bool crossNear) =>
        AssertSameBytesWithAndWithoutTheHierarchy(count, cameraName, crossNear);

    private static void AssertSameBytesWithAndWithoutTheHierarchy(int count, string cameraName, bool crossNear)
    {
        Camera camera = CameraOf(cameraName);
        Sphere[] spheres = Spheres(count, seed: count + cameraName.Length, crossNear);
        Scene without = SceneOf(spheres, SceneAcceleration.None), with = SceneOf(spheres, SceneAcceleration.Hierarchy);
        Assert.False(without.UsesHierarchy);
        Assert.True(with.UsesHierarchy);

        var methods = new List<(string Name, RenderMethod Method, RenderKernel Kernel)>
        {
            ("jittered 4, packets", RenderMethod.Sampled(new JitteredSampler(4, seed: 3)), RenderKernel.Auto),
            ("regular 1, packets 128", RenderMethod.Sampled(new RegularSampler(1)), RenderKernel.Vector128),
            ("jittered 9, scalar", RenderMethod.Sampled(new JitteredSampler(9, seed: 5)), RenderKernel.Scalar),
            ("adaptive", RenderMethod.Adaptive(new AdaptiveSampler(maxDepth: 2)), RenderKernel.Auto),
        };
        if (count <= 400)
        {
            methods.Add(("exact", RenderMethod.Exact, RenderKernel.Auto));
        }

        // Every point sampler through the packet kernel: the permutation samplers and Sobol' make their points in
        // blocks (ILaneSampler.Prepare), which the hierarchy's sample loop must ask for as the flat one does; 100
        // samples span two blocks.
        foreach (string name in Samplers.Names)
        {
            methods.Add(($"{name} 16, packets", RenderMethod.Sampled(Samplers.Create(name, 16, 7)), RenderKernel.Auto));
        }

        methods.Add(("cmj 100, packets", RenderMethod.Sampled(Samplers.Create("cmj", 100, 7)), RenderKernel.Auto));

        foreach ((string name, RenderMethod method, RenderKernel kernel) in methods)
        {
            byte[] expected = Render(without, camera, method, kernel);
            byte[] actual = Render(with, camera, method, kernel);
            Assert.True(expected.AsSpan().SequenceEqual(actual), $"{name}: {count} spheres, {cameraName}, crossing the near plane: {crossNear}");
        }
    }

    [Fact]
    public void ThePacketPathTraversesTheHierarchyAndGivesTheSameBytesForEveryThreadCount()
    {
        Scene scene = SceneOf(Spheres(500, 11, crossNear: false), SceneAcceleration.Auto);
        byte[] one = Render(scene, Perspective, RenderMethod.Sampled(new JitteredSampler(4, seed: 1)), RenderKernel.Vector256, threads: 1);
        byte[] many = Render(scene, Perspective, RenderMethod.Sampled(new JitteredSampler(4, seed: 1)), RenderKernel.Vector256, threads: -1);
        Assert.Equal(one, many);
        Assert.True(scene.UsesHierarchy);
    }

    /// <summary>
    /// A dense cluster of overlapping spheres (hits a hair apart along many rays, the case the per-lane depth
    /// tolerance decides): the packet kernel and the adaptive lattice through the hierarchy give the double
    /// path's bytes, and they did retrace samples (the float path ran and found close hits).
    /// </summary>
    [Theory]
    [InlineData("perspective")]
    [InlineData("orthographic")]
    public void OverlappingSpheresThroughTheHierarchyGiveTheDoublePathsBytes(string cameraName)
    {
        var random = new Random(17);
        var spheres = new Sphere[600];
        for (int i = 0; i < spheres.Length; i++)
        {
            var centre = new Double3((random.NextDouble() * 6) - 3, (random.NextDouble() * 4) - 2, -6 - (random.NextDouble() * 4));
            spheres[i] = new Sphere(centre, 0.3 + (0.4 * random.NextDouble()), new Intensity(random.NextDouble(), random.NextDouble(), random.NextDouble()));
        }

        // Pairs a float rounding apart or a little more: their hits' order along a ray is what float may get wrong.
        double[] shifts = [1e-7, 1e-6, 3e-6, 1e-5, 3e-5, 1e-4];
        for (int k = 0; k < 40; k++)
        {
            var direction = new Double3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            Double3 shift = shifts[k % shifts.Length] / direction.Length * direction;
            spheres[(2 * k) + 1] = new Sphere(spheres[2 * k].Center + shift, spheres[2 * k].Radius, new Intensity(random.NextDouble(), random.NextDouble(), random.NextDouble()));
        }

        Camera camera = CameraOf(cameraName);
        Scene scene = SceneOf(spheres, SceneAcceleration.Hierarchy);
        foreach (RenderMethod method in new[] { RenderMethod.Sampled(new JitteredSampler(16, seed: 2)), RenderMethod.Adaptive(new AdaptiveSampler(maxDepth: 2)) })
        {
            byte[] reference = Render(scene, camera, method, RenderKernel.Scalar);
            var image = new Image(53, 37);
            RenderStatistics stats = new Renderer { Kernel = RenderKernel.Auto }.Render(scene, camera, method, image);
            Assert.True(reference.AsSpan().SequenceEqual(image.PixelBytes), $"{method}: {cameraName}");
            Assert.NotEqual(RenderKernel.Scalar, stats.Kernel);
            Assert.InRange(stats.RetracedSamples, 1, stats.PrimaryRays / 4);
        }
    }

    [Fact]
    public void NearestIsTheLoopsAnswerForRandomRaysIncludingTiesAndRaysAlongAnAxis()
    {
        // Two identical spheres away from the rest: hit at the same t, the loop keeps the later one.
        var twin = new Sphere(new Double3(50, 50, 50), 1, Intensity.White);
        Sphere[] spheres = [.. Spheres(700, 5, crossNear: true), twin, twin];
        SphereHierarchy hierarchy = SphereHierarchy.Build(spheres)!;
        var random = new Random(9);
        int hits = 0;
        for (int k = 0; k < 20_000; k++)
        {
            var origin = new Double3((random.NextDouble() * 20) - 10, (random.NextDouble() * 10) - 5, 5 - (random.NextDouble() * 30));
            var direction = new Double3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            if (k % 4 == 0)
            {
                direction = new Double3(0, 0, -1); // components exactly 0
            }

            var ray = new Ray(origin, direction);
            int expected = SphereHierarchy.NearestOfAll(spheres, ray, 0.01, 100);
            Assert.Equal(expected, hierarchy.Nearest(spheres, ray, 0.01, 100));
            hits += expected >= 0 ? 1 : 0;
        }

        Assert.InRange(hits, 2_000, 19_000);

        var straight = new Ray(new Double3(50, 50, 55), new Double3(0, 0, -1));
        Assert.Equal(spheres.Length - 1, SphereHierarchy.NearestOfAll(spheres, straight, 0.01, 100));
        Assert.Equal(spheres.Length - 1, hierarchy.Nearest(spheres, straight, 0.01, 100));
    }

    [Fact]
    public void EverySphereThatCanBeHitIsInExactlyOneLeafAndEveryBoxHoldsItsChildren()
    {
        Sphere[] spheres = [.. Spheres(1000, 2, crossNear: false), new Sphere(Double3.Zero, 0, Intensity.White)];
        SphereHierarchy hierarchy = SphereHierarchy.Build(spheres)!;
        int[] order = hierarchy.Order.ToArray();
        Assert.Equal(Enumerable.Range(0, 1000), order.Order());
        ReadOnlySpan<HierarchyNode> nodes = hierarchy.Nodes;
        for (int i = 0; i < nodes.Length; i++)
        {
            HierarchyNode node = nodes[i];
            if (node.Count > 0)
            {
                Assert.InRange(node.Count, 1, SphereHierarchy.LeafSize * 2);
                for (int k = node.Start; k < node.Start + node.Count; k++)
                {
                    Sphere s = spheres[order[k]];
                    Assert.True(Inside(s.Center - new Double3(s.Radius, s.Radius, s.Radius), node) && Inside(s.Center + new Double3(s.Radius, s.Radius, s.Radius), node));
                }
            }
            else
            {
                Assert.True(Inside(nodes[i + 1].Lo, node) && Inside(nodes[i + 1].Hi, node));
                Assert.True(Inside(nodes[node.Start].Lo, node) && Inside(nodes[node.Start].Hi, node));
            }
        }

        Assert.InRange(hierarchy.Depth, 8, 40);
    }

    [Fact]
    public void ScenesWithoutASphereThatCanBeHitHaveNoHierarchy()
    {
        Assert.Null(SphereHierarchy.Build([]));
        Assert.Null(SphereHierarchy.Build([new Sphere(Double3.Zero, 0, Intensity.White)]));
        var scene = new Scene(Enumerable.Repeat(new Sphere(Double3.Zero, 0, Intensity.White), 20), Intensity.Black, Intensity.White);
        Assert.Equal(-1, scene.Nearest(new Ray(new Double3(0, 0, 5), new Double3(0, 0, -1)), 0, 100));
    }

    [Fact]
    public void AutoUsesTheHierarchyFromTheMeasuredThresholdOn()
    {
        Sphere[] spheres = Spheres(Scene.HierarchyThreshold, 1, crossNear: false);
        Assert.False(SceneOf(spheres[..^1], SceneAcceleration.Auto).UsesHierarchy);
        Assert.True(SceneOf(spheres, SceneAcceleration.Auto).UsesHierarchy);
        Assert.Null(SceneOf(spheres, SceneAcceleration.None).Hierarchy);
    }

    [Fact]
    [Trait("Category", "Slow")]
    public void AMillionSpheresRender()
    {
        var random = new Random(1);
        var spheres = new Sphere[1_000_000];
        for (int i = 0; i < spheres.Length; i++)
        {
            spheres[i] = new Sphere(new Double3((random.NextDouble() * 200) - 100, (random.NextDouble() * 200) - 100, -10 - (random.NextDouble() * 200)), 0.3, Intensity.White);
        }

        Scene scene = SceneOf(spheres, SceneAcceleration.Auto);
        var image = new Image(32, 24);
        RenderStatistics stats = new Renderer().Render(scene, Perspective with { FarPlane = 1000 }, new JitteredSampler(4, seed: 1), image);
        Assert.Equal(32L * 24 * 4, stats.PrimaryRays);
        Assert.Contains(image.PixelBytes.ToArray(), b => b > 200); // some white sphere is hit
    }

    [Fact]
    public void TheExactRendererRefusesMoreSpheresInViewThanItsLimitWithAOneLineMessageNamingIt()
    {
        var random = new Random(2);
        var spheres = new Sphere[OutlineSet.MaxSpheresInView + 1];
        for (int i = 0; i < spheres.Length; i++)
        {
            spheres[i] = new Sphere(new Double3((random.NextDouble() * 8) - 4, (random.NextDouble() * 4) - 2, -5 - (random.NextDouble() * 20)), 0.01, Intensity.White);
        }

        Scene scene = SceneOf(spheres, SceneAcceleration.Auto);
        var e = Assert.Throws<UnsupportedSceneException>(() => new Renderer().Render(scene, Perspective, RenderMethod.Exact, new Image(16, 12)));
        Assert.Equal(spheres.Length - 1, e.SphereIndex);
        Assert.Contains("at most 20000", e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
    }

    private static bool Inside(Double3 p, HierarchyNode node) =>
        p.X >= node.Lo.X && p.Y >= node.Lo.Y && p.Z >= node.Lo.Z && p.X <= node.Hi.X && p.Y <= node.Hi.Y && p.Z <= node.Hi.Z;
}
