using SkiaSharp;

namespace RayLab.Reports.Imaging;

/// <summary>
/// Writes WebP (<see cref="ReportsImageFormats.Webp"/>) and JPEG (for the benchmarks' comparison with
/// the core's managed encoder) through SkiaSharp: libwebp and libjpeg-turbo inside Skia's native library.
/// </summary>
internal static class SkiaEncoder
{
    /// <summary>The formats Skia writes here.</summary>
    public enum Kind
    {
        /// <summary>JPEG, 4:4:4.</summary>
        Jpeg,

        /// <summary>WebP, lossy.</summary>
        Webp,
    }

    /// <summary>Encodes <paramref name="image"/> as <paramref name="format"/> into <paramref name="stream"/>.</summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="image">The image.</param>
    /// <param name="format">JPEG or WebP.</param>
    /// <param name="quality">0–100; higher keeps more detail in a larger file.</param>
    public static void Write(Stream stream, Image image, Kind format, int quality)
    {
        using SKBitmap bitmap = image.ToSKBitmap();
        using SKPixmap pixmap = bitmap.PeekPixels();
        using SKData? data = format switch
        {
            // 4:4:4 keeps the colour of thin edges (a red sphere's outline) that 4:2:0 would smear over two pixels.
            Kind.Jpeg => pixmap.Encode(new SKJpegEncoderOptions(quality, SKJpegEncoderDownsample.Downsample444, SKJpegEncoderAlphaOption.Ignore)),
            Kind.Webp => pixmap.Encode(new SKWebpEncoderOptions(SKWebpEncoderCompression.Lossy, quality)),
            _ => throw new ArgumentOutOfRangeException(nameof(format), format, "Skia writes JPEG and WebP here; PNG and BMP have RayLab's own encoders."),
        };
        if (data is null)
        {
            throw new IOException($"SkiaSharp could not encode the {image.Width}×{image.Height} image as {format}.");
        }

        data.SaveTo(stream);
    }
}
