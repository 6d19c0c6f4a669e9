using RayLab.Sampling;

namespace RayLab.Tests.Rendering.PixelMethods;

public class PixelMethodTests
{
    private static readonly Scene TwoSpheres = new(
        [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(1.2, 0.2, -1), 1.2, new Intensity(0.2, 0.8, 0.3))],
        new Intensity(0.1, 0.1, 0.15),
        Intensity.White);

    private static readonly PerspectiveCamera Camera = new() { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1, FarPlane = 100 };

    /// <summary>Traces the centre only: the same picture as one regular sample.</summary>
    private sealed class CentreMethod : IPixelMethod<int>
    {
        public string Name => "centre";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch) => pixel.Trace(0.5, 0.5);
    }

    /// <summary>
    /// Traces 1 to 3 points depending on the column, and a fourth where the left neighbour differs from the first
    /// point: its rays vary per pixel and it reads a neighbour, as an adaptive method does.
    /// </summary>
    private sealed class UnevenMethod : IPixelMethod<Intensity[]>
    {
        public string Name => "uneven";

        public Intensity[] CreateScratch() => new Intensity[4];

        public Intensity RenderPixel(PixelTracer pixel, ref Intensity[] scratch)
        {
            int n = 1 + (pixel.X % 3);
            Intensity sum = default;
            for (int i = 0; i < n; i++)
            {
                scratch[i] = pixel.Trace((i + 0.5) / n, (i + 0.5) / n);
                sum += scratch[i];
            }

            if (pixel.PreviousInRow.Length > 0 && pixel.PreviousInRow[^1] != scratch[0])
            {
                sum += pixel.Trace(1, 0);
                n++;
            }

            return sum / n;
        }
    }

    private static (byte[] Bytes, RenderStatistics Stats, float[] Rays) Render<T>(IPixelMethod<T> method, int threads, int w = 48, int h = 36)
    {
        var image = new Image(w, h);
        var rays = new float[w * h];
        RenderStatistics stats = new Renderer { MaxDegreeOfParallelism = threads }.Render(TwoSpheres, Camera, RenderMethod.Custom(method), image, rays);
        return (image.PixelBytes.ToArray(), stats, rays);
    }

    [Fact]
    public void ACentreMethodGivesTheBytesOfOneRegularSample()
    {
        var image = new Image(48, 36);
        new Renderer { Kernel = RenderKernel.Scalar }.Render(TwoSpheres, Camera, new RegularSampler(1), image);
        (byte[] bytes, RenderStatistics stats, float[] rays) = Render(new CentreMethod(), 2);
        Assert.Equal(image.PixelBytes.ToArray(), bytes);
        Assert.Equal(48 * 36, stats.PrimaryRays);
        Assert.All(rays, r => Assert.Equal(1, r));
    }

    [Fact]
    public void BytesAndRaysAreIdenticalForOneAndTwoThreads()
    {
        var one = Render(new UnevenMethod(), 1);
        var two = Render(new UnevenMethod(), 2);
        Assert.Equal(one.Bytes, two.Bytes);
        Assert.Equal(one.Rays, two.Rays);
        Assert.Equal(one.Stats.PrimaryRays, two.Stats.PrimaryRays);
    }

    [Fact]
    public void PrimaryRaysAreTheSumOfTheRaysPerPixel()
    {
        (_, RenderStatistics stats, float[] rays) = Render(new UnevenMethod(), 2);
        Assert.Equal((long)rays.Sum(), stats.PrimaryRays);
        // Columns trace 1, 2, 3 points, plus one where the left neighbour differs: the edges cost a ray more.
        Assert.Contains(rays, r => r == 4);
        Assert.Equal(1, rays[0]);
        Assert.True(stats.PrimaryRays > 2 * 48 * 36);
    }

    [Fact]
    public void ProgressCountsEveryRow()
    {
        var progress = new RenderProgress();
        new Renderer { MaxDegreeOfParallelism = 2, Progress = progress }.Render(TwoSpheres, Camera, RenderMethod.Custom(new CentreMethod()), new Image(10, 7));
        Assert.Equal((7, 7), (progress.RowsCompleted, progress.TotalRows));
    }

    [Fact]
    public void ACancelledTokenStopsTheRender()
    {
        using var cancel = new CancellationTokenSource();
        cancel.Cancel();
        var renderer = new Renderer { CancellationToken = cancel.Token };
        Assert.ThrowsAny<OperationCanceledException>(() => renderer.Render(TwoSpheres, Camera, RenderMethod.Custom(new CentreMethod()), new Image(10, 7)));
    }

    private sealed class OutsideMethod(double sx, double sy) : IPixelMethod<int>
    {
        public string Name => "outside";

        public int CreateScratch() => 0;

        public Intensity RenderPixel(PixelTracer pixel, ref int scratch) => pixel.Trace(sx, sy);
    }

    [Theory]
    [InlineData(-0.01, 0.5, "sx")]
    [InlineData(0.5, 1.01, "sy")]
    [InlineData(double.NaN, 0.5, "sx")]
    public void APointOutsideThePixelIsRejectedNamingTheOffset(double sx, double sy, string name)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => new Renderer { MaxDegreeOfParallelism = 1 }
            .Render(TwoSpheres, Camera, RenderMethod.Custom(new OutsideMethod(sx, sy)), new Image(4, 3)));
        Assert.Equal(name, e.ParamName);
    }

    [Fact]
    public void TheMethodIsNamedAndNullIsRejected()
    {
        Assert.Equal("uneven", RenderMethod.Custom(new UnevenMethod()).Name);
        Assert.Equal(0, RenderMethod.Custom(new UnevenMethod()).SamplesPerPixel);
        Assert.Throws<ArgumentNullException>(() => RenderMethod.Custom<int>(null!));
    }

    [Fact]
    public void ATracedPixelHasTheRendersRaysAndValueAndTheMethodsOwnPoints()
    {
        (byte[] bytes, _, float[] rays) = Render(new UnevenMethod(), 1);
        int row = 18, edges = 0;
        for (int x = 0; x < 48; x++)
        {
            PixelTrace trace = Renderer.TracePixel(TwoSpheres, Camera, 48, 36, RenderMethod.Custom(new UnevenMethod()), x, row);
            Assert.Equal((x, row), (trace.X, trace.Y));
            Assert.Equal(rays[(row * 48) + x], trace.Points.Count);
            int at = ((row * 48) + x) * 3;
            Assert.Equal(new Rgb24(bytes[at], bytes[at + 1], bytes[at + 2]), Rgb24.FromIntensity(trace.Value));
            int n = 1 + (x % 3);
            Assert.Equal(Enumerable.Range(0, n).Select(i => ((i + 0.5) / n, (i + 0.5) / n)), trace.Points.Take(n).Select(p => (p.X, p.Y)));
            // The fourth point comes from the left neighbour's value: the trace ran the row up to this pixel.
            if (trace.Points.Count > n)
            {
                edges++;
                Assert.Equal((1.0, 0.0), (trace.Points[n].X, trace.Points[n].Y));
            }
        }

        Assert.True(edges > 0, "the row crosses an edge");
    }

    [Theory]
    [InlineData(-1, 0, "x")]
    [InlineData(48, 0, "x")]
    [InlineData(0, 36, "y")]
    public void APixelOutsideTheImageIsRejectedNamingIt(int px, int py, string name)
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => Renderer.TracePixel(TwoSpheres, Camera, 48, 36, RenderMethod.Custom(new CentreMethod()), px, py));
        Assert.Equal(name, e.ParamName);
    }
}
