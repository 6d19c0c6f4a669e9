using System.Buffers;
using System.Diagnostics.CodeAnalysis;
using RayLab.Imaging;

namespace RayLab;

/// <summary>Writes an image to a stream in one file format.</summary>
/// <param name="stream">A writable stream.</param>
/// <param name="image">The image.</param>
/// <param name="quality">0–100, already checked; lossless formats ignore it.</param>
public delegate void ImageEncoder(Stream stream, Image image, int quality);

/// <summary>
/// A file format an <see cref="Image"/> is saved in (the lab's "zapis obrazu"): its name, its file extensions and its
/// encoder. The core writes <see cref="Png"/> and <see cref="Bmp"/> by its own encoders and <see cref="Jpeg"/> by
/// JpegLibrary (managed); an add-on package makes a format of its own and registers it with
/// <see cref="ImageFormats.Register"/>, after which <see cref="Image.Save(string)"/> picks it by extension.
/// </summary>
public sealed class ImageFormat
{
    // First: the built-in formats below are made with it, and static initializers run in the order they are written.
    private static readonly SearchValues<char> ExtensionCharacters = SearchValues.Create("abcdefghijklmnopqrstuvwxyz0123456789");

    private readonly ImageEncoder _encoder;

    /// <summary>Makes a format; <see cref="ImageFormats.Register"/> then lets <see cref="Image.Save(string)"/> choose it by extension.</summary>
    /// <param name="name">What messages call it, e.g. "WebP".</param>
    /// <param name="extensions">Its file extensions with the dot, e.g. ".webp" (stored lower case), the usual one first.</param>
    /// <param name="encoder">Writes an image in the format.</param>
    /// <exception cref="ArgumentException">The name is empty, there is no extension, or one is not a dot followed by letters or digits.</exception>
    public ImageFormat(string name, IEnumerable<string> extensions, ImageEncoder encoder)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(name);
        ArgumentNullException.ThrowIfNull(extensions);
        ArgumentNullException.ThrowIfNull(encoder);
        string[] list = [.. extensions.Select(e => e?.ToLowerInvariant() ?? "")];
        if (list.Length == 0)
        {
            throw new ArgumentException($"The format {name} needs at least one extension, e.g. \".{name.ToLowerInvariant()}\".", nameof(extensions));
        }

        foreach (string extension in list)
        {
            if (extension.Length < 2 || extension[0] != '.' || extension.AsSpan(1).ContainsAnyExcept(ExtensionCharacters))
            {
                throw new ArgumentException($"'{extension}' is not a file extension: a dot followed by letters or digits, e.g. \".png\".", nameof(extensions));
            }
        }

        Name = name;
        Extensions = list;
        _encoder = encoder;
    }

    /// <summary>PNG, 8-bit RGB, DEFLATE by the runtime's <c>ZLibStream</c> (RayLab's own encoder); <c>.png</c>.</summary>
    public static ImageFormat Png { get; } = new("PNG", [".png"], static (stream, image, _) => PngEncoder.Write(stream, image));

    /// <summary>BMP, 24-bit uncompressed (the lab's "bitmap"; RayLab's own encoder); <c>.bmp</c>.</summary>
    public static ImageFormat Bmp { get; } = new("BMP", [".bmp"], static (stream, image, _) => BmpEncoder.Write(stream, image));

    /// <summary>JPEG, lossy (the format of the lab's <c>obrazkoncowy.jpg</c>), 4:4:4, encoded by JpegLibrary (managed); <c>.jpg</c>, <c>.jpeg</c>.</summary>
    public static ImageFormat Jpeg { get; } = new("JPEG", [".jpg", ".jpeg"], static (stream, image, quality) => JpegEncoder.Write(stream, image, quality));

    /// <summary>What messages call the format, e.g. "PNG".</summary>
    public string Name { get; }

    /// <summary>The format's file extensions, lower case with the dot, the usual one first.</summary>
    public IReadOnlyList<string> Extensions { get; }

    /// <summary>The registered format for a file name's extension (case-insensitive); see <see cref="ImageFormats.FromPath"/>.</summary>
    /// <param name="path">A file path.</param>
    /// <exception cref="NotSupportedException">The extension is missing or no registered format has it (the message names the registered ones).</exception>
    public static ImageFormat FromPath(string path) => ImageFormats.FromPath(path);

    /// <summary>The format's name.</summary>
    /// <returns><see cref="Name"/>.</returns>
    public override string ToString() => Name;

    internal void Write(Stream stream, Image image, int quality) => _encoder(stream, image, quality);
}

