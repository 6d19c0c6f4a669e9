using RayLab.Reports.Imaging;

namespace RayLab.Reports.Tests.Imaging;

/// <summary>WebP reaches <see cref="Image.Save(string)"/> through the core's public registry, once the app registers this package's formats.</summary>
public sealed class ReportsImageFormatsTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void Register_adds_webp_to_the_core_registry_once()
    {
        ReportsImageFormats.Register();
        ReportsImageFormats.Register();

        Assert.Equal("WebP", ReportsImageFormats.Webp.Name);
        Assert.Equal([".webp"], ReportsImageFormats.Webp.Extensions);
        Assert.Same(ReportsImageFormats.Webp, ImageFormat.FromPath("out/picture.WebP"));
        Assert.True(ImageFormats.TryFindByExtension("webp", out ImageFormat? found));
        Assert.Same(ReportsImageFormats.Webp, found);
        Assert.Single(ImageFormats.All, f => ReferenceEquals(f, ReportsImageFormats.Webp));
        Assert.Equal([".png", ".bmp", ".jpg", ".jpeg"], ImageFormats.Extensions.Take(4));
        Assert.Contains(".webp", ImageFormats.Extensions);
    }

    [Fact]
    public void A_registered_webp_save_writes_a_webp_file_skia_reads_back()
    {
        ReportsImageFormats.Register();
        var image = new Image(24, 16);
        image.PixelBytes.Fill(128);
        string path = _dir.File("grey.webp");

        image.Save(path);

        SkiaDecode.Result decoded = SkiaDecode.Load(path);
        Assert.Equal((SkiaSharp.SKEncodedImageFormat.Webp, 24, 16), (decoded.Format, decoded.Width, decoded.Height));
        Assert.All(decoded.Rgb, b => Assert.InRange(b, 126, 130));
    }
}
