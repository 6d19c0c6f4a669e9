using System.IO.Compression;

namespace RayLab.Grading.Tests;

public sealed class SafeZipTests : IDisposable
{
    private readonly string _root = Directory.CreateTempSubdirectory("raylab-zip-").FullName;

    public void Dispose() => Directory.Delete(_root, recursive: true);

    [Fact]
    public void ALabZipUnpacksIntoItsFolder()
    {
        string zip = Zip(("lab/src/Lab/Lab.csproj", "<Project />"), ("lab/README.md", "hello"));
        string into = Path.Combine(_root, "out");
        SafeZip.Extract(zip, into, ZipLimits.Upload);
        Assert.Equal("<Project />", File.ReadAllText(Path.Combine(into, "lab", "src", "Lab", "Lab.csproj")));
        Assert.Equal("hello", File.ReadAllText(Path.Combine(into, "lab", "README.md")));
    }

    [Theory]
    [InlineData("../../x")]
    [InlineData("lab/../../x")]
    [InlineData("/etc/x")]
    [InlineData("..\\x")]
    [InlineData("C:/x")]
    public void AnEntryThatClimbsOutIsRefusedAndNothingIsWritten(string name)
    {
        string zip = Zip(("lab/a.txt", "a"), (name, "outside"));
        string into = Path.Combine(_root, "deep", "out");
        ZipRefusedException e = Assert.Throws<ZipRefusedException>(() => SafeZip.Extract(zip, into, ZipLimits.Upload));
        Assert.Equal($"entry {name} climbs out of the folder", e.Message);
        Assert.Equal($"wpis {name} wychodzi poza folder", e.Polish);
        Assert.False(Directory.Exists(into));
        Assert.False(File.Exists(Path.Combine(_root, "x")));
    }

    [Fact]
    public void ASymlinkEntryIsRefused()
    {
        string zip = Path.Combine(_root, "link.zip");
        using (ZipArchive archive = ZipFile.Open(zip, ZipArchiveMode.Create))
        {
            Write(archive, "lab/a.txt", "a");
            ZipArchiveEntry link = archive.CreateEntry("lab/solution");
            link.ExternalAttributes = unchecked((int)((0xA000u | 0x1FFu) << 16)); // S_IFLNK | 0777
            using var writer = new StreamWriter(link.Open());
            writer.Write("/home/instructor/kit/checks");
        }

        string into = Path.Combine(_root, "out");
        ZipRefusedException e = Assert.Throws<ZipRefusedException>(() => SafeZip.Extract(zip, into, ZipLimits.Upload));
        Assert.Equal("entry lab/solution is a link", e.Message);
        Assert.False(Directory.Exists(into));
    }

    [Fact]
    public void AZipBombBySizeIsRefusedOnTheBytesWrittenAndNothingIsLeft()
    {
        // 4 MB of zeros compress to a few kB; the limit is on what is written, not on what the zip's headers say.
        string zip = Path.Combine(_root, "bomb.zip");
        using (ZipArchive archive = ZipFile.Open(zip, ZipArchiveMode.Create))
        {
            Write(archive, "lab/small.txt", "a");
            using Stream s = archive.CreateEntry("lab/zeros.bin", CompressionLevel.Optimal).Open();
            s.Write(new byte[4 << 20]);
        }

        Assert.True(new FileInfo(zip).Length < 100_000);
        string into = Path.Combine(_root, "out");
        ZipRefusedException e = Assert.Throws<ZipRefusedException>(() => SafeZip.Extract(zip, into, new ZipLimits(1 << 20, 100)));
        Assert.Equal("unpacks to more than the 1048576 bytes allowed (at lab/zeros.bin)", e.Message);
        Assert.False(Directory.Exists(into));
    }

    [Fact]
    public void AZipWhoseHeadersUnderstateItsSizeWritesNoMoreThanTheLimit()
    {
        // The entry's local and central headers claim 10 bytes; the data inflates to 4 MB.
        string zip = Path.Combine(_root, "liar.zip");
        using (ZipArchive archive = ZipFile.Open(zip, ZipArchiveMode.Create))
        {
            using Stream s = archive.CreateEntry("zeros.bin", CompressionLevel.Optimal).Open();
            s.Write(new byte[4 << 20]);
        }

        byte[] bytes = File.ReadAllBytes(zip);
        PatchUncompressedSizes(bytes, 10);
        File.WriteAllBytes(zip, bytes);
        string into = Path.Combine(_root, "out");
        try
        {
            SafeZip.Extract(zip, into, new ZipLimits(1 << 20, 100));
            Assert.InRange(new FileInfo(Path.Combine(into, "zeros.bin")).Length, 0, 1 << 20);
        }
        catch (ZipRefusedException)
        {
            Assert.False(Directory.Exists(into));
        }
    }

