using System.Collections.Concurrent;
using System.Reflection;
using System.Runtime.CompilerServices;

namespace RayLab.Imaging;

/// <summary>
/// The encoders of formats the core does not write itself (WebP): the <c>RayLab.Reports</c> package registers them
/// when it loads. <see cref="Image.Save(string)"/> loads that package's assembly if the app references it and has not
/// touched it yet, so a reference is all a student adds; without it the save is a one-line error naming the package.
/// </summary>
internal static class ImageEncoders
{
    /// <summary>The assembly that registers the encoders.</summary>
    public const string ReportsAssembly = "RayLab.Reports";

    private static readonly ConcurrentDictionary<ImageFormat, Action<Stream, Image, int>> Encoders = new();
    private static readonly Lazy<bool> ReportsLoaded = new(LoadReports, LazyThreadSafetyMode.ExecutionAndPublication);

    /// <summary>Registers the encoder of <paramref name="format"/> (the last registration wins).</summary>
    /// <param name="format">The format.</param>
    /// <param name="encoder">Writes an image to a stream at a quality 0–100.</param>
    public static void Register(ImageFormat format, Action<Stream, Image, int> encoder)
    {
        ArgumentNullException.ThrowIfNull(encoder);
        Encoders[format] = encoder;
    }

    /// <summary>The encoder of <paramref name="format"/>.</summary>
    /// <param name="format">A format the core does not write itself.</param>
    /// <exception cref="NotSupportedException">No package that writes the format is referenced (the message names it).</exception>
    public static Action<Stream, Image, int> Get(ImageFormat format)
    {
        if (Encoders.TryGetValue(format, out Action<Stream, Image, int>? encoder)
            || (ReportsLoaded.Value && Encoders.TryGetValue(format, out encoder)))
        {
            return encoder;
        }

        throw new NotSupportedException(
            $"{(format == ImageFormat.Webp ? "WebP" : format.ToString())} files are written by the {ReportsAssembly} package, which this app does not reference: add it (dotnet add package {ReportsAssembly}), or save as .png, .bmp or .jpg.");
    }

    private static bool LoadReports()
    {
        try
        {
            Assembly reports = Assembly.Load(new AssemblyName(ReportsAssembly));
            RuntimeHelpers.RunModuleConstructor(reports.ManifestModule.ModuleHandle);
            return true;
        }
        catch (Exception e) when (e is FileNotFoundException or FileLoadException or BadImageFormatException or PlatformNotSupportedException)
        {
            return false;
        }
    }
}
