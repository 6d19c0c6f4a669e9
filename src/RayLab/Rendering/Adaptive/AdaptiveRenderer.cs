using System.Diagnostics;
using RayLab.Cameras;
using RayLab.Imaging;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The lab's adaptive antialiasing (section 4.1.4) as a renderer: the pixel corners are traced once for the
/// whole image (<see cref="AdaptiveLattice"/>), then each pixel is subdivided where its values disagree
/// (<see cref="AdaptivePixel"/>), a row per task, each thread with its own reusable buffers. It relies
/// on the scene's flat shading: a point is kept as the index of what it hit, its value that index's
/// <see cref="Scene.ColourOf"/>.
/// </summary>
internal static class AdaptiveRenderer
{
    /// <summary>Pixels per side of the blocks the guard tests first: a block no silhouette may cross clears its pixels at once.</summary>
    private const int GuardBlock = 8;

    /// <summary>
    /// The guard for a flat pixel: false at once when its <see cref="GuardBlock"/>-pixel block is clear of every
    /// silhouette (the test is conservative for every ray of the block, so for the pixel's too), else the pixel's own test.
    /// </summary>
    private static bool MayCross(SilhouetteGuard guard, int x, int row, long size, ref int block, ref bool blockFree)
    {
        if (x / GuardBlock != block)
        {
            block = x / GuardBlock;
            blockFree = !guard.MayCross((long)block * GuardBlock * size, (long)(row / GuardBlock) * GuardBlock * size, GuardBlock * size);
        }

        return !blockFree && guard.MayCross(x * size, row * size, size);
    }

    /// <summary>Renders with <paramref name="sampler"/>'s settings; <paramref name="raysPerPixel"/>, if given, receives each pixel's rays.</summary>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, AdaptiveSampler sampler, Image image, RenderOptions options, float[]? raysPerPixel)
    {
        options.Progress?.Start(image.Height);
        var clock = Stopwatch.StartNew();
        var lattice = new AdaptiveLattice(scene, plane, sampler.MinDepth, sampler.MaxDepth, sampler.Quincunx, sampler.Guard, options);
        long rays = lattice.CornerRays + lattice.DenseRays + lattice.CentreRays;
        bool flatWithoutCentre = !sampler.Quincunx && sampler.MinDepth == 0;
        Parallel.For(0, image.Height, options.Parallel, lattice.Rent, (row, _, source) =>
        {
            Span<Rgb24> pixels = image.GetRowSpan(row);
            source.BeginRow(row);
            // The guard may refine a pixel whose points agree: then only the recursion knows its value.
            bool dense = lattice.DenseDepth != 0 && lattice.Guard is null;
            bool centres = lattice.CentreLine && lattice.Guard is null;
            SilhouetteGuard? guard = lattice.Guard;
            long size = lattice.Size;
            int block = -1;
            bool blockFree = false;
            Span<float> counts = raysPerPixel is null ? default : raysPerPixel.AsSpan((int)((long)row * pixels.Length), pixels.Length);
            for (int x = 0; x < pixels.Length; x++)
            {
                // Most pixels: four corners on the same sphere (or the background), nothing more to trace.
                if (flatWithoutCentre && lattice.TryFlat(x, row, out Rgb24 flat) && !(guard is not null && MayCross(guard, x, row, size, ref block, ref blockFree)))
                {
                    pixels[x] = flat;
                    if (!counts.IsEmpty)
                    {
                        counts[x] = 1;
                    }

                    continue;
                }

                // With a minimum depth (its band of points) or the quincunx (corners and centre): a pixel whose traced
                // points all agree is refined no further, and its value is known per colour.
                Intensity value;
                double samples;
                if (!(dense && source.TryUniform(sampler, x, row, out value, out samples))
                    && !(centres && source.TryUniformWithCentre(sampler, x, row, out value, out samples)))
                {
                    source.NextPixel(x, row);
                    value = AdaptivePixel.Evaluate(sampler, ref source, x, row, out samples);
                }

                pixels[x] = Rgb24.FromIntensity(value);
                if (!counts.IsEmpty)
                {
                    counts[x] = (float)samples;
                }
            }

            source.EndRow(row);
            options.Progress?.CompleteRow();
            return source;
        }, source =>
        {
            Interlocked.Add(ref rays, source.Rays);
            lattice.Return(source);
        });
        rays -= lattice.SharedEdgeDuplicates();
        clock.Stop();
        return new RenderStatistics(rays, clock.Elapsed) { Kernel = lattice.Kernel, RetracedSamples = lattice.RetracedPoints };
    }
}
