using System.Runtime.InteropServices;
using SkiaSharp;

namespace RayLab.Reports.Imaging;

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

        /// <summary>
        /// Reads a picture file into a new <see cref="Image"/>: PNG, JPEG, WebP, BMP or GIF (its first frame), decoded
        /// by SkiaSharp to 8-bit RGB as stored, without colour management (as FLIP's tool and the lab read pictures); an
        /// alpha channel is dropped. The whole file must decode: a file cut short is an error, not a partial image.
        /// </summary>
        /// <param name="path">The file.</param>
        /// <returns>The picture.</returns>
        /// <exception cref="FileNotFoundException">There is no such file.</exception>
        /// <exception cref="IOException">The file cannot be read.</exception>
        /// <exception cref="UnauthorizedAccessException">The file may not be read.</exception>
        /// <exception cref="InvalidDataException">The file is not a picture SkiaSharp decodes, is cut short or damaged, or has more than 2³¹ / 4 pixels (each message names the file).</exception>
        public static Image Load(string path)
        {
            ArgumentException.ThrowIfNullOrWhiteSpace(path);
            if (Directory.Exists(path))
            {
                throw new UnauthorizedAccessException($"{path}: is a folder, not a picture");
            }

            return Decode(File.ReadAllBytes(path), path, int.MaxValue, int.MaxValue);
        }

        /// <summary>
        /// Reads a picture held in memory into a new <see cref="Image"/>, as <see cref="Load(string)"/> reads a file,
        /// but only one of at most <paramref name="maxWidth"/>×<paramref name="maxHeight"/> pixels: the size is read
        /// from the picture's header, and a larger picture is refused before any pixel is decoded or any memory is
        /// taken for its pixels. For pictures from a source you do not trust, whose header may claim any size (a PNG
        /// of 74 bytes can claim 23000×23000 pixels, 2 GB to decode into).
        /// </summary>
        /// <param name="data">The picture file's bytes.</param>
        /// <param name="name">The picture's name in messages (its file, for example).</param>
        /// <param name="maxWidth">The widest picture read, ≥ 1.</param>
        /// <param name="maxHeight">The tallest picture read, ≥ 1.</param>
        /// <returns>The picture.</returns>
        /// <exception cref="ArgumentOutOfRangeException">A largest size is less than 1.</exception>
        /// <exception cref="InvalidDataException">
        /// The data is not a picture SkiaSharp decodes, is cut short or damaged, is larger than
        /// <paramref name="maxWidth"/>×<paramref name="maxHeight"/> or has more than 2³¹ / 4 pixels (each message
        /// starts with <paramref name="name"/>).
        /// </exception>
        public static Image Load(ReadOnlySpan<byte> data, string name, int maxWidth, int maxHeight)
        {
            ArgumentNullException.ThrowIfNull(name);
            ArgumentOutOfRangeException.ThrowIfLessThan(maxWidth, 1);
            ArgumentOutOfRangeException.ThrowIfLessThan(maxHeight, 1);
            return Decode(data, name, maxWidth, maxHeight);
        }
    }

    /// <summary>
    /// The size a picture held in memory claims in its header (PNG, JPEG, WebP, BMP or GIF), read without decoding a
    /// pixel: what a caller checks before it decodes a picture from a source it does not trust.
    /// </summary>
    /// <param name="data">The picture file's bytes.</param>
    /// <returns>The width and height its header claims, or null when SkiaSharp does not take it for a picture.</returns>
    public static (int Width, int Height)? ReadSize(ReadOnlySpan<byte> data)
    {
        if (data.IsEmpty)
        {
            return null;
        }

        using SKData copy = SKData.CreateCopy(data);
        using SKCodec? codec = SKCodec.Create(copy);
        return codec is null ? null : (codec.Info.Width, codec.Info.Height);
    }

    private static Image Decode(ReadOnlySpan<byte> bytes, string name, int maxWidth, int maxHeight)
    {
        using SKData data = SKData.CreateCopy(bytes);
        using SKCodec? codec = bytes.Length == 0 ? null : SKCodec.Create(data);
        if (codec is null)
        {
            throw new InvalidDataException($"{name}: not a picture (expected PNG, JPEG, WebP, BMP or GIF)");
        }

        // The header's size, before anything is allocated for the pixels.
        int width = codec.Info.Width, height = codec.Info.Height;
        if (width > maxWidth || height > maxHeight)
        {
            throw new InvalidDataException($"{name}: a {width}×{height} picture is larger than the {maxWidth}×{maxHeight} read here; not decoded");
        }

        // Decoded as RGBA first: four bytes a pixel must fit in one array.
        if (width < 1 || height < 1 || (long)width * height * 4 > Array.MaxLength)
        {
            throw new InvalidDataException($"{name}: a {width}×{height} picture is more than can be read (at most {Array.MaxLength / 4:N0} pixels)");
        }

        var info = new SKImageInfo(width, height, SKColorType.Rgba8888, SKAlphaType.Unpremul);
        byte[] rgba = new byte[info.BytesSize64];
        GCHandle pin = GCHandle.Alloc(rgba, GCHandleType.Pinned);
        SKCodecResult result;
        try
        {
            result = codec.GetPixels(info, pin.AddrOfPinnedObject());
        }
        finally
        {
            pin.Free();
        }

        if (result != SKCodecResult.Success)
        {
            throw new InvalidDataException(result == SKCodecResult.IncompleteInput
                ? $"{name}: the picture's data is cut short"
                : $"{name}: the picture cannot be decoded ({result})");
        }

        var picture = new Image(width, height);
        Span<byte> target = picture.PixelBytes;
        for (int y = 0; y < height; y++)
        {
            DropAlpha(rgba.AsSpan(y * info.RowBytes, width * 4), target.Slice(y * width * 3, width * 3));
        }

        return picture;
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
