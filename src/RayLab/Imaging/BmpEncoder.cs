using System.Buffers.Binary;

namespace RayLab.Imaging;

/// <summary>Writes 24-bit uncompressed BMP (BITMAPINFOHEADER, bottom-up rows, BGR, rows padded to 4 bytes).</summary>
internal static class BmpEncoder
{
    private const int HeaderSize = 14 + 40;

    /// <summary>Writes <paramref name="image"/> to <paramref name="stream"/> as BMP.</summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="image">The image.</param>
    /// <exception cref="ArgumentException">The file would exceed BMP's 4 GiB size field.</exception>
    public static void Write(Stream stream, Image image)
    {
        ArgumentNullException.ThrowIfNull(stream);
        ArgumentNullException.ThrowIfNull(image);
        int rowBytes = image.Width * 3;
        int stride = (rowBytes + 3) & ~3;
        long fileSize = HeaderSize + ((long)stride * image.Height);
        if (fileSize > uint.MaxValue)
        {
            throw new ArgumentException($"A {image.Width}×{image.Height} BMP would exceed 4 GiB; use PNG.", nameof(image));
        }

        Span<byte> header = stackalloc byte[HeaderSize];
        header.Clear();
        header[0] = (byte)'B';
        header[1] = (byte)'M';
        BinaryPrimitives.WriteUInt32LittleEndian(header[2..], (uint)fileSize);
        BinaryPrimitives.WriteUInt32LittleEndian(header[10..], HeaderSize);
        BinaryPrimitives.WriteUInt32LittleEndian(header[14..], 40);              // BITMAPINFOHEADER size
        BinaryPrimitives.WriteInt32LittleEndian(header[18..], image.Width);
        BinaryPrimitives.WriteInt32LittleEndian(header[22..], image.Height);     // positive: bottom-up
        BinaryPrimitives.WriteUInt16LittleEndian(header[26..], 1);               // planes
        BinaryPrimitives.WriteUInt16LittleEndian(header[28..], 24);              // bits per pixel
        BinaryPrimitives.WriteUInt32LittleEndian(header[34..], (uint)(stride * (long)image.Height));
        BinaryPrimitives.WriteInt32LittleEndian(header[38..], 2835);             // 72 dpi
        BinaryPrimitives.WriteInt32LittleEndian(header[42..], 2835);
        stream.Write(header);

        byte[] row = new byte[stride];
        for (int y = image.Height - 1; y >= 0; y--)
        {
            ReadOnlySpan<Rgb24> source = image.GetRowSpan(y);
            for (int x = 0, i = 0; x < source.Length; x++, i += 3)
            {
                row[i] = source[x].B;
                row[i + 1] = source[x].G;
                row[i + 2] = source[x].R;
            }

            stream.Write(row);
        }
    }
}
