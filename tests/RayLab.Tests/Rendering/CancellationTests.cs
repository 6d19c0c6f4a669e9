using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>
/// Every renderer checks its token before each row: a render cancelled from another thread once its first row is
/// done throws <see cref="OperationCanceledException"/> having finished at most the rows that were in flight when
/// the request returned (one per thread). Counted in rows, never timed.
/// </summary>
public sealed class CancellationTests
{
    private const int Threads = 2;

    // Tall and narrow: many cheap rows, so the render is still far from done when the watcher cancels it (exact
    // rows are the cheapest, so its image is taller).
    private const int Width = 96, Height = 4096, ExactHeight = 4 * Height;

    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0, 12), Target = Double3.Zero, Fov = 50, NearPlane = 0.1, FarPlane = 100 };

    // A grid of spheres across the view, so every row crosses outlines (the adaptive and exact renderers' work).
    private static readonly Scene Spheres = new(
        from i in Enumerable.Range(0, 12)
        from j in Enumerable.Range(0, 12)
        select new Sphere(new Double3((i - 5.5) * 0.9, (j - 5.5) * 0.9, (i + j) % 3 * -0.5), 0.45, new Intensity(0.1 + (0.07 * i), 0.9 - (0.07 * j), 0.5)),
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    public static TheoryData<string> Methods => ["point scalar", "point packets", "adaptive", "exact"];

    [Theory]
    [MemberData(nameof(Methods))]
    public void ACancelledRenderStopsWithinTheRowsInFlight(string method)
    {
        (RenderMethod render, RenderKernel kernel, int height) = method switch
        {
            "point scalar" => (RenderMethod.Sampled(Samplers.Create("random", 64, 1)), RenderKernel.Scalar, Height),
            "point packets" => (RenderMethod.Sampled(Samplers.Create("random", 1024, 1)), RenderKernel.Auto, Height),
            "adaptive" => (RenderMethod.Adaptive(new AdaptiveSampler(3, 3, 0)), RenderKernel.Auto, Height),
            _ => (RenderMethod.Exact, RenderKernel.Auto, ExactHeight),
        };
        var progress = new RenderProgress();
        using var cancel = new CancellationTokenSource();
        var renderer = new Renderer { MaxDegreeOfParallelism = Threads, Kernel = kernel, Progress = progress, CancellationToken = cancel.Token };

        int rowsAtCancel = CancelAfterFirstRow(progress, cancel, () => renderer.Render(Spheres, Camera, render, new Image(Width, height)));

        AssertStoppedEarly(progress, rowsAtCancel, height);
    }

    [Fact]
    public void AnExactRenderIntoLinearValuesIsCancelledToo()
    {
        var progress = new RenderProgress();
        using var cancel = new CancellationTokenSource();
        var renderer = new Renderer { MaxDegreeOfParallelism = Threads, Progress = progress, CancellationToken = cancel.Token };

        int rowsAtCancel = CancelAfterFirstRow(progress, cancel, () => renderer.Render(Spheres, Camera, RenderMethod.Exact, new Intensity[Width * ExactHeight], Width, ExactHeight));

        AssertStoppedEarly(progress, rowsAtCancel, ExactHeight);
    }

    [Fact]
    public void ARenderCancelledBeforeItStartsDrawsNoRow()
    {
        var progress = new RenderProgress();
        var renderer = new Renderer { Progress = progress, CancellationToken = new CancellationToken(canceled: true) };

        Assert.ThrowsAny<OperationCanceledException>(() => renderer.Render(Spheres, Camera, RenderMethod.Exact, new Image(8, 8)));
        Assert.ThrowsAny<OperationCanceledException>(() => renderer.Render(Spheres, Camera, new AdaptiveSampler(), new Image(8, 8)));
        Assert.ThrowsAny<OperationCanceledException>(() => renderer.Render(Spheres, Camera, Samplers.Create("jittered", 4, 1), new Image(8, 8)));
        Assert.Equal(0, progress.RowsCompleted);
    }

    /// <summary>Runs <paramref name="render"/> while a watcher cancels it once a row is done; returns the rows done when <see cref="CancellationTokenSource.Cancel()"/> returned.</summary>
    private static int CancelAfterFirstRow(RenderProgress progress, CancellationTokenSource cancel, Action render)
    {
        int rowsAtCancel = -1;
        bool ended = false;
        var watcher = new Thread(() =>
        {
            SpinWait.SpinUntil(() => progress.RowsCompleted >= 1 || Volatile.Read(ref ended));
            cancel.Cancel();
            rowsAtCancel = progress.RowsCompleted;
        }) { IsBackground = true };
        watcher.Start();
        try
        {
            Assert.ThrowsAny<OperationCanceledException>(render);
        }
        finally
        {
            Volatile.Write(ref ended, true);
            watcher.Join();
        }

        return rowsAtCancel;
    }

    private static void AssertStoppedEarly(RenderProgress progress, int rowsAtCancel, int height)
    {
        TestContext.Current.TestOutputHelper?.WriteLine($"rows done when cancelled: {rowsAtCancel}, when stopped: {progress.RowsCompleted}, of {height}");
        Assert.Equal(height, progress.TotalRows);
        Assert.InRange(rowsAtCancel, 1, height - 1);
        // After the request, only the rows already being drawn (one per thread) may finish.
        Assert.InRange(progress.RowsCompleted, rowsAtCancel, rowsAtCancel + Threads);
        Assert.True(progress.RowsCompleted < height, $"{progress.RowsCompleted} of {height} rows drawn");
    }
}
