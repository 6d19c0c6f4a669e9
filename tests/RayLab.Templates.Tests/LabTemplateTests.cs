using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;
using SkiaSharp;

namespace RayLab.Templates.Tests;

/// <summary>
/// What a student (and the instructor who hands out the lab) does with the template package, end to end, with child
/// <c>dotnet</c> processes in a temporary DOTNET_CLI_HOME and an empty NUGET_PACKAGES: install <c>RayLab.Templates</c>
/// from a folder feed packed from this checkout (with <c>RayLab</c> and <c>RayLab.Reports</c>), create a lab with
/// each <c>--method</c>, run its tests (green) and the app (both pictures and <c>obrazkoncowy.jpg</c>), then sabotage
/// <c>MyMethod</c> and see its tests fail; and the exercise lab (ExerciseLabTests.cs). The packing and the install are
/// shared (<see cref="TemplateFeed"/>).
/// </summary>
[Trait("Category", "Templates")]
[Collection(TemplateFeedSharing.Name)]
public sealed partial class LabTemplateTests(TemplateFeed feed)
{
    /// <summary>
    /// Each kind of method: the line of MyMethod.cs to replace and what makes its pictures black; and whether the lab
    /// restores offline, from the feed and the machine's NuGet cache alone (otherwise from the feed and the sources
    /// the machine already has, nuget.org for xUnit).
    /// </summary>
    public static TheoryData<string, string, string, string, bool> Methods => new()
    {
        // A pixel method that returns black for every pixel; the lab's name is not a C# identifier.
        { "pixel-method", "pixel-lab", "return sum / Points.Length;", "return Intensity.Black;", false },
        // A sampler has no colour to return: with no samples in a pixel the renderer has nothing to average, and the pixel is black.
        { "sampler", "SamplerLab", "public int SamplesPerPixel => Points.Length;", "public int SamplesPerPixel => 0;", true },
    };

