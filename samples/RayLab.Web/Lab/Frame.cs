namespace RayLab.Web.Lab;

/// <summary>A finished render: the picture, the rays charged to each pixel, the exact picture of the same view and the figures.</summary>
/// <param name="Picture">The rendered image.</param>
/// <param name="Rays">Rays per pixel, row 0 first.</param>
/// <param name="Exact">The exact image of the same scene, camera and size.</param>
/// <param name="Statistics">The library's statistics (rays, render time, kernel), summed over the bands.</param>
/// <param name="WallMilliseconds">From the start of the render to the last band, yields to the browser included.</param>
/// <param name="Error">The picture's error against <paramref name="Exact"/>.</param>
/// <param name="Method">The method as the library names it.</param>
internal sealed record Frame(Image Picture, float[] Rays, Image Exact, RenderStatistics Statistics, double WallMilliseconds, ImageError Error, string Method)
{
    /// <summary>Rays per pixel, averaged over the image.</summary>
    public double RaysPerPixel => (double)Statistics.PrimaryRays / ((long)Picture.Width * Picture.Height);
}

/// <summary>One render of this visit, a point of the error-against-time chart.</summary>
/// <param name="Method">The method with its settings.</param>
/// <param name="Sampler">The sampler's name (the chart's colour).</param>
/// <param name="Milliseconds">The library's render time.</param>
/// <param name="Rmse">RMSE against exact, in 8-bit levels.</param>
internal sealed record Trial(string Method, string Sampler, double Milliseconds, double Rmse);

/// <summary>One sample point inside the inspected pixel.</summary>
/// <param name="Label">The adaptive diagram's letter, or the sample's index.</param>
/// <param name="X">Across the pixel, 0 to 1.</param>
/// <param name="Y">Down the pixel, 0 to 1.</param>
/// <param name="Colour">The point's traced value.</param>
/// <param name="Weight">Its share of the pixel's value.</param>
internal sealed record InspectedPoint(string Label, double X, double Y, Intensity Colour, double Weight);

/// <summary>What the pixel inspector shows for one pixel.</summary>
internal sealed record Inspection(
    int X, int Y, string Method, IReadOnlyList<InspectedPoint> Points, IReadOnlyList<RayLab.Rendering.Inspection.AdaptiveSquare> Squares,
    Intensity Value, Intensity Exact, Rgb24 Rendered, string InsideDataUrl);
