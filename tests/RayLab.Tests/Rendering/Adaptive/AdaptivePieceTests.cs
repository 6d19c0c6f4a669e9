using RayLab.Rendering;
using RayLab.Rendering.Adaptive;
using RayLab.Sampling;

namespace RayLab.Tests.Rendering.Adaptive;

/// <summary>
/// The adaptive renderer cuts each row into pieces, left to right, the row loop's units of work. How the rows are cut
/// may change which thread traces what, never the bytes, the rays, the points traced again in double or the heat map.
/// </summary>
public class AdaptivePieceTests
{
    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    // A sphere of radius 4 pixels centred on a pixel corner, seen straight on: its silhouette passes through lattice
    // points, whose float answers are uncertain and are traced again in double.
    private static readonly OrthoCamera OnTheLattice = new() { Position = new Double3(0, 0, 10), Target = Double3.Zero, Window = new Window(-3, -2, 3, 2) };

    private static Scene TwoSpheres() => new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15), Intensity.White);

    private static Scene LatticeSpheres() => new(
        [new Sphere(new Double3(1, 1, 0), 0.5, Intensity.White), new Sphere(new Double3(-1.25, 0.5, -1), 0.75, new Intensity(0.3, 0.6, 0.9))],
        Intensity.Black, Intensity.White);

    private static readonly PerspectiveCamera FieldCamera = new() { Position = new Double3(0, 1.6, 4), Target = new Double3(0, 0, -6), Fov = 50, NearPlane = 0.1, FarPlane = 1000 };

    /// <summary>96 small spheres receding to the horizon, traced through the hierarchy: a packet's lanes decide together which spheres it tests.</summary>
    private static Scene Field() => new(
        [.. Enumerable.Range(0, 96).Select(k => new Sphere(new Double3((k % 8) - 3.5, 0, -(k / 8)), 0.35, k % 2 == 0 ? new Intensity(0.95, 0.95, 0.9) : new Intensity(0.15, 0.3, 0.8)))],
        new Intensity(0.05, 0.05, 0.08), Intensity.White);

    private static readonly AdaptiveSampler[] Samplers =
    [
        new(0, 3, 0.02),
        new(0, 3, 0.02, guard: true),
        new(1, 3, 0.05),
        new(2, 2, 0.1),
        new(0, 2, 0.02, quincunx: true),
    ];

    public static TheoryData<int, string> Cases => new()
    {
        { 0, "two spheres" }, { 1, "two spheres" }, { 2, "two spheres" }, { 3, "two spheres" }, { 4, "two spheres" },
        { 0, "on the lattice" }, { 1, "on the lattice" }, { 2, "on the lattice" }, { 4, "on the lattice" },
        { 0, "field" }, { 1, "field" }, { 2, "field" }, { 4, "field" },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void EveryCutOfTheRowsGivesTheBytesRaysRetracedPointsAndHeatMapOfWholeRows(int sampler, string view)
    {
        const int W = 48, H = 32;
        (Scene scene, Camera camera) = view switch
        {
            "on the lattice" => (LatticeSpheres(), (Camera)OnTheLattice),
            "field" => (Field(), FieldCamera),
            _ => (TwoSpheres(), Camera),
        };
        (byte[] bytes, RenderStatistics whole, float[] heat) = Render(scene, camera, Samplers[sampler], W, H, pieces: 1, threads: 1);
        if (view != "two spheres")
        {
            Assert.True(whole.RetracedSamples > 0, $"{view}: no point was traced again in double, so the count is not checked");
        }

        foreach (int pieces in new[] { 2, 3, 4, 5, 7, W })
        {
            foreach (int threads in new[] { 1, 3 })
            {
                (byte[] cutBytes, RenderStatistics cut, float[] cutHeat) = Render(scene, camera, Samplers[sampler], W, H, pieces, threads);
                Assert.Equal(bytes, cutBytes);
                Assert.Equal((whole.PrimaryRays, whole.RetracedSamples), (cut.PrimaryRays, cut.RetracedSamples));
                Assert.Equal(heat, cutHeat);
            }
        }
    }

    [Theory]
    [InlineData(1)]
    [InlineData(3)]
    public void PointsOnTheLineBetweenTwoPiecesAreTracedOnce(int threads)
    {
        // MinDepth 1 = MaxDepth 1 splits every pixel once: per pixel 4 quadrant centres; per pixel edge one midpoint,
        // shared by the two pixels beside it, whichever piece each is in.
        var scene = new Scene([], Intensity.Black, Intensity.White);
        const int W = 64, H = 9;
        RenderStatistics stats = new Renderer { MaxDegreeOfParallelism = threads, RowPieces = 4 }.Render(scene, Camera, new AdaptiveSampler(1, 1, 0.1), new Image(W, H));
        long corners = (W + 1L) * (H + 1), centres = (long)W * H, quadrantCentres = 4L * W * H;
        long edgeMidpoints = ((long)W * (H + 1)) + ((W + 1L) * H);
        Assert.Equal(corners + centres + quadrantCentres + edgeMidpoints, stats.PrimaryRays);
    }

    [Theory]
    [InlineData(1920, 1, true, 0, 1)]
    [InlineData(1920, 2, true, 0, 1)]
    [InlineData(1920, 7, true, 0, 1)]
    [InlineData(1920, 8, true, 0, 4)]
    [InlineData(1920, 16, true, 0, 8)]
    [InlineData(1920, 64, true, 0, 8)]
    [InlineData(1920, 16, false, 0, 1)]
    [InlineData(48, 16, true, 0, 3)]
    [InlineData(31, 16, true, 0, 1)]
    [InlineData(1920, 1, false, 4, 4)]
    [InlineData(13, 2, true, 7, 7)]
    [InlineData(5, 1, false, 9, 5)]
    public void CostlyRowsAreCutOnManyThreadsIntoPiecesNoNarrowerThanAPacket(int width, int threads, bool costlyRows, int requested, int pieces) =>
        Assert.Equal(pieces, AdaptiveRenderer.Pieces(width, threads, costlyRows, requested));

    [Fact]
    public void TheLoopRendersEveryPieceOfEveryRowOnceAndCountsRowsWorthOfPieces()
    {
        const int W = 64, H = 20;
        var progress = new RenderProgress();
        var trace = new RowLoopTrace();
        var renderer = new Renderer { MaxDegreeOfParallelism = 3, Progress = progress, Trace = trace, RowPieces = 4 };
        renderer.Render(TwoSpheres(), Camera, new AdaptiveSampler(), new Image(W, H));
        Assert.Equal(H * 4, trace.BandTicks.Length);
        Assert.All(trace.BandWorker, worker => Assert.InRange(worker, 0, 2));
        Assert.All(trace.BandTicks, ticks => Assert.True(ticks > 0, "a band the loop never rendered"));
        Assert.Equal((H, H, 1.0), (progress.RowsCompleted, progress.TotalRows, progress.Fraction));
    }

    [Fact]
    public void ARendererKeepingItsNotesAcrossRendersCountsEachRendersRaysAsAFreshOne()
    {
        // Where a piece's row above was another thread's, the two pieces' notes of the points both traced meet in a
        // slot the renderer keeps for its next render: every render, of whatever height and cut, counts only its own.
        var kept = new Renderer { MaxDegreeOfParallelism = 3 };
        AdaptiveSampler sampler = Samplers[1];
        foreach ((int pieces, int h) in new[] { (4, 32), (4, 32), (2, 20), (7, 32), (1, 24), (4, 32) })
        {
            kept.RowPieces = pieces;
            var image = new Image(48, h);
            var heat = new float[48 * h];
            RenderStatistics stats = kept.Render(Field(), FieldCamera, sampler, image, heat);
            (byte[] bytes, RenderStatistics fresh, float[] freshHeat) = Render(Field(), FieldCamera, sampler, 48, h, pieces, threads: 3);
            Assert.Equal(bytes, image.PixelBytes.ToArray());
            Assert.Equal((fresh.PrimaryRays, fresh.RetracedSamples), (stats.PrimaryRays, stats.RetracedSamples));
            Assert.Equal(freshHeat, heat);
        }
    }

    private static (byte[] Bytes, RenderStatistics Stats, float[] Heat) Render(Scene scene, Camera camera, AdaptiveSampler sampler, int w, int h, int pieces, int threads)
    {
        var image = new Image(w, h);
        var heat = new float[w * h];
        RenderStatistics stats = new Renderer { MaxDegreeOfParallelism = threads, RowPieces = pieces }.Render(scene, camera, sampler, image, heat);
        return (image.PixelBytes.ToArray(), stats, heat);
    }
}
