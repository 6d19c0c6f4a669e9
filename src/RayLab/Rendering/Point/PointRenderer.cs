using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Rendering.Point.Packets;
using RayLab.Sampling;
using RayLab.Simd;

namespace RayLab.Rendering.Point;

/// <summary>
/// The point-sampling renderer (lab section 4): rows on the <see cref="RowLoop"/> (the lab's render loop), each
/// pixel the mean of its samples, each row written straight into the image's row span. The SIMD packet kernel (<see cref="PacketKernel"/>) renders where the hardware and the
/// frame allow it, the scalar double loop (<see cref="RenderPixel(Scene, ImagePlane, IPixelSampler, int, int)"/>) everywhere else; each loop is
/// compiled for the camera's projection (<see cref="IProjection"/>), chosen once per render. Every sample is
/// independent of the thread that takes it, so the bytes are the same whatever the thread count.
/// </summary>
internal static class PointRenderer
{
    /// <summary>Renders the scene with <paramref name="sampler"/> into <paramref name="image"/>.</summary>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image, RenderOptions options)
    {
        (int first, int end) = options.Rows(image.Height);
        long rays = (long)image.Width * (end - first) * sampler.SamplesPerPixel;
        RenderKernel kernel = KernelChoice.Choose(options.Kernel, scene, plane, out PacketFrame? frame, out string? reason);
        var loop = RowLoop.Start(options, image.Height);
        long retraced = kernel switch
        {
            RenderKernel.Vector512 => RenderPackets<Lanes512>(plane, frame!, sampler, image, loop),
            RenderKernel.Vector256 => RenderPackets<Lanes256>(plane, frame!, sampler, image, loop),
            RenderKernel.Vector128 => RenderPackets<Lanes128>(plane, frame!, sampler, image, loop),
            _ => RenderScalar(scene, plane, sampler, image, loop),
        };
        return loop.Finish(rays, kernel, retraced, reason);
    }

    private static long RenderScalar(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image, RowLoop loop)
    {
        var rows = new ScalarLoop(scene, sampler, image, loop);
        return plane.Dispatch<ScalarLoop, long>(ref rows);
    }

    private static long RenderScalar<TP>(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image, RowLoop loop)
        where TP : struct, IProjection
    {
        loop.Run(new ScalarRows<TP>(scene, plane, sampler, image));
        return 0;
    }

    /// <summary>
    /// The packet kernel with the sampler's own lane form (<see cref="ILaneSampled"/>), or, for a sampler without one,
    /// the buffered lanes that ask it for each pixel's points.
    /// </summary>
    private static long RenderPackets<TL>(ImagePlane plane, PacketFrame frame, IPixelSampler sampler, PixelTarget image, RowLoop loop)
        where TL : struct, ILanes<TL>
    {
        var packets = new PacketStart<TL>(plane, frame, sampler.SamplesPerPixel, image, loop);
        return sampler is ILaneSampled sampled
            ? sampled.WithLanes<TL, PacketStart<TL>, long>(ref packets)
            : packets.Run(() => new BufferedLanes<TL>(sampler));
    }

    private static long RenderPackets<TL, TS>(ImagePlane plane, PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, PixelTarget image, RowLoop loop)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
    {
        var rows = new PacketLoop<TL, TS>(frame, newSampler, samplesPerPixel, image, loop);
        return plane.Dispatch<PacketLoop<TL, TS>, long>(ref rows);
    }

    private static long RenderPackets<TL, TS, TP>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, PixelTarget image, RowLoop loop)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, IProjection => loop.Run(new PacketRows<TL, TS, TP>(frame, newSampler, samplesPerPixel, image)).Retraced;

    /// <summary>The scalar double loop's rows: each pixel the mean of its samples.</summary>
    private sealed class ScalarRows<TP>(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image) : IRowRenderer<NoScratch>
        where TP : struct, IProjection
    {
        public NoScratch Rent() => default;

        public void RenderRow(int row, ref NoScratch scratch)
        {
            TargetRow pixels = image.Row(row);
            for (int x = 0; x < pixels.Length; x++)
            {
                pixels.Set(x, RenderPixel<TP>(scene, plane, sampler, x, row));
            }
        }
    }

    /// <summary>The packet kernel's rows; each thread has its own lane sampler (the buffered one owns arrays).</summary>
    private sealed class PacketRows<TL, TS, TP>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, PixelTarget image) : IRowRenderer<PacketRows<TL, TS, TP>.Scratch>
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, IProjection
    {
        public Scratch Rent() => new() { Sampler = newSampler() };

        public void RenderRow(int row, ref Scratch scratch) =>
            scratch.Retraced += PacketKernel.RenderRow<TL, TS, TP>(frame, ref scratch.Sampler, samplesPerPixel, row, image.Row(row));

        public void Return(Scratch scratch, ref RowTotals totals) => totals.Retraced += scratch.Retraced;

        /// <summary>A thread's lane sampler and the samples it traced again in double.</summary>
        public sealed class Scratch
        {
            public TS Sampler;

            public long Retraced;
        }
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
            Ray ray = TP.GetRay(in plane.Basis, plane.Alpha(x, s.X), plane.Beta(row, s.Y));
            Intensity value = plane.Trace(scene, ray);
            r += value.R;
            g += value.G;
            b += value.B;
        }

        return new Intensity(r / n, g / n, b / n);
    }

    /// <summary>The scalar loop over the image's rows, compiled for the plane's projection.</summary>
    private readonly struct ScalarLoop(Scene scene, IPixelSampler sampler, PixelTarget image, RowLoop loop) : IProjectionAction<long>
    {
        public long Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => RenderScalar<TP>(scene, plane, sampler, image, loop);
    }

    /// <summary>The packet loop, started with the lane sampler the sampler hands it.</summary>
    private readonly struct PacketStart<TL>(ImagePlane plane, PacketFrame frame, int samplesPerPixel, PixelTarget image, RowLoop loop) : ILaneSamplerUser<TL, long>
        where TL : struct, ILanes<TL>
    {
        public long Run<TS>(Func<TS> create)
            where TS : struct, ILaneSampler<TL> => RenderPackets<TL, TS>(plane, frame, create, samplesPerPixel, image, loop);
    }

    /// <summary>The packet loop over the image's rows, compiled for the plane's projection.</summary>
    private readonly struct PacketLoop<TL, TS>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, PixelTarget image, RowLoop loop) : IProjectionAction<long>
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
    {
        public long Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => RenderPackets<TL, TS, TP>(frame, newSampler, samplesPerPixel, image, loop);
    }

    /// <summary>One pixel's mean by the scalar loop, compiled for the plane's projection.</summary>
    private readonly struct PixelMean(Scene scene, IPixelSampler sampler, int x, int row) : IProjectionAction<Intensity>
    {
        public Intensity Run<TP>(ImagePlane<TP> plane)
            where TP : struct, IProjection => RenderPixel<TP>(scene, plane, sampler, x, row);
    }
}
