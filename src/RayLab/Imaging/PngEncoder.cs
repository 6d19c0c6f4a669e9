using System.Buffers;
using System.Buffers.Binary;
using System.IO.Compression;
using System.IO.Hashing;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;
using System.Text;

namespace RayLab.Imaging;

/// <summary>
/// Writes 8-bit RGB PNG (the lab's image file): signature, IHDR, the filtered rows as one zlib stream, IEND.
/// The rows are cut into bands of about <see cref="BandBytes"/> bytes, and every band is filtered, DEFLATE-compressed
/// (the runtime's <see cref="DeflateStream"/>) and Adler-32-summed on its own, on every core. The bands join into one
/// valid zlib stream as pigz joins them: each band but the last ends with a sync flush (an empty stored block, so it
/// ends on a byte), only the last one ends with a final block, and the stream's Adler-32 is the bands' sums combined.
/// Each band is written as one IDAT chunk. The bands depend only on the image's width, so the file is the same bytes
/// whatever the thread count.
/// </summary>
internal static class PngEncoder
{
    /// <summary>
    /// About how many filtered bytes one band holds (whole rows, at least one): 512 KiB, 12 bands for a 1920×1080
    /// picture — enough to share among cores (each band restarts DEFLATE's window, which costs a flat-coloured picture little).
    /// </summary>
    internal const int BandBytes = 1 << 19;

    /// <summary>About how many filtered bytes a band filters, sums and compresses at a time (whole rows, at least one): 64 KiB.</summary>
    private const int ChunkBytes = 1 << 16;

    /// <summary>The capacity a band's DEFLATE output starts with: 4 KiB.</summary>
    private const int InitialDeflatedBytes = 1 << 12;

