using System.Buffers.Binary;

namespace RayLab.Tests.Imaging;

/// <summary>
/// A strict reader for exactly the BMP RayLab writes: BITMAPFILEHEADER + BITMAPINFOHEADER (40 bytes), positive
/// height (bottom-up rows), 24 bits per pixel, BI_RGB, rows of BGR padded with zeros to a multiple of 4 bytes.
/// </summary>
internal static class BmpTestDecoder
{
    public const int HeaderSize = 54;

    /// <summary>A decoded image: size, tightly packed RGB24 rows (top first), and the padding bytes per row.</summary>
    public sealed record Result(int Width, int Height, byte[] Rgb, int Stride, int PaddingPerRow);

    public sealed class BmpFormatException(string message) : Exception(message);

    public static int StrideFor(int width) => ((width * 3) + 3) / 4 * 4;

    public static Result Decode(byte[] bmp)
    {
        ArgumentNullException.ThrowIfNull(bmp);
        if (bmp.Length < HeaderSize)
        {
            throw new BmpFormatException($"File is {bmp.Length} bytes, shorter than the 54-byte headers.");
        }

        ReadOnlySpan<byte> file = bmp;
        Check(file[0] == (byte)'B' && file[1] == (byte)'M', "magic is not 'BM'");
        uint fileSize = BinaryPrimitives.ReadUInt32LittleEndian(file[2..]);
        Check(fileSize == (uint)bmp.Length, $"file size field {fileSize} != actual length {bmp.Length}");
        Check(BinaryPrimitives.ReadUInt32LittleEndian(file[6..]) == 0, "reserved fields are not 0");
        uint offset = BinaryPrimitives.ReadUInt32LittleEndian(file[10..]);
        Check(offset == HeaderSize, $"pixel data offset {offset} != 54");

        uint infoSize = BinaryPrimitives.ReadUInt32LittleEndian(file[14..]);
        Check(infoSize == 40, $"info header size {infoSize} != 40 (BITMAPINFOHEADER)");
        int width = BinaryPrimitives.ReadInt32LittleEndian(file[18..]);
        int height = BinaryPrimitives.ReadInt32LittleEndian(file[22..]);
        Check(width > 0, $"width {width} is not positive");
        Check(height > 0, $"height {height} is not positive (expected bottom-up rows)");
        Check(BinaryPrimitives.ReadUInt16LittleEndian(file[26..]) == 1, "planes != 1");
        ushort bpp = BinaryPrimitives.ReadUInt16LittleEndian(file[28..]);
        Check(bpp == 24, $"bits per pixel {bpp} != 24");
        uint compression = BinaryPrimitives.ReadUInt32LittleEndian(file[30..]);
        Check(compression == 0, $"compression {compression} != BI_RGB (0)");

        int rowBytes = width * 3;
        int stride = StrideFor(width);
        Check(stride % 4 == 0 && stride >= rowBytes && stride - rowBytes < 4, "internal stride computation");
        long expectedLength = HeaderSize + ((long)stride * height);
        Check(bmp.Length == expectedLength, $"length {bmp.Length} != 54 + stride {stride} × height {height}");
        uint imageSize = BinaryPrimitives.ReadUInt32LittleEndian(file[34..]);
        Check(imageSize == 0 || imageSize == (uint)(stride * (long)height), $"biSizeImage {imageSize} != {stride * (long)height}");
        uint colorsUsed = BinaryPrimitives.ReadUInt32LittleEndian(file[46..]);
        Check(colorsUsed == 0, $"biClrUsed {colorsUsed} != 0");

        var rgb = new byte[(long)rowBytes * height];
        for (int fileRow = 0; fileRow < height; fileRow++)
        {
            int y = height - 1 - fileRow; // bottom-up: the first stored row is the bottom of the image
            ReadOnlySpan<byte> row = file.Slice(HeaderSize + (fileRow * stride), stride);
            for (int x = 0; x < width; x++)
            {
                int dst = ((y * width) + x) * 3;
                rgb[dst] = row[(x * 3) + 2];     // R
                rgb[dst + 1] = row[(x * 3) + 1]; // G
                rgb[dst + 2] = row[x * 3];       // B
            }

            foreach (byte pad in row[rowBytes..])
            {
                Check(pad == 0, $"padding byte in stored row {fileRow} is {pad}, not 0");
            }
        }

        return new Result(width, height, rgb, stride, stride - rowBytes);
    }

    private static void Check(bool condition, string message)
    {
        if (!condition)
        {
            throw new BmpFormatException("Invalid BMP: " + message + ".");
        }
    }
}
