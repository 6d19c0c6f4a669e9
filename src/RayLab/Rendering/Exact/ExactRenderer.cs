using System.Runtime.CompilerServices;
using RayLab.Cameras;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The exact reference: each pixel gets the exact area-weighted mean of the scene over its whole square — the
/// limit that every sampler approaches as its sample count grows — so the image has no aliasing at all. It is
/// RayLab's "method of our own" for antialiasing (lab section 5), and the truth the samplers are measured against.
/// </summary>
/// <remarks>
/// <para><b>Why it can be exact.</b> It relies on the scene's flat shading: a sample's value is the
/// <see cref="Scene.ColourOf"/> the sphere it hits (colour × ambient), so the picture is made of regions of one colour, and the colour can only change where a ray touches a sphere (the sphere's outline),
/// where a hit crosses the near or the far plane (the circle where that plane cuts a sphere), or where two
/// spheres are hit at the same point (the circle where they meet). Every one of these borders is the picture of
/// a circle, which in pixel coordinates is an ellipse: a circle for a sphere seen by the orthographic camera, an
/// ellipse (a conic section of the cone of rays) for the perspective one.</para>
/// <para><b>The method, one pixel row at a time.</b> (1) Cut the row into horizontal strips at every height
/// where the picture changes: where an ellipse begins or ends, turns, crosses a pixel's left or right edge, or
/// crosses another ellipse. (2) Inside a strip each ellipse has a left and a right branch,
/// <c>X = Xc + P c ∓ Q √(1 − c²)</c> with <c>c = (Y − Yc)/Hy</c>, and the branches split the strip into pieces of
/// one colour — one ray through the middle of each piece (<see cref="Scene.Trace"/>) says which. (3) Each piece's
/// area in each pixel is an integral of the branches, in closed form (the area under a circle arc,
/// <c>∫ √(1 − c²) dc = (c √(1 − c²) + asin c)/2</c>). Pixels that no border crosses are spans of one colour and
/// cost nothing: the work grows with the length of the borders, not with the number of pixels.</para>
/// <para><b>Accuracy.</b> There is no sampling error; what is left is double rounding, far below 1e-5 per
/// channel (the tests check pixels against independent closed forms to 1e-9). It agrees with
/// <see cref="Renderer"/> in the limit of many samples, and <see cref="RenderStatistics.PrimaryRays"/> is 0
/// because it integrates rather than samples (it still traces one ray per piece to find its colour).</para>
/// <para><b>Not supported.</b> With the perspective camera, a sphere that visible rays can reach must lie
/// wholly in front of the eye (nearest point at a depth above 1e-4 of its radius): otherwise its outline is a
/// parabola or a hyperbola, and a render throws an <see cref="UnsupportedSceneException"/> naming
/// the sphere rather than draw a wrong picture. The same happens at a zoom so extreme (pixels some 1e-10 of the
/// distance to the sphere) that double rounding alone could move its picture by more than 1e-6 of a pixel.
/// Spheres that cannot be seen (beyond the far plane, nearer than the near plane, outside the view pyramid) are
/// simply left out, and the near and far planes cutting spheres are handled exactly for both cameras.</para>
/// <para>It is reached through <see cref="Renderer"/> with <see cref="RenderMethod.Exact"/>, like every other method, and
/// writes 8-bit rows or linear intensities through the same <see cref="PixelTarget"/>.</para>
/// </remarks>
internal static class ExactRenderer
{
    /// <summary>
    /// The exact render into <paramref name="target"/>: each row's exact values, 8-bit by the lab's rule
    /// (<see cref="Rgb24.FromIntensity"/>) or linear. The bytes do not depend on the thread count.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <param name="target">Where the rows go.</param>
    /// <param name="options">Threads, progress, cancellation and the rows to render.</param>
    /// <param name="sweep">
    /// The row sweep on (the renderer's way), or off: every strip of every row cut afresh, for tests that the sweep
    /// changes nothing.
    /// </param>
    /// <returns>Render time; <see cref="RenderStatistics.PrimaryRays"/> is 0 (nothing is sampled).</returns>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline (see the remarks).</exception>
    public static RenderStatistics Render(Scene scene, ImagePlane plane, PixelTarget target, RenderOptions options, bool sweep = true)
    {
        var loop = RowLoop.Start(options, plane.Height);
        OutlineSet outlines = OutlineSet.Build(scene, plane, options.Parallel, options.Trace);
        loop.Run(new Rows(scene, plane, outlines, sweep, target, options));
        return loop.Finish(0, RenderKernel.Scalar);
    }

    /// <summary>
    /// The exact linear values of the rows <paramref name="options"/> names (all, or a band), W per row, the band's
    /// first row first.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <param name="options">Threads, progress, cancellation and the rows to render.</param>
    /// <param name="sweep">The row sweep on, or off (see <see cref="Render"/>).</param>
    /// <returns>The rows' values.</returns>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline (see the remarks).</exception>
    public static unsafe Intensity[] RenderLinear(Scene scene, ImagePlane plane, RenderOptions options, bool sweep = true)
    {
        (int first, int end) = options.Rows(plane.Height);
        var values = new Intensity[(long)plane.Width * Math.Max(0, end - first)];
        fixed (Intensity* pixels = values)
        {
            Render(scene, plane, PixelTarget.Linear(pixels, plane.Width, plane.Height, first), options, sweep);
        }

        return values;
    }

    /// <summary>Throws what a render would throw for <paramref name="scene"/> seen through <paramref name="plane"/>, without making the outlines.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline.</exception>
    public static void Check(Scene scene, ImagePlane plane) => OutlineSet.Check(scene, plane);

    /// <summary>The exact rows: each thread integrates rows with its own <see cref="ExactRow"/>, then writes them.</summary>
    private sealed class Rows(Scene scene, ImagePlane plane, OutlineSet outlines, bool sweep, PixelTarget target, RenderOptions options) : IRowRenderer<ExactRow>
    {
        public ExactRow Rent() => new(scene, plane, outlines, sweep, options.Rent<RowPixels.Buffers>());

        public void Return(ExactRow worker, ref RowTotals totals) => options.Return(worker.Buffers);

        [MethodImpl(MethodImplOptions.AggressiveOptimization)]
        public void RenderRow(int row, ref ExactRow worker)
        {
            worker.Integrate(row);
            TargetRow pixels = target.Row(row);
            if (worker.IsUniform)
            {
                pixels.Fill(0, pixels.Length, worker.UniformColor);
                return;
            }

            double[] values = worker.Values;
            for (int x = 0; x < pixels.Length; x++)
            {
                pixels.Set(x, new Intensity(values[3 * x], values[(3 * x) + 1], values[(3 * x) + 2]));
            }
        }
    }
}