    [Theory]
    [MemberData(nameof(Methods))]
    public async Task TheLabBuildsPassesItsTestsRendersAndFailsWhenMyMethodIsSabotaged(string method, string name, string line, string sabotage, bool offline)
    {
        // Created under a folder whose Directory.Build.props and Directory.Packages.props would break any project that
        // inherited them: the lab's own Directory.Build.props must stop the walk up.
        string work = Directory.CreateDirectory(Path.Combine(feed.Root, "work-" + method)).FullName;
        File.WriteAllText(Path.Combine(work, "Directory.Build.props"), """
            <Project>
              <Target Name="NotTheLabs" BeforeTargets="Restore;CollectPackageReferences;Build">
                <Error Text="The lab inherited a Directory.Build.props from a folder above it." />
              </Target>
            </Project>
            """);
        File.WriteAllText(Path.Combine(work, "Directory.Packages.props"), """
            <Project>
              <PropertyGroup><ManagePackageVersionsCentrally>true</ManagePackageVersionsCentrally></PropertyGroup>
            </Project>
            """);

        if (offline)
        {
            // No network source: the machine's own NuGet cache (which holds xUnit, SkiaSharp, … from building this
            // repository) as a read-only folder source, and the lab's nuget.config adds the feed.
            string cache = Environment.GetEnvironmentVariable("NUGET_PACKAGES") is { Length: > 0 } packages
                ? packages
                : Path.Combine(Environment.GetFolderPath(Environment.SpecialFolder.UserProfile), ".nuget", "packages");
            File.WriteAllText(Path.Combine(work, "nuget.config"), $"""
                <?xml version="1.0" encoding="utf-8"?>
                <configuration>
                  <packageSources>
                    <clear />
                    <add key="machine-cache" value="{cache}" />
                  </packageSources>
                </configuration>
                """);
        }

        // 1. dotnet new, with the feed the packages come from today.
        string lab = Path.Combine(work, name);
        await feed.RunAsync(work, "dotnet", "new", "raylab-lab", "-o", lab, "--kind", "method", "--method", method, "--feed", feed.Feed);
        string myMethod = Path.Combine(lab, "src", "Lab", "MyMethod.cs");
        Assert.True(File.Exists(myMethod), $"{myMethod} was not created");
        Assert.Empty(Directory.GetFiles(Path.Combine(lab, "src", "Lab"), "MyMethod.*.cs")); // the other kind's file is left out
        Assert.True(File.Exists(Path.Combine(lab, name + ".slnx")), "the solution is not named after the lab");
        Assert.Contains(method == "sampler" ? ": IPixelSampler" : ": IPixelMethod<", File.ReadAllText(myMethod), StringComparison.Ordinal);
        string props = File.ReadAllText(Path.Combine(lab, "Directory.Build.props"));
        Assert.Contains($"<RayLabVersion>{feed.Version}</RayLabVersion>", props, StringComparison.Ordinal);
        Assert.Contains("<TreatWarningsAsErrors>true</TreatWarningsAsErrors>", props, StringComparison.Ordinal);
        foreach (string file in Directory.GetFiles(lab, "*", SearchOption.AllDirectories).Where(f => !IsBuildOutput(lab, f)))
        {
            string text = File.ReadAllText(file);
            Assert.DoesNotContain("0.0.0-raylab-version", text, StringComparison.Ordinal);
            Assert.DoesNotContain("RAYLAB_", text, StringComparison.Ordinal);
            Assert.DoesNotContain("#if (", text, StringComparison.Ordinal);
        }

        // 2. dotnet test: green out of the box, with the packages of this checkout's version from the feed.
        (int testExit, string testOutput) = await feed.RunUncheckedAsync(lab, "dotnet", "test");
        Assert.True(testExit == 0, $"dotnet test failed in the new lab:\n{testOutput}");
        (int passed, int failed) = DetailedCounts(testOutput);
        Assert.Equal(0, failed);
        Assert.True(passed >= 15, $"only {passed} tests passed:\n{testOutput}");
        foreach (string camera in new[] { "orthographic", "perspective" })
        {
            // MyMethodTests' figures, in what dotnet test shows.
            Assert.Matches($@"{camera}: RMSE [\d.]+, mean [\d.]+, max \d+ levels, [\d.]+ rays per pixel, [\d.]+ ms", testOutput);
        }
        Assert.True(Directory.Exists(Path.Combine(feed.Packages, "raylab", feed.Version)), "RayLab was not restored at the packed version");

        // 3. dotnet run: rays and time for each camera and method, both pictures (and the exact ones), obrazkoncowy.jpg.
        string output = await feed.RunAsync(lab, "dotnet", "run", "--project", Path.Combine("src", "Lab"));
        Assert.Matches(@"(?m)^warm-up \(80×60, both cameras, both methods, not counted\) [\d.]+ ms", output);
        string outDir = Path.Combine(lab, "out");
        foreach (string camera in new[] { "orthographic", "perspective" })
        {
            foreach (string kind in new[] { "adaptive", "mymethod" })
            {
                Assert.Matches($@"(?m)^{camera} +{kind} +[\d,]+ rays \( *[\d.]+ per pixel\) +[\d.]+ ms .*RMSE [\d.]+", output);
                AssertPicture(Path.Combine(outDir, $"two-spheres-{camera}-{kind}.png"), SKEncodedImageFormat.Png);
            }

            AssertPicture(Path.Combine(outDir, $"two-spheres-{camera}-exact.png"), SKEncodedImageFormat.Png);
        }

        string jpeg = Path.Combine(outDir, "obrazkoncowy.jpg");
        Assert.Equal(new byte[] { 0xFF, 0xD8, 0xFF }, File.ReadAllBytes(jpeg).AsSpan(0, 3).ToArray());
        Assert.InRange(new FileInfo(jpeg).Length, 5_000, 2_000_000);
        double difference = MeanDifference(AssertPicture(jpeg, SKEncodedImageFormat.Jpeg),
            AssertPicture(Path.Combine(outDir, "two-spheres-perspective-adaptive.png"), SKEncodedImageFormat.Png));
        Assert.True(difference < 2, $"obrazkoncowy.jpg differs from the perspective picture by {difference:F2} levels on average");

        // 4. Sabotage: MyMethod's pictures turn black, the lab still builds, and its tests of MyMethod fail.
        string source = File.ReadAllText(myMethod);
        Assert.Contains(line, source, StringComparison.Ordinal);
        File.WriteAllText(myMethod, source.Replace(line, sabotage, StringComparison.Ordinal));
        (int sabotagedExit, string sabotagedOutput) = await feed.RunUncheckedAsync(lab, "dotnet", "test", "--no-restore"); // restored above
        Assert.NotEqual(0, sabotagedExit);
        (int stillPassing, int nowFailing) = DetailedCounts(sabotagedOutput); // a summary: it built, and tests ran and failed
        Assert.True(nowFailing >= 1, $"no test failed with the sabotaged MyMethod:\n{sabotagedOutput}");
        string tests = name.Replace('-', '_') + ".Tests"; // the namespace: the name as a C# identifier
        Assert.Matches($@"(?m)^\s*Failed {tests}\.MyMethodTests\.MyMethodIsCloseToTheExactImageAtAStatedCost", sabotagedOutput);
        Assert.DoesNotMatch(@"(?m)\[FAIL\]\s*$", sabotagedOutput); // each failure once, in dotnet test's list, not again in xUnit's own report
        Assert.Matches($@"(?m)^\s*Failed {tests}\.TwoSpheresTests\.", sabotagedOutput);
        Assert.Matches(@"RMSE [\d.]+ levels > [\d.]+ \(perspective: RMSE [\d.]+, mean [\d.]+, max \d+ levels, [\d.]+ rays per pixel, [\d.]+ ms\)", sabotagedOutput); // the figures in the failure message
        Assert.True(stillPassing > 0, "the tests that do not use MyMethod should still pass");
    }

