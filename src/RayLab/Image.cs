using System.Runtime.InteropServices;

namespace RayLab;

/// <summary>
/// The lab's image ("obraz", section 2.2): W×H pixels of 8-bit RGB, kept as tightly packed RGB24 rows, top
/// row first — the layout ImageSharp's <c>Image.LoadPixelData&lt;Rgb24&gt;</c> takes. Intensities are
/// converted on the way in by the lab's rule (<see cref="EightBit.Level"/>).
/// </summary>
public sealed class Image : IPixelRows
{
    /// <summary>The largest pixel buffer: one .NET array, <see cref="Array.MaxLength"/> bytes (about 715 million pixels).</summary>
    public static long MaxBytes => Array.MaxLength;

    private readonly byte[] _pixels;

    /// <summary>Creates a black image.</summary>
    /// <param name="width">Width W in pixels, ≥ 1.</param>
    /// <param name="height">Height H in pixels, ≥ 1.</param>
    /// <exception cref="ArgumentOutOfRangeException">A size is less than 1, or W·H·3 exceeds <see cref="MaxBytes"/>.</exception>
    public Image(int width, int height)
    {
        CheckSize(width, height);
        Width = width;
        Height = height;
        _pixels = new byte[(long)width * height * 3];
    }

    /// <summary>The width W in pixels.</summary>
    public int Width { get; }

    /// <summary>The height H in pixels.</summary>
    public int Height { get; }

    /// <summary>Throws unless a <paramref name="width"/>×<paramref name="height"/> image can be allocated.</summary>
    /// <param name="width">Width in pixels.</param>
    /// <param name="height">Height in pixels.</param>
    /// <exception cref="ArgumentOutOfRangeException">
    /// A size is less than 1 (the exception names <c>width</c> or <c>height</c>), or W·H·3 exceeds
    /// <see cref="MaxBytes"/> (it names <c>size</c>).
    /// </exception>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2208:Instantiate argument exceptions correctly", Justification = "Width and height are each valid; their product, the image's size, is too large.")]
    internal static void CheckSize(int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        // Compare without forming W·H·3, which can overflow a long for two huge sizes.
        if (width > MaxBytes / 3 / height)
        {
            throw new ArgumentOutOfRangeException("size", $"{width}×{height} is too large: W·H·3 must be at most {MaxBytes:N0} bytes.");
        }
    }

    /// <summary>All pixels as bytes R, G, B, …, row 0 (the top row) first, with no padding between rows.</summary>
    public Span<byte> PixelBytes => _pixels;

    /// <summary>Row <paramref name="y"/> (0 at the top) as pixels, for writing a whole row at once.</summary>
    /// <param name="y">The row.</param>
    /// <exception cref="ArgumentOutOfRangeException">The row is outside the image.</exception>
    public Span<Rgb24> GetRowSpan(int y)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(y);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, Height);
        return MemoryMarshal.Cast<byte, Rgb24>(_pixels.AsSpan(y * 3 * Width, 3 * Width));
    }

    /// <summary>Sets pixel (x, y) from an intensity by the lab's 8-bit rule.</summary>
    /// <param name="x">Column, 0 at the left.</param>
    /// <param name="y">Row, 0 at the top.</param>
    /// <param name="value">The intensity.</param>
    /// <exception cref="ArgumentOutOfRangeException">(x, y) is outside the image.</exception>
    public void SetPixel(int x, int y, Intensity value) => GetRowSpan(y)[CheckX(x)] = Rgb24.FromIntensity(value);

    /// <summary>The 8-bit value of pixel (x, y).</summary>
    /// <param name="x">Column, 0 at the left.</param>
    /// <param name="y">Row, 0 at the top.</param>
    /// <exception cref="ArgumentOutOfRangeException">(x, y) is outside the image.</exception>
    public Rgb24 GetPixel(int x, int y) => GetRowSpan(y)[CheckX(x)];

    /// <summary>
    /// Saves the image, choosing the format from the extension as System.Drawing's <c>Bitmap.Save</c> does:
    /// <c>.png</c>, <c>.bmp</c>, <c>.jpg</c>/<c>.jpeg</c>, or the extension of a format a package registered
    /// (<see cref="ImageFormats.Register"/>); lossy formats at quality <see cref="ImageFormats.DefaultQuality"/>.
    /// The file is written under a temporary name in the same folder and renamed, so a failure never leaves a partial file.
    /// </summary>
    /// <param name="path">The output path.</param>
    /// <exception cref="NotSupportedException">No registered format has the extension (the message names the registered ones).</exception>
    /// <exception cref="DirectoryNotFoundException">The folder does not exist (the message names it).</exception>
    /// <exception cref="IOException">The folder cannot be written.</exception>
    public void Save(string path) => Save(path, ImageFormats.DefaultQuality);

    /// <summary>
    /// Saves the image, choosing the format from the extension (see <see cref="Save(string)"/>); lossy formats (JPEG)
    /// are written at <paramref name="quality"/>, which lossless ones (PNG, BMP) ignore.
    /// </summary>
    /// <param name="path">The output path.</param>
    /// <param name="quality">Lossy quality, 0–100 (90 by default; higher keeps more detail in a larger file).</param>
    /// <exception cref="ArgumentOutOfRangeException">The quality is outside 0–100.</exception>
    /// <exception cref="NotSupportedException">No registered format has the extension (the message names the registered ones); no file is made.</exception>
    /// <exception cref="DirectoryNotFoundException">The folder does not exist (the message names it).</exception>
    /// <exception cref="IOException">The folder cannot be written.</exception>
    public void Save(string path, int quality)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        CheckQuality(quality);
        ImageFormat format = ImageFormat.FromPath(path);
        string full = Path.GetFullPath(path);
        string folder = Path.GetDirectoryName(full) ?? ".";
        if (!Directory.Exists(folder))
        {
            throw new DirectoryNotFoundException($"Cannot save '{path}': the folder '{folder}' does not exist.");
        }

        string temp = Path.Combine(folder, $".{Path.GetFileName(full)}.{Guid.NewGuid():N}.tmp");
        try
        {
            using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
            {
                Save(stream, format, quality);
                stream.Flush(flushToDisk: true);
            }

            File.Move(temp, full, overwrite: true);
        }
        catch
        {
            if (File.Exists(temp))
            {
                File.Delete(temp);
            }

            throw;
        }
    }

    /// <summary>Writes the image to a stream in the given format (lossy formats at quality <see cref="ImageFormats.DefaultQuality"/>).</summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="format">The format, e.g. <see cref="ImageFormat.Png"/>.</param>
    public void Save(Stream stream, ImageFormat format) => Save(stream, format, ImageFormats.DefaultQuality);

    /// <summary>Writes the image to a stream in the given format (registered or not).</summary>
    /// <param name="stream">A writable stream.</param>
    /// <param name="format">The format, e.g. <see cref="ImageFormat.Png"/>.</param>
    /// <param name="quality">Lossy quality, 0–100; PNG and BMP ignore it.</param>
    /// <exception cref="ArgumentOutOfRangeException">The quality is outside 0–100.</exception>
    public void Save(Stream stream, ImageFormat format, int quality)
    {
        ArgumentNullException.ThrowIfNull(stream);
        ArgumentNullException.ThrowIfNull(format);
        CheckQuality(quality);
        format.Write(stream, this, quality);
    }

    private static void CheckQuality(int quality)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(quality);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(quality, 100);
    }

    private int CheckX(int x)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(x);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(x, Width);
        return x;
    }
}
