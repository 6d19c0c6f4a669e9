using RayLab.Rendering;
using RayLab.Cameras;
using RayLab.Sampling;

namespace RayLab;

/// <summary>
/// Renders a scene through a camera into an image (the lab's render loop): the one door to RayLab's three
/// renderers, one room each — point sampling (<c>Rendering/Point</c>), the lab's adaptive antialiasing
/// (<c>Rendering/Adaptive</c>) and the exact reference (<c>Rendering/Exact</c>). Rows are rendered in
/// parallel; every pixel's value is independent of the thread that takes it, so the bytes are the same
/// whatever <see cref="MaxDegreeOfParallelism"/> is. Every method renders 8-bit rows into an image, or linear
/// intensities into a span, and <see cref="TracePixel"/> traces one pixel of any method.
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
    /// silhouette (see the README's performance section). The adaptive renderer traces its pixel corners with the
    /// same choice, and gives the same bytes with every kernel; its refinement points go one at a time in double.
    /// The exact renderer runs its own loop.
    /// </summary>
    public RenderKernel Kernel { get; init; } = RenderKernel.Auto;

    /// <summary>
    /// Where point-sampled and adaptive renders run: <see cref="RenderDevice.Cpu"/> (the default), or a device from another package
    /// (<c>RayLab.Gpu</c>). A device gives the bytes of the CPU kernel <see cref="Kernel"/> chooses; what it cannot
    /// render (a sampler of your own, exact, a pixel method) the CPU renders in the same call, and
    /// <see cref="RenderStatistics.Device"/> says which ran.
    /// </summary>
    /// <exception cref="ArgumentNullException">The value is null.</exception>
    public RenderDevice Device
    {
        get => _device;
        init => _device = value ?? throw new ArgumentNullException(nameof(value));
    }

    private readonly RenderDevice _device = RenderDevice.Cpu;

    /// <summary>
    /// Optional: counts finished rows while a render runs, for a progress bar polled from another thread.
    /// </summary>
    public RenderProgress? Progress { get; init; }

    /// <summary>
    /// Cancels a render: it is checked before each row, and a cancelled render throws
    /// <see cref="OperationCanceledException"/> with the image partly written.
    /// </summary>
    public CancellationToken CancellationToken { get; init; }

    /// <summary>The per-thread buffers kept from one render to the next (the adaptive renderer's lines and caches).</summary>
    private readonly ScratchPool _pool = new();

    internal RenderOptions Options => new(MaxDegreeOfParallelism, Kernel, Progress, CancellationToken, _pool) { Trace = Trace, RowPieces = RowPieces, Device = _device };

    /// <summary>Records the next renders' row-loop phases and band times (the scaling tool); null records nothing.</summary>
    internal RowLoopTrace? Trace { get; set; }

    /// <summary>Pieces per row for the adaptive renderer (the scaling tool); 0, the default, lets it choose.</summary>
    internal int RowPieces { get; set; }

    /// <summary>
    /// Renders <paramref name="scene"/> into <paramref name="image"/> by <paramref name="method"/>: the one place
    /// that hands a render to its renderer.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="image">The image to fill; its size sets the camera's window.</param>
    /// <param name="raysPerPixel">
    /// Optional, W·H long, row 0 first: receives the rays charged to each pixel (a point sampler's samples per
    /// pixel; for adaptive, its centre and inner points, each pixel corner counted ¼ and each point on a pixel
    /// edge ½, since they are shared; for a pixel method, the points it traced in that pixel; 0 for exact).
    /// </param>
    /// <returns>Rays traced, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view (see <see cref="Camera.GetImagePlane"/>), or <paramref name="raysPerPixel"/> has the wrong length.</exception>
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public RenderStatistics Render(Scene scene, Camera camera, RenderMethod method, Image image, float[]? raysPerPixel = null) =>
        Render(scene, camera, method, (IPixelRows)image, raysPerPixel);

    /// <summary>
    /// Renders <paramref name="scene"/> by <paramref name="method"/> into any 8-bit picture that hands out its rows
    /// (<see cref="IPixelRows"/>): each row is written straight into the picture's own memory by the thread that
    /// renders it, with the bytes a render into an <see cref="Image"/> of the same size gives. This is how the
    /// <c>RayLab.ImageSharp</c> package renders into an ImageSharp <c>Image&lt;Rgb24&gt;</c>.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="image">The picture to fill; its size sets the camera's window.</param>
    /// <param name="raysPerPixel">Optional, W·H long, row 0 first: receives the rays charged to each pixel (as for an <see cref="Image"/>).</param>
    /// <returns>Rays traced, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view, the picture's size is less than 1×1, or <paramref name="raysPerPixel"/> has the wrong length.</exception>
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public RenderStatistics Render(Scene scene, Camera camera, RenderMethod method, IPixelRows image, float[]? raysPerPixel = null)
    {
        ArgumentNullException.ThrowIfNull(image);
        return Render(scene, camera, method, PixelTarget.Of(image), raysPerPixel, Options);
    }

    /// <summary>
    /// Renders <paramref name="scene"/> by <paramref name="method"/> into linear intensities — each pixel's value before
    /// the lab's 8-bit rule — for measuring error below one 8-bit level, or for a display of your own. Every method
    /// renders this way; <see cref="Rgb24.FromIntensity"/> of each value gives the bytes a render into an
    /// <see cref="Image"/> of the same size gives.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="pixels">Receives W·H values, row 0 (the top) first, W per row (an <see cref="Intensity"/> array will do).</param>
    /// <param name="width">The image width W, ≥ 1; it and <paramref name="height"/> set the camera's window.</param>
    /// <param name="height">The image height H, ≥ 1.</param>
    /// <param name="raysPerPixel">Optional, W·H long, row 0 first: receives the rays charged to each pixel (as for an <see cref="Image"/>).</param>
    /// <returns>Rays traced, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="width"/> or <paramref name="height"/> is less than 1.</exception>
    /// <exception cref="ArgumentException"><paramref name="pixels"/> does not hold W·H values, <paramref name="raysPerPixel"/> has the wrong length, or the camera's settings do not form a valid view.</exception>
    /// <exception cref="UnsupportedSceneException">A sphere reaches too far from the camera for double, or the exact method cannot draw the scene (see <see cref="RenderMethod.Check(Scene, Camera, int, int)"/>).</exception>
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public unsafe RenderStatistics Render(Scene scene, Camera camera, RenderMethod method, Span<Intensity> pixels, int width, int height, float[]? raysPerPixel = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        if (pixels.Length != (long)width * height)
        {
            throw new ArgumentException($"Expected {width}×{height} values, got {pixels.Length}.", nameof(pixels));
        }

        // The rows are written by several threads: the caller's memory stays pinned until the render returns.
        fixed (Intensity* first = pixels)
        {
            return Render(scene, camera, method, PixelTarget.Linear(first, width, height), raysPerPixel, Options);
        }
    }

    /// <summary>Renders through an image plane already built from the camera (a prepared scene's), into <paramref name="image"/> of the plane's size.</summary>
    internal RenderStatistics Render(Scene scene, ImagePlane plane, RenderMethod method, Image image, float[]? raysPerPixel)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(method);
        PixelTarget target = PixelTarget.Of(image);
        CheckRays(target, raysPerPixel);
        DoubleReach.Check(scene, plane);
        return method.Render(scene, plane, target, Options, raysPerPixel);
    }

    private static void CheckRays(PixelTarget image, float[]? raysPerPixel)
    {
        if (raysPerPixel is not null && raysPerPixel.LongLength != (long)image.Width * image.Height)
        {
            throw new ArgumentException($"Expected {image.Width}×{image.Height} entries, got {raysPerPixel.Length}.", nameof(raysPerPixel));
        }
    }

    private static RenderStatistics Render(Scene scene, Camera camera, RenderMethod method, PixelTarget image, float[]? raysPerPixel, RenderOptions options)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(method);
        CheckRays(image, raysPerPixel);
        return method.Render(scene, PlaneFor(scene, camera, image.Width, image.Height), image, options, raysPerPixel);
    }

    /// <summary>The plane a W×H render of <paramref name="camera"/> traces through, checked against <paramref name="scene"/>: every render and pixel trace starts here.</summary>
    private static ImagePlane PlaneFor(Scene scene, Camera camera, int width, int height)
    {
        ImagePlane plane = camera.GetImagePlane(width, height);
        DoubleReach.Check(scene, plane);
        return plane;
    }

    /// <summary>
    /// Traces pixel (<paramref name="x"/>, <paramref name="y"/>) of a W×H render by <paramref name="method"/>, as the
    /// render traces it: the pixel's linear value and every point traced in it with its share of the value (the
    /// pixel inspector, the adaptive diagram). The value is the one a render into linear intensities gives the pixel
    /// (for point sampling, with the scalar kernel, <see cref="RenderKernel.Scalar"/>; the packet kernels agree with
    /// it except for samples within float resolution of a silhouette).
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">The render's width W.</param>
    /// <param name="height">The render's height H.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="x">The pixel's column, 0 ≤ x &lt; W.</param>
    /// <param name="y">The pixel's row, 0 (the top) ≤ y &lt; H.</param>
    /// <returns>The pixel's value and points.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The pixel is outside the image.</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view.</exception>
    /// <exception cref="UnsupportedSceneException">A sphere reaches too far from the camera for double, or the exact method cannot draw the scene.</exception>
    public static PixelTrace TracePixel(Scene scene, Camera camera, int width, int height, RenderMethod method, int x, int y)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(method);
        ArgumentOutOfRangeException.ThrowIfNegative(x);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(x, width);
        ArgumentOutOfRangeException.ThrowIfNegative(y);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, height);
        return method.TracePixel(scene, PlaneFor(scene, camera, width, height), x, y);
    }

    /// <summary>
    /// Renders rows <paramref name="firstRow"/> to <paramref name="firstRow"/> + <paramref name="rowCount"/> − 1 of
    /// <paramref name="image"/> and leaves the others as they are: a band of the picture, for a caller that shows
    /// progress or yields between bands (the browser playground, which has one thread). A pixel's value does not
    /// depend on the rows rendered with it, so bands rendered one after another give the bytes of one
    /// <see cref="Render(Scene, Camera, RenderMethod, Image, float[])"/>. The statistics count the band's rays for
    /// point sampling and pixel methods; adaptive's count the whole image's pixel corners (the band's rays per pixel
    /// are exact: sum <paramref name="raysPerPixel"/> for the band's cost).
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="image">The whole image; its size sets the camera's window.</param>
    /// <param name="firstRow">The band's first row, 0 the top.</param>
    /// <param name="rowCount">How many rows the band has (0 renders nothing).</param>
    /// <param name="raysPerPixel">Optional, W·H long: receives the rays charged to each pixel of the band.</param>
    /// <returns>The band's rays, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The band does not lie inside the image.</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view, or <paramref name="raysPerPixel"/> has the wrong length.</exception>
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public RenderStatistics RenderRows(Scene scene, Camera camera, RenderMethod method, Image image, int firstRow, int rowCount, float[]? raysPerPixel = null) =>
        RenderRows(scene, camera, method, (IPixelRows)image, firstRow, rowCount, raysPerPixel);

    /// <summary>
    /// Renders a band of rows of any <see cref="IPixelRows"/> picture and leaves the others as they are (see
    /// <see cref="RenderRows(Scene, Camera, RenderMethod, Image, int, int, float[])"/>).
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="image">The whole picture; its size sets the camera's window.</param>
    /// <param name="firstRow">The band's first row, 0 the top.</param>
    /// <param name="rowCount">How many rows the band has (0 renders nothing).</param>
    /// <param name="raysPerPixel">Optional, W·H long: receives the rays charged to each pixel of the band.</param>
    /// <returns>The band's rays, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The band does not lie inside the picture.</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view, or <paramref name="raysPerPixel"/> has the wrong length.</exception>
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public RenderStatistics RenderRows(Scene scene, Camera camera, RenderMethod method, IPixelRows image, int firstRow, int rowCount, float[]? raysPerPixel = null)
    {
        ArgumentNullException.ThrowIfNull(image);
        ArgumentOutOfRangeException.ThrowIfNegative(firstRow);
        ArgumentOutOfRangeException.ThrowIfNegative(rowCount);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(rowCount, image.Height - firstRow);
        return Render(scene, camera, method, PixelTarget.Of(image), raysPerPixel, Options with { FirstRow = firstRow, EndRow = firstRow + rowCount });
    }

    /// <summary>Renders <paramref name="scene"/> into <paramref name="image"/> with a point sampler.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="sampler">Where the samples go in each pixel.</param>
    /// <param name="image">The image to fill; its size sets the camera's window.</param>
    /// <returns>Rays traced and render time.</returns>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view (see <see cref="Camera.GetImagePlane"/>).</exception>
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public RenderStatistics Render(Scene scene, Camera camera, IPixelSampler sampler, Image image) =>
        Render(scene, camera, RenderMethod.Sampled(sampler), image);

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
    /// <exception cref="OperationCanceledException"><see cref="CancellationToken"/> was cancelled.</exception>
    public RenderStatistics Render(Scene scene, Camera camera, AdaptiveSampler sampler, Image image, float[]? raysPerPixel = null) =>
        Render(scene, camera, RenderMethod.Adaptive(sampler), image, raysPerPixel);
}
