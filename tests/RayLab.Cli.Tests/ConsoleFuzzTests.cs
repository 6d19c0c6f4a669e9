using System.Text;
using System.Text.RegularExpressions;
using FsCheck;
using FsCheck.Fluent;

namespace RayLab.Cli.Tests;

/// <summary>
/// Fuzzing <c>raylab render</c> in-process (fixed FsCheck seed): random mutations of the shipped two-sphere
/// scene and random bytes. Whatever the file, the app either renders (exit 0, one summary line, a PNG that
/// decodes) or refuses it (exit 1, exactly one line on stderr naming the file, no image and no temporary file):
/// never exit 70 (an internal error), never a stack trace.
/// </summary>
public sealed partial class ConsoleFuzzTests : IDisposable
{
    private readonly TempDirectory _dir = new();
    private readonly ITestOutputHelper _output;

    public ConsoleFuzzTests(ITestOutputHelper output) => _output = output;

    public void Dispose() => _dir.Dispose();

    /// <summary>
    /// The shipped scene at 24×18 instead of 800×600 (every other byte as shipped), so that the mutants which
    /// stay valid render in milliseconds.
    /// </summary>
    private static readonly string BaseScene = File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json"))
        .Replace("\"width\": 800, \"height\": 600", "\"width\": 24, \"height\": 18", StringComparison.Ordinal);

    [Fact]
    public void TheBaseSceneRenders()
    {
        Assert.Contains("\"width\": 24, \"height\": 18", BaseScene, StringComparison.Ordinal);
        Assert.Equal(0, RunOn(Encoding.UTF8.GetBytes(BaseScene)));
    }

    [Theory]
    // What the fuzzer found, kept whatever the seed: an escaped line break in a field name split the error over
    // two lines; a raw one inside broken JSON did too (the parser quotes it); an unpaired surrogate escape made
    // System.Text.Json throw InvalidOperationException, which came out as exit 70.
    [InlineData("\"fov\": 40", "\"line\\r\\nbreak\": 40")]
    [InlineData("\"near\": 0.1", "\"near\": tru\ne")]
    [InlineData("\"type\": \"perspective\"", "\"type\": \"\\ud800\"")]
    [InlineData("\"radius\": 1,", "\"\\udc00\": 1,")]
    public void WhatTheFuzzerFoundFailsWithOneLine(string find, string replace)
    {
        string scene = BaseScene.Replace(find, replace, StringComparison.Ordinal);
        Assert.NotEqual(BaseScene, scene);
        Assert.Equal(1, RunOn(Encoding.UTF8.GetBytes(scene)));
    }

    [Fact]
    public void AnOptionValueWithALineBreakStillGivesOneLine()
    {
        File.WriteAllText(_dir.File("scene.json"), BaseScene);
        var stderr = new StringWriter();

        int code = Program.Run(["render", _dir.File("scene.json"), "-o", _dir.File("no\nsuch/out.png")], new StringWriter(), stderr, TestContext.Current.CancellationToken);

        Assert.Equal(1, code);
        string line = Assert.Single(Lines(stderr.ToString()));
        Assert.StartsWith("raylab: error: --output: the folder ", line, StringComparison.Ordinal);
        Assert.Contains("no\\nsuch", line, StringComparison.Ordinal);
    }

    [Fact]
    public void MutatedScenesRenderOrFailWithOneLineAndNoFiles()
    {
        int[] codes = new int[2];
        PropertyCheck.ForAll(Mutants, 400, mutant => codes[RunOn(mutant.Apply(Encoding.UTF8.GetBytes(BaseScene)))]++);
        _output.WriteLine($"400 mutants: {codes[0]} rendered, {codes[1]} refused");
        Assert.True(codes[0] >= 40 && codes[1] >= 40, "the mutants should exercise both outcomes");
    }

    [Fact]
    public void RandomBytesFailWithOneLineAndNoFiles()
    {
        PropertyCheck.ForAll(RandomFiles, 150, bytes => Assert.Equal(1, RunOn(bytes.Bytes)));
    }

    /// <summary>Runs <c>raylab render scene.json -o out.png</c> on the bytes and checks the outcome; returns the exit code.</summary>
    private int RunOn(byte[] scene)
    {
        string scenePath = _dir.File("scene.json");
        string output = _dir.File("out.png");
        File.WriteAllBytes(scenePath, scene);
        var stdout = new StringWriter();
        var stderr = new StringWriter();

        int code = Program.Run(["render", scenePath, "-o", output], stdout, stderr);

        string err = stderr.ToString(), @out = stdout.ToString();
        string context = $"exit {code}; stderr: {err}; stdout: {@out}";
        Assert.DoesNotContain("   at ", err, StringComparison.Ordinal);
        if (code == 0)
        {
            Assert.Equal("", err);
            Assert.Single(Lines(@out));
            Assert.Equal(["out.png", "scene.json"], _dir.Entries());
            SkiaDecode.Result png = SkiaDecode.Decode(File.ReadAllBytes(output));
            Assert.True(png.Width >= 1 && png.Height >= 1);
            File.Delete(output);
        }
        else
        {
            Assert.True(code == 1, context);
            Assert.Equal("", @out);
            string line = Assert.Single(Lines(err));
            Assert.StartsWith($"raylab: error: {scenePath}: ", line, StringComparison.Ordinal);
            Assert.Equal(["scene.json"], _dir.Entries());
        }

        return code;
    }

    private static string[] Lines(string text)
    {
        Assert.EndsWith(Environment.NewLine, text, StringComparison.Ordinal);
        return text[..^Environment.NewLine.Length].Split('\n');
    }

    // ---- generators ------------------------------------------------------------------------------------

