using System.Buffers.Binary;
using System.Text.Json;

namespace RayLab.Cli.Tests;

/// <summary>
/// The <c>raylab</c> console end to end: <see cref="Program.Run"/> in-process with string writers, and the built
/// <c>raylab.dll</c> as a child process where the current directory or the process exit matters.
/// </summary>
public sealed class ConsoleTests : IDisposable
{
    // 40×30, a sphere of radius 1 at the origin seen from 5 units away: it fills the centre and misses the corners.
    private const string SmallScene = """
        {
          "image": { "width": 40, "height": 30 },
          "background": [0, 0, 0],
          "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "fov": 40, "height": 2.5 },
          "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": [0.5, 0.25, 1] } ],
          "sampler": { "type": "regular", "samples": 1 }
        }
        """;

    /// <summary>[0.5, 0.25, 1] by the lab's rule int(256·I) clamped to 255.</summary>
    private static readonly Rgb24 SphereLevels = new(128, 64, 255);

    private static readonly Rgb24 Black = new(0, 0, 0);

    private static readonly byte[] PngSignature = [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    private readonly string _dir = Path.Combine(Path.GetTempPath(), "raylab-tests-" + Guid.NewGuid().ToString("N"));

    public ConsoleTests() => Directory.CreateDirectory(_dir);

    public void Dispose()
    {
        if (Directory.Exists(_dir))
        {
            Directory.Delete(_dir, recursive: true);
        }
    }

    // ---- successful renders ----------------------------------------------------------------------------

    [Fact]
    public void RenderWritesThePngAndOneSummaryLine()
    {
        string scene = WriteScene(SmallScene);
        string output = InDir("out.png");

        Result r = Run("render", scene, "-o", output);

        Assert.Equal(0, r.Code);
        Assert.Equal("", r.Err);
        Assert.True(File.Exists(output));
        byte[] png = File.ReadAllBytes(output);
        Assert.Equal(PngSignature, png.Take(8));
        Assert.Equal(40, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(16)));  // IHDR width
        Assert.Equal(30, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(20)));  // IHDR height
        string line = Assert.Single(Lines(r.Out));
        Assert.Contains(output, line, StringComparison.Ordinal);
        Assert.Contains("rays", line, StringComparison.Ordinal);
        Assert.Contains("40×30", line, StringComparison.Ordinal);
        Assert.Contains("perspective camera", line, StringComparison.Ordinal);
        AssertNoTempFiles();
    }

    [Fact]
    public void RenderToBmpHasTheSphereLevelsInTheCentreAndTheBackgroundInTheCorners()
    {
        string scene = WriteScene(SmallScene);
        string output = InDir("out.bmp");

        Result r = Run("render", scene, "-o", output);

        Assert.Equal(0, r.Code);
        Assert.Equal("", r.Err);
        Bmp bmp = Bmp.Read(output);
        Assert.Equal(40, bmp.Width);
        Assert.Equal(30, bmp.Height);
        Assert.Equal(SphereLevels, bmp.Pixel(20, 15));
        Assert.Equal(SphereLevels, bmp.Pixel(19, 14));
        Assert.Equal(Black, bmp.Pixel(0, 0));
        Assert.Equal(Black, bmp.Pixel(39, 0));
        Assert.Equal(Black, bmp.Pixel(0, 29));
        Assert.Equal(Black, bmp.Pixel(39, 29));
        string line = Assert.Single(Lines(r.Out));
        Assert.Contains(output, line, StringComparison.Ordinal);
        Assert.Contains("rays", line, StringComparison.Ordinal);
        AssertNoTempFiles();
    }

    [Theory]
    // background, ambient, sphere colour → levels: sphere shows as colour × ambient; int(256·I) clamped to 255.
    [InlineData("[0.2, 0.4, 0.6]", "[1, 1, 1]", "[0.5, 0.25, 1]", 51, 102, 153, 128, 64, 255)]
    [InlineData("[1, 2, 0]", "[0.5, 1, 0.25]", "[0.5, 0.25, 1]", 255, 255, 0, 64, 64, 64)]
    [InlineData("[0.999, 0.001, 0.5]", "[2, 2, 2]", "[0.1, 0.7, 0]", 255, 0, 128, 51, 255, 0)]
    public void PixelLevelsFollowTheLabsEightBitRule(
        string background, string ambient, string color, byte bgR, byte bgG, byte bgB, byte sR, byte sG, byte sB)
    {
        string scene = WriteScene($$"""
            {
              "image": { "width": 40, "height": 30 },
              "background": {{background}},
              "ambient": {{ambient}},
              "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "fov": 40 },
              "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": {{color}} } ]
            }
            """);
        string output = InDir("levels.bmp");

        Result r = Run("render", scene, "-o", output);

        Assert.Equal(0, r.Code);
        Bmp bmp = Bmp.Read(output);
        Assert.Equal(new Rgb24(sR, sG, sB), bmp.Pixel(20, 15));
        Assert.Equal(new Rgb24(bgR, bgG, bgB), bmp.Pixel(0, 0));
        Assert.Equal(new Rgb24(bgR, bgG, bgB), bmp.Pixel(39, 29));
    }

    [Fact]
    public void StatsAreWrittenAsJson()
    {
        string scene = WriteScene(SmallScene);
        string output = InDir("out.png");
        string stats = InDir("stats.json");

        Result r = Run("render", scene, "-o", output, "--stats", stats);

        Assert.Equal(0, r.Code);
        Assert.Equal("", r.Err);
        Assert.True(File.Exists(output));
        using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
        JsonElement root = json.RootElement;
        Assert.Equal(40, root.GetProperty("width").GetInt32());
        Assert.Equal(30, root.GetProperty("height").GetInt32());
        Assert.Equal("regular", root.GetProperty("sampler").GetString());
        Assert.Equal(1, root.GetProperty("samplesPerPixel").GetInt32());
        Assert.Equal(40 * 30 * 1, root.GetProperty("rays").GetInt64());
        Assert.Equal("perspective", root.GetProperty("camera").GetString());
        Assert.True(root.GetProperty("renderMs").GetDouble() >= 0);
        Assert.True(root.GetProperty("encodeMs").GetDouble() >= 0);
        Assert.False(root.TryGetProperty("commitMs", out _)); // no harness without --warmup
        Assert.Single(Lines(r.Out));
        AssertNoTempFiles();
    }

    [Fact]
    public void WidthAndHeightOptionsChangeTheImageSize()
    {
        string scene = WriteScene(SmallScene);
        string output = InDir("resized.bmp");
        string stats = InDir("stats.json");

        // 41 × 3 = 123 bytes per row: each row is padded to 124.
        Result r = Run("render", scene, "-o", output, "--width", "41", "--height", "31", "--stats", stats);

        Assert.Equal(0, r.Code);
        Bmp bmp = Bmp.Read(output);
        Assert.Equal(41, bmp.Width);
        Assert.Equal(31, bmp.Height);
        Assert.Equal(54 + (124 * 31), new FileInfo(output).Length);
        Assert.Equal(SphereLevels, bmp.Pixel(20, 15));
        Assert.Equal(Black, bmp.Pixel(0, 0));
        Assert.Equal(Black, bmp.Pixel(40, 30));
        using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
        Assert.Equal(41 * 31, json.RootElement.GetProperty("rays").GetInt64());
        Assert.Contains("41×31", Assert.Single(Lines(r.Out)), StringComparison.Ordinal);
    }

    [Fact]
    public void TheCameraOptionSwitchesToTheOrthographicCamera()
    {
        string scene = WriteScene(SmallScene);
        string perspective = InDir("perspective.bmp");
        string orthographic = InDir("orthographic.bmp");

        Result p = Run("render", scene, "-o", perspective);
        Result o = Run("render", scene, "-o", orthographic, "--camera", "orthographic");

        Assert.Equal(0, p.Code);
        Assert.Equal(0, o.Code);
        Assert.Equal("", o.Err);
        Assert.Contains("orthographic camera", Assert.Single(Lines(o.Out)), StringComparison.Ordinal);
        Bmp ortho = Bmp.Read(orthographic);
        Bmp persp = Bmp.Read(perspective);
        Assert.Equal(SphereLevels, ortho.Pixel(20, 15));
        Assert.Equal(Black, ortho.Pixel(0, 0));
        // Row 5 is 2/3 of the way from the centre to the top edge: inside the sphere for the 2.5-unit
        // orthographic view (v ≈ 0.79 < 1), outside it for the 40° perspective view from 5 units.
        Assert.Equal(SphereLevels, ortho.Pixel(20, 5));
        Assert.Equal(Black, persp.Pixel(20, 5));
    }

    [Fact]
    public void TheRandomSamplerTakesAnySampleCount()
    {
        string scene = WriteScene(SmallScene);
        string output = InDir("random.png");
        string stats = InDir("stats.json");

        Result r = Run("render", scene, "-o", output, "--sampler", "random", "--samples", "3", "--stats", stats);

        Assert.Equal(0, r.Code);
        Assert.Equal("", r.Err);
        Assert.True(File.Exists(output));
        using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
        Assert.Equal("random", json.RootElement.GetProperty("sampler").GetString());
        Assert.Equal(3, json.RootElement.GetProperty("samplesPerPixel").GetInt32());
        Assert.Equal(40 * 30 * 3, json.RootElement.GetProperty("rays").GetInt64());
        Assert.Contains("random 3 spp", Assert.Single(Lines(r.Out)), StringComparison.Ordinal);
    }

    [Fact]
    public void OneThreadAndTwoThreadsGiveTheSameBytes()
    {
        string scene = WriteScene(SmallScene);
        string one = InDir("one.bmp");
        string two = InDir("two.bmp");

        Result r1 = Run("render", scene, "-o", one, "--sampler", "jittered", "--samples", "4", "--seed", "7", "--threads", "1");
        Result r2 = Run("render", scene, "-o", two, "--sampler", "jittered", "--samples", "4", "--seed", "7", "--threads", "2");

        Assert.Equal(0, r1.Code);
        Assert.Equal(0, r2.Code);
        Assert.Equal(File.ReadAllBytes(one), File.ReadAllBytes(two));
        // The comparison means something only if the jitter shows: some edge pixels are a blend.
        Bmp bmp = Bmp.Read(one);
        Assert.Contains(bmp.AllPixels(), p => p != SphereLevels && p != Black);
    }

    [Fact]
    public void DifferentSeedsGiveDifferentJitteredImagesAndTheSameSeedTheSame()
    {
        string scene = WriteScene(SmallScene);
        string a = InDir("seed1.bmp");
        string b = InDir("seed2.bmp");
        string again = InDir("seed1-again.bmp");

        Assert.Equal(0, Run("render", scene, "-o", a, "--sampler", "jittered", "--samples", "4", "--seed", "1").Code);
        Assert.Equal(0, Run("render", scene, "-o", b, "--sampler", "jittered", "--samples", "4", "--seed", "2").Code);
        Assert.Equal(0, Run("render", scene, "-o", again, "--sampler", "jittered", "--samples", "4", "--seed", "1").Code);

        Assert.NotEqual(File.ReadAllBytes(a), File.ReadAllBytes(b));
        Assert.Equal(File.ReadAllBytes(a), File.ReadAllBytes(again));
    }

    // ---- errors ---------------------------------------------------------------------------------------

    [Theory]
    [InlineData("none", "raylab: error: {scene}: ", "missing.json", "render", "{scene}", "-o", "{out}")]
    [InlineData("malformed", "raylab: error: {scene}: not valid JSON", "scene.json", "render", "{scene}", "-o", "{out}")]
    [InlineData("fov190", "raylab: error: {scene}: camera.fov: ", "camera.fov", "render", "{scene}", "-o", "{out}")]
    [InlineData("jittered", "raylab: error: --samples", "--samples", "render", "{scene}", "-o", "{out}", "--samples", "5")]
    [InlineData("small", "raylab: error: --samples", "--samples", "render", "{scene}", "-o", "{out}", "--sampler", "jittered", "--samples", "5")]
    [InlineData("small", "raylab: error: --samples", "--samples", "render", "{scene}", "-o", "{out}", "--sampler", "random", "--samples", "0")]
    [InlineData("small", "raylab: error: --samples", "--samples", "render", "{scene}", "-o", "{out}", "--samples", "-1")]
    [InlineData("small", "raylab: error: --threads", "--threads", "render", "{scene}", "-o", "{out}", "--threads", "0")]
    [InlineData("small", "raylab: error: --width", "--width", "render", "{scene}", "-o", "{out}", "--width", "0")]
    [InlineData("small", "raylab: error: ", "--bogus", "render", "{scene}", "-o", "{out}", "--bogus")]
    [InlineData("small", "raylab: error: ", "--output", "render", "{scene}")]
    [InlineData("small", "raylab: error: --output", ".jpg", "render", "{scene}", "-o", "{dir}/out.tiff")]
    [InlineData("small", "raylab: error: --output", "no-such-folder", "render", "{scene}", "-o", "{dir}/no-such-folder/out.png")]
    [InlineData("small", "raylab: error: --stats", "no-such-folder", "render", "{scene}", "-o", "{out}", "--stats", "{dir}/no-such-folder/stats.json")]
    public void AnErrorIsOneLineNamingTheProblemAndLeavesNoFiles(string scene, string expectedStart, string mention, params string[] args) =>
        AssertFailsCleanly(scene, expectedStart, mention, args);

    [Fact]
    public void AnUnknownSamplerIsOneLineNamingTheOption() =>
        AssertFailsCleanly("small", "raylab: error: ", "--sampler", "render", "{scene}", "-o", "{out}", "--sampler", "bogus");

    [Fact]
    public void AnUnknownCameraIsOneLineNamingTheOption() =>
        AssertFailsCleanly("small", "raylab: error: ", "--camera", "render", "{scene}", "-o", "{out}", "--camera", "fisheye");

    [Fact]
    public void AnImageTooLargeBecauseOfTheHeightOptionNamesTheOption() =>
        AssertFailsCleanly("small", "raylab: error: --height", "--height", "render", "{scene}", "-o", "{out}", "--height", "100000000");

    [Fact]
    public void StatsIntoTheOutputFileIsRejected() =>
        AssertFailsCleanly("small", "raylab: error: --stats", "--stats", "render", "{scene}", "-o", "{out}", "--stats", "{out}");

    [Theory]
    [InlineData("--sampler", "bogus")]
    [InlineData("--camera", "fisheye")]
    public void AnUnknownChoiceIsRejectedWithoutOutput(string option, string value)
    {
        string scene = WriteScene(SmallScene);
        string[] before = FilesInDir();

        Result r = Run("render", scene, "-o", InDir("out.png"), option, value);

        Assert.Equal(1, r.Code); // a bad option value is bad input (1); a malformed command line is 2
        Assert.Equal("", r.Out);
        Assert.StartsWith("raylab: error:", r.Err, StringComparison.Ordinal);
        Assert.Contains($"'{value}'", r.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", r.Err, StringComparison.Ordinal);
        Assert.Equal(before, FilesInDir());
    }

    [Fact]
    public void AFailedRenderKeepsAnExistingOutputFile()
    {
        string scene = WriteScene(SmallScene.Replace("\"fov\": 40", "\"fov\": 190", StringComparison.Ordinal));
        string output = InDir("out.png");
        File.WriteAllText(output, "previous");

        Result r = Run("render", scene, "-o", output);

        Assert.Equal(1, r.Code);
        Assert.Equal("previous", File.ReadAllText(output));
        AssertNoTempFiles();
    }

    // ---- the built app as a child process -------------------------------------------------------------

    [Fact]
    public async Task WithNoArgumentsTheAppRendersBothCamerasIntoOut()
    {
        Result r = await RunChildAsync();

        Assert.Equal(0, r.Code);
        Assert.Equal("", r.Err);
        foreach (string camera in new[] { "orthographic", "perspective" })
        {
            string path = Path.Combine(_dir, "out", $"two-spheres-{camera}.png");
            Assert.True(File.Exists(path), $"{path} was not written");
            byte[] png = File.ReadAllBytes(path);
            Assert.Equal(PngSignature, png.Take(8));
            Assert.Equal(800, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(16)));
            Assert.Equal(600, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(20)));
        }

        string[] lines = Lines(r.Out);
        Assert.Equal(2, lines.Length);
        Assert.Single(lines, l => l.Contains("orthographic", StringComparison.Ordinal));
        Assert.Single(lines, l => l.Contains("perspective", StringComparison.Ordinal));
        Assert.All(lines, l => Assert.Contains("rays", l, StringComparison.Ordinal));
        Assert.Empty(Directory.GetFiles(_dir, "*.tmp", SearchOption.AllDirectories));
    }

    [Fact]
    public async Task WithNoArgumentsAFileNamedOutIsOneLineAndExitOne()
    {
        File.WriteAllText(Path.Combine(_dir, "out"), "mine");

        Result r = await RunChildAsync();

        Assert.True(r.Code == 1, $"exit {r.Code}: {r.Err}");
        Assert.Equal("", r.Out);
        string line = Assert.Single(Lines(r.Err));
        Assert.StartsWith("raylab: error: out: ", line, StringComparison.Ordinal);
        Assert.Contains("is a file", line, StringComparison.Ordinal);
        Assert.Equal("mine", File.ReadAllText(Path.Combine(_dir, "out")));
    }

    [Fact]
    public async Task TheAppReportsAnErrorAsOneLineAndANonZeroExitCode()
    {
        Result r = await RunChildAsync("render", "missing.json", "-o", "out.png");

        Assert.NotEqual(0, r.Code);
        Assert.Equal("", r.Out);
        string line = Assert.Single(Lines(r.Err));
        Assert.StartsWith("raylab: error:", line, StringComparison.Ordinal);
        Assert.Contains("missing.json", line, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", r.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("Unhandled exception", r.Err, StringComparison.Ordinal);
        Assert.Empty(Directory.GetFileSystemEntries(_dir));
    }

    // ---- helpers --------------------------------------------------------------------------------------

    private readonly record struct Result(int Code, string Out, string Err);

    private static Result Run(params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int code = Program.Run(args, stdout, stderr);
        return new Result(code, stdout.ToString(), stderr.ToString());
    }

    private void AssertFailsCleanly(string sceneKind, string expectedStart, string mention, params string[] args)
    {
        string scene = sceneKind switch
        {
            "none" => InDir("missing.json"),
            "small" => WriteScene(SmallScene),
            "malformed" => WriteScene("{ \"image\": { \"width\": 40, "),
            "fov190" => WriteScene(SmallScene.Replace("\"fov\": 40", "\"fov\": 190", StringComparison.Ordinal)),
            "jittered" => WriteScene(SmallScene.Replace("\"type\": \"regular\"", "\"type\": \"jittered\"", StringComparison.Ordinal)),
            _ => throw new ArgumentOutOfRangeException(nameof(sceneKind), sceneKind, null),
        };
        string Fill(string s) => s
            .Replace("{scene}", scene, StringComparison.Ordinal)
            .Replace("{out}", InDir("out.png"), StringComparison.Ordinal)
            .Replace("{dir}", _dir, StringComparison.Ordinal);
        string[] before = FilesInDir();

        Result r = Run([.. args.Select(Fill)]);

        Assert.NotEqual(0, r.Code);
        Assert.True(r.Code is 1 or 2, $"exit code {r.Code}"); // not 70, the code for an internal error
        Assert.Equal("", r.Out);
        string line = Assert.Single(Lines(r.Err));
        Assert.StartsWith(Fill(expectedStart), line, StringComparison.Ordinal);
        Assert.Contains(Fill(mention), line, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", r.Err, StringComparison.Ordinal);
        Assert.Equal(before, FilesInDir()); // no image, no stats, no *.tmp
    }

    private string WriteScene(string json)
    {
        string path = InDir("scene.json");
        File.WriteAllText(path, json);
        return path;
    }

    private string InDir(string name) => Path.Combine(_dir, name);

    private string[] FilesInDir() =>
        [.. Directory.GetFileSystemEntries(_dir, "*", SearchOption.AllDirectories).Order(StringComparer.Ordinal)];

    private void AssertNoTempFiles() =>
        Assert.Empty(Directory.GetFiles(_dir, "*.tmp", SearchOption.AllDirectories));

    /// <summary>The lines of some output; the text must end with a newline (or be empty).</summary>
    private static string[] Lines(string text)
    {
        if (text.Length == 0)
        {
            return [];
        }

        Assert.EndsWith("\n", text, StringComparison.Ordinal);
        return text[..^1].Replace("\r\n", "\n", StringComparison.Ordinal).TrimEnd('\r').Split('\n');
    }

    private async Task<Result> RunChildAsync(params string[] args)
    {
        (int code, string stdout, string stderr) = await ConsoleRunner.RunChildAsync(_dir, args);
        return new Result(code, stdout, stderr);
    }

    /// <summary>Reads a 24-bit BMP: BITMAPINFOHEADER, bottom-up rows, BGR, rows padded to 4 bytes.</summary>
    private sealed class Bmp
    {
        private readonly byte[] _bytes;
        private readonly int _offset;
        private readonly int _stride;

        private Bmp(byte[] bytes)
        {
            _bytes = bytes;
            Assert.Equal((byte)'B', bytes[0]);
            Assert.Equal((byte)'M', bytes[1]);
            Assert.Equal((uint)bytes.Length, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(2)));
            _offset = (int)BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(10));
            Assert.Equal(40u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(14)));
            Width = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(18));
            Height = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(22));
            Assert.True(Height > 0, "expected a bottom-up BMP (positive height)");
            Assert.Equal(1, BinaryPrimitives.ReadUInt16LittleEndian(bytes.AsSpan(26)));   // planes
            Assert.Equal(24, BinaryPrimitives.ReadUInt16LittleEndian(bytes.AsSpan(28)));  // bits per pixel
            Assert.Equal(0u, BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(30)));  // BI_RGB
            _stride = ((Width * 3) + 3) & ~3;
            Assert.Equal(_offset + ((long)_stride * Height), bytes.Length);
        }

        public int Width { get; }

        public int Height { get; }

        public static Bmp Read(string path) => new(File.ReadAllBytes(path));

        /// <summary>Pixel (x, y) with y = 0 the top row.</summary>
        public Rgb24 Pixel(int x, int y)
        {
            int i = _offset + ((Height - 1 - y) * _stride) + (x * 3);
            return new Rgb24(_bytes[i + 2], _bytes[i + 1], _bytes[i]);
        }

        public IEnumerable<Rgb24> AllPixels()
        {
            for (int y = 0; y < Height; y++)
            {
                for (int x = 0; x < Width; x++)
                {
                    yield return Pixel(x, y);
                }
            }
        }
    }
}
