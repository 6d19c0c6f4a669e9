using RayLab.Sampling;
using Bitmap = SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>;

namespace RayLab.ImageSharp;

/// <summary>
/// The lab's render loop into the lab's bitmap ("obraz", section 2.2): <see cref="Renderer"/>'s render methods for an
/// ImageSharp <c>Image&lt;Rgb24&gt;</c>. The renderer's one row loop writes each row straight into the bitmap's pixel
/// memory (no second frame buffer, no copy), and the bytes equal those of a render into RayLab's <see cref="Image"/>
/// for every method, at any thread count. Progress and cancellation are the renderer's own: a cancelled render throws
/// <see cref="OperationCanceledException"/> before you save anything.
/// </summary>
public static class BitmapRendering
{
    /// <summary>Renders <paramref name="scene"/> by <paramref name="method"/> into <paramref name="bitmap"/>.</summary>
    /// <param name="renderer">The renderer (threads, kernel, progress, cancellation).</param>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="bitmap">The bitmap to fill; its size sets the camera's window.</param>
    /// <param name="raysPerPixel">Optional, W·H long, row 0 first: receives the rays charged to each pixel (see <see cref="Renderer.Render(Scene, Camera, RenderMethod, Image, float[])"/>).</param>
    /// <returns>Rays traced, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="ArgumentException">The camera's settings do not form a valid view, or <paramref name="raysPerPixel"/> has the wrong length.</exception>
    /// <exception cref="OperationCanceledException">The renderer's cancellation token was cancelled.</exception>
    public static RenderStatistics Render(this Renderer renderer, Scene scene, Camera camera, RenderMethod method, Bitmap bitmap, float[]? raysPerPixel = null)
    {
        ArgumentNullException.ThrowIfNull(renderer);
        return renderer.Render(scene, camera, method, bitmap.AsPixelRows(), raysPerPixel);
    }

    /// <summary>Renders <paramref name="scene"/> into <paramref name="bitmap"/> with a point sampler (the lab's regular, random, jittered, or your own <see cref="IPixelSampler"/>).</summary>
    /// <param name="renderer">The renderer.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="sampler">Where the samples go in each pixel.</param>
    /// <param name="bitmap">The bitmap to fill.</param>
    /// <returns>Rays traced and render time.</returns>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="OperationCanceledException">The renderer's cancellation token was cancelled.</exception>
    public static RenderStatistics Render(this Renderer renderer, Scene scene, Camera camera, IPixelSampler sampler, Bitmap bitmap) =>
        renderer.Render(scene, camera, RenderMethod.Sampled(sampler), bitmap);

    /// <summary>Renders <paramref name="scene"/> into <paramref name="bitmap"/> with the lab's adaptive antialiasing (4.1.4).</summary>
    /// <param name="renderer">The renderer.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="sampler">The adaptive settings.</param>
    /// <param name="bitmap">The bitmap to fill.</param>
    /// <param name="raysPerPixel">Optional, W·H long: receives the rays charged to each pixel.</param>
    /// <returns>Rays traced (each point once) and render time.</returns>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="OperationCanceledException">The renderer's cancellation token was cancelled.</exception>
    public static RenderStatistics Render(this Renderer renderer, Scene scene, Camera camera, AdaptiveSampler sampler, Bitmap bitmap, float[]? raysPerPixel = null) =>
        renderer.Render(scene, camera, RenderMethod.Adaptive(sampler), bitmap, raysPerPixel);

    /// <summary>
    /// Renders rows <paramref name="firstRow"/> to <paramref name="firstRow"/> + <paramref name="rowCount"/> − 1 of
    /// <paramref name="bitmap"/> and leaves the others as they are (see <see cref="Renderer.RenderRows(Scene, Camera, RenderMethod, Image, int, int, float[])"/>).
    /// </summary>
    /// <param name="renderer">The renderer.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="method">Point sampling, adaptive, a pixel method of your own, or exact.</param>
    /// <param name="bitmap">The whole bitmap; its size sets the camera's window.</param>
    /// <param name="firstRow">The band's first row, 0 the top.</param>
    /// <param name="rowCount">How many rows the band has.</param>
    /// <param name="raysPerPixel">Optional, W·H long: receives the rays charged to each pixel of the band.</param>
    /// <returns>The band's rays, render time and the kernel that ran.</returns>
    /// <exception cref="ArgumentNullException">An argument is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The band does not lie inside the bitmap.</exception>
    /// <exception cref="OperationCanceledException">The renderer's cancellation token was cancelled.</exception>
    public static RenderStatistics RenderRows(this Renderer renderer, Scene scene, Camera camera, RenderMethod method, Bitmap bitmap, int firstRow, int rowCount, float[]? raysPerPixel = null)
    {
        ArgumentNullException.ThrowIfNull(renderer);
        return renderer.RenderRows(scene, camera, method, bitmap.AsPixelRows(), firstRow, rowCount, raysPerPixel);
    }

    /// <summary>
    /// The bitmap as the rows a renderer fills (<see cref="IPixelRows"/>): each row is the bitmap's own memory, so
    /// writing a row writes the bitmap. For code of your own that takes any RayLab picture.
    /// </summary>
    /// <param name="bitmap">The bitmap.</param>
    /// <returns>Its rows; valid while the bitmap is.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="bitmap"/> is null.</exception>
    public static IPixelRows AsPixelRows(this Bitmap bitmap) => new BitmapRows(bitmap);
}
