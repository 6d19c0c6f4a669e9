using System.Diagnostics;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Imaging;
using RayLab.Rendering.Packets;
using RayLab.Sampling;

namespace RayLab.Rendering;

/// <summary>
/// Renders a scene through a camera into an image: a <see cref="Parallel.For(int, int, Action{int})"/> over
/// rows (the lab's render loop), each row written straight into the image's row span. Each pixel is the mean
/// of its samples; every sample is independent of the thread that takes it, so the bytes are the same
/// whatever <see cref="MaxDegreeOfParallelism"/> is.
/// </summary>
public sealed class Renderer
{
    private readonly int _threads = -1;

    /// <summary>The most threads to use; −1 (the default) means as many as the runtime likes.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is 0 or less than −1.</exception>
    public int MaxDegreeOfParallelism
    {
        get => _threads;
        init => _threads = ThreadCount.Check(value);
    }

    /// <summary>
    /// Which loop renders point-sampled images. <see cref="RenderKernel.Auto"/> (the default) takes the widest
    /// SIMD packet the hardware runs natively; a packet width asked for explicitly runs even where the hardware
    /// lacks it (emulated, slowly), which is how tests compare the widths on any machine. Every packet width gives
    /// the same bytes; the scalar double path agrees with them except for samples within float resolution of a
    /// silhouette (see the README's performance section). Adaptive renders always use the scalar path.
    /// </summary>
    public RenderKernel Kernel { get; init; } = RenderKernel.Auto;

    /// <summary>
    /// Optional: counts finished rows while a render runs, for a progress bar polled from another thread.
    /// </summary>
    public RenderProgress? Progress { get; init; }

