using RayLab.Tests.Shared;

namespace RayLab.Grading.Tests;

/// <summary>
/// What <c>raylab grade</c> reads back from a lab's copy, read as the lab's own and untrusted: its pictures (no link,
/// a capped size, the header before any pixel), its program's start, its output in the log, its words in the CSV.
/// Graded end to end in ClassKitTests (tests/RayLab.Templates.Tests).
/// </summary>
public sealed class GradeReadBackTests : IDisposable
{
    private readonly TempDirectory _dir = new();

    public GradeReadBackTests()
    {
        Directory.CreateDirectory(Lab("out"));
    }

    public void Dispose() => _dir.Dispose();

    [Theory]
    [InlineData("=1+1", "'=1+1")]
    [InlineData("+48123456789", "'+48123456789")]
    [InlineData("-2+3", "'-2+3")]
    [InlineData("@SUM(A1:A9)", "'@SUM(A1:A9)")]
    [InlineData("\t=1", "'\t=1")]
    [InlineData("\r=1", "\"'\r=1\"")]
    [InlineData("=HYPERLINK(\"http://evil.example/\",\"click\")", "\"'=HYPERLINK(\"\"http://evil.example/\"\",\"\"click\"\")\"")]
    [InlineData("Anna Nowak", "Anna Nowak")]
    [InlineData("a = b", "a = b")]
    [InlineData("does not build; error CS1002, line 3", "\"does not build; error CS1002, line 3\"")]
    [InlineData("", "")]
    public void ACsvCellThatASpreadsheetWouldTakeForAFormulaStartsWithAQuote(string text, string cell) =>
        Assert.Equal(cell, GradeCsv.Cell(text));

    [Fact]
    public void APictureInTheCopyIsReadAndScoredAtItsSize()
    {
        Picture(8, 6).Save(Lab("out/p.png"));
        PictureRead read = GradeJob.ReadPicture(Lab(), "out/p.png", 8, 6);
        Assert.Null(read.Status);
        Assert.NotNull(read.Picture);
        Assert.Equal(Picture(8, 6).PixelBytes.ToArray(), read.Picture.PixelBytes.ToArray());
        Assert.True(GradeJob.ReadPicture(Lab(), "out/none.png", 8, 6).Missing);
    }

    [Theory]
    [InlineData("outside")]   // the picture: a link to a file outside the copy
    [InlineData("folder")]    // a folder on its path: a link to a folder outside the copy
    [InlineData("inside")]    // a link to another file of the copy: no link is followed at all
    [InlineData("dangling")]  // a link to nothing
    public void APictureThatIsALinkOrHasOneOnItsPathIsRefused(string kind)
    {
        string outside = Directory.CreateDirectory(_dir.File("elsewhere")).FullName;
        Picture(8, 6).Save(Path.Combine(outside, "p.png"));
        Picture(8, 6).Save(Lab("out/real.png"));
        string file = "out/p.png";
        switch (kind)
        {
            case "outside":
                File.CreateSymbolicLink(Lab("out/p.png"), Path.Combine(outside, "p.png"));
                break;
            case "folder":
                Directory.CreateSymbolicLink(Lab("pictures"), outside);
                file = "pictures/p.png";
                break;
            case "inside":
                File.CreateSymbolicLink(Lab("out/p.png"), "real.png");
                break;
            default:
                File.CreateSymbolicLink(Lab("out/p.png"), Path.Combine(outside, "none.png"));
                break;
        }

        PictureRead read = GradeJob.ReadPicture(Lab(), file, 8, 6);
        Assert.Equal(GradeJob.PictureIsALink, read.Status);
        Assert.Null(read.Picture);
        Assert.False(read.Missing);
        Assert.Equal($"{file} is a link, or a folder on its path is: the grader follows no link out of a lab's copy", read.Problem);
    }

    [Theory]
    [InlineData(100_000, 100_000)] // more than RayLab's reader takes at all
    [InlineData(20_000, 20_000)]   // within it: 1.6 GB of pixels, 2.1 GB to decode into
    [InlineData(8, 60_000)]        // as wide as the exact image, much taller
    public void APngClaimingAHugeSizeIsRefusedFromItsHeaderWithoutAllocatingItsPixels(int width, int height)
    {
        File.WriteAllBytes(Lab("out/p.png"), ClaimingPng.Of(width, height));
        long before = GC.GetAllocatedBytesForCurrentThread();
        PictureRead read = GradeJob.ReadPicture(Lab(), "out/p.png", 8, 6);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(GradeJob.PictureTooLarge, read.Status);
        Assert.Null(read.Picture);
        Assert.Equal($"out/p.png claims {width}×{height} pixels, more than the exact image's 8×6; not decoded", read.Problem);
        Assert.True(allocated < 1 << 20, $"{allocated:N0} bytes allocated to refuse it");
    }

    [Fact]
    public void APictureFileLargerThanItsSizeCanTakeIsNotRead()
    {
        long cap = GradeJob.PictureByteCap(8, 6);
        byte[] png = ClaimingPng.Of(8, 6);
        using (FileStream file = File.Create(Lab("out/p.png")))
        {
            file.Write(png);
            file.SetLength(cap + 1); // a valid header, then zeros
        }

        PictureRead read = GradeJob.ReadPicture(Lab(), "out/p.png", 8, 6);
        Assert.Equal(GradeJob.PictureTooLarge, read.Status);
        Assert.Equal($"out/p.png: {cap + 1:N0} bytes, more than the {cap:N0} a 8×6 picture takes; not read", read.Problem);
    }

