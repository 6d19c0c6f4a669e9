using System.Diagnostics;
using RayLab.Cameras;
using RayLab.Imaging;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The lab's adaptive antialiasing (section 4.1.4) as a renderer: the pixel corners are traced once for the
/// whole image, then each pixel is subdivided where its values disagree (<see cref="AdaptivePixel"/>). It relies
/// on the scene's flat shading: a corner is kept as the index of what it hit, its value that index's
/// <see cref="Scene.ColourOf"/> (<see cref="AdaptiveLattice"/>).
/// </summary>
internal static class AdaptiveRenderer
{
    /// <summary>Renders with <paramref name="sampler"/>'s settings; <paramref name="raysPerPixel"/>, if given, receives each pixel's rays.</summary>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, AdaptiveSampler sampler, Image image, RenderOptions options, float[]? raysPerPixel)
    {
        options.Progress?.Start(image.Height);
        var clock = Stopwatch.StartNew();
        var lattice = new AdaptiveLattice(scene, plane, sampler.MaxDepth, options.Parallel);
        long interiorRays = 0;
        Parallel.For(0, image.Height, options.Parallel, () => new AdaptiveLattice.Source(lattice), (row, _, source) =>
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

            options.Progress?.CompleteRow();
            return source;
        }, source => Interlocked.Add(ref interiorRays, source.Rays));
        clock.Stop();
        return new RenderStatistics(lattice.SharedRays + interiorRays, clock.Elapsed) { Kernel = RenderKernel.Scalar };
    }
}
