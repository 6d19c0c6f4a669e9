using System.Runtime.InteropServices;
using SkiaSharp;

namespace RayLab.Imaging;

/// <summary>
/// The lab's image (<see cref="Image"/>) to and from SkiaSharp's <see cref="SKBitmap"/>, for a student who wants to
/// show the picture in a window, draw on it or post-process it with Skia. Each row is converted in one bulk pass
/// (RGB24 ↔ RGBA8888); there are no per-pixel calls.
/// </summary>
public static class SkiaBitmaps
{
    extension(Image image)
    {
        /// <summary>A new opaque RGBA8888 <see cref="SKBitmap"/> with the image's pixels (the caller disposes it).</summary>
        /// <returns>A bitmap of the same size.</returns>
        public SKBitmap ToSKBitmap()
        {
            ArgumentNullException.ThrowIfNull(image);
            var bitmap = new SKBitmap(new SKImageInfo(image.Width, image.Height, SKColorType.Rgba8888, SKAlphaType.Opaque));
            Span<byte> target = bitmap.GetPixelSpan();
            int rowBytes = bitmap.RowBytes;
            ReadOnlySpan<byte> source = image.PixelBytes;
            int width = image.Width;
            for (int y = 0; y < image.Height; y++)
            {
                ExpandRow(source.Slice(y * width * 3, width * 3), target.Slice(y * rowBytes, width * 4));
            }

            return bitmap;
        }

        /// <summary>
        /// Copies a Skia bitmap of any colour type into a new <see cref="Image"/>: Skia converts it to RGBA8888
        /// (unpremultiplied) and the alpha channel is dropped.
        /// </summary>
        /// <param name="bitmap">The bitmap.</param>
        /// <returns>An image of the same size.</returns>
        /// <exception cref="ArgumentException">The bitmap is empty or Skia cannot convert its pixels.</exception>
        public static Image FromSKBitmap(SKBitmap bitmap)
        {
            ArgumentNullException.ThrowIfNull(bitmap);
            if (bitmap.Width < 1 || bitmap.Height < 1)
            {
                throw new ArgumentException($"The bitmap is {bitmap.Width}×{bitmap.Height}; an image needs at least 1×1 pixels.", nameof(bitmap));
            }

            var copy = new Image(bitmap.Width, bitmap.Height);
            var info = new SKImageInfo(bitmap.Width, bitmap.Height, SKColorType.Rgba8888, SKAlphaType.Unpremul);
            byte[] rgba = new byte[info.BytesSize64];
            GCHandle pin = GCHandle.Alloc(rgba, GCHandleType.Pinned);
            try
            {
                using SKPixmap pixmap = bitmap.PeekPixels();
                if (pixmap is null || !pixmap.ReadPixels(info, pin.AddrOfPinnedObject(), info.RowBytes))
                {
                    throw new ArgumentException($"SkiaSharp cannot convert a {bitmap.ColorType} bitmap to RGBA8888.", nameof(bitmap));
                }
            }
            finally
            {
                pin.Free();
            }

            Span<byte> target = copy.PixelBytes;
            int width = copy.Width;
            for (int y = 0; y < copy.Height; y++)
            {
                DropAlpha(rgba.AsSpan(y * info.RowBytes, width * 4), target.Slice(y * width * 3, width * 3));
            }

            return copy;
        }
    }

    private static void ExpandRow(ReadOnlySpan<byte> rgb, Span<byte> rgba)
    {
        for (int i = 0, j = 0; i < rgb.Length; i += 3, j += 4)
        {
            rgba[j] = rgb[i];
            rgba[j + 1] = rgb[i + 1];
            rgba[j + 2] = rgb[i + 2];
            rgba[j + 3] = 255;
        }
    }

    private static void DropAlpha(ReadOnlySpan<byte> rgba, Span<byte> rgb)
    {
        for (int i = 0, j = 0; j < rgb.Length; i += 4, j += 3)
        {
            rgb[j] = rgba[i];
            rgb[j + 1] = rgba[i + 1];
            rgb[j + 2] = rgba[i + 2];
        }
    }
}
