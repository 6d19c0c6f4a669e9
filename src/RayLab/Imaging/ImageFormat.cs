namespace RayLab;

/// <summary>
/// The file formats RayLab writes (the lab's "zapis obrazu"). PNG and BMP are written by RayLab's own encoders;
/// JPEG by JpegLibrary (managed); WebP by the <c>RayLab.Reports</c> package (SkiaSharp).
/// </summary>
public enum ImageFormat
{
    /// <summary>PNG, 8-bit RGB, DEFLATE by the runtime's <c>ZLibStream</c> (RayLab's own encoder).</summary>
    Png,

    /// <summary>BMP, 24-bit uncompressed (the lab's "bitmap"; RayLab's own encoder).</summary>
    Bmp,

    /// <summary>JPEG, lossy (the format of the lab's <c>obrazkoncowy.jpg</c>), 4:4:4, encoded by JpegLibrary (managed).</summary>
    Jpeg,

    /// <summary>WebP, lossy, encoded by SkiaSharp: written once the app references the <c>RayLab.Reports</c> package.</summary>
    Webp,
}

/// <summary>Extension helpers for <see cref="ImageFormat"/>.</summary>
public static class ImageFormats
{
    /// <summary>The quality JPEG and WebP are written with unless told otherwise (0–100).</summary>
    public const int DefaultQuality = 90;

    /// <summary>The supported extensions, lower case with the dot.</summary>
    public static IReadOnlyList<string> Extensions { get; } = [".png", ".bmp", ".jpg", ".jpeg", ".webp"];

    extension(ImageFormat)
    {
        /// <summary>The format for a file name's extension (case-insensitive).</summary>
        /// <param name="path">A file path.</param>
        /// <exception cref="NotSupportedException">The extension is missing or not supported (the message names the supported ones).</exception>
        public static ImageFormat FromPath(string path)
        {
            string ext = Path.GetExtension(path).ToLowerInvariant();
            return ext switch
            {
                ".png" => ImageFormat.Png,
                ".bmp" => ImageFormat.Bmp,
                ".jpg" or ".jpeg" => ImageFormat.Jpeg,
                ".webp" => ImageFormat.Webp,
                _ => throw new NotSupportedException(
                    $"Unsupported image format '{(ext.Length == 0 ? "(no extension)" : ext)}' for '{path}'; supported: {string.Join(", ", Extensions)}."),
            };
        }
    }
}
