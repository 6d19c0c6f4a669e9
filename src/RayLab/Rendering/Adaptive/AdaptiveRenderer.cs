using RayLab.Sampling;
using System.Diagnostics;
using RayLab.Cameras;

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

    /// <summary>How many entries from the start of <paramref name="line"/> equal <paramref name="id"/>.</summary>
    private static int RunLength(ReadOnlySpan<int> line, int id)
    {
        int other = line.IndexOfAnyExcept(id);
        return other < 0 ? line.Length : other;
    }

    /// <summary>Writes a run of flat pixels of one colour (one ray each for the heat map); returns its length.</summary>
    private static int Fill(Span<Rgb24> pixels, Span<float> counts, Rgb24 colour)
    {
        pixels.Fill(colour);
        counts.Fill(1);
        return pixels.Length;
    }

    /// <summary>
    /// Writes the flat pixels of the run of <paramref name="run"/> from <paramref name="x"/> up to the first one a
    /// silhouette may cross (<see cref="MayCross"/>); returns how many it wrote.
    /// </summary>
    private static int FillGuarded(SilhouetteGuard guard, Span<Rgb24> pixels, Span<float> counts, int x, int run, int row, long size, Rgb24 colour, ref int block, ref bool blockFree)
    {
        int start = x, end = x + run;
        while (x < end)
        {
            if (MayCross(guard, x, row, size, ref block, ref blockFree))
            {
                break;
            }

            // The rest of the pixel's block is clear too when the block is.
            int clear = blockFree ? Math.Min(end, (block + 1) * GuardBlock) : x + 1;
            Fill(pixels[x..clear], counts.IsEmpty ? default : counts[x..clear], colour);
            x = clear;
        }

        return x - start;
    }

    /// <summary>Renders with <paramref name="sampler"/>'s settings; <paramref name="raysPerPixel"/>, if given, receives each pixel's rays.</summary>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, AdaptiveSampler sampler, Image image, RenderOptions options, float[]? raysPerPixel)
    {
        (int first, int end) = options.Rows(image.Height);
        options.Progress?.Start(end - first);
        var clock = Stopwatch.StartNew();
        var lattice = new AdaptiveLattice(scene, plane, sampler.MinDepth, sampler.MaxDepth, sampler.Quincunx, sampler.Guard, options);
        long rays = lattice.CornerRays + lattice.DenseRays + lattice.CentreRays;
        bool flatWithoutCentre = !sampler.Quincunx && sampler.MinDepth == 0;
        Parallel.For(first, end, options.Parallel, lattice.Rent, (row, _, source) =>
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
            ReadOnlySpan<int> top = lattice.CornerLine(row), bottom = lattice.CornerLine(row + 1);
            for (int x = 0; x < pixels.Length; x++)
            {
                if (flatWithoutCentre)
                {
                    // Most pixels: four corners on the same sphere (or the background), nothing more to trace. The run
                    // of flat pixels from x that hit what corner x hit ends where either corner line first hits
                    // something else; the pixel after the run is not flat.
                    int id = top[x];
                    int run = Math.Min(RunLength(top[x..], id), RunLength(bottom[x..], id)) - 1;
                    if (run > 0)
                    {
                        x += guard is null
                            ? Fill(pixels.Slice(x, run), counts.IsEmpty ? default : counts.Slice(x, run), lattice.Level(id))
                            : FillGuarded(guard, pixels, counts, x, run, row, size, lattice.Level(id), ref block, ref blockFree);
                        if (x == pixels.Length)
                        {
                            break;
                        }
                    }
                }

                else if (dense)
                {
                    // With a minimum depth: the run of pixels from x whose band points all hit one thing is refined no
                    // further; the pixel after the run is not uniform.
                    int run = source.UniformRun(x, out int id);
                    if (run > 0)
                    {
                        source.Uniform(sampler, id, x, row, out Intensity uniform, out double charged);
                        pixels.Slice(x, run).Fill(Rgb24.FromIntensity(uniform));
                        if (!counts.IsEmpty)
                        {
                            counts.Slice(x, run).Fill((float)charged);
                        }

                        x += run;
                        if (x == pixels.Length)
                        {
                            break;
                        }
                    }
                }

                // A pixel whose corners disagree, one the guard stopped a run at, one whose band points disagree, or
                // any pixel with the quincunx: the recursion decides. With the quincunx (corners and centre): a pixel
                // whose traced points all agree is refined no further, and its value is known per colour.
                Intensity value;
                double samples;
                if (!(centres && source.TryUniformWithCentre(sampler, x, row, out value, out samples)))
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