    /// <summary>Renders <paramref name="scene"/> into <paramref name="image"/>, sized by the image.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="sampler">Where the samples go in each pixel.</param>
    /// <param name="image">The image to fill; its size sets the camera's window.</param>
    /// <returns>Rays traced and render time.</returns>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view (see <see cref="Camera.GetImagePlane"/>).</exception>
    public RenderStatistics Render(Scene scene, Camera camera, IPixelSampler sampler, Image image)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(sampler);
        ArgumentNullException.ThrowIfNull(image);
        ImagePlane plane = camera.GetImagePlane(image.Width, image.Height);
        var options = new ParallelOptions { MaxDegreeOfParallelism = MaxDegreeOfParallelism };
        long rays = (long)image.Width * image.Height * sampler.SamplesPerPixel;
        RenderKernel kernel = ChooseKernel(scene, plane, out PacketFrame? frame, out string? reason);
        Progress?.Start(image.Height);
        var clock = Stopwatch.StartNew();
        long retraced = kernel switch
        {
            RenderKernel.Vector512 => RenderPackets<Lanes512>(frame!, sampler, image, options),
            RenderKernel.Vector256 => RenderPackets<Lanes256>(frame!, sampler, image, options),
            RenderKernel.Vector128 => RenderPackets<Lanes128>(frame!, sampler, image, options),
            _ => RenderScalar(scene, plane, sampler, image, options),
        };
        clock.Stop();
        return new RenderStatistics(rays, clock.Elapsed) { Kernel = kernel, RetracedSamples = retraced, ScalarReason = reason };
    }

    private RenderKernel ChooseKernel(Scene scene, ImagePlane plane, out PacketFrame? frame, out string? reason)
    {
        frame = null;
        reason = null;
        if (Kernel == RenderKernel.Scalar)
        {
            return RenderKernel.Scalar;
        }

        if (!PacketFrame.TryCreate(scene, plane, out frame, out reason))
        {
            return RenderKernel.Scalar;
        }

        return Kernel switch
        {
            RenderKernel.Auto when Lanes512.IsHardwareAccelerated => RenderKernel.Vector512,
            RenderKernel.Auto when Lanes256.IsHardwareAccelerated => RenderKernel.Vector256,
            RenderKernel.Auto when Lanes128.IsHardwareAccelerated => RenderKernel.Vector128,
            RenderKernel.Auto => RenderKernel.Scalar,
            _ => Kernel,
        };
    }

    private long RenderScalar(Scene scene, ImagePlane plane, IPixelSampler sampler, Image image, ParallelOptions options)
    {
        Parallel.For(0, image.Height, options, row =>
        {
            Span<Rgb24> pixels = image.GetRowSpan(row);
            for (int x = 0; x < pixels.Length; x++)
            {
                pixels[x] = Rgb24.FromIntensity(RenderPixel(scene, plane, sampler, x, row));
            }

            Progress?.CompleteRow();
        });
        return 0;
    }

    private long RenderPackets<TL>(PacketFrame frame, IPixelSampler sampler, Image image, ParallelOptions options)
        where TL : struct, ILanes<TL> => sampler switch
        {
            JitteredSampler jittered => RenderPackets<TL, JitteredLanes<TL>>(frame, () => new(jittered), sampler.SamplesPerPixel, image, options),
            RandomSampler random => RenderPackets<TL, RandomLanes<TL>>(frame, () => new(random), sampler.SamplesPerPixel, image, options),
            RegularSampler regular => RenderPackets<TL, RegularLanes<TL>>(frame, () => new(regular), sampler.SamplesPerPixel, image, options),
            _ => RenderPackets<TL, BufferedLanes<TL>>(frame, () => new(sampler), sampler.SamplesPerPixel, image, options),
        };

    private long RenderPackets<TL, TS>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, Image image, ParallelOptions options)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL> => frame.IsOrthographic
            ? RenderPackets<TL, TS, OrthographicRays>(frame, newSampler, samplesPerPixel, image, options)
            : RenderPackets<TL, TS, PerspectiveRays>(frame, newSampler, samplesPerPixel, image, options);

    private long RenderPackets<TL, TS, TP>(PacketFrame frame, Func<TS> newSampler, int samplesPerPixel, Image image, ParallelOptions options)
        where TL : struct, ILanes<TL>
        where TS : struct, ILaneSampler<TL>
        where TP : struct, IProjection
    {
        long retraced = 0;
        // Each thread gets its own lane sampler (the buffered one owns arrays); rows are independent.
        Parallel.For(0, image.Height, options, newSampler, (row, _, sampler) =>
        {
            int count = PacketKernel.RenderRow<TL, TS, TP>(frame, ref sampler, samplesPerPixel, row, image.GetRowSpan(row));
            if (count != 0)
            {
                Interlocked.Add(ref retraced, count);
            }

            Progress?.CompleteRow();
            return sampler;
        }, _ => { });
        return retraced;
    }

    /// <summary>
    /// Renders with the lab's adaptive antialiasing (<see cref="AdaptiveSampler"/>): pixel corners are traced
    /// once for the whole image, then each pixel is subdivided where its values disagree.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="sampler">The adaptive settings.</param>
    /// <param name="image">The image to fill.</param>
    /// <param name="raysPerPixel">
    /// Optional, W·H long, row 0 first: receives the rays charged to each pixel — its centre and the points
    /// inside it, with each pixel corner counted ¼ and each point on a pixel edge ½ (they are shared).
    /// </param>
    /// <returns>Rays traced (each point once) and render time.</returns>
    /// <exception cref="ArgumentException"><paramref name="raysPerPixel"/> has the wrong length, or the camera is invalid.</exception>
    public RenderStatistics Render(Scene scene, Camera camera, AdaptiveSampler sampler, Image image, float[]? raysPerPixel = null)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(sampler);
        ArgumentNullException.ThrowIfNull(image);
        if (raysPerPixel is not null && raysPerPixel.LongLength != (long)image.Width * image.Height)
        {
            throw new ArgumentException($"Expected {image.Width}×{image.Height} entries, got {raysPerPixel.Length}.", nameof(raysPerPixel));
        }

        ImagePlane plane = camera.GetImagePlane(image.Width, image.Height);
        var options = new ParallelOptions { MaxDegreeOfParallelism = MaxDegreeOfParallelism };
        Progress?.Start(image.Height);
        var clock = Stopwatch.StartNew();
        var lattice = new AdaptiveLattice(scene, plane, sampler.MaxDepth, options);
        long interiorRays = 0;
        Parallel.For(0, image.Height, options, () => new AdaptiveLattice.Source(lattice), (row, _, source) =>
        {
            Span<Rgb24> pixels = image.GetRowSpan(row);
            bool flatWithoutCentre = !sampler.Quincunx && sampler.MinDepth == 0;
            for (int x = 0; x < pixels.Length; x++)
            {
                // Most pixels: four corners on the same sphere (or the background), nothing more to trace.
                if (flatWithoutCentre && lattice.TryFlat(x, row, out Intensity flat))
                {
                    pixels[x] = Rgb24.FromIntensity(flat);
                    if (raysPerPixel is not null)
                    {
                        raysPerPixel[((long)row * pixels.Length) + x] = 1;
                    }

                    continue;
                }

                source.NextPixel();
                Intensity value = AdaptivePixel.Evaluate(sampler, ref source, x, row, out double samples);
                pixels[x] = Rgb24.FromIntensity(value);
                if (raysPerPixel is not null)
                {
                    raysPerPixel[((long)row * pixels.Length) + x] = (float)samples;
                }
            }

            Progress?.CompleteRow();
            return source;
        }, source => Interlocked.Add(ref interiorRays, source.Rays));
        clock.Stop();
        return new RenderStatistics(lattice.SharedRays + interiorRays, clock.Elapsed) { Kernel = RenderKernel.Scalar };
    }

    /// <summary>The mean of a pixel's samples, in linear intensity (before the 8-bit rule).</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <param name="sampler">The sampler.</param>
    /// <param name="x">The pixel column.</param>
    /// <param name="row">The pixel row, 0 at the top.</param>
    public static Intensity RenderPixel(Scene scene, ImagePlane plane, IPixelSampler sampler, int x, int row)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(plane);
        ArgumentNullException.ThrowIfNull(sampler);
        int n = sampler.SamplesPerPixel;
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++)
        {
            SamplePoint s = sampler.GetSample(x, row, i);
            Ray ray = plane.GetPixelRay(x, row, s.X, s.Y);
            Intensity value = scene.Trace(ray, plane.TMin, plane.TMax);
            r += value.R;
            g += value.G;
            b += value.B;
        }

        return new Intensity(r / n, g / n, b / n);
    }
}
