using System.Diagnostics;
using RayLab.Cameras;
using RayLab.Rendering.Point.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Rendering.Point;

/// <summary>
/// The point-sampling renderer (lab section 4): a <see cref="Parallel.For(int, int, ParallelOptions, Action{int})"/>
/// over rows (the lab's render loop), each pixel the mean of its samples, each row written straight into the
/// image's row span. The SIMD packet kernel (<see cref="PacketKernel"/>) renders where the hardware and the
/// frame allow it, the scalar double loop (<see cref="RenderPixel(Scene, ImagePlane, IPixelSampler, int, int)"/>) everywhere else; each loop is
/// compiled for the camera's projection (<see cref="IProjection"/>), chosen once per render. Every sample is
/// independent of the thread that takes it, so the bytes are the same whatever the thread count.
/// </summary>
internal static class PointRenderer
{
    /// <summary>Renders the scene with <paramref name="sampler"/> into <paramref name="image"/>.</summary>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, IPixelSampler sampler, Image image, RenderOptions options)
    {
        long rays = (long)image.Width * image.Height * sampler.SamplesPerPixel;
        RenderKernel kernel = KernelChoice.Choose(options.Kernel, scene, plane, out PacketFrame? frame, out string? reason);
        options.Progress?.Start(image.Height);
        var clock = Stopwatch.StartNew();
        long retraced = kernel switch
        {
            RenderKernel.Vector512 => RenderPackets<Lanes512>(plane, frame!, sampler, image, options),
            RenderKernel.Vector256 => RenderPackets<Lanes256>(plane, frame!, sampler, image, options),
            RenderKernel.Vector128 => RenderPackets<Lanes128>(plane, frame!, sampler, image, options),
            _ => RenderScalar(scene, plane, sampler, image, options),
        };
        clock.Stop();
        return new RenderStatistics(rays, clock.Elapsed) { Kernel = kernel, RetracedSamples = retraced, ScalarReason = reason };
    }

    private static long RenderScalar(Scene scene, ImagePlane plane, IPixelSampler sampler, Image image, RenderOptions options)
    {
        var rows = new ScalarRows(scene, sampler, image, options);
        return plane.Dispatch<ScalarRows, long>(ref rows);
    }

    private static long RenderScalar<TP>(Scene scene, ImagePlane plane, IPixelSampler sampler, Image image, RenderOptions options)
        where TP : struct, IProjection
    {
        Parallel.For(0, image.Height, options.Parallel, row =>
        {
            Span<Rgb24> pixels = image.GetRowSpan(row);
            for (int x = 0; x < pixels.Length; x++)
            {
                pixels[x] = Rgb24.FromIntensity(RenderPixel<TP>(scene, plane, sampler, x, row));
            }

            options.Progress?.CompleteRow();
        });
        return 0;
    }

    private static long RenderPackets<TL>(ImagePlane plane, PacketFrame frame, IPixelSampler sampler, Image image, RenderOptions options)
        where TL : struct, ILanes<TL> => sampler switch
        {
            JitteredSampler jittered => RenderPackets<TL, JitteredLanes<TL>>(plane, frame, () => new(jittered), sampler.SamplesPerPixel, image, options),
            RandomSampler random => RenderPackets<TL, RandomLanes<TL>>(plane, frame, () => new(random), sampler.SamplesPerPixel, image, options),
            RegularSampler regular => RenderPackets<TL, RegularLanes<TL>>(plane, frame, () => new(regular), sampler.SamplesPerPixel, image, options),
            SobolSampler sobol => RenderPackets<TL, SobolLanes<TL>>(plane, frame, () => new(sobol), sampler.SamplesPerPixel, image, options),
            HammersleySampler hammersley => RenderPackets<TL, HammersleyLanes<TL>>(plane, frame, () => new(hammersley), sampler.SamplesPerPixel, image, options),
            CorrelatedMultiJitteredSampler cmj when cmj.SamplesPerPixel <= PatternLimits.MaxSamples =>
                RenderPackets<TL, CorrelatedMultiJitteredLanes<TL>>(plane, frame, () => new(cmj), sampler.SamplesPerPixel, image, options),
            MultiJitteredSampler multiJittered when multiJittered.SamplesPerPixel <= PatternLimits.MaxSamples =>
                RenderPackets<TL, MultiJitteredLanes<TL>>(plane, frame, () => new(multiJittered), sampler.SamplesPerPixel, image, options),
            NRooksSampler nrooks when nrooks.SamplesPerPixel <= PatternLimits.MaxSamples =>
                RenderPackets<TL, NRooksLanes<TL>>(plane, frame, () => new(nrooks), sampler.SamplesPerPixel, image, options),
            _ => RenderPackets<TL, BufferedLanes<TL>>(plane, frame, () => new(sampler), sampler.SamplesPerPixel, image, options),
        };