/// <summary>
/// The registry of the formats <see cref="Image.Save(string)"/> writes, by extension: the core's own
/// (<see cref="ImageFormat.Png"/>, <see cref="ImageFormat.Bmp"/>, <see cref="ImageFormat.Jpeg"/>) and those packages
/// register at startup. Thread-safe.
/// </summary>
public static class ImageFormats
{
    /// <summary>The quality lossy formats are written with unless told otherwise (0–100).</summary>
    public const int DefaultQuality = 90;

    private static readonly Lock Gate = new();
    private static ImageFormat[] _formats = [ImageFormat.Png, ImageFormat.Bmp, ImageFormat.Jpeg];

    /// <summary>The registered formats, the core's first, then in the order they were registered.</summary>
    public static IReadOnlyList<ImageFormat> All => Volatile.Read(ref _formats);

    /// <summary>The registered formats' extensions, lower case with the dot, in <see cref="All"/>'s order.</summary>
    public static IReadOnlyList<string> Extensions => [.. All.SelectMany(f => f.Extensions).Distinct(StringComparer.Ordinal)];

    /// <summary>
    /// Registers a format, so that <see cref="Image.Save(string)"/> writes files with its extensions. Registering the same
    /// format again does nothing; a format with an extension another one has takes that extension over (the last
    /// registration wins, so an app may replace a core encoder).
    /// </summary>
    /// <param name="format">The format.</param>
    public static void Register(ImageFormat format)
    {
        ArgumentNullException.ThrowIfNull(format);
        lock (Gate)
        {
            if (!_formats.Contains(format))
            {
                Volatile.Write(ref _formats, [.. _formats, format]);
            }
        }
    }

    /// <summary>The registered format with an extension (case-insensitive, with or without the dot).</summary>
    /// <param name="extension">E.g. ".png" or "png".</param>
    /// <param name="format">The format, when one has the extension.</param>
    /// <returns>Whether a registered format has the extension.</returns>
    public static bool TryFindByExtension(string extension, [NotNullWhen(true)] out ImageFormat? format)
    {
        ArgumentNullException.ThrowIfNull(extension);
        string wanted = extension.StartsWith('.') ? extension.ToLowerInvariant() : "." + extension.ToLowerInvariant();
        ImageFormat[] formats = Volatile.Read(ref _formats);
        for (int i = formats.Length - 1; i >= 0; i--)
        {
            if (formats[i].Extensions.Contains(wanted, StringComparer.Ordinal))
            {
                format = formats[i];
                return true;
            }
        }

        format = null;
        return false;
    }

    /// <summary>The registered format for a file name's extension (case-insensitive).</summary>
    /// <param name="path">A file path.</param>
    /// <exception cref="NotSupportedException">
    /// The extension is missing or no registered format has it: the message names the extension and the registered ones,
    /// and says that a package writing the format registers it.
    /// </exception>
    public static ImageFormat FromPath(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        string extension = Path.GetExtension(path).ToLowerInvariant();
        if (extension.Length > 1 && TryFindByExtension(extension, out ImageFormat? format))
        {
            return format;
        }

        string registered = string.Join(", ", Extensions);
        throw new NotSupportedException(extension.Length <= 1
            ? $"Cannot tell the image format of '{path}': it has no extension; registered: {registered}."
            : $"No registered image format writes '{extension}' files ('{path}'); registered: {registered}. " +
              $"A package that writes {extension} files registers its format at startup (ImageFormats.Register).");
    }
}
