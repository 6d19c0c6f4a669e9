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
/// parabola or a hyperbola, and <see cref="Render"/> throws an <see cref="UnsupportedSceneException"/> naming
/// the sphere rather than draw a wrong picture. The same happens at a zoom so extreme (pixels some 1e-10 of the
/// distance to the sphere) that double rounding alone could move its picture by more than 1e-6 of a pixel.
/// Spheres that cannot be seen (beyond the far plane, nearer than the near plane, outside the view pyramid) are
/// simply left out, and the near and far planes cutting spheres are handled exactly for both cameras.</para>
/// </remarks>
public sealed class ExactRenderer
{
    private readonly int _threads = -1;

    /// <summary>The most threads to use; −1 (the default) means as many as the runtime likes.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is 0 or less than −1.</exception>
    public int MaxDegreeOfParallelism
    {
        get => _threads;
        init => _threads = ThreadCount.Check(value);
    }

    /// <summary>Optional: counts finished rows while a render runs, for a progress bar polled from another thread.</summary>
    public RenderProgress? Progress { get; init; }

    /// <summary>Cancels a render: checked before each row; a cancelled render throws <see cref="OperationCanceledException"/>.</summary>
    public CancellationToken CancellationToken { get; init; }

    private RenderOptions Options => new(MaxDegreeOfParallelism, RenderKernel.Scalar, Progress, CancellationToken);

    /// <summary>
    /// Fills the 8-bit image with the exact pixel values, each converted by the lab's rule
    /// (<see cref="Rgb24.FromIntensity"/>). The bytes do not depend on the thread count.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="image">The image to fill; its size sets the camera's window.</param>
    /// <returns>Render time; <see cref="RenderStatistics.PrimaryRays"/> is 0 (nothing is sampled).</returns>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline (see the remarks).</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view.</exception>
    public RenderStatistics Render(Scene scene, Camera camera, Image image)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(image);
        return RenderPlane(scene, camera.GetImagePlane(image.Width, image.Height), image, Options);
    }

    /// <summary>The exact render into an 8-bit image, for <see cref="RenderMethod.Exact"/>.</summary>
    internal static RenderStatistics RenderPlane(Scene scene, ImagePlane plane, IPixelRows image, RenderOptions options) =>
        Run(scene, plane, options, sweep: true, [MethodImpl(MethodImplOptions.AggressiveOptimization)] (row, worker) =>
        {
            Span<Rgb24> pixels = image.GetRowSpan(row);
            if (worker.IsUniform)
            {
                pixels.Fill(Rgb24.FromIntensity(worker.UniformColor));
                return;
            }

            double[] values = worker.Values;
            for (int x = 0; x < pixels.Length; x++)
            {
                pixels[x] = Rgb24.FromIntensity(new Intensity(values[3 * x], values[(3 * x) + 1], values[(3 * x) + 2]));
            }
        });

    /// <summary>
    /// The exact linear pixel values (before the 8-bit rule), row 0 (the top) first, W·H entries: for measuring
    /// other renderers' error below one 8-bit level.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">The image width W, ≥ 1.</param>
    /// <param name="height">The image height H, ≥ 1.</param>
    /// <returns>W·H intensities.</returns>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline (see the remarks).</exception>
    /// <exception cref="ArgumentException">The size is not positive or the camera's settings do not form a valid view.</exception>
    public Intensity[] RenderLinear(Scene scene, Camera camera, int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        return RenderLinear(scene, camera, width, height, sweep: true);
    }

    /// <summary>
    /// <see cref="RenderLinear(Scene, Camera, int, int)"/> with the row sweep on, or off (every strip of every row
    /// cut afresh, as the row does without the sweep): for tests that the sweep changes nothing.
    /// </summary>
    internal Intensity[] RenderLinear(Scene scene, Camera camera, int width, int height, bool sweep)
    {
        var result = new Intensity[(long)width * height];
        Run(scene, camera.GetImagePlane(width, height), Options, sweep, (row, worker) =>
        {
            Span<Intensity> pixels = result.AsSpan(row * width, width);
            if (worker.IsUniform)
            {
                pixels.Fill(worker.UniformColor);
                return;
            }

            double[] values = worker.Values;
            for (int x = 0; x < width; x++)
            {
                pixels[x] = new Intensity(values[3 * x], values[(3 * x) + 1], values[(3 * x) + 2]);
            }
        });
        return result;
    }

    /// <summary>
    /// Checks that the exact reference can draw <paramref name="scene"/> through <paramref name="camera"/> at this
    /// size, without drawing it (what <see cref="Render"/> would throw, it throws).
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">The image width.</param>
    /// <param name="height">The image height.</param>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline.</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view.</exception>
    public static void Check(Scene scene, Camera camera, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        Check(scene, camera.GetImagePlane(width, height));
    }

    /// <summary>Throws what <see cref="Render"/> would throw for <paramref name="scene"/> seen through <paramref name="plane"/>, without making the outlines.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="plane">The camera's image plane.</param>
    /// <exception cref="UnsupportedSceneException">A sphere the exact reference cannot outline.</exception>
    internal static void Check(Scene scene, ImagePlane plane) => OutlineSet.Check(scene, plane);

    private static RenderStatistics Run(Scene scene, ImagePlane plane, RenderOptions options, bool sweep, Action<int, ExactRow> writeRow)
    {
        var loop = RowLoop.Start(options, plane.Height);
        OutlineSet outlines = OutlineSet.Build(scene, plane, parallel: options.Parallel);
        loop.Run(new Rows(scene, plane, outlines, sweep, writeRow));
        return loop.Finish(0, RenderKernel.Scalar);
    }

    /// <summary>The exact rows: each thread integrates rows with its own <see cref="ExactRow"/>, then writes them.</summary>
    private sealed class Rows(Scene scene, ImagePlane plane, OutlineSet outlines, bool sweep, Action<int, ExactRow> writeRow) : IRowRenderer<ExactRow>
    {
        public ExactRow Rent() => new(scene, plane, outlines, sweep);

        public void RenderRow(int row, ref ExactRow worker)
        {
            worker.Integrate(row);
            writeRow(row, worker);
        }
    }
}
