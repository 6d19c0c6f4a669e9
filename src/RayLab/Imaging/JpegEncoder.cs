using System.Buffers;
using System.Runtime.CompilerServices;
using JpegLibrary;
using LibraryEncoder = JpegLibrary.JpegEncoder;

namespace RayLab.Imaging;

/// <summary>
/// Writes baseline JPEG files with JpegLibrary, a managed encoder: JFIF, YCbCr without chroma subsampling (4:4:4, so the
/// thin red outline of a sphere keeps its colour instead of smearing over two pixels as with 4:2:0), the standard
/// quantisation tables scaled by quality as libjpeg scales them, and Huffman tables fitted to the image (as Skia writes
/// them: the same size as Skia's file at quality 90). The measurement
/// against Skia's libjpeg-turbo and StbImageWriteSharp is in docs/bench/jpeg.md.
/// </summary>
internal static class JpegEncoder
{
    /// <summary>The largest width or height a JPEG frame header can state.</summary>
    public const int MaxSize = ushort.MaxValue;

    /// <summary>Encodes <paramref name="image"/> as JPEG at <paramref name="quality"/> into <paramref name="stream"/>.</summary>
    /// <param name="stream">A writable stream; the file is written through a 64 KiB buffer, not built in memory first.</param>
    /// <param name="image">The image.</param>
    /// <param name="quality">
    /// 0–100; higher keeps more detail in a larger file. 0 is taken as 1, as libjpeg takes it (both give the coarsest
    /// tables).
    /// </param>
    /// <exception cref="ArgumentNullException"><paramref name="stream"/> or <paramref name="image"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="quality"/> is outside 0–100.</exception>
    /// <exception cref="ArgumentException">The image is wider or taller than <see cref="MaxSize"/>, JPEG's limit.</exception>
    public static void Write(Stream stream, Image image, int quality) => Write(stream, image, quality, optimizeCoding: true);

    /// <summary>
    /// Encodes <paramref name="image"/> as <see cref="Write(Stream, Image, int)"/> does, with Huffman tables fitted to
    /// the image (<paramref name="optimizeCoding"/>, two passes over a buffer of all coefficients, 6 bytes a pixel) or
    /// the standard tables of the JPEG specification (one pass, a larger file): the benchmarks measure both.
    /// </summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="image">The image.</param>
    /// <param name="quality">0–100.</param>
    /// <param name="optimizeCoding">True for Huffman tables fitted to the image, as Skia's libjpeg-turbo writes them.</param>
    /// <exception cref="ArgumentNullException"><paramref name="stream"/> or <paramref name="image"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="quality"/> is outside 0–100.</exception>
    /// <exception cref="ArgumentException">The image is wider or taller than <see cref="MaxSize"/>.</exception>
    public static void Write(Stream stream, Image image, int quality, bool optimizeCoding) =>
        Write(stream, image, quality, optimizeCoding, BufferSize);

    /// <summary>The size of the buffer between JpegLibrary and the stream.</summary>
    internal const int BufferSize = 64 * 1024;