    [Fact]
    public async Task AMyMethodThatNeverReturnsFailsItsTestsAtTheTimeLimitNamingThePixel()
    {
        // The method lab with a MyMethod that stops for good at one pixel; the limit set to 5 s for this run.
        string work = Directory.CreateDirectory(Path.Combine(feed.Root, "work-hang")).FullName;
        string lab = Path.Combine(work, "HangLab");
        await feed.RunAsync(work, "dotnet", "new", "raylab-lab", "-o", lab, "--kind", "method", "--feed", feed.Feed);
        string myMethod = Path.Combine(lab, "src", "Lab", "MyMethod.cs");
        string line = "return sum / Points.Length;";
        string source = File.ReadAllText(myMethod);
        Assert.Contains(line, source, StringComparison.Ordinal);
        File.WriteAllText(myMethod, source.Replace(line, "if (pixel.X == 123 && pixel.Row == 45) { Thread.Sleep(Timeout.Infinite); }\n        " + line, StringComparison.Ordinal));

        // dotnet test ends (the child's own timeout is minutes, not seconds): the tests that render with MyMethod fail
        // at the limit, each naming the pixel; the one that reads what MyMethod uses, which runs nothing, passes.
        (int exit, string output) = await feed.RunUncheckedAsync(lab, new Dictionary<string, string?> { ["LAB_TIME_LIMIT_S"] = "5" },
            "dotnet", "test", "--filter", "FullyQualifiedName~MyMethodTests");
        Assert.NotEqual(0, exit);
        (int passed, int failed) = DetailedCounts(output);
        Assert.True(passed == 1 && failed == 2, $"the hanging method: {passed} passed, {failed} failed:\n{output}");
        Assert.Contains("Passed HangLab.Tests.MyMethodTests.MyMethodUsesOnlyWhatTheLabAllows", output, StringComparison.Ordinal);
        // (dotnet test shows each failure's message twice: as it happens, and in the list of failures)
        int limits = Regex.Count(output, @"Time limit of \d+ s passed");
        Assert.True(limits >= 2, $"no test failed at the time limit:\n{output}");
        Assert.Equal(limits, Regex.Count(output, @"Time limit of 5 s passed: MyMethod did not finish \(an endless loop\?\)\. It was working on pixel \(123, 45\)\."));

        // dotnet run stops at the limit too, naming the render and the rows it had finished (row 45 holds it up).
        (exit, output) = await feed.RunUncheckedAsync(lab, new Dictionary<string, string?> { ["LAB_TIME_LIMIT_S"] = "5" },
            "dotnet", "run", "--project", "src/Lab");
        Assert.True(exit == 1, $"dotnet run with the hanging method exited with {exit}:\n{output}");
        Match stopped = Regex.Match(output, @"Time limit of 5 s passed: orthographic mymethod did not finish \(an endless loop in MyMethod\?\)\. (?<done>\d+) of 600 rows were done");
        Assert.True(stopped.Success, $"dotnet run did not name the hanging render:\n{output}");
        Assert.InRange(int.Parse(stopped.Groups["done"].Value, CultureInfo.InvariantCulture), 0, 599);
    }

