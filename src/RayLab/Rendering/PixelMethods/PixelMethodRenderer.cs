using RayLab.Sampling;
using System.Diagnostics;
using System.Runtime.ExceptionServices;
using RayLab.Cameras;

namespace RayLab.Rendering.PixelMethods;

/// <summary>
/// Renders an <see cref="IPixelMethod{TScratch}"/>: a <see cref="Parallel.For(int, int, ParallelOptions, Action{int})"/>
/// over rows, left to right in each row, each thread with its own <see cref="PixelTracer"/> and scratch. A pixel's
/// value depends only on the pixel and its row, so the bytes are the same whatever the thread count.
/// </summary>
internal static class PixelMethodRenderer
{
    /// <summary>Renders the scene by <paramref name="method"/>; fills <paramref name="raysPerPixel"/> (if given) with each pixel's traced rays.</summary>
    public static RenderStatistics Render<TScratch>(Scene scene, ImagePlane plane, IPixelMethod<TScratch> method, Image image,
        RenderOptions options, float[]? raysPerPixel)
    {
        long rays = 0;
        (int first, int end) = options.Rows(image.Height);
        options.Progress?.Start(end - first);
        var clock = Stopwatch.StartNew();
        try
        {
            RenderRows(scene, plane, method, image, options, raysPerPixel, ref rays);
        }
        catch (AggregateException e) when (e.InnerExceptions.Count == 1)
        {
            // The method's own exception (a point outside the pixel, say), not Parallel.For's wrapper around it.
            ExceptionDispatchInfo.Capture(e.InnerExceptions[0]).Throw();
        }

        clock.Stop();
        return new RenderStatistics(rays, clock.Elapsed) { Kernel = RenderKernel.Scalar };
    }

    private static void RenderRows<TScratch>(Scene scene, ImagePlane plane, IPixelMethod<TScratch> method, Image image,
        RenderOptions options, float[]? raysPerPixel, ref long rays)
    {
        long total = 0;
        (int first, int end) = options.Rows(image.Height);
        Parallel.For(first, end, options.Parallel,
            () => new ThreadState<TScratch>(new PixelTracer(scene, plane), method.CreateScratch()),
            (row, _, state) =>
            {
                Span<Rgb24> pixels = image.GetRowSpan(row);
                PixelTracer tracer = state.Tracer;
                for (int x = 0; x < pixels.Length; x++)
                {
                    tracer.Begin(x, row);
                    Intensity value = method.RenderPixel(tracer, ref state.Scratch);
                    tracer.Keep(value);
                    pixels[x] = Rgb24.FromIntensity(value);
                    state.Rays += tracer.RaysTraced;
                    if (raysPerPixel is not null)
                    {
                        raysPerPixel[((long)row * pixels.Length) + x] = tracer.RaysTraced;
                    }
                }

                options.Progress?.CompleteRow();
                return state;
            },
            state => Interlocked.Add(ref total, state.Rays));
        rays = total;
    }

    /// <summary>What one thread keeps between rows: its tracer, the method's scratch, and the rays it traced.</summary>
    private sealed class ThreadState<TScratch>(PixelTracer tracer, TScratch scratch)
    {
        public PixelTracer Tracer { get; } = tracer;

        public TScratch Scratch = scratch;

        public long Rays { get; set; }
    }
}
