using RayLab.Rendering;
using RayLab.Cameras;
using RayLab.Rendering.Adaptive;
using RayLab.Rendering.Exact;
using RayLab.Rendering.PixelMethods;
using RayLab.Rendering.Point;
using RayLab.Sampling;

namespace RayLab;

/// <summary>
/// How a pixel's value is found — the one choice between RayLab's renderers, made here and nowhere else:
/// point sampling (<see cref="Sampled"/>: the lab's regular, random and jittered sampling and the rest, section 4),
/// the lab's adaptive antialiasing (<see cref="Adaptive(AdaptiveSampler)"/>, section 4.1.4), a method of your own
/// (<see cref="Custom{TScratch}(IPixelMethod{TScratch})"/>), or the exact area-weighted reference (<see cref="Exact"/>). <see cref="Renderer.Render(Scene, Camera, RenderMethod, Image, float[])"/>
/// renders any of them; the scene-file layer and the console build one from the sampler settings.
/// </summary>
public abstract class RenderMethod
{
    private protected RenderMethod()
    {
    }

    /// <summary>The exact reference (<see cref="ExactRenderer"/>).</summary>
    public static RenderMethod Exact { get; } = new ExactMethod();

    /// <summary>The sampler's name (<c>jittered</c>, <c>adaptive</c>, <c>exact</c>, …).</summary>
    public abstract string Name { get; }

    /// <summary>Samples per pixel for a point sampler; 0 for the adaptive, custom and exact methods, whose cost is not fixed.</summary>
    public virtual int SamplesPerPixel => 0;

    /// <summary>Point sampling: the mean of <paramref name="sampler"/>'s samples in each pixel.</summary>
    /// <param name="sampler">The sampler.</param>
    /// <returns>The method.</returns>
    public static RenderMethod Sampled(IPixelSampler sampler) => new SampledMethod(sampler ?? throw new ArgumentNullException(nameof(sampler)));

    /// <summary>The lab's adaptive antialiasing with these settings.</summary>
    /// <param name="sampler">The adaptive settings.</param>
    /// <returns>The method.</returns>
    public static RenderMethod Adaptive(AdaptiveSampler sampler) => new AdaptiveMethod(sampler ?? throw new ArgumentNullException(nameof(sampler)));

    /// <summary>
    /// A method of your own: <paramref name="method"/> decides each pixel's value by tracing points of its choosing
    /// inside it (<see cref="PixelTracer.Trace"/>); every traced point counts as one primary ray.
    /// </summary>
    /// <typeparam name="TScratch">The method's per-thread working space.</typeparam>
    /// <param name="method">The pixel method.</param>
    /// <returns>The method.</returns>
    public static RenderMethod Custom<TScratch>(IPixelMethod<TScratch> method) =>
        new CustomMethod<TScratch>(method ?? throw new ArgumentNullException(nameof(method)));

    /// <summary>Renders into <paramref name="image"/>; fills <paramref name="raysPerPixel"/> (if given) with the rays charged to each pixel.</summary>
    internal abstract RenderStatistics Render(Scene scene, ImagePlane plane, IPixelRows image, RenderOptions options, float[]? raysPerPixel);

    /// <summary>The entries of <paramref name="raysPerPixel"/> for the rows this render fills (empty when it is null).</summary>
    private static Span<float> RowsOf(float[]? raysPerPixel, IPixelRows image, RenderOptions options)
    {
        (int first, int end) = options.Rows(image.Height);
        return raysPerPixel is null ? default : raysPerPixel.AsSpan(first * image.Width, (end - first) * image.Width);
    }

    private sealed class SampledMethod(IPixelSampler sampler) : RenderMethod
    {
        public override string Name => sampler.Name;

        public override int SamplesPerPixel => sampler.SamplesPerPixel;

        public override string ToString() => $"{sampler.Name} {sampler.SamplesPerPixel} spp";

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, IPixelRows image, RenderOptions options, float[]? raysPerPixel)
        {
            RenderStatistics stats = PointRenderer.Render(scene, plane, sampler, image, options);
            RowsOf(raysPerPixel, image, options).Fill(sampler.SamplesPerPixel);
            return stats;
        }
    }

    private sealed class AdaptiveMethod(AdaptiveSampler sampler) : RenderMethod
    {
        public override string Name => sampler.Name;

        public override string ToString() => sampler.ToString();

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, IPixelRows image, RenderOptions options, float[]? raysPerPixel) =>
            AdaptiveRenderer.Render(scene, plane, sampler, image, options, raysPerPixel);
    }

    private sealed class CustomMethod<TScratch>(IPixelMethod<TScratch> method) : RenderMethod
    {
        public override string Name => method.Name;

        public override string ToString() => method.Name;

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, IPixelRows image, RenderOptions options, float[]? raysPerPixel) =>
            PixelMethodRenderer.Render(scene, plane, method, image, options, raysPerPixel);
    }

    private sealed class ExactMethod : RenderMethod
    {
        public override string Name => "exact";

        public override string ToString() => "exact (area-weighted)";

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, IPixelRows image, RenderOptions options, float[]? raysPerPixel)
        {
            RenderStatistics stats = ExactRenderer.RenderPlane(scene, plane, image, options);
            RowsOf(raysPerPixel, image, options).Clear();
            return stats;
        }
    }
}