    private static readonly byte[] Signature = [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    /// <summary>Writes <paramref name="image"/> to <paramref name="stream"/> as PNG.</summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="image">The image.</param>
    /// <param name="level">
    /// The DEFLATE compression level. <see cref="CompressionLevel.Optimal"/>, the balance of speed and size, is zlib
    /// level 4 here rather than the runtime's 6: on the rendered 1080p two-sphere pictures (jittered and exact) level 6
    /// took 1.2–1.6× the time for 1–2 % fewer bytes (docs/performance.md, "PNG": ZlibLevelBenchmarks).
    /// <see cref="CompressionLevel.Fastest"/> is level 1, <see cref="CompressionLevel.SmallestSize"/> level 9.
    /// </param>
    /// <param name="filter">
    /// The row filter. The default, <see cref="PngFilter.Up"/>, was measured on the rendered 1920×1080 two-sphere
    /// picture (docs/performance.md: BenchmarkDotNet's PngBenchmarks and <c>-- png-sizes</c>): the smallest file of
    /// the filters at <see cref="CompressionLevel.Optimal"/> and about 5× faster than trying all five per row
    /// (<see cref="PngFilter.Adaptive"/>), because a flat-coloured picture is mostly rows equal to the row above.
    /// </param>
    /// <param name="maxDegreeOfParallelism">The most bands encoded at once: −1 (the default) for every core, or ≥ 1. It changes the speed only, never the bytes.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="maxDegreeOfParallelism"/> is 0 or below −1, or <paramref name="level"/> is not a <see cref="CompressionLevel"/>.</exception>
    public static void Write(Stream stream, Image image, CompressionLevel level = CompressionLevel.Optimal, PngFilter filter = PngFilter.Up, int maxDegreeOfParallelism = -1)
    {
        ArgumentNullException.ThrowIfNull(stream);
        ArgumentNullException.ThrowIfNull(image);
        if (maxDegreeOfParallelism is 0 or < -1)
        {
            throw new ArgumentOutOfRangeException(nameof(maxDegreeOfParallelism), maxDegreeOfParallelism, "Must be -1 (every core) or at least 1.");
        }

        int zlibLevel = ZlibLevel(level);
        stream.Write(Signature);
        WriteHeader(stream, image);
        byte[] zlibHeader = ZlibHeader(zlibLevel);
        Band[] bands = EncodeBands(image, zlibLevel, filter, zlibHeader, maxDegreeOfParallelism);
        WriteData(stream, bands, zlibHeader);
        WriteChunk(stream, "IEND", []);
    }

    /// <summary>The IHDR chunk: the image's size, 8-bit truecolour, DEFLATE, filter method 0, no interlace.</summary>
    private static void WriteHeader(Stream stream, Image image)
    {
        Span<byte> ihdr = stackalloc byte[13];
        BinaryPrimitives.WriteInt32BigEndian(ihdr, image.Width);
        BinaryPrimitives.WriteInt32BigEndian(ihdr[4..], image.Height);
        ihdr[8] = 8;  // bit depth
        ihdr[9] = 2;  // colour type: truecolour
        ihdr[10] = 0; // compression: DEFLATE
        ihdr[11] = 0; // filter method 0
        ihdr[12] = 0; // no interlace
        WriteChunk(stream, "IHDR", ihdr);
    }

    /// <summary>Filters and compresses the image's bands, on up to <paramref name="maxDegreeOfParallelism"/> threads.</summary>
    private static Band[] EncodeBands(Image image, int zlibLevel, PngFilter filter, byte[] zlibHeader, int maxDegreeOfParallelism)
    {
        int rowsPerBand = RowsPerBand(image.Width);
        int bandCount = (int)(((long)image.Height + rowsPerBand - 1) / rowsPerBand);
        var bands = new Band[bandCount];
        if (bandCount == 1 || maxDegreeOfParallelism == 1)
        {
            for (int i = 0; i < bandCount; i++)
            {
                bands[i] = EncodeBand(image, i, rowsPerBand, bandCount, zlibLevel, filter, zlibHeader);
            }
        }
        else
        {
            // −1 is one band per core at a time: left unlimited, Parallel.For takes every thread-pool thread it finds
            // (three workers on two cores after a render), and each thread's zlib state costs fresh pages.
            int threads = maxDegreeOfParallelism == -1 ? Environment.ProcessorCount : maxDegreeOfParallelism;
            Parallel.For(0, bandCount, new ParallelOptions { MaxDegreeOfParallelism = threads },
                i => bands[i] = EncodeBand(image, i, rowsPerBand, bandCount, zlibLevel, filter, zlibHeader));
        }

        return bands;
    }

    /// <summary>The IDAT chunks, one a band: the zlib stream's header, the bands' DEFLATE data in order, the Adler-32 of all the filtered bytes.</summary>
    private static void WriteData(Stream stream, Band[] bands, byte[] zlibHeader)
    {
        int bandCount = bands.Length;
        uint adler = bands[0].Adler;
        for (int i = 1; i < bandCount; i++)
        {
            adler = Adler32Combine.Combine(adler, bands[i].Adler, bands[i].FilteredLength);
        }

        Span<byte> trailer = stackalloc byte[4];
        BinaryPrimitives.WriteUInt32BigEndian(trailer, adler);
        Span<byte> header = stackalloc byte[8];
        for (int i = 0; i < bandCount; i++)
        {
            Band band = bands[i];
            bool first = i == 0, last = i == bandCount - 1;
            ReadOnlySpan<byte> data = band.Deflated.AsSpan(0, band.DeflatedLength);
            BinaryPrimitives.WriteInt32BigEndian(header, data.Length + (first ? zlibHeader.Length : 0) + (last ? trailer.Length : 0));
            Encoding.ASCII.GetBytes("IDAT", header[4..]);
            stream.Write(header);
            if (first)
            {
                stream.Write(zlibHeader);
            }

            stream.Write(data);
            Crc32 crc = band.Crc;
            if (last)
            {
                stream.Write(trailer);
                crc.Append(trailer);
            }

            WriteCrc(stream, crc);
        }
    }

    /// <summary>The rows in one band of an image <paramref name="width"/> pixels wide: <see cref="BandBytes"/> filtered bytes' worth, at least 1.</summary>
    internal static int RowsPerBand(int width) => Math.Max(1, BandBytes / ((width * 3) + 1));

    /// <summary>
    /// The zlib header (CMF, FLG) for a zlib level, as zlib writes it: deflate with a 32 KiB window (0x78), then the
    /// level's class in FLG's top two bits (0 for levels 0–1, 1 for 2–5, 2 for 6, 3 for 7–9; informative only) and
    /// the check bits that make CMF·256 + FLG a multiple of 31.
    /// </summary>
    private static byte[] ZlibHeader(int zlibLevel)
    {
        const int cmf = 0x78;
        int levelClass = zlibLevel < 2 ? 0 : zlibLevel < 6 ? 1 : zlibLevel == 6 ? 2 : 3;
        int flags = levelClass << 6;
        flags += (31 - (((cmf << 8) + flags) % 31)) % 31;
        return [cmf, (byte)flags];
    }

    /// <summary>The zlib level <paramref name="level"/> stands for here: <see cref="CompressionLevel.Optimal"/> is level 4 (see <see cref="Write"/>).</summary>
    internal static int ZlibLevel(CompressionLevel level) => level switch
    {
        CompressionLevel.NoCompression => 0,
        CompressionLevel.Fastest => 1,
        CompressionLevel.SmallestSize => 9,
        CompressionLevel.Optimal => OptimalZlibLevel,
        _ => throw new ArgumentOutOfRangeException(nameof(level), level, "Not a CompressionLevel."),
    };

    /// <summary>The zlib level of <see cref="CompressionLevel.Optimal"/>.</summary>
    private const int OptimalZlibLevel = 4;

    /// <summary>One band's output: its DEFLATE data, the running CRC of its IDAT chunk so far, and its filtered bytes' Adler-32 and length.</summary>
    private readonly record struct Band(byte[] Deflated, int DeflatedLength, Crc32 Crc, uint Adler, int FilteredLength);

    /// <summary>
    /// Filters, sums and compresses band <paramref name="index"/>, <see cref="ChunkBytes"/> of filtered rows at a time
    /// (so the filtered bytes stay in cache and no band-sized buffer is ever committed); every band but the last ends
    /// with a sync flush.
    /// </summary>
    private static Band EncodeBand(Image image, int index, int rowsPerBand, int bandCount, int zlibLevel, PngFilter filter, byte[] zlibHeader)
    {
        int rowBytes = image.Width * 3;
        int filteredRowBytes = rowBytes + 1;
        int y0 = index * rowsPerBand;
        int rows = Math.Min(rowsPerBand, image.Height - y0);
        int rowsPerChunk = Math.Min(rows, Math.Max(1, ChunkBytes / filteredRowBytes));
        byte[] chunk = ArrayPool<byte>.Shared.Rent(rowsPerChunk * filteredRowBytes);
        byte[]? trial = filter == PngFilter.Adaptive ? ArrayPool<byte>.Shared.Rent(filteredRowBytes) : null;
        byte[] zeros = y0 == 0 ? new byte[rowBytes] : []; // the row above the first
        try
        {
            var adler = new Adler32();
            // Rendered pictures deflate to a few KiB a band; start small (the stream doubles as it needs) rather than
            // commit a large guess: 64 KiB a band cost 192 of the 1080p render's page faults (wall-breakdown.py --faults).
            var deflated = new MemoryStream(InitialDeflatedBytes);
            int length;
            using (var deflate = new DeflateStream(deflated, new ZLibCompressionOptions { CompressionLevel = zlibLevel }, leaveOpen: true))
            {
                for (int r0 = 0; r0 < rows; r0 += rowsPerChunk)
                {
                    int count = Math.Min(rowsPerChunk, rows - r0);
                    FilterRows(image, y0 + r0, count, filter, zeros, chunk, trial);
                    ReadOnlySpan<byte> data = chunk.AsSpan(0, count * filteredRowBytes);
                    adler.Append(data);
                    deflate.Write(data);
                }

                if (index < bandCount - 1)
                {
                    deflate.Flush(); // a sync flush: the band's data out, ending on a byte with an empty stored block
                    length = (int)deflated.Length;
                }
                else
                {
                    length = -1;
                }
            }

            // The last band keeps the final block that closing the stream wrote; the others drop it.
            if (length < 0)
            {
                length = (int)deflated.Length;
            }

            byte[] bytes = deflated.GetBuffer();
            return new Band(bytes, length, ChunkCrc(bytes.AsSpan(0, length), index == 0 ? zlibHeader : []), adler.GetCurrentHashAsUInt32(), rows * filteredRowBytes);
        }
        finally
        {
            ArrayPool<byte>.Shared.Return(chunk);
            if (trial is not null)
            {
                ArrayPool<byte>.Shared.Return(trial);
            }
        }
    }

    /// <summary>The running CRC of an IDAT chunk holding <paramref name="zlibHeader"/> (the first band's) and <paramref name="data"/>.</summary>
    private static Crc32 ChunkCrc(ReadOnlySpan<byte> data, ReadOnlySpan<byte> zlibHeader)
    {
        var crc = new Crc32(); // System.IO.Hashing: the ISO 3309 CRC PNG chunks use, vectorised; each band's computed on its own core
        crc.Append("IDAT"u8);
        crc.Append(zlibHeader);
        crc.Append(data);
        return crc;
    }

    /// <summary>Filters the <paramref name="count"/> rows from <paramref name="y"/> on into <paramref name="output"/>, one filter-type byte and the row's bytes each.</summary>
    private static void FilterRows(Image image, int y, int count, PngFilter filter, byte[] zeros, byte[] output, byte[]? trial)
    {
        int rowBytes = image.Width * 3, filteredRowBytes = rowBytes + 1;
        ReadOnlySpan<byte> pixels = image.PixelBytes;
        for (int r = 0; r < count; r++, y++)
        {
            ReadOnlySpan<byte> row = pixels.Slice(y * rowBytes, rowBytes);
            ReadOnlySpan<byte> up = y == 0 ? zeros : pixels.Slice((y - 1) * rowBytes, rowBytes);
            Span<byte> filtered = output.AsSpan(r * filteredRowBytes, filteredRowBytes);
            if (filter != PngFilter.Adaptive)
            {
                Filter(filter, row, up, filtered);
            }
            else
            {
                FilterAdaptive(row, up, filtered, trial);
            }
        }
    }

    /// <summary>Tries the five filters on a row and keeps, in <paramref name="best"/>, the one with the smallest sum of absolute values.</summary>
    private static void FilterAdaptive(ReadOnlySpan<byte> row, ReadOnlySpan<byte> up, Span<byte> best, Span<byte> trial)
    {
        long bestScore = long.MaxValue;
        for (PngFilter candidate = PngFilter.None; candidate <= PngFilter.Paeth; candidate++)
        {
            Span<byte> output = trial[..best.Length];
            Filter(candidate, row, up, output);
            long score = Score(output[1..]);
            if (score < bestScore)
            {
                bestScore = score;
                output.CopyTo(best);
            }
        }
    }

    /// <summary>
    /// The sum of the filtered bytes taken as signed (the PNG book's minimum-sum heuristic): smaller compresses better.
    /// </summary>
    private static long Score(ReadOnlySpan<byte> filtered)
    {
        long score = 0;
        foreach (byte value in filtered)
        {
            score += value < 128 ? value : 256 - value; // |value| taken as a signed byte
        }

        return score;
    }

    /// <summary>Applies PNG filter <paramref name="type"/> to one row into <paramref name="output"/> (type byte first). One loop per filter type.</summary>
    internal static void Filter(PngFilter type, ReadOnlySpan<byte> row, ReadOnlySpan<byte> up, Span<byte> output)
    {
        const int Bpp = 3;
        output[0] = (byte)type;
        Span<byte> filtered = output.Slice(1, row.Length);
        switch (type)
        {
            case PngFilter.None:
                row.CopyTo(filtered);
                break;
            case PngFilter.Sub:
                for (int i = 0; i < row.Length; i++)
                {
                    filtered[i] = (byte)(row[i] - (i >= Bpp ? row[i - Bpp] : 0));
                }

                break;
            case PngFilter.Up:
                Subtract(row, up, filtered);
                break;
            case PngFilter.Average:
                for (int i = 0; i < row.Length; i++)
                {
                    filtered[i] = (byte)(row[i] - (((i >= Bpp ? row[i - Bpp] : 0) + up[i]) >> 1));
                }

                break;
            default:
                for (int i = 0; i < row.Length; i++)
                {
                    filtered[i] = (byte)(row[i] - (i >= Bpp ? Paeth(row[i - Bpp], up[i], up[i - Bpp]) : up[i]));
                }

                break;
        }
    }

    /// <summary><paramref name="row"/> − <paramref name="up"/>, byte by byte (mod 256), in the widest SIMD the CPU runs: the Up filter.</summary>
    private static void Subtract(ReadOnlySpan<byte> row, ReadOnlySpan<byte> up, Span<byte> output)
    {
        int n = row.Length, i = 0;
        ref byte r = ref MemoryMarshal.GetReference(row);
        ref byte u = ref MemoryMarshal.GetReference(up);
        ref byte o = ref MemoryMarshal.GetReference(output);
        if (Vector256.IsHardwareAccelerated)
        {
            for (; i <= n - Vector256<byte>.Count; i += Vector256<byte>.Count)
            {
                (Vector256.LoadUnsafe(ref r, (nuint)i) - Vector256.LoadUnsafe(ref u, (nuint)i)).StoreUnsafe(ref o, (nuint)i);
            }
        }

        if (Vector128.IsHardwareAccelerated)
        {
            for (; i <= n - Vector128<byte>.Count; i += Vector128<byte>.Count)
            {
                (Vector128.LoadUnsafe(ref r, (nuint)i) - Vector128.LoadUnsafe(ref u, (nuint)i)).StoreUnsafe(ref o, (nuint)i);
            }
        }

        for (; i < n; i++)
        {
            Unsafe.Add(ref o, i) = (byte)(Unsafe.Add(ref r, i) - Unsafe.Add(ref u, i));
        }
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
        var crc = new Crc32();
        crc.Append(header[4..]);
        crc.Append(data);
        WriteCrc(stream, crc);
    }

    private static void WriteCrc(Stream stream, Crc32 crc)
    {
        Span<byte> crcBytes = stackalloc byte[4];
        BinaryPrimitives.WriteUInt32BigEndian(crcBytes, crc.GetCurrentHashAsUInt32());
        stream.Write(crcBytes);
    }
}