    /// <summary>One to three edits of the scene's bytes.</summary>
    public sealed record Mutant(Edit[] Edits)
    {
        public byte[] Apply(byte[] bytes) => Edits.Aggregate(bytes, (b, e) => e.Apply(b));

        public override string ToString() => string.Join("; ", Edits.Select(e => e.ToString()));
    }

    /// <summary>An edit: its kind and three random numbers that pick where and what.</summary>
    public sealed record Edit(int Kind, int A, int B, int C)
    {
        private static readonly string[] Numbers =
        [
            "0", "-0", "-1", "1", "2", "0.5", "1.5", "3", "10", "11", "180", "65536", "65537", "1048576", "1048577",
            "2147483648", "4294967296", "-4294967296", "1e308", "-1e308", "1e999", "-1e999", "1e-320", "5e-324",
            "123456789012345678901234567890", "NaN", "Infinity", "\"1\"", "null", "true", "[]", "{}", "[1, 2]", "[0, 0, 0]",
        ];

        private static readonly string[] Strings =
        [
            "\"\"", "\"bogus\"", "\"perspective\"", "\"orthographic\"", "\"adaptive\"", "\"regular\"", "\"random\"",
            "\"jittered\"", "\"sobol\"", "\"cmj\"", "\"width\"", "\"samples\"", "\"a\\nb\"", "\"line\\r\\nbreak\"",
            "\"\\u0000\"", "\"\\ud800\"", "\"\\t\"", "\"é\"", "\"" + new string('x', 300) + "\"", "1", "null", "[]", "{}",
        ];

        private static readonly byte[] Bytes = "\0\"{}[],:-.e\n\\/*0"u8.ToArray().Concat(new byte[] { 0xFF, 0xC3, 0xEF, 0xBB, 0xBF, 0x80 }).ToArray();

        public byte[] Apply(byte[] input)
        {
            if (input.Length == 0)
            {
                return input;
            }

            string text = Encoding.UTF8.GetString(input);
            int at = A % input.Length;
            switch (Kind)
            {
                case 0: // flip one bit
                    byte[] flipped = (byte[])input.Clone();
                    flipped[at] ^= (byte)(1 << (B % 8));
                    return flipped;
                case 1: // overwrite one byte with a JSON-significant or UTF-8-breaking one
                    byte[] replaced = (byte[])input.Clone();
                    replaced[at] = Bytes[B % Bytes.Length];
                    return replaced;
                case 2: // delete up to 20 bytes
                    return [.. input[..at], .. input[Math.Min(input.Length, at + 1 + (B % 20))..]];
                case 3: // duplicate up to 40 bytes
                    int end = Math.Min(input.Length, at + 1 + (B % 40));
                    return [.. input[..end], .. input[at..end], .. input[end..]];
                case 4: // truncate
                    return input[..at];
                case 5: // replace a number with an interesting literal
                    return ReplaceToken(text, NumberToken(), Numbers[B % Numbers.Length]);
                case 6: // replace a string (a key or a value) with an interesting one
                    return ReplaceToken(text, StringToken(), Strings[B % Strings.Length]);
                default: // remove one "key": value member
                    return ReplaceToken(text, MemberToken(), "");
            }
        }

        public override string ToString() => Kind switch
        {
            0 => $"flip bit {B % 8} of byte #{A}",
            1 => $"byte #{A} := 0x{Bytes[B % Bytes.Length]:X2}",
            2 => $"delete {1 + (B % 20)} bytes at #{A}",
            3 => $"duplicate {1 + (B % 40)} bytes at #{A}",
            4 => $"truncate at #{A}",
            5 => $"number #{C} := {Numbers[B % Numbers.Length]}",
            6 => $"string #{C} := {Strings[B % Strings.Length]}",
            _ => $"remove member #{C}",
        };

        private byte[] ReplaceToken(string text, Regex token, string replacement)
        {
            MatchCollection matches = token.Matches(text);
            if (matches.Count == 0)
            {
                return Encoding.UTF8.GetBytes(text);
            }

            Match m = matches[C % matches.Count];
            return Encoding.UTF8.GetBytes(string.Concat(text.AsSpan(0, m.Index), replacement, text.AsSpan(m.Index + m.Length)));
        }
    }

    /// <summary>Random bytes, or random text from JSON's alphabet.</summary>
    public sealed record RandomFile(byte[] Bytes)
    {
        public override string ToString() => Convert.ToHexString(Bytes);
    }

    private static Gen<Mutant> Mutants { get; } =
        Gen.Choose(1, 3).SelectMany(n => Gen.ArrayOf(
            from kind in Gen.Choose(0, 7)
            from a in Gen.Choose(0, int.MaxValue)
            from b in Gen.Choose(0, int.MaxValue)
            from c in Gen.Choose(0, int.MaxValue)
            select new Edit(kind, a, b, c), n)).Select(edits => new Mutant(edits));

    private static Gen<RandomFile> RandomFiles { get; } = Gen.Frequency(
        (1, Gen.Choose(0, 300).SelectMany(n => Gen.ArrayOf(Gen.Choose(0, 255).Select(b => (byte)b), n))),
        (1, Gen.Choose(0, 300).SelectMany(n => Gen.ArrayOf(Gen.Elements("{}[]\":,0123456789.-eE truefalsn\n"u8.ToArray()), n))))
        .Select(b => new RandomFile(b));

    [GeneratedRegex(@"-?\d+(\.\d+)?([eE][+-]?\d+)?")]
    private static partial Regex NumberToken();

    [GeneratedRegex(@"""(?:[^""\\]|\\.)*""")]
    private static partial Regex StringToken();

    [GeneratedRegex(@"""[A-Za-z]+""\s*:\s*(\[[^\[\]]*\]|""[^""]*""|[-0-9.eE]+|\{[^{}]*\}),?")]
    private static partial Regex MemberToken();
}
