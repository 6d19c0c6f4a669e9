namespace RayLab;

/// <summary>
/// "A method of your own" (the lab's section 5) for deciding a pixel's value: the renderer hands the method each
/// pixel in turn through a <see cref="PixelTracer"/>, and the method traces the points of its choosing inside the
/// pixel (a few first, more where they disagree, as it likes) and returns the pixel's intensity. Render it with
/// <see cref="RenderMethod.Custom{TScratch}(IPixelMethod{TScratch})"/>.
/// </summary>
/// <remarks>
/// The renderer counts every traced point as one primary ray, the same way for every method, so statistics and
/// heat maps work unchanged. For the same bytes whatever the thread count, a pixel's value must depend only on the
/// pixel, the intensities its traces return and <see cref="PixelTracer.PreviousInRow"/>, never on what a scratch
/// held from an earlier pixel.
/// </remarks>
/// <typeparam name="TScratch">
/// Per-thread working space (sample buffers, say), created once for each thread that renders rows; a method with
/// no need of one may use any type and return <c>default</c>.
/// </typeparam>
public interface IPixelMethod<TScratch>
{
    /// <summary>The method's name, for reports and file names (e.g. <c>mitchell</c>).</summary>
    string Name { get; }

    /// <summary>Creates one thread's working space; called once for each thread that renders rows.</summary>
    /// <returns>The new scratch.</returns>
    TScratch CreateScratch();

    /// <summary>The value of pixel (<see cref="PixelTracer.X"/>, <see cref="PixelTracer.Row"/>), in linear intensity (before the 8-bit rule).</summary>
    /// <param name="pixel">The pixel: its coordinates and the trace function for points inside it.</param>
    /// <param name="scratch">This thread's working space.</param>
    /// <returns>The pixel's intensity.</returns>
    Intensity RenderPixel(PixelTracer pixel, ref TScratch scratch);
}
