namespace RayLab.Reports.Imaging;

/// <summary>
/// The image formats this package writes, for the core's <see cref="ImageFormats"/> registry: WebP (SkiaSharp).
/// An app calls <see cref="Register"/> once at startup; <see cref="Image.Save(string)"/> then writes <c>.webp</c>.
/// </summary>
/// <remarks>
/// Registration is a call, not a module initializer: the runtime loads this assembly (and would run an initializer) only
/// when the app first uses one of its types, so a <c>.webp</c> save would work or fail by whether something else in the
/// app had touched the package before. A call at startup makes it the same every run.
/// </remarks>
public static class ReportsImageFormats
{
    /// <summary>WebP, lossy, encoded by SkiaSharp (libwebp); <c>.webp</c>.</summary>
    public static ImageFormat Webp { get; } =
        new("WebP", [".webp"], static (stream, image, quality) => SkiaEncoder.Write(stream, image, SkiaEncoder.Kind.Webp, quality));

    /// <summary>Registers this package's formats (<see cref="Webp"/>) with <see cref="ImageFormats.Register"/>; calling it again does nothing.</summary>
    public static void Register() => ImageFormats.Register(Webp);
}
