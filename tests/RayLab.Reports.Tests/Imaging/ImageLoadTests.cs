using RayLab.Reports.Imaging;

namespace RayLab.Reports.Tests.Imaging;

/// <summary><see cref="SkiaBitmaps"/>' <c>Image.Load</c>: what the core writes reads back exactly; anything else is an error naming the file.</summary>
public sealed class ImageLoadTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    private static Image Pattern(int width, int height)
    {
        var image = new Image(width, height);
        for (int y = 0; y < height; y++)
        {
            for (int x = 0; x < width; x++)
            {
                image.GetRowSpan(y)[x] = new Rgb24((byte)(x * 7), (byte)(y * 11), (byte)((x * y) % 256));
            }
        }

        return image;
    }

    [Theory]
    [InlineData("p.png")]
    [InlineData("p.bmp")]
    public void ALosslessPictureReadsBackByteForByte(string name)
    {
        Image image = Pattern(37, 23);
        string path = _dir.File(name);
        image.Save(path);

        Image read = Image.Load(path);

        Assert.Equal((37, 23), (read.Width, read.Height));
        Assert.Equal(image.PixelBytes.ToArray(), read.PixelBytes.ToArray());
    }

    [Fact]
    public void ALossyPictureReadsAtItsSize()
    {
        string path = _dir.File("p.jpg");
        Pattern(40, 30).Save(path);

        Image read = Image.Load(path);

        Assert.Equal((40, 30), (read.Width, read.Height));
    }

    [Fact]
    public void ABadFileIsAnErrorNamingIt()
    {
        string text = _dir.File("text.png");
        File.WriteAllText(text, "not a picture");
        string empty = _dir.File("empty.png");
        File.WriteAllBytes(empty, []);
        string cut = _dir.File("cut.png");
        Pattern(64, 64).Save(cut);
        byte[] whole = File.ReadAllBytes(cut);
        File.WriteAllBytes(cut, whole[..(whole.Length / 2)]);

        Assert.StartsWith($"{text}: not a picture", Assert.Throws<InvalidDataException>(() => Image.Load(text)).Message, StringComparison.Ordinal);
        Assert.StartsWith($"{empty}: not a picture", Assert.Throws<InvalidDataException>(() => Image.Load(empty)).Message, StringComparison.Ordinal);
        Assert.StartsWith($"{cut}: ", Assert.Throws<InvalidDataException>(() => Image.Load(cut)).Message, StringComparison.Ordinal);
        Assert.Throws<FileNotFoundException>(() => Image.Load(_dir.File("missing.png")));
        Assert.Throws<UnauthorizedAccessException>(() => Image.Load(_dir.Path));
    }

    [Fact]
    public void APictureInMemoryReadsBackAsFromItsFile()
    {
        Image image = Pattern(37, 23);
        string path = _dir.File("p.png");
        image.Save(path);
        byte[] bytes = File.ReadAllBytes(path);

        Assert.Equal((37, 23), SkiaBitmaps.ReadSize(bytes));
        Assert.Equal(image.PixelBytes.ToArray(), Image.Load(bytes, "p.png", 37, 23).PixelBytes.ToArray());
        Assert.Null(SkiaBitmaps.ReadSize("not a picture"u8));
        Assert.Null(SkiaBitmaps.ReadSize([]));
        Assert.Equal("p.png: a 37×23 picture is larger than the 37×22 read here; not decoded",
            Assert.Throws<InvalidDataException>(() => Image.Load(bytes, "p.png", 37, 22)).Message);
    }

    [Theory]
    [InlineData(100_000, 100_000)] // more than an image can hold: refused by Load(path) too
    [InlineData(20_000, 20_000)]   // what an image can hold: Load(path) allocates 1.6 GB for it before it finds the data cut short
    public void APngClaimingAHugeSizeIsRefusedFromItsHeaderBeforeItsPixelsAreAllocated(int width, int height)
    {
        byte[] claim = ClaimingPng.Of(width, height);
        Assert.Equal((width, height), SkiaBitmaps.ReadSize(claim));
        long before = GC.GetAllocatedBytesForCurrentThread();
        var e = Assert.Throws<InvalidDataException>(() => Image.Load(claim, "claim.png", 800, 600));
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal($"claim.png: a {width}×{height} picture is larger than the 800×600 read here; not decoded", e.Message);
        Assert.True(allocated < 1 << 20, $"{allocated:N0} bytes allocated to refuse it");
    }
}
