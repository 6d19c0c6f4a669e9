namespace RayLab.Tests.Imaging;

/// <summary>
/// The format registry behind <see cref="Image.Save(string)"/>: a package registers a format with its extensions and
/// encoder, and a save picks it by extension. Each test registers formats under its own made-up extensions, so the
/// registrations (process-wide) do not meet.
/// </summary>
public sealed class ImageFormatRegistryTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public void Dispose() => _dir.Dispose();

    /// <summary>A format whose files are the bytes 'R', 'L', the marker and the quality.</summary>
    private static ImageFormat Marker(string extension, byte marker) =>
        new($"marker {marker}", [extension], (stream, image, quality) => stream.Write([(byte)'R', (byte)'L', marker, (byte)quality]));

    [Fact]
    public void A_registered_format_is_found_by_extension_and_writes_the_files_saved_with_it()
    {
        ImageFormat format = Marker(".rlone", 1);

        ImageFormats.Register(format);
        ImageFormats.Register(format);
        new Image(2, 2).Save(_dir.File("a.RLONE"), quality: 77);

        Assert.Equal([(byte)'R', (byte)'L', 1, 77], File.ReadAllBytes(_dir.File("a.RLONE")));
        Assert.Same(format, ImageFormat.FromPath("x/y.rlone"));
        Assert.True(ImageFormats.TryFindByExtension("RLONE", out ImageFormat? found));
        Assert.Same(format, found);
        Assert.Single(ImageFormats.All, f => ReferenceEquals(f, format));
        Assert.Single(ImageFormats.Extensions, e => e == ".rlone");
    }

    [Fact]
    public void The_last_format_registered_for_an_extension_wins()
    {
        ImageFormat first = Marker(".rltwo", 1), second = Marker(".rltwo", 2);

        ImageFormats.Register(first);
        ImageFormats.Register(second);

        Assert.Same(second, ImageFormat.FromPath("b.rltwo"));
    }

    [Fact]
    public void An_unregistered_extension_is_a_one_line_error_naming_it_and_how_formats_are_added_and_makes_no_file()
    {
        string path = _dir.File("picture.rlnone");

        var ex = Assert.Throws<NotSupportedException>(() => new Image(2, 2).Save(path));

        Assert.False(ImageFormats.TryFindByExtension(".rlnone", out _));
        Assert.DoesNotContain("\n", ex.Message, StringComparison.Ordinal);
        Assert.Contains("'.rlnone'", ex.Message, StringComparison.Ordinal);
        Assert.Contains("registered: .png, .bmp, .jpg, .jpeg", ex.Message, StringComparison.Ordinal);
        Assert.Contains("ImageFormats.Register", ex.Message, StringComparison.Ordinal);
        Assert.Empty(_dir.Entries());
    }

    [Fact]
    public void Extensions_are_stored_lower_case_and_the_usual_one_first()
    {
        var format = new ImageFormat("Test", [".RLThree", ".rl3"], (_, _, _) => { });

        Assert.Equal([".rlthree", ".rl3"], format.Extensions);
        Assert.Equal("Test", format.ToString());
    }

    [Theory]
    [InlineData("rlfour")]
    [InlineData(".")]
    [InlineData(".rl.four")]
    [InlineData(".rl four")]
    [InlineData("")]
    public void A_format_needs_extensions_that_are_a_dot_and_letters_or_digits(string extension)
    {
        var ex = Assert.Throws<ArgumentException>(() => new ImageFormat("Test", [extension], (_, _, _) => { }));

        Assert.Equal("extensions", ex.ParamName);
    }

    [Fact]
    public void A_format_needs_a_name_an_extension_and_an_encoder()
    {
        Assert.Throws<ArgumentException>(() => new ImageFormat(" ", [".rlfive"], (_, _, _) => { }));
        Assert.Equal("extensions", Assert.Throws<ArgumentException>(() => new ImageFormat("Test", [], (_, _, _) => { })).ParamName);
        Assert.Throws<ArgumentNullException>(() => new ImageFormat("Test", [".rlfive"], null!));
        Assert.Throws<ArgumentNullException>(() => ImageFormats.Register(null!));
    }
}
