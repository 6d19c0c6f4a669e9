using RayLab.Rendering.Adaptive;
using RayLab.Sampling;

namespace RayLab.Tests.Rendering.Adaptive;

/// <summary>
/// Adaptive, plain and guarded, on 1, 3 and 16 threads, with rows whole, cut by the renderer's own rule and cut into
/// more pieces than a row has packets: the same bytes, rays, points traced again and rays per pixel as one thread
/// rendering whole rows. Each piece carries its own part of the two corner lines down to the same piece of the next
/// row; a piece whose row above another thread rendered traces its top line itself. On a small machine most of 16
/// threads start late and find their ranges stolen, so pieces begin both ways.
/// </summary>
public class AdaptiveThreadPieceTests
{
    private static readonly PerspectiveCamera Perspective = new() { Position = new Double3(0, 1.6, 4), Target = new Double3(0, 0, -4), Fov = 55, NearPlane = 0.1, FarPlane = 1000 };

    private static readonly OrthoCamera Ortho = new() { Position = new Double3(0, 6, 6), Target = new Double3(0, 0, -4), Window = new Window(-4.5, -3, 4.5, 3) };

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, -1), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -2), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15), Intensity.White);

    /// <summary>96 small spheres receding to the horizon, through the hierarchy (the renderer's rule cuts its rows on 8 threads or more).</summary>
    private static Scene Field() => new(
        [.. Enumerable.Range(0, 96).Select(k => new Sphere(new Double3((k % 8) - 3.5, 0, -(k / 8)), 0.35, k % 2 == 0 ? new Intensity(0.95, 0.95, 0.9) : new Intensity(0.15, 0.3, 0.8)))],
        new Intensity(0.05, 0.05, 0.08), Intensity.White);

    public static TheoryData<string, string, bool, int, int> Cases()
    {
        var cases = new TheoryData<string, string, bool, int, int>();
        foreach (string scene in new[] { "two spheres", "field" })
        {
            foreach (string camera in new[] { "perspective", "ortho" })
            {
                foreach (bool guard in new[] { false, true })
                {
                    // Rows long enough to cut, a one-pixel-wide image and a one-row image.
                    foreach ((int w, int h) in new[] { (112, 36), (1, 40), (112, 1) })
                    {
                        cases.Add(scene, camera, guard, w, h);
                    }
                }
            }
        }

        return cases;
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public void OneThreeAndSixteenThreadsInEveryCutGiveTheBytesRaysAndRaysPerPixelOfOneThreadInWholeRows(string view, string projection, bool guard, int w, int h)
    {
        Scene scene = view == "field" ? Field() : TwoSpheres();
        Camera camera = projection == "ortho" ? Ortho : Perspective;
        var sampler = new AdaptiveSampler(0, 3, 0.02, guard: guard);
        Assert.Equal(view == "field", scene.UsesHierarchy);
        var one = Render(scene, camera, sampler, w, h, threads: 1, pieces: 1);
        if (w > 1 && h > 1)
        {
            Assert.True(one.Bytes.Distinct().Count() > 4, "a picture of one colour checks nothing");
            Assert.Contains(one.Heat, rays => rays > 1);
        }

        // 0: the renderer's own cut (on 16 threads the field's rows in pieces); 5 and 16: every row cut, 16 pieces
        // narrower than a packet of corners.
        foreach (int pieces in new[] { 0, 5, 16 })
        {
            foreach (int threads in new[] { 1, 3, 16 })
            {
                var cut = Render(scene, camera, sampler, w, h, threads, pieces);
                string at = $"{threads} threads, {(pieces == 0 ? "the renderer's cut" : $"{pieces} pieces")}";
                Assert.True(one.Bytes.AsSpan().SequenceEqual(cut.Bytes), $"{at}: other bytes");
                Assert.True((one.Rays, one.Retraced) == (cut.Rays, cut.Retraced), $"{at}: rays, retraced {(cut.Rays, cut.Retraced)} against {(one.Rays, one.Retraced)}");
                Assert.True(one.Heat.AsSpan().SequenceEqual(cut.Heat), $"{at}: other rays per pixel");
            }
        }
    }

    [Fact]
    public void TheFieldsRowsAreCutOnSixteenThreadsAndNotOnThree()
    {
        Assert.True(Field().UsesHierarchy);
        Assert.Equal(7, AdaptiveRenderer.Pieces(112, 16, costlyRows: true));
        Assert.Equal(1, AdaptiveRenderer.Pieces(112, 3, costlyRows: true));
        Assert.Equal(1, AdaptiveRenderer.Pieces(112, 16, costlyRows: false));
    }

    private static (byte[] Bytes, long Rays, long Retraced, float[] Heat) Render(Scene scene, Camera camera, AdaptiveSampler sampler, int w, int h, int threads, int pieces)
    {
        var image = new Image(w, h);
        var heat = new float[w * h];
        RenderStatistics stats = new Renderer { MaxDegreeOfParallelism = threads, RowPieces = pieces }.Render(scene, camera, sampler, image, heat);
        return (image.PixelBytes.ToArray(), stats.PrimaryRays, stats.RetracedSamples, heat);
    }
}
