using RayLab.Rendering;
using RayLab.Cameras;
using RayLab.Rendering.Adaptive;
using RayLab.Rendering.Exact;
using RayLab.Rendering.Inspection;
using RayLab.Rendering.PixelMethods;
using RayLab.Rendering.Point;
using RayLab.Sampling;

namespace RayLab;

/// <summary>
/// How a pixel's value is found — the one choice between RayLab's renderers, made here and nowhere else:
/// point sampling (<see cref="Sampled"/>: the lab's regular, random and jittered sampling and the rest, section 4),
/// the lab's adaptive antialiasing (<see cref="Adaptive(AdaptiveSampler)"/>, section 4.1.4), a method of your own
/// (<see cref="Custom{TScratch}(IPixelMethod{TScratch})"/>), or the exact area-weighted reference (<see cref="Exact"/>). <see cref="Renderer.Render(Scene, Camera, RenderMethod, Image, float[])"/>
/// renders any of them, into 8-bit rows or linear intensities, and <see cref="Renderer.TracePixel"/> traces one pixel of any of them; the scene-file layer and the console build one from the sampler settings.
/// </summary>
public abstract class RenderMethod
{
    private protected RenderMethod()
    {
    }

    /// <summary>
    /// The exact reference: each pixel the exact area-weighted mean of the scene over its square, with no sampling
    /// error (<c>docs/exact.md</c>). It draws spheres the perspective camera sees wholly in front of the eye; a render
    /// of any other throws an <see cref="UnsupportedSceneException"/> naming the sphere (<see cref="Check(Scene, Camera, int, int)"/> says so
    /// beforehand).
    /// </summary>
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

    /// <summary>
    /// Throws what a render by this method would throw for <paramref name="scene"/> seen through
    /// <paramref name="camera"/> at <paramref name="width"/>×<paramref name="height"/>, without rendering: an
    /// <see cref="UnsupportedSceneException"/> naming a sphere that reaches too far from the camera for double (some
    /// 5e152 on an axis, where the ray–sphere test's squares overflow), and for <see cref="Exact"/> one it cannot outline.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">The image width W.</param>
    /// <param name="height">The image height H.</param>
    /// <exception cref="UnsupportedSceneException">The method cannot render this scene: a sphere out of double's reach, or (<see cref="Exact"/>) one it cannot outline.</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view at this size.</exception>
    public void Check(Scene scene, Camera camera, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        Check(scene, camera.GetImagePlane(width, height));
    }

    /// <summary>
    /// Throws what a render through <paramref name="plane"/> would throw for the scene: a sphere out of double's reach
    /// from the camera (<see cref="DoubleReach"/>), and for the exact method a sphere it cannot outline.
    /// </summary>
    internal virtual void Check(Scene scene, ImagePlane plane) => DoubleReach.Check(scene, plane);

    /// <summary>Renders into <paramref name="image"/> (8-bit or linear); fills <paramref name="raysPerPixel"/> (if given) with the rays charged to each pixel.</summary>
    internal abstract RenderStatistics Render(Scene scene, ImagePlane plane, PixelTarget image, RenderOptions options, float[]? raysPerPixel);

    /// <summary>Pixel (<paramref name="x"/>, <paramref name="y"/>) traced as a render would trace it, with the points it used.</summary>
    internal abstract PixelTrace TracePixel(Scene scene, ImagePlane plane, int x, int y);

    /// <summary>The entries of <paramref name="raysPerPixel"/> for the rows this render fills (empty when it is null).</summary>
    private static Span<float> RowsOf(float[]? raysPerPixel, PixelTarget image, RenderOptions options)
    {
        (int first, int end) = options.Rows(image.Height);
        return raysPerPixel is null ? default : raysPerPixel.AsSpan(first * image.Width, (end - first) * image.Width);
    }

    private sealed class SampledMethod(IPixelSampler sampler) : RenderMethod
    {
        public override string Name => sampler.Name;