    /// <summary>
    /// <see cref="Write(Stream, Image, int, bool)"/> through a buffer of <paramref name="bufferSize"/> bytes: the
    /// bytes written do not depend on it (tests use a small one to reach the case <see cref="StreamBufferWriter.DropAfterEndOfImage"/> handles).
    /// </summary>
    internal static void Write(Stream stream, Image image, int quality, bool optimizeCoding, int bufferSize)
    {
        ArgumentNullException.ThrowIfNull(stream);
        ArgumentNullException.ThrowIfNull(image);
        // JpegLibrary's own check lets 0 through to a division by zero, so the range is checked here.
        ArgumentOutOfRangeException.ThrowIfNegative(quality);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(quality, 100);
        if (image.Width > MaxSize || image.Height > MaxSize)
        {
            throw new ArgumentException($"A {image.Width}×{image.Height} image cannot be a JPEG: its width and height must be at most {MaxSize}; use PNG.", nameof(image));
        }

        int scaled = Math.Max(quality, 1);
        // The coefficient buffer of the fitted tables is one array of 128 bytes a block (JpegLibrary indexes it with
        // an int): a picture too large for it gets the standard tables.
        long blocks = 3L * ((image.Width + 7) / 8) * ((image.Height + 7) / 8);
        optimizeCoding &= (blocks + 1) * 128 <= Array.MaxLength;
        var encoder = new JfifEncoder(optimizeCoding);
        encoder.SetQuantizationTable(JpegStandardQuantizationTable.ScaleByQuality(JpegStandardQuantizationTable.GetLuminanceTable(JpegElementPrecision.Precision8Bit, 0), scaled));
        encoder.SetQuantizationTable(JpegStandardQuantizationTable.ScaleByQuality(JpegStandardQuantizationTable.GetChrominanceTable(JpegElementPrecision.Precision8Bit, 1), scaled));
        if (optimizeCoding)
        {
            // No table given: JpegLibrary counts the symbols of the whole image and builds the tables (libjpeg's method).
            encoder.SetHuffmanTable(true, 0);
            encoder.SetHuffmanTable(false, 0);
            encoder.SetHuffmanTable(true, 1);
            encoder.SetHuffmanTable(false, 1);
        }
        else
        {
            encoder.SetHuffmanTable(true, 0, JpegStandardHuffmanEncodingTable.GetLuminanceDCTable());
            encoder.SetHuffmanTable(false, 0, JpegStandardHuffmanEncodingTable.GetLuminanceACTable());
            encoder.SetHuffmanTable(true, 1, JpegStandardHuffmanEncodingTable.GetChrominanceDCTable());
            encoder.SetHuffmanTable(false, 1, JpegStandardHuffmanEncodingTable.GetChrominanceACTable());
        }

        // Component id, quantisation table, DC and AC Huffman tables, horizontal and vertical sampling factors:
        // 1×1 for all three is 4:4:4.
        encoder.AddComponent(1, 0, 0, 0, 1, 1);
        encoder.AddComponent(2, 1, 1, 1, 1, 1);
        encoder.AddComponent(3, 1, 1, 1, 1, 1);
        encoder.SetInputReader(new YCbCrReader(image));
        var output = new StreamBufferWriter(stream, bufferSize);
        encoder.SetOutput(output);
        encoder.Encode();
        output.DropAfterEndOfImage();
        output.Flush();
    }

    /// <summary>JpegLibrary's baseline encoder with a JFIF header (APP0) after the start of the image, as libjpeg writes it.</summary>
    private sealed class JfifEncoder(bool optimizeCoding) : LibraryEncoder
    {
        /// <summary>"JFIF\0", version 1.01, no density unit, aspect ratio 1:1, no thumbnail.</summary>
        private static ReadOnlySpan<byte> Jfif => [(byte)'J', (byte)'F', (byte)'I', (byte)'F', 0, 1, 1, 0, 0, 1, 0, 1, 0, 0];

        /// <summary>The library's <see cref="LibraryEncoder.Encode"/>, step by step, with the JFIF header added after the start of the image.</summary>
        public override void Encode()
        {
            JpegWriter writer = CreateJpegWriter();
            WriteStartOfImage(ref writer);
            writer.WriteMarker(JpegMarker.App0);
            writer.WriteLength((ushort)Jfif.Length);
            writer.WriteBytes(Jfif);
            WriteQuantizationTables(ref writer);
            JpegFrameHeader frame = WriteStartOfFrame(ref writer);
            if (optimizeCoding)
            {
                // First pass: every block transformed and quantised into the buffer, the symbols counted, the tables
                // built ("optimal: false" is libjpeg's construction, which gave the same sizes here); second pass:
                // the tables and the blocks written.
                using var blocks = new JpegBlockAllocator(MemoryPool);
                blocks.Allocate(frame);
                TransformBlocks(blocks);
                BuildHuffmanTables(frame, blocks, optimal: false);
                WriteHuffmanTables(ref writer);
                WriteStartOfScan(ref writer);
                WritePreparedScanData(frame, blocks, ref writer);
            }
            else
            {
                WriteHuffmanTables(ref writer);
                WriteStartOfScan(ref writer);
                WriteScanData(ref writer);
            }

            WriteEndOfImage(ref writer);
            writer.Flush();
        }
    }

