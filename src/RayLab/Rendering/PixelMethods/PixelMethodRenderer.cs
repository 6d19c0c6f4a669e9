using RayLab.Cameras;

namespace RayLab.Rendering.PixelMethods;

/// <summary>
/// Renders an <see cref="IPixelMethod{TScratch}"/>: rows on the <see cref="RowLoop"/>, left to right in each row,
/// each thread with its own <see cref="PixelTracer"/> and scratch. A pixel's value depends only on the pixel and its
/// row, so the bytes are the same whatever the thread count.
/// </summary>
internal static class PixelMethodRenderer
{
    /// <summary>Renders the scene by <paramref name="method"/>; fills <paramref name="raysPerPixel"/> (if given) with each pixel's traced rays.</summary>
    public static RenderStatistics Render<TScratch>(Scene scene, ImagePlane plane, IPixelMethod<TScratch> method, PixelTarget image,
        RenderOptions options, float[]? raysPerPixel)
    {
        var loop = RowLoop.Start(options, image.Height);
        RowTotals totals = loop.Run(new Rows<TScratch>(scene, plane, method, image, raysPerPixel));
        return loop.Finish(totals.Rays, RenderKernel.Scalar);
    }

    /// <summary>
    /// Pixel (<paramref name="x"/>, <paramref name="y"/>) as a render decides it, with the points the method traced
    /// there: the row's pixels to its left are decided first, so <see cref="PixelTracer.PreviousInRow"/> holds what it
    /// holds in a render.
    /// </summary>
    public static (Intensity Value, List<(double X, double Y, Intensity Value)> Points) TracePixel<TScratch>(Scene scene, ImagePlane plane, IPixelMethod<TScratch> method, int x, int y)
    {
        var tracer = new PixelTracer(scene, plane);
        TScratch scratch = method.CreateScratch();
        var points = new List<(double X, double Y, Intensity Value)>();
        Intensity value = default;
        for (int left = 0; left <= x; left++)
        {
            tracer.Begin(left, y);
            tracer.Recorded = left == x ? points : null;
            value = method.RenderPixel(tracer, ref scratch);
            tracer.Keep(value);
        }

        tracer.Recorded = null;
        return (value, points);
    }

    /// <summary>The method's rows: each pixel handed to the method through the thread's tracer.</summary>
    private sealed class Rows<TScratch>(Scene scene, ImagePlane plane, IPixelMethod<TScratch> method, PixelTarget image, float[]? raysPerPixel)
        : IRowRenderer<ThreadState<TScratch>>
    {
        public ThreadState<TScratch> Rent() => new(new PixelTracer(scene, plane), method.CreateScratch());

        public void RenderRow(int row, ref ThreadState<TScratch> state)
        {
            TargetRow pixels = image.Row(row);
            PixelTracer tracer = state.Tracer;
            for (int x = 0; x < pixels.Length; x++)
            {
                tracer.Begin(x, row);
                Intensity value = method.RenderPixel(tracer, ref state.Scratch);
                tracer.Keep(value);
                pixels.Set(x, value);
                state.Rays += tracer.RaysTraced;
                if (raysPerPixel is not null)
                {
                    raysPerPixel[((long)row * pixels.Length) + x] = tracer.RaysTraced;
                }
            }
        }

        public void Return(ThreadState<TScratch> state, ref RowTotals totals) => totals.Rays += state.Rays;
    }

    /// <summary>What one thread keeps between rows: its tracer, the method's scratch, and the rays it traced.</summary>
    private sealed class ThreadState<TScratch>(PixelTracer tracer, TScratch scratch)
    {
        public PixelTracer Tracer { get; } = tracer;

        public TScratch Scratch = scratch;

        public long Rays { get; set; }
    }
}