    [Fact]
    public async Task TheMethodLabsReadmeCompareExampleBuildsAsPastedAndItsLinksStayInTheLab()
    {
        string work = Directory.CreateDirectory(Path.Combine(feed.Root, "work-readme")).FullName;
        string lab = Path.Combine(work, "ReadmeLab");
        await feed.RunAsync(work, "dotnet", "new", "raylab-lab", "-o", lab, "--kind", "method", "--feed", feed.Feed);
        string readme = File.ReadAllText(Path.Combine(lab, "README.md"));

        // No link leaves the lab: no web address, and every relative link names a file or folder of the lab.
        Assert.DoesNotMatch(@"https?://", readme);
        foreach (Match link in Regex.Matches(readme, @"\]\((?<target>[^)#]+)(#[^)]*)?\)"))
        {
            string target = link.Groups["target"].Value;
            Assert.True(File.Exists(Path.Combine(lab, target)) || Directory.Exists(Path.Combine(lab, target)), $"the README links to {target}, which the lab does not have");
        }

        // The compare example, as the README says: the package added with its command, the file pasted, the call added.
        Match add = Regex.Match(readme, @"`(?<command>dotnet add src/Lab package RayLab\.Reports[^`]*)`");
        Assert.True(add.Success, "the README gives no command that adds RayLab.Reports");
        await feed.RunAsync(lab, "dotnet", [.. add.Groups["command"].Value.Split(' ')[1..]]);
        Match example = Regex.Match(readme, @"`src/Lab/Compare\.cs`:\s*```csharp\n(?<code>.*?)```", RegexOptions.Singleline);
        Assert.True(example.Success, "the README has no Compare.cs example");
        File.WriteAllText(Path.Combine(lab, "src", "Lab", "Compare.cs"), example.Groups["code"].Value);
        Assert.Contains("`Compare.Run();` at the end of `Main`", readme, StringComparison.Ordinal);
        string program = Path.Combine(lab, "src", "Lab", "Program.cs");
        string source = File.ReadAllText(program);
        const string last = "        Console.WriteLine(\"wrote out/obrazkoncowy.jpg\");\n";
        Assert.Contains(last, source, StringComparison.Ordinal);
        File.WriteAllText(program, source.Replace(last, last + "        Compare.Run();\n", StringComparison.Ordinal));
        (int exit, string output) = await feed.RunUncheckedAsync(lab, "dotnet", "build");
        Assert.True(exit == 0, $"the lab with the README's Compare.cs does not build:\n{output}");
    }