    /// <summary>
    /// Hands JpegLibrary 8×8 blocks of one component straight from the image's RGB24 rows, converted to YCbCr by
    /// libjpeg's fixed-point rule (16 fraction bits); blocks past the right or bottom edge repeat the last column or
    /// row, as libjpeg pads them.
    /// </summary>
    private sealed class YCbCrReader(Image image) : JpegBlockInputReader
    {
        private const int Shift = 16;
        private const int Half = 1 << (Shift - 1);
        private const int ChromaOffset = (128 << Shift) + Half - 1;

        public override int Width => image.Width;

        public override int Height => image.Height;

        public override void ReadBlock(ref short blockRef, int componentIndex, int x, int y)
        {
            ReadOnlySpan<byte> pixels = image.PixelBytes;
            int width = image.Width, height = image.Height, stride = 3 * width;
            // Coefficients for R, G and B, and the offset with rounding, of the component asked for.
            (int r, int g, int b, int offset) = componentIndex switch
            {
                0 => (19595, 38470, 7471, Half),      // Y  =  0.299 R + 0.587 G + 0.114 B
                1 => (-11058, -21710, 32768, ChromaOffset), // Cb = -0.1687 R - 0.3313 G + 0.5 B + 128
                _ => (32768, -27439, -5329, ChromaOffset),  // Cr =  0.5 R - 0.4187 G - 0.0813 B + 128
            };
            for (int row = 0; row < 8; row++)
            {
                ReadOnlySpan<byte> line = pixels.Slice(Math.Min(y + row, height - 1) * stride, stride);
                ref short target = ref Unsafe.Add(ref blockRef, row * 8);
                for (int column = 0; column < 8; column++)
                {
                    int i = 3 * Math.Min(x + column, width - 1);
                    Unsafe.Add(ref target, column) = (short)(((r * line[i]) + (g * line[i + 1]) + (b * line[i + 2]) + offset) >> Shift);
                }
            }
        }
    }

    /// <summary>
    /// A buffer writer over a stream: JpegLibrary writes into one 64 KiB buffer, which goes to the stream when it is
    /// full and at the end. A span handed out stays valid after <see cref="Advance"/> until the next
    /// <see cref="GetSpan"/>, which JpegLibrary's writer relies on (it goes on writing into the rest of a span it has
    /// already advanced past).
    /// </summary>
    private sealed class StreamBufferWriter(Stream stream, int size) : IBufferWriter<byte>
    {
        private byte[] _buffer = new byte[size];
        private int _written;

        /// <summary>
        /// Drops what follows the last end-of-image marker (FF D9) in the buffer. JpegLibrary 0.4.32's
        /// <c>JpegWriter.ExitBitMode</c>, when the span has under 16 bytes left after the scan's last flush, advances
        /// over the bytes of that flush a second time, so as many stale bytes follow the marker (3 of 3000 noise
        /// pictures through a 4 KiB buffer; rarer through 64 KiB, as the scan must end near the buffer's end). The marker is the last thing written, so it is in
        /// the buffer; FF D9 cannot occur in entropy-coded data, where FF is always followed by 00, and searching for
        /// the last one never cuts the picture short.
        /// </summary>
        public void DropAfterEndOfImage()
        {
            int end = _buffer.AsSpan(0, _written).LastIndexOf([(byte)0xFF, (byte)0xD9]);
            if (end >= 0)
            {
                _written = end + 2;
            }
        }

        public void Advance(int count)
        {
            ArgumentOutOfRangeException.ThrowIfNegative(count);
            ArgumentOutOfRangeException.ThrowIfGreaterThan(count, _buffer.Length - _written);
            _written += count;
        }

        public Memory<byte> GetMemory(int sizeHint = 0)
        {
            Reserve(sizeHint);
            return _buffer.AsMemory(_written);
        }

        public Span<byte> GetSpan(int sizeHint = 0)
        {
            Reserve(sizeHint);
            return _buffer.AsSpan(_written);
        }

        /// <summary>Writes what has been advanced over to the stream.</summary>
        public void Flush()
        {
            stream.Write(_buffer, 0, _written);
            _written = 0;
        }

        private void Reserve(int sizeHint)
        {
            int needed = Math.Max(sizeHint, 1);
            if (_buffer.Length - _written >= needed)
            {
                return;
            }

            Flush();
            if (_buffer.Length < needed)
            {
                _buffer = new byte[needed];
            }
        }
    }
}
