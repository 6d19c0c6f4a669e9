namespace RayLab.Imaging;

/// <summary>The file formats RayLab writes. No imaging library is a dependency: both are written on the runtime's own APIs.</summary>
public enum ImageFormat
{
    /// <summary>PNG, 8-bit RGB, DEFLATE by the runtime's <c>ZLibStream</c>.</summary>
    Png,

    /// <summary>BMP, 24-bit uncompressed (the lab's "bitmap").</summary>
    Bmp,
}

/// <summary>Extension helpers for <see cref="ImageFormat"/>.</summary>
public static class ImageFormats
{
    /// <summary>The supported extensions, lower case with the dot.</summary>
    public static IReadOnlyList<string> Extensions { get; } = [".png", ".bmp"];

    extension(ImageFormat)
    {
        /// <summary>The format for a file name's extension (case-insensitive).</summary>
        /// <param name="path">A file path.</param>
        /// <exception cref="NotSupportedException">The extension is missing or not supported.</exception>
        public static ImageFormat FromPath(string path)
        {
            string ext = Path.GetExtension(path).ToLowerInvariant();
            return ext switch
            {
                ".png" => ImageFormat.Png,
                ".bmp" => ImageFormat.Bmp,
                _ => throw new NotSupportedException(
                    $"Unsupported image format '{(ext.Length == 0 ? "(no extension)" : ext)}' for '{path}'; supported: {string.Join(", ", Extensions)}."),
            };
        }
    }
}