    [Fact]
    public void AZipBombByCountIsRefused()
    {
        string zip = Zip([.. Enumerable.Range(0, 101).Select(i => ($"lab/{i}.txt", "x"))]);
        string into = Path.Combine(_root, "out");
        ZipRefusedException e = Assert.Throws<ZipRefusedException>(() => SafeZip.Extract(zip, into, new ZipLimits(1 << 20, 100)));
        Assert.Equal("101 entries, more than the 100 allowed", e.Message);
        Assert.False(Directory.Exists(into));
    }

    [Fact]
    public void AFileThatIsNotAZipIsRefusedWithOneLine()
    {
        string zip = Path.Combine(_root, "lab.zip");
        File.WriteAllText(zip, "not a zip");
        ZipRefusedException e = Assert.Throws<ZipRefusedException>(() => SafeZip.Extract(zip, Path.Combine(_root, "out"), ZipLimits.Upload));
        Assert.StartsWith("not a zip that can be read: ", e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void TheLimitsNameTheirParameter()
    {
        Assert.Equal("maxBytes", Assert.Throws<ArgumentOutOfRangeException>(() => new ZipLimits(0, 1)).ParamName);
        Assert.Equal("maxEntries", Assert.Throws<ArgumentOutOfRangeException>(() => new ZipLimits(1, 0)).ParamName);
    }

    [Fact]
    public void AnUploadedZipIsUnpackedAndARefusedOneGivesTheRowItsStatus()
    {
        string student = Directory.CreateDirectory(Path.Combine(_root, "Jan Kowalski_1_assignsubmission_file_")).FullName;
        File.Move(Zip(("Lab_Kowalski/src/Lab/Lab.csproj", "<Project />")), Path.Combine(student, "lab.zip"));
        UploadedLab ok = UploadedLab.Unpack(student, Path.Combine(_root, "unpacked-1"), ZipLimits.Upload);
        Assert.Equal(Path.Combine(_root, "unpacked-1"), ok.Folder);
        Assert.Null(ok.Refusal);

        string other = Directory.CreateDirectory(Path.Combine(_root, "Ewa Nowak_2_assignsubmission_file_")).FullName;
        File.Move(Zip(("lab/src/Lab/Lab.csproj", "<Project />"), ("../../x", "outside")), Path.Combine(other, "lab.zip"));
        UploadedLab refused = UploadedLab.Unpack(other, Path.Combine(_root, "unpacked-2"), ZipLimits.Upload);
        Assert.Null(refused.Folder);
        Assert.Equal("zip refused: lab.zip: entry ../../x climbs out of the folder", refused.Refusal);
        Assert.Equal("Archiwum odrzucone: lab.zip: wpis ../../x wychodzi poza folder", refused.PolishRefusal);
        Assert.False(Directory.Exists(Path.Combine(_root, "unpacked-2")));

        // A folder that holds a lab is taken as it is, whatever zips it holds.
        string plain = Directory.CreateDirectory(Path.Combine(_root, "plain", "src", "Lab")).FullName;
        File.WriteAllText(Path.Combine(plain, "Lab.csproj"), "<Project />");
        Assert.Equal(Path.Combine(_root, "plain"), UploadedLab.Unpack(Path.Combine(_root, "plain"), Path.Combine(_root, "unpacked-3"), ZipLimits.Upload).Folder);
    }

    private string Zip(params (string Name, string Text)[] entries)
    {
        string zip = Path.Combine(_root, $"{Guid.NewGuid():N}.zip");
        using ZipArchive archive = ZipFile.Open(zip, ZipArchiveMode.Create);
        foreach ((string name, string text) in entries)
        {
            Write(archive, name, text);
        }

        return zip;
    }

    private static void Write(ZipArchive archive, string name, string text)
    {
        using var writer = new StreamWriter(archive.CreateEntry(name).Open());
        writer.Write(text);
    }

    /// <summary>Sets every local and central header's uncompressed size (ZIP's PK\3\4 at +22, PK\1\2 at +24).</summary>
    private static void PatchUncompressedSizes(byte[] zip, uint size)
    {
        for (int i = 0; i + 4 <= zip.Length; i++)
        {
            if (zip[i] == 0x50 && zip[i + 1] == 0x4B && zip[i + 2] == 3 && zip[i + 3] == 4)
            {
                BitConverter.TryWriteBytes(zip.AsSpan(i + 22, 4), size);
            }
            else if (zip[i] == 0x50 && zip[i + 1] == 0x4B && zip[i + 2] == 1 && zip[i + 3] == 2)
            {
                BitConverter.TryWriteBytes(zip.AsSpan(i + 24, 4), size);
            }
        }
    }
}
