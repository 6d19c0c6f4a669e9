using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace RayLab.Tests.Shared;

/// <summary>
/// A deliberately small, strict PNG reader for the tests: 8-bit truecolour (colour type 2), no interlace only.
/// It shares no code with the library — the CRC is its own bitwise implementation and the filters are undone
/// straight from the PNG specification — so an encoder bug cannot be hidden by the same bug in the reader.
/// </summary>
internal static class PngTestDecoder
{
    public static readonly byte[] Signature = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];

    /// <summary>A decoded image: size, tightly packed RGB24 rows (top first), and the filter type of each row.</summary>
    public sealed record Result(int Width, int Height, byte[] Rgb, byte[] RowFilters, IReadOnlyList<string> ChunkTypes);

    /// <summary>Thrown for any malformed or unsupported input.</summary>
    public sealed class PngFormatException(string message) : Exception(message);

    /// <summary>CRC-32 (polynomial 0xEDB88320), bit by bit, no table.</summary>
    public static uint Crc32(ReadOnlySpan<byte> data)
    {
        uint crc = 0xFFFFFFFFu;
        foreach (byte b in data)
        {
            crc ^= b;
            for (int k = 0; k < 8; k++)
            {
                crc = (crc & 1) != 0 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
            }
        }

        return ~crc;
    }

    public static Result Decode(byte[] png)
    {
        ArgumentNullException.ThrowIfNull(png);
        if (png.Length < Signature.Length || !png.AsSpan(0, Signature.Length).SequenceEqual(Signature))
        {
            throw new PngFormatException("Bad PNG signature.");
        }

        var chunkTypes = new List<string>();
        var idat = new MemoryStream();
        int width = 0, height = 0;
        bool sawIend = false;
        int pos = Signature.Length;
        int? lastIdatIndex = null;

        while (pos < png.Length)
        {
            if (sawIend)
            {
                throw new PngFormatException("Data after IEND.");
            }

            if (png.Length - pos < 12)
            {
                throw new PngFormatException($"Truncated chunk header at offset {pos}.");
            }

            uint length = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(pos));
            if (length > int.MaxValue || length > png.Length - pos - 12)
            {
                throw new PngFormatException($"Chunk length {length} at offset {pos} runs past the end of the file.");
            }

            ReadOnlySpan<byte> typeAndData = png.AsSpan(pos + 4, 4 + (int)length);
            string type = Encoding.ASCII.GetString(typeAndData[..4]);
            foreach (char ch in type)
            {
                if (!char.IsAsciiLetter(ch))
                {
                    throw new PngFormatException($"Invalid chunk type '{type}'.");
                }
            }

            ReadOnlySpan<byte> data = typeAndData[4..];
            uint storedCrc = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(pos + 8 + (int)length));
            uint actualCrc = Crc32(typeAndData);
            if (storedCrc != actualCrc)
            {
                throw new PngFormatException($"CRC mismatch in {type}: stored {storedCrc:X8}, computed {actualCrc:X8}.");
            }

            if (chunkTypes.Count == 0 && type != "IHDR")
            {
                throw new PngFormatException($"First chunk is {type}, not IHDR.");
            }

            switch (type)
            {
                case "IHDR":
                    if (chunkTypes.Count != 0)
                    {
                        throw new PngFormatException("Duplicate IHDR.");
                    }

                    if (data.Length != 13)
                    {
                        throw new PngFormatException($"IHDR is {data.Length} bytes, not 13.");
                    }

                    uint w = BinaryPrimitives.ReadUInt32BigEndian(data);
                    uint h = BinaryPrimitives.ReadUInt32BigEndian(data[4..]);
                    if (w == 0 || h == 0 || w > int.MaxValue || h > int.MaxValue)
                    {
                        throw new PngFormatException($"Invalid size {w}×{h}.");
                    }

                    (width, height) = ((int)w, (int)h);
                    Expect(data[8], 8, "bit depth");
                    Expect(data[9], 2, "colour type");
                    Expect(data[10], 0, "compression method");
                    Expect(data[11], 0, "filter method");
                    Expect(data[12], 0, "interlace method");
                    break;
                case "IDAT":
                    if (lastIdatIndex is int last && last != chunkTypes.Count - 1)
                    {
                        throw new PngFormatException("IDAT chunks are not consecutive.");
                    }

                    lastIdatIndex = chunkTypes.Count;
                    idat.Write(data);
                    break;
                case "IEND":
                    if (data.Length != 0)
                    {
                        throw new PngFormatException("IEND has data.");
                    }

                    sawIend = true;
                    break;
                default:
                    if (char.IsAsciiLetterUpper(type[0]))
                    {
                        throw new PngFormatException($"Unknown critical chunk {type}.");
                    }

                    break; // ancillary: ignored
            }

            chunkTypes.Add(type);
            pos += 12 + (int)length;
        }

        if (!sawIend)
        {
            throw new PngFormatException("No IEND chunk (or IEND is not last).");
        }

        if (lastIdatIndex is null)
        {
            throw new PngFormatException("No IDAT chunk.");
        }

        byte[] raw = Inflate(idat.ToArray());
        int rowBytes = checked(width * 3);
        long expected = (long)height * (rowBytes + 1);
        if (raw.LongLength != expected)
        {
            throw new PngFormatException($"Decompressed {raw.LongLength} bytes, expected {expected}.");
        }

        var rgb = new byte[(long)rowBytes * height];
        var filters = new byte[height];
        Unfilter(raw, rgb, filters, rowBytes, height);
        return new Result(width, height, rgb, filters, chunkTypes);
    }

    private static void Expect(byte actual, byte expected, string what)
    {
        if (actual != expected)
        {
            throw new PngFormatException($"IHDR {what} is {actual}, expected {expected}.");
        }
    }

    private static byte[] Inflate(byte[] zlibData)
    {
        using var input = new MemoryStream(zlibData);
        using var zlib = new ZLibStream(input, CompressionMode.Decompress);
        using var output = new MemoryStream();
        zlib.CopyTo(output);
        return output.ToArray();
    }

    /// <summary>Undoes filter types 0–4 of PNG filter method 0 (bytes per pixel 3).</summary>
    private static void Unfilter(byte[] raw, byte[] rgb, byte[] filters, int rowBytes, int height)
    {
        const int Bpp = 3;
        for (int y = 0; y < height; y++)
        {
            int src = y * (rowBytes + 1);
            int dst = y * rowBytes;
            byte filter = raw[src];
            if (filter > 4)
            {
                throw new PngFormatException($"Row {y} has unknown filter type {filter}.");
            }

            filters[y] = filter;
            for (int i = 0; i < rowBytes; i++)
            {
                int x = raw[src + 1 + i];
                int a = i >= Bpp ? rgb[dst + i - Bpp] : 0;
                int b = y > 0 ? rgb[dst - rowBytes + i] : 0;
                int c = i >= Bpp && y > 0 ? rgb[dst - rowBytes + i - Bpp] : 0;
                int predicted = filter switch
                {
                    0 => 0,
                    1 => a,
                    2 => b,
                    3 => (a + b) / 2,
                    _ => PaethPredictor(a, b, c),
                };
                rgb[dst + i] = (byte)((x + predicted) & 0xFF);
            }
        }
    }

    /// <summary>The Paeth predictor exactly as written in the PNG specification (section 9.4).</summary>
    public static int PaethPredictor(int a, int b, int c)
    {
        int p = a + b - c;
        int pa = Math.Abs(p - a);
        int pb = Math.Abs(p - b);
        int pc = Math.Abs(p - c);
        if (pa <= pb && pa <= pc)
        {
            return a;
        }

        if (pb <= pc)
        {
            return b;
        }

        return c;
    }

    /// <summary>Builds a chunk (length, type, data, CRC) for hand-made test files.</summary>
    public static byte[] Chunk(string type, ReadOnlySpan<byte> data)
    {
        var chunk = new byte[12 + data.Length];
        BinaryPrimitives.WriteUInt32BigEndian(chunk, (uint)data.Length);
        Encoding.ASCII.GetBytes(type, chunk.AsSpan(4, 4));
        data.CopyTo(chunk.AsSpan(8));
        BinaryPrimitives.WriteUInt32BigEndian(chunk.AsSpan(8 + data.Length), Crc32(chunk.AsSpan(4, 4 + data.Length)));
        return chunk;
    }

    /// <summary>Compresses already-filtered scanlines (filter byte first on each row) with ZLibStream.</summary>
    public static byte[] Deflate(ReadOnlySpan<byte> filteredRows)
    {
        using var output = new MemoryStream();
        using (var zlib = new ZLibStream(output, CompressionLevel.Optimal, leaveOpen: true))
        {
            zlib.Write(filteredRows);
        }

        return output.ToArray();
    }

    /// <summary>Builds the 13-byte IHDR payload.</summary>
    public static byte[] Ihdr(int width, int height, byte bitDepth = 8, byte colourType = 2, byte compression = 0, byte filter = 0, byte interlace = 0)
    {
        var ihdr = new byte[13];
        BinaryPrimitives.WriteInt32BigEndian(ihdr, width);
        BinaryPrimitives.WriteInt32BigEndian(ihdr.AsSpan(4), height);
        ihdr[8] = bitDepth;
        ihdr[9] = colourType;
        ihdr[10] = compression;
        ihdr[11] = filter;
        ihdr[12] = interlace;
        return ihdr;
    }
}
