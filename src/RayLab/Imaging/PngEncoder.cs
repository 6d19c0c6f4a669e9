using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace RayLab.Imaging;

/// <summary>
/// Writes 8-bit RGB PNG: signature, IHDR, one IDAT compressed by the runtime's <see cref="ZLibStream"/>, IEND.
/// Each row gets the filter (None, Sub, Up, Average, Paeth) with the smallest sum of absolute values — the
/// heuristic the PNG specification recommends for truecolour images.
/// </summary>
public static class PngEncoder
{
    private static readonly byte[] Signature = [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    /// <summary>Writes <paramref name="image"/> to <paramref name="stream"/> as PNG.</summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="image">The image.</param>
    /// <param name="level">The DEFLATE compression level.</param>
    public static void Write(Stream stream, Image image, CompressionLevel level = CompressionLevel.Optimal)
    {
        ArgumentNullException.ThrowIfNull(stream);
        ArgumentNullException.ThrowIfNull(image);
        stream.Write(Signature);

        Span<byte> ihdr = stackalloc byte[13];
        BinaryPrimitives.WriteInt32BigEndian(ihdr, image.Width);
        BinaryPrimitives.WriteInt32BigEndian(ihdr[4..], image.Height);
        ihdr[8] = 8;  // bit depth
        ihdr[9] = 2;  // colour type: truecolour
        ihdr[10] = 0; // compression: DEFLATE
        ihdr[11] = 0; // filter method 0
        ihdr[12] = 0; // no interlace
        WriteChunk(stream, "IHDR", ihdr);

        using var compressed = new MemoryStream();
        using (var zlib = new ZLibStream(compressed, level, leaveOpen: true))
        {
            int rowBytes = image.Width * 3;
            byte[] previous = new byte[rowBytes];
            byte[] best = new byte[rowBytes + 1];
            byte[] trial = new byte[rowBytes + 1];
            ReadOnlySpan<byte> pixels = image.PixelBytes;
            for (int y = 0; y < image.Height; y++)
            {
                ReadOnlySpan<byte> row = pixels.Slice(y * rowBytes, rowBytes);
                long bestScore = long.MaxValue;
                for (byte filter = 0; filter <= 4; filter++)
                {
                    long score = Filter(filter, row, previous, trial);
                    if (score < bestScore)
                    {
                        bestScore = score;
                        (best, trial) = (trial, best);
                    }
                }

                zlib.Write(best);
                row.CopyTo(previous);
            }
        }

        WriteChunk(stream, "IDAT", compressed.GetBuffer().AsSpan(0, (int)compressed.Length));
        WriteChunk(stream, "IEND", []);
    }

    /// <summary>Applies PNG filter <paramref name="type"/> to one row into <paramref name="output"/> (type byte first).</summary>
    /// <returns>The sum of the filtered bytes taken as signed values (smaller compresses better).</returns>
    private static long Filter(byte type, ReadOnlySpan<byte> row, ReadOnlySpan<byte> up, Span<byte> output)
    {
        const int Bpp = 3;
        output[0] = type;
        long score = 0;
        for (int i = 0; i < row.Length; i++)
        {
            int a = i >= Bpp ? row[i - Bpp] : 0;
            int b = up[i];
            int c = i >= Bpp ? up[i - Bpp] : 0;
            int predictor = type switch
            {
                0 => 0,
                1 => a,
                2 => b,
                3 => (a + b) >> 1,
                _ => Paeth(a, b, c),
            };
            byte value = (byte)(row[i] - predictor);
            output[i + 1] = value;
            score += value < 128 ? value : 256 - value; // |value| taken as a signed byte
        }

        return score;
    }

    /// <summary>The Paeth predictor of the PNG specification.</summary>
    internal static int Paeth(int a, int b, int c)
    {
        int p = a + b - c;
        int pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
        return pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
    }

    private static void WriteChunk(Stream stream, string type, ReadOnlySpan<byte> data)
    {
        Span<byte> header = stackalloc byte[8];
        BinaryPrimitives.WriteInt32BigEndian(header, data.Length);
        Encoding.ASCII.GetBytes(type, header[4..]);
        stream.Write(header);
        stream.Write(data);
        uint crc = Crc32.Update(Crc32.Update(0xFFFFFFFFu, header[4..]), data) ^ 0xFFFFFFFFu;
        Span<byte> crcBytes = stackalloc byte[4];
        BinaryPrimitives.WriteUInt32BigEndian(crcBytes, crc);
        stream.Write(crcBytes);
    }
}