    [Fact]
    public async Task HelpDescribesEveryOption()
    {
        // The descriptions are the template's own, in Polish, whatever the machine's language: an English one too.
        (int exit, string shown) = await feed.RunUncheckedAsync(feed.Root, new Dictionary<string, string?> { ["DOTNET_CLI_UI_LANGUAGE"] = "en" }, "dotnet", "new", "raylab-lab", "--help");
        Assert.True(exit == 0, $"dotnet new raylab-lab --help failed:\n{shown}");
        string help = Collapse(shown);
        using JsonDocument template = JsonDocument.Parse(File.ReadAllText(Path.Combine(RepoPaths.Root(),
            "templates", "RayLab.Templates", "content", "raylab-lab", ".template.config", "template.json")));
        int options = 0;
        foreach (JsonProperty symbol in template.RootElement.GetProperty("symbols").EnumerateObject())
        {
            if (symbol.Value.GetProperty("type").GetString() != "parameter")
            {
                continue;
            }

            options++;
            Assert.Contains($"--{symbol.Name}", help, StringComparison.Ordinal);
            string description = symbol.Value.TryGetProperty("description", out JsonElement d) ? d.GetString() ?? "" : "";
            Assert.False(string.IsNullOrWhiteSpace(description), $"--{symbol.Name} has no description in template.json");
            Assert.Contains(Collapse(description), help, StringComparison.Ordinal);
            Assert.False(IsEnglish(description), $"--{symbol.Name}'s description is English: {description}");
            if (symbol.Value.TryGetProperty("choices", out JsonElement choices))
            {
                foreach (JsonElement choice in choices.EnumerateArray())
                {
                    string said = choice.GetProperty("description").GetString()!;
                    Assert.Contains(Collapse($"{choice.GetProperty("choice").GetString()} {said}"), help, StringComparison.Ordinal);
                    Assert.False(IsEnglish(said), $"--{symbol.Name} {choice.GetProperty("choice").GetString()}'s description is English: {said}");
                }
            }
        }

        Assert.Equal(6, options); // --kind, --lang, --method, --feed, --offline, --skipRestore
    }

    private static bool IsBuildOutput(string lab, string file)
    {
        string[] parts = Path.GetRelativePath(lab, file).Split(Path.DirectorySeparatorChar);
        return parts.Contains("bin") || parts.Contains("obj") || parts[0] == "out";
    }

    [GeneratedRegex(@"\s+")]
    private static partial Regex Whitespace();

    private static string Collapse(string text) => Whitespace().Replace(text, " ").Trim();

    /// <summary>Decodes <paramref name="path"/> (an 800×600 picture of the given format that is not one flat colour).</summary>
    /// <returns>Its RGB bytes.</returns>
    private static byte[] AssertPicture(string path, SKEncodedImageFormat format)
    {
        Assert.True(File.Exists(path), $"{path} was not written");
        byte[] bytes = File.ReadAllBytes(path);
        if (format == SKEncodedImageFormat.Png)
        {
            Assert.Equal(new byte[] { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A }, bytes.AsSpan(0, 8).ToArray());
            Assert.Equal("IHDR", Encoding.ASCII.GetString(bytes, 12, 4));
            Assert.Equal((800, 600), (BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(16)), BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(20))));
        }

        using var codec = SKCodec.Create(new SKMemoryStream(bytes));
        Assert.True(codec is not null, $"{path} does not decode");
        Assert.Equal(format, codec.EncodedFormat);
        var info = new SKImageInfo(codec.Info.Width, codec.Info.Height, SKColorType.Rgba8888, SKAlphaType.Unpremul);
        Assert.Equal((800, 600), (info.Width, info.Height));
        using var bitmap = new SKBitmap(info);
        Assert.Equal(SKCodecResult.Success, codec.GetPixels(info, bitmap.GetPixels()));
        ReadOnlySpan<byte> rgba = bitmap.GetPixelSpan();
        byte[] rgb = new byte[info.Width * info.Height * 3];
        for (int y = 0; y < info.Height; y++)
        {
            for (int x = 0; x < info.Width; x++)
            {
                int from = (y * bitmap.RowBytes) + (x * 4), to = ((y * info.Width) + x) * 3;
                rgb[to] = rgba[from];
                rgb[to + 1] = rgba[from + 1];
                rgb[to + 2] = rgba[from + 2];
            }
        }

        Assert.Contains(rgb, b => b != rgb[0]);
        return rgb;
    }

    private static double MeanDifference(byte[] a, byte[] b) =>
        a.Zip(b, (x, y) => (double)Math.Abs(x - y)).Average();
}