        public override int SamplesPerPixel => sampler.SamplesPerPixel;

        public override string ToString() => $"{sampler.Name} {sampler.SamplesPerPixel} spp";

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, PixelTarget image, RenderOptions options, float[]? raysPerPixel)
        {
            RenderStatistics stats = options.Device?.TryRender(scene, plane, sampler, image, options)
                ?? PointRenderer.Render(scene, plane, sampler, image, options);
            RowsOf(raysPerPixel, image, options).Fill(sampler.SamplesPerPixel);
            return stats;
        }

        internal override PixelTrace TracePixel(Scene scene, ImagePlane plane, int x, int y)
        {
            int n = sampler.SamplesPerPixel;
            var points = new TracedPoint[n];
            for (int i = 0; i < n; i++)
            {
                SamplePoint s = sampler.GetSample(x, y, i);
                points[i] = new TracedPoint(s.X, s.Y, plane.Trace(scene, plane.GetPixelRay(x, y, s.X, s.Y)), 1.0 / n);
            }

            return new PixelTrace(x, y, this, PointRenderer.RenderPixel(scene, plane, sampler, x, y), points, []);
        }
    }

    private sealed class AdaptiveMethod(AdaptiveSampler sampler) : RenderMethod
    {
        public override string Name => sampler.Name;

        public override string ToString() => sampler.ToString();

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, PixelTarget image, RenderOptions options, float[]? raysPerPixel) =>
            options.Device?.TryRenderAdaptive(scene, plane, sampler, image, options, raysPerPixel)
            ?? AdaptiveRenderer.Render(scene, plane, sampler, image, options, raysPerPixel);

        internal override PixelTrace TracePixel(Scene scene, ImagePlane plane, int x, int y)
        {
            AdaptiveTrace trace = AdaptiveTrace.Run(scene, plane, sampler, x, y);
            return new PixelTrace(x, y, this, trace.Value, trace.Points, trace.Squares);
        }
    }

    private sealed class CustomMethod<TScratch>(IPixelMethod<TScratch> method) : RenderMethod
    {
        public override string Name => method.Name;

        public override string ToString() => method.Name;

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, PixelTarget image, RenderOptions options, float[]? raysPerPixel) =>
            PixelMethodRenderer.Render(scene, plane, method, image, options, raysPerPixel);

        internal override PixelTrace TracePixel(Scene scene, ImagePlane plane, int x, int y)
        {
            (Intensity value, List<(double X, double Y, Intensity Value)> traced) = PixelMethodRenderer.TracePixel(scene, plane, method, x, y);
            TracedPoint[] points = [.. traced.Select(p => new TracedPoint(p.X, p.Y, p.Value, 1.0 / traced.Count))];
            return new PixelTrace(x, y, this, value, points, []);
        }
    }

    private sealed class ExactMethod : RenderMethod
    {
        public override string Name => "exact";

        public override string ToString() => "exact (area-weighted)";

        internal override RenderStatistics Render(Scene scene, ImagePlane plane, PixelTarget image, RenderOptions options, float[]? raysPerPixel)
        {
            RenderStatistics stats = ExactRenderer.Render(scene, plane, image, options);
            RowsOf(raysPerPixel, image, options).Clear();
            return stats;
        }

        internal override void Check(Scene scene, ImagePlane plane)
        {
            base.Check(scene, plane);
            ExactRenderer.Check(scene, plane);
        }

        internal override PixelTrace TracePixel(Scene scene, ImagePlane plane, int x, int y)
        {
            // The pixel's row alone: a row's exact values do not depend on the rows rendered with it.
            var options = new RenderOptions(1, RenderKernel.Scalar, null, default) { FirstRow = y, EndRow = y + 1 };
            return new PixelTrace(x, y, this, ExactRenderer.RenderLinear(scene, plane, options)[x], [], []);
        }
    }
}
