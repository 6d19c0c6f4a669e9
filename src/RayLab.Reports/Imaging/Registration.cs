using System.Runtime.CompilerServices;

namespace RayLab.Imaging;

/// <summary>Registers the formats this package writes with the core's <see cref="Image.Save(string)"/> when the assembly loads.</summary>
internal static class Registration
{
    [ModuleInitializer]
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2255:The 'ModuleInitializer' attribute should not be used in libraries", Justification = "Registering the package's encoders with the core is what a module initializer is for; it allocates nothing else.")]
    internal static void Register()
    {
        ImageEncoders.Register(ImageFormat.Webp, (stream, image, quality) => SkiaEncoder.Write(stream, image, ImageFormat.Webp, quality));
    }
}