    [Fact]
    public void APictureThatIsNoPictureOrAFolderDoesNotDecodeAndIsNoRowProblem()
    {
        File.WriteAllText(Lab("out/text.png"), "not a picture");
        File.WriteAllBytes(Lab("out/empty.png"), []);
        Directory.CreateDirectory(Lab("out/folder.png"));
        foreach (string file in (string[])["out/text.png", "out/empty.png", "out/folder.png"])
        {
            PictureRead read = GradeJob.ReadPicture(Lab(), file, 8, 6);
            Assert.Null(read.Status);
            Assert.Null(read.Picture);
            Assert.StartsWith($"{file} does not decode", read.Problem, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void TheProgramIsTheBuiltAssemblyStartedDirectlyWhenItIsAProgram()
    {
        Directory.CreateDirectory(Lab("src/Lab"));
        File.WriteAllText(Lab("src/Lab/Lab.csproj"), "<Project />");
        ProgramLaunch none = GradeJob.ProgramCommand(Lab()); // nothing built: dotnet run says why
        Assert.Equal(["run", "--project", Path.Combine("src", "Lab"), "--no-build"], none.Args);
        Assert.Contains("its start counted", none.TimedBy, StringComparison.Ordinal);

        string bin = Directory.CreateDirectory(Lab("src/Lab/bin/Debug/net10.0")).FullName;
        File.WriteAllText(Path.Combine(bin, "Lab.dll"), "");
        Assert.Equal(none.Args, GradeJob.ProgramCommand(Lab()).Args); // a library, not a program: no runtimeconfig.json beside it

        File.WriteAllText(Path.Combine(bin, "Lab.runtimeconfig.json"), "{}");
        ProgramLaunch direct = GradeJob.ProgramCommand(Lab());
        Assert.Equal("dotnet", direct.Command);
        Assert.Equal(["src/Lab/bin/Debug/net10.0/Lab.dll"], direct.Args);
        Assert.Contains("the grader's clock around the built program", direct.TimedBy, StringComparison.Ordinal);
    }

    [Fact]
    public void AStepsOutputPastItsLimitKeepsItsHeadAndTailAndSaysWhereItWasCut()
    {
        string log = _dir.File("log.txt");
        string output = "HEAD" + new string('x', 3 * GradeSandbox.LogStepLimit) + "TAIL\u001b[31m";
        GradeSandbox.AppendLog(log, "$ dotnet run", output, "[exit 0, 1.0 s]");
        string text = File.ReadAllText(log);
        Assert.StartsWith("$ dotnet run\nHEAD", text, StringComparison.Ordinal);
        Assert.EndsWith("TAIL?[31m\n[exit 0, 1.0 s]\n\n", text, StringComparison.Ordinal); // the escape shown as '?'
        Assert.Contains($"[… {output.Length - GradeSandbox.LogStepLimit:N0} characters of this step's output left out here: the log keeps the first and the last {GradeSandbox.LogStepLimit / 2:N0} of each step …]", text, StringComparison.Ordinal);
        Assert.InRange(text.Length, GradeSandbox.LogStepLimit, GradeSandbox.LogStepLimit + 500);
    }

    [Fact]
    public void ALogPastItsLimitEndsWithTheLineThatSaysSoAndGrowsNoMore()
    {
        string log = _dir.File("log.txt");
        string step = new('é', GradeSandbox.LogStepLimit / 2); // two bytes each: a cut must not split one
        int steps = 0;
        while (!File.Exists(log) || !File.ReadAllText(log).EndsWith(GradeSandbox.LogFullLine + "\n", StringComparison.Ordinal))
        {
            GradeSandbox.AppendLog(log, "$ dotnet test", step, "[exit 1, 2.0 s]");
            Assert.True(++steps < 100, "the log never reached its limit");
        }

        long length = new FileInfo(log).Length;
        Assert.InRange(length, GradeSandbox.LogTotalLimit - 200, GradeSandbox.LogTotalLimit);
        Assert.DoesNotContain('\uFFFD', File.ReadAllText(log)); // every character whole
        GradeSandbox.AppendLog(log, "$ dotnet run", "more", "[exit 0, 1.0 s]");
        Assert.Equal(length, new FileInfo(log).Length);
    }

    [Fact]
    public void ARealStepsLogIsCappedToo()
    {
        // A real child through the sandbox's runner (unsandboxed): 1 MB of output, in the log at most its limit.
        GradeSandbox plain = GradeSandbox.Create(unsafeNoSandbox: true, [], Directory.CreateDirectory(_dir.File("packages")).FullName);
        string log = _dir.File("real-log.txt");
        ChildRun run = plain.Run(Lab(), log, TimeSpan.FromMinutes(1), "sh", ["-c", "head -c 1000000 /dev/zero | tr '\\0' x; echo; echo done"], TestContext.Current.CancellationToken);
        Assert.Equal(0, run.ExitCode);
        string text = File.ReadAllText(log);
        Assert.InRange(text.Length, GradeSandbox.LogStepLimit, GradeSandbox.LogStepLimit + 500);
        Assert.Contains("characters of this step's output left out here", text, StringComparison.Ordinal);
        Assert.Contains("done\n\n[exit 0,", text, StringComparison.Ordinal);
    }

    private string Lab(string? path = null) => path is null ? _dir.File("lab") : Path.Combine(_dir.File("lab"), path);

    private static Image Picture(int width, int height)
    {
        var image = new Image(width, height);
        for (int y = 0; y < height; y++)
        {
            for (int x = 0; x < width; x++)
            {
                image.GetRowSpan(y)[x] = new Rgb24((byte)(x * 30), (byte)(y * 40), 77);
            }
        }

        return image;
    }
}