    private static long RenderPackets<TL, TS>(ImagePlane plane, PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, Image image, RenderOptions options)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
    {
        var rows = new PacketRows<TL, TS>(frame, newSampler, samplesPerPixel, image, options);
        return plane.Dispatch<PacketRows<TL, TS>, long>(ref rows);
    }

    private static long RenderPackets<TL, TS, TP>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, Image image, RenderOptions options)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, IProjection
    {
        long retraced = 0;
        // Each thread gets its own lane sampler (the buffered one owns arrays); rows are independent.
        Parallel.For(0, image.Height, options.Parallel, newSampler, (row, _, sampler) =>
        {
            int count = PacketKernel.RenderRow<TL, TS, TP>(frame, ref sampler, samplesPerPixel, row, image.GetRowSpan(row));
            if (count != 0)
            {
                Interlocked.Add(ref retraced, count);
            }

            options.Progress?.CompleteRow();
            return sampler;
        }, _ => { });
        return retraced;
    }

    /// <summary>The mean of a pixel's samples, in linear intensity (before the 8-bit rule): the scalar double loop.</summary>
    public static Intensity RenderPixel(Scene scene, ImagePlane plane, IPixelSampler sampler, int x, int row)
    {
        var pixel = new PixelMean(scene, sampler, x, row);
        return plane.Dispatch<PixelMean, Intensity>(ref pixel);
    }

    /// <summary>The scalar double loop for one pixel, compiled for the plane's projection <typeparamref name="TP"/>.</summary>
    private static Intensity RenderPixel<TP>(Scene scene, ImagePlane plane, IPixelSampler sampler, int x, int row)
        where TP : struct, IProjection
    {
        int n = sampler.SamplesPerPixel;
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++)
        {
            SamplePoint s = sampler.GetSample(x, row, i);
            Ray ray = TP.GetRay(plane, plane.Alpha(x, s.X), plane.Beta(row, s.Y));
            Intensity value = scene.Trace(ray, plane.TMin, plane.TMax);
            r += value.R;
            g += value.G;
            b += value.B;
        }

        return new Intensity(r / n, g / n, b / n);
    }

    /// <summary>The scalar loop over the image's rows, compiled for the plane's projection.</summary>
    private readonly struct ScalarRows(Scene scene, IPixelSampler sampler, Image image, RenderOptions options) : IProjectionAction<long>
    {
        public long Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => RenderScalar<TP>(scene, plane, sampler, image, options);
    }

    /// <summary>The packet loop over the image's rows, compiled for the plane's projection.</summary>
    private readonly struct PacketRows<TL, TS>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, Image image, RenderOptions options) : IProjectionAction<long>
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
    {
        public long Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => RenderPackets<TL, TS, TP>(frame, newSampler, samplesPerPixel, image, options);
    }

    /// <summary>One pixel's mean by the scalar loop, compiled for the plane's projection.</summary>
    private readonly struct PixelMean(Scene scene, IPixelSampler sampler, int x, int row) : IProjectionAction<Intensity>
    {
        public Intensity Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => RenderPixel<TP>(scene, plane, sampler, x, row);
    }
}
