using SkiaSharp;

namespace RayLab.Tests.Shared;

/// <summary>
/// Decodes PNG, BMP, JPEG and WebP files with SkiaSharp — a decoder independent of RayLab's encoders and of its
/// <c>SKBitmap</c> conversion — into tightly packed RGB24 rows, top row first.
/// </summary>
internal static class SkiaDecode
{
    /// <summary>A decoded image: its size and its RGB24 bytes.</summary>
    public sealed record Result(int Width, int Height, byte[] Rgb, SKEncodedImageFormat Format);

    public static Result Decode(byte[] encoded)
    {
        using var codec = SKCodec.Create(new SKMemoryStream(encoded)) ?? throw new InvalidDataException("SkiaSharp does not recognise the data as an image.");
        var info = new SKImageInfo(codec.Info.Width, codec.Info.Height, SKColorType.Rgba8888, SKAlphaType.Unpremul);
        using var bitmap = new SKBitmap(info);
        SKCodecResult result = codec.GetPixels(info, bitmap.GetPixels());
        if (result != SKCodecResult.Success)
        {
            throw new InvalidDataException($"SkiaSharp could not decode the {codec.EncodedFormat} image: {result}.");
        }

        ReadOnlySpan<byte> rgba = bitmap.GetPixelSpan();
        byte[] rgb = new byte[info.Width * info.Height * 3];
        for (int y = 0; y < info.Height; y++)
        {
            for (int x = 0; x < info.Width; x++)
            {
                int from = (y * bitmap.RowBytes) + (x * 4), to = ((y * info.Width) + x) * 3;
                rgb[to] = rgba[from];
                rgb[to + 1] = rgba[from + 1];
                rgb[to + 2] = rgba[from + 2];
            }
        }

        return new Result(info.Width, info.Height, rgb, codec.EncodedFormat);
    }

    public static Result Load(string path) => Decode(File.ReadAllBytes(path));
}
