using System.Buffers.Binary;
using System.Reflection.PortableExecutable;
using System.Runtime.Intrinsics.X86;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;
using SkiaSharp;

namespace RayLab.Package.Tests;

/// <summary>
/// What a new user does, end to end, with child <c>dotnet</c> processes against the packages in a folder feed
/// (<see cref="PackedFeed"/>: <c>RayLab</c>, <c>RayLab.Reports</c> and the tool <c>RayLab.Tool</c>, packed once):
/// a fresh app on the core alone runs the README's ten lines and carries no native library; a fresh app on both
/// packages writes WebP and draws a chart; the own-method sample and the getting-started guide's test project build
/// against the packages and run; the tool installs from the feed and renders. Every child gets the fixture's empty
/// NUGET_PACKAGES folder, so no cached copy of an older RayLab package can stand in.
/// </summary>
[Trait("Category", "Packaging")]
public sealed partial class PackageTests(PackedFeed feed) : IClassFixture<PackedFeed>
{
    /// <summary>The environment variable that makes the native tool's launcher start the x86-64-v2 build whatever the CPU.</summary>
    private const string NoDispatchVariable = "RAYLAB_NO_DISPATCH";

    /// <summary>The core-only app's build output must stay under this (587 MB when the core carried SkiaSharp).</summary>
    private const long CoreAppBinLimit = 10 * 1024 * 1024;

    /// <summary>
    /// What <c>dotnet list package --include-transitive</c> may show for an app on the core alone: the core, and the
    /// managed base-library packages it builds on (System.IO.Hashing; the JPEG encoder the core serves, whichever of
    /// the two measured it uses).
    /// </summary>
    private static readonly string[] CoreAllowList = ["RayLab", "System.IO.Hashing", "JpegLibrary", "StbImageWriteSharp"];

    [Fact]
    public async Task An_app_on_the_core_alone_runs_the_readme_ten_lines_with_no_native_library()
    {
        string app = feed.NewProject("core-app", ["RayLab"]);
        // The README's ten lines verbatim, then one probe: WebP from the core alone is a one-line error naming the extension
        // and how a package adds a format.
        File.WriteAllText(Path.Combine(app, "Program.cs"), ReadmeLibraryExample(feed.Repo) + """

            try
            {
                image.Save("x.webp");
                Console.WriteLine("webp-probe: saved, no exception");
            }
            catch (NotSupportedException e)
            {
                Console.WriteLine("webp-probe: " + e.Message.ReplaceLineEndings("\\n"));
            }
            """);

        string stdout = await feed.RunAsync(app, "dotnet", "run", "-c", "Release");
        AssertPng(Path.Combine(app, "two-spheres.png"), 800, 600);
        foreach ((string file, SKEncodedImageFormat format) in new[] { ("two-spheres.bmp", SKEncodedImageFormat.Bmp), ("two-spheres.jpg", SKEncodedImageFormat.Jpeg) })
        {
            string path = Path.Combine(app, file);
            Assert.True(File.Exists(path), $"the README's ten lines on the core alone wrote no {file}");
            SkiaDecode.Result decoded = SkiaDecode.Load(path);
            Assert.True((800, 600, format) == (decoded.Width, decoded.Height, decoded.Format),
                $"{file} from the core alone decodes as {decoded.Format} {decoded.Width}x{decoded.Height}, not {format} 800x600");
        }

        string probe = stdout.Split('\n').Select(l => l.TrimEnd('\r')).SingleOrDefault(l => l.StartsWith("webp-probe: ", StringComparison.Ordinal))
            ?? throw new Xunit.Sdk.XunitException($"the core-only app printed no webp-probe line:\n{stdout}");
        Assert.False(File.Exists(Path.Combine(app, "x.webp")), "image.Save(\"x.webp\") from the core alone wrote a file");
        Assert.True(probe.Contains("'.webp'", StringComparison.Ordinal) && probe.Contains("ImageFormats.Register", StringComparison.Ordinal)
            && !probe.Contains("\\n", StringComparison.Ordinal),
            $"image.Save(\"x.webp\") from the core alone should be a one-line NotSupportedException naming .webp and ImageFormats.Register; got: {probe}");

        // The build output: managed assemblies only, no runtimes/ folder, under 10 MB.
        string bin = Path.Combine(app, "bin", "Release", "net10.0");
        Assert.True(Directory.Exists(bin), $"{bin} is missing");
        string runtimes = Path.Combine(bin, "runtimes");
        if (Directory.Exists(runtimes))
        {
            Assert.Fail($"the core-only app's output has a runtimes/ folder: {string.Join(", ", Directory.GetFiles(runtimes, "*", SearchOption.AllDirectories).Select(f => Path.GetRelativePath(bin, f)))}");
        }
        string[] files = Directory.GetFiles(bin, "*", SearchOption.AllDirectories);
        string[] native = [.. files.Where(IsNativeLibrary).Select(f => Path.GetRelativePath(bin, f))];
        Assert.True(native.Length == 0, $"the core-only app's output holds native libraries: {string.Join(", ", native)}");
        string[] skia = [.. files.Select(f => Path.GetRelativePath(bin, f)).Where(f => f.Contains("skia", StringComparison.OrdinalIgnoreCase) || f.Contains("harfbuzz", StringComparison.OrdinalIgnoreCase) || f.Contains("scottplot", StringComparison.OrdinalIgnoreCase) || f.Contains("sixlabors", StringComparison.OrdinalIgnoreCase) || f.Contains("imagesharp", StringComparison.OrdinalIgnoreCase))];
        Assert.True(skia.Length == 0, $"the core-only app's output holds Skia/HarfBuzz/ScottPlot/ImageSharp files: {string.Join(", ", skia)}");
        long size = files.Sum(f => new FileInfo(f).Length);
        TestContext.Current.TestOutputHelper?.WriteLine($"core-only app: bin/Release/net10.0 holds {files.Length} files, {size:N0} bytes");
        Assert.True(size < CoreAppBinLimit, $"the core-only app's output is {size:N0} bytes, over {CoreAppBinLimit:N0}: {Largest(bin, files)}");

        // The packages it depends on: the core and managed base-library packages only.
        string list = await feed.RunAsync(app, "dotnet", "list", "package", "--include-transitive");
        string[] packages = [.. PackageLine().Matches(list).Select(m => m.Groups["id"].Value).Distinct(StringComparer.OrdinalIgnoreCase)];
        TestContext.Current.TestOutputHelper?.WriteLine($"core-only app's packages: {string.Join(", ", packages)}");
        Assert.Contains("RayLab", packages);
        string[] unexpected = [.. packages.Where(p => !CoreAllowList.Contains(p, StringComparer.OrdinalIgnoreCase))];
        Assert.True(unexpected.Length == 0,
            $"an app on the RayLab package alone pulls packages outside the allow-list ({string.Join(", ", CoreAllowList)}): {string.Join(", ", unexpected)}\n{list}");
    }

    [Fact]
    public void The_reports_package_depends_on_exactly_the_core_it_was_built_with()
    {
        // RayLab.Reports uses the core's internals, so "this core or later" would let NuGet pair it with a core whose
        // internals moved; the nuspec must name the one version, in brackets.
        string package = Path.Combine(feed.Feed, $"RayLab.Reports.{feed.Version}.nupkg");
        using var zip = System.IO.Compression.ZipFile.OpenRead(package);
        System.IO.Compression.ZipArchiveEntry nuspec = zip.Entries.Single(e => e.FullName.EndsWith(".nuspec", StringComparison.Ordinal));
        using var reader = new StreamReader(nuspec.Open());
        System.Xml.Linq.XDocument document = System.Xml.Linq.XDocument.Load(reader);
        string[] versions = [.. document.Descendants().Where(e => e.Name.LocalName == "dependency" && (string?)e.Attribute("id") == "RayLab")
            .Select(e => (string?)e.Attribute("version") ?? "")];
        Assert.NotEmpty(versions);
        Assert.All(versions, v => Assert.Equal($"[{feed.Version}]", v));
    }

    [Fact]
    public void The_imagesharp_package_pins_the_core_and_imagesharp_2_1_13_exactly()
    {
        // ImageSharp 3 and newer carry a paid licence: the adapter's nuspec must never let NuGet float up to one.
        string package = Path.Combine(feed.Feed, $"RayLab.ImageSharp.{feed.Version}.nupkg");
        using var zip = System.IO.Compression.ZipFile.OpenRead(package);
        System.IO.Compression.ZipArchiveEntry nuspec = zip.Entries.Single(e => e.FullName.EndsWith(".nuspec", StringComparison.Ordinal));
        using var reader = new StreamReader(nuspec.Open());
        System.Xml.Linq.XDocument document = System.Xml.Linq.XDocument.Load(reader);
        Dictionary<string, string> dependencies = document.Descendants().Where(e => e.Name.LocalName == "dependency")
            .ToDictionary(e => (string?)e.Attribute("id") ?? "", e => (string?)e.Attribute("version") ?? "");
        Assert.Equal($"[{feed.Version}]", dependencies["RayLab"]);
        Assert.Equal("[2.1.13]", dependencies["SixLabors.ImageSharp"]);
    }

    [Fact]
    public async Task An_app_on_the_imagesharp_package_runs_the_readme_bitmap_lines_and_saves_jpeg_and_png()
    {
        string app = feed.NewProject("imagesharp-app", ["RayLab.ImageSharp"]);
        File.WriteAllText(Path.Combine(app, "Program.cs"), ReadmeLibraryExample(feed.Repo, block: 1));
        await feed.RunAsync(app, "dotnet", "run", "-c", "Release");

        SkiaDecode.Result jpeg = SkiaDecode.Load(Path.Combine(app, "obrazkoncowy.jpg"));
        Assert.True((800, 600, SKEncodedImageFormat.Jpeg) == (jpeg.Width, jpeg.Height, jpeg.Format),
            $"obrazkoncowy.jpg decodes as {jpeg.Format} {jpeg.Width}x{jpeg.Height}, not Jpeg 800x600");
        AssertPng(Path.Combine(app, "two-spheres.png"), 800, 600);
        string list = await feed.RunAsync(app, "dotnet", "list", "package", "--include-transitive");
        Assert.Matches(@"SixLabors\.ImageSharp +2\.1\.13", list);
    }

    [Fact]
    public async Task An_app_on_both_packages_writes_webp_and_draws_a_chart()
    {
        string app = feed.NewProject("reports-app", ["RayLab", "RayLab.Reports"]);
        File.WriteAllText(Path.Combine(app, "Program.cs"), """
            using RayLab;
            using RayLab.Reports.Comparison;
            using RayLab.Reports.Imaging;
            using RayLab.Sampling;

            ReportsImageFormats.Register();
            var scene = new Scene(
                [new Sphere(new Double3(-1.1, 0, 0), 1, new Intensity(0.9, 0.2, 0.2))],
                background: new Intensity(0.1, 0.1, 0.15), ambient: Intensity.White);
            var camera = new PerspectiveCamera { Position = new Double3(0, 0.5, 6), Target = Double3.Zero, Fov = 40, NearPlane = 0.1 };
            var image = new Image(160, 120);
            new Renderer().Render(scene, camera, new AdaptiveSampler(maxDepth: 2, contrast: 0.05), image);
            image.Save("sphere.webp");
            LogLogChart.Save("chart", "error against time", "time (ms)", "error",
                [new LogLogChart.Series("adaptive", [(1.0, 0.1), (10.0, 0.01), (100.0, 0.001)])]);
            """);
        await feed.RunAsync(app, "dotnet", "run", "-c", "Release");

        string webp = Path.Combine(app, "sphere.webp");
        Assert.True(File.Exists(webp), "the app on both packages wrote no sphere.webp");
        SkiaDecode.Result decoded = SkiaDecode.Load(webp);
        Assert.True((160, 120, SKEncodedImageFormat.Webp) == (decoded.Width, decoded.Height, decoded.Format),
            $"sphere.webp decodes as {decoded.Format} {decoded.Width}x{decoded.Height}, not Webp 160x120");
        AssertPng(Path.Combine(app, "chart.png"), 900, 540);
        Assert.True(File.Exists(Path.Combine(app, "chart.svg")), "LogLogChart.Save wrote no chart.svg");
    }

    [Fact]
    public async Task The_own_method_sample_builds_and_runs_against_the_packages()
    {
        // The guide "Your own antialiasing method": the sources of samples/RayLab.OwnMethod (a point sampler and a
        // pixel method of the student's own, compared through the compare API) beside a project file on both packages
        // and the lab's scene. It renders each method into out/ and writes the compare report into out/report.
        string own = feed.NewProject("own", ["RayLab", "RayLab.Reports"],
            "<ItemGroup><None Include=\"scenes/two-spheres.json\" CopyToOutputDirectory=\"PreserveNewest\" /></ItemGroup>");
        foreach (string file in Directory.GetFiles(Path.Combine(feed.Repo, "samples", "RayLab.OwnMethod"), "*.cs"))
        {
            File.Copy(file, Path.Combine(own, Path.GetFileName(file)));
        }

        Directory.CreateDirectory(Path.Combine(own, "scenes"));
        File.Copy(Path.Combine(feed.Repo, "samples", "scenes", "two-spheres.json"), Path.Combine(own, "scenes", "two-spheres.json"));
        await feed.RunAsync(own, "dotnet", "run", "-c", "Release");

        AssertPng(Path.Combine(own, "out", "rotated-grid-16.png"), 800, 600);
        AssertPng(Path.Combine(own, "out", "mitchell.png"), 800, 600);
        string report = Path.Combine(own, "out", "report");
        Assert.True(File.Exists(Path.Combine(report, "index.html")), "the own-method sample wrote no out/report/index.html");
        AssertPng(Path.Combine(report, "error-vs-time.png"), 900, 540);
        string[] series = [.. File.ReadAllLines(Path.Combine(report, "results.csv")).Skip(1).Select(line => line.Split(',')[0]).Distinct()];
        Assert.True(series.SequenceEqual(["jittered", "rotated-grid", "mitchell"]),
            $"the own-method sample's results.csv has the series [{string.Join(", ", series)}], not [jittered, rotated-grid, mitchell]");
        AssertPng(Path.Combine(report, "images", "mitchell-4---16.png"), 200, 150);
    }

    [Fact]
    public async Task The_getting_started_test_project_builds_against_the_package_and_passes()
    {
        // docs/getting-started.md, "Your own test project": the example tests (tests/RayLab.Tests/Examples) beside the
        // project file the guide writes, with RayLab added from the feed.
        string tests = Directory.CreateDirectory(Path.Combine(feed.Root, "student-tests")).FullName;
        foreach (string file in Directory.GetFiles(Path.Combine(feed.Repo, "tests", "RayLab.Tests", "Examples"), "*.cs"))
        {
            File.Copy(file, Path.Combine(tests, Path.GetFileName(file)));
        }

        File.WriteAllText(Path.Combine(tests, "RayLabTests.csproj"), GettingStartedTestProject(feed.Repo));
        feed.WriteNugetConfig(tests);
        await feed.RunAsync(tests, "dotnet", "add", "package", "RayLab", "--version", feed.Version);
        string output = await feed.RunAsync(tests, "dotnet", "test", "-c", "Release");
        Assert.True(PassedLine().IsMatch(output), $"the getting-started test project ran no passing tests:\n{output}");
    }

    [Fact]
    public async Task The_tool_installs_from_the_feed_and_renders()
    {
        // On linux-x64 the native build, elsewhere the framework-dependent one.
        string tools = Path.Combine(feed.Root, "tools");
        await feed.RunAsync(feed.Root, "dotnet", "tool", "install", "RayLab.Tool", "--tool-path", tools,
            "--add-source", feed.Feed, "--version", feed.Version);
        string raylab = Path.Combine(tools, OperatingSystem.IsWindows() ? "raylab.exe" : "raylab");
        AssertInstalledBuild(tools, raylab, native: PackedFeed.NativeToolHere);

        string rendered = Path.Combine(feed.Root, "t.png");
        await feed.RunAsync(feed.Root, raylab, "render", Path.Combine(feed.Repo, "samples", "scenes", "two-spheres.json"),
            "-o", rendered, "--width", "64", "--height", "48");
        AssertPng(rendered, 64, 48);

        // With no arguments it renders the scene shipped inside the tool package into out/ of the working folder.
        string work = Directory.CreateDirectory(Path.Combine(feed.Root, "work")).FullName;
        await feed.RunAsync(work, raylab);
        AssertPng(Path.Combine(work, "out", "two-spheres-perspective.png"), 800, 600);

        // The scenes it carries, listed and rendered by name from a folder outside the repository.
        await AssertCarriedScenesAsync(work, feed.Packages, raylab, native: PackedFeed.NativeToolHere);
        if (PackedFeed.NativeToolHere)
        {
            await AssertDispatchAsync(work, feed.Packages, raylab);
        }

        // The fallback: a pointer package that names a native package for another platform only (as RayLab.Tool
        // does for linux-x64 on every other platform) installs RayLab.Tool.any, which renders with the JIT.
        string otherFeed = Directory.CreateDirectory(Path.Combine(feed.Root, "feed-other")).FullName;
        string otherPackages = Path.Combine(feed.Root, "nuget-packages-other"); // the first pointer package must not be reused
        string otherRid = PackedFeed.NativeToolHere ? "win-arm64" : "linux-x64";
        await PackedFeed.RunChildAsync(feed.Root, otherPackages, null, "dotnet", "pack", feed.ConsoleProject, "-c", "Release", "-o", otherFeed,
            "--artifacts-path", Path.Combine(feed.Root, "artifacts-other"), $"-p:RayLabNativeRid={otherRid}",
            $"-p:MinVerVersionOverride={feed.Version}"); // the feed's version, even if a commit landed since it was packed
        File.Copy(Path.Combine(feed.Feed, $"RayLab.Tool.any.{feed.Version}.nupkg"), Path.Combine(otherFeed, $"RayLab.Tool.any.{feed.Version}.nupkg"));
        string fallbackTools = Path.Combine(feed.Root, "tools-fallback");
        await PackedFeed.RunChildAsync(feed.Root, otherPackages, null, "dotnet", "tool", "install", "RayLab.Tool", "--tool-path", fallbackTools,
            "--add-source", otherFeed, "--version", feed.Version);
        string fallback = Path.Combine(fallbackTools, OperatingSystem.IsWindows() ? "raylab.exe" : "raylab");
        AssertInstalledBuild(fallbackTools, fallback, native: false);
        await AssertCarriedScenesAsync(work, otherPackages, fallback, native: false);
    }

    /// <summary>A native library: a .so/.dylib/.a, or a .dll or .exe that is not a managed assembly.</summary>
    private static bool IsNativeLibrary(string path)
    {
        string ext = Path.GetExtension(path).ToLowerInvariant();
        if (ext is ".so" or ".dylib" or ".a" || Path.GetFileName(path).Contains(".so.", StringComparison.Ordinal))
        {
            return true;
        }

        if (ext is not (".dll" or ".exe"))
        {
            return false;
        }

        using FileStream stream = File.OpenRead(path);
        try
        {
            using var pe = new PEReader(stream);
            return !pe.HasMetadata;
        }
        catch (BadImageFormatException)
        {
            return true;
        }
    }

    private static string Largest(string bin, string[] files) => string.Join(", ",
        files.Select(f => (File: Path.GetRelativePath(bin, f), new FileInfo(f).Length)).OrderByDescending(f => f.Length).Take(5)
            .Select(f => $"{f.File} {f.Length:N0}"));

    /// <summary>
    /// Which package <c>dotnet tool install</c> put into <paramref name="toolPath"/>: the native one is a single ELF
    /// executable that the command links to, with no assembly beside it; the framework-dependent one runs raylab.dll.
    /// </summary>
    private static void AssertInstalledBuild(string toolPath, string command, bool native)
    {
        Assert.True(File.Exists(command), $"{command} was not installed");
        string[] assemblies = Directory.GetFiles(Path.Combine(toolPath, ".store"), "raylab.dll", SearchOption.AllDirectories);
        // The pointer package's folder is raylab.tool; the package it chose, raylab.tool.RID.
        string[] packageFolders = [.. Directory.GetDirectories(Path.Combine(toolPath, ".store"), "*", SearchOption.AllDirectories)
            .Select(d => Path.GetFileName(d)!).Where(name => name.StartsWith("raylab.tool.", StringComparison.Ordinal))];
        if (native)
        {
            Assert.Equal(["raylab.tool.linux-x64"], packageFolders);
            Assert.Empty(assemblies);
            FileSystemInfo? target = new FileInfo(command).ResolveLinkTarget(returnFinalTarget: true);
            Assert.NotNull(target);
            byte[] head = File.ReadAllBytes(target.FullName).AsSpan(0, 4).ToArray();
            Assert.Equal(new byte[] { 0x7F, (byte)'E', (byte)'L', (byte)'F' }, head);
            Assert.Equal("raylab", target.Name);

            // The entry is the launcher (samples/RayLab.Launcher); the console builds it execs, one per x86-64 level, lie
            // beside it.
            string folder = Path.GetDirectoryName(target.FullName)!;
            string[] siblings = [.. Directory.GetFiles(folder, "raylab-*").Select(f => Path.GetFileName(f)!).Order(StringComparer.Ordinal)];
            Assert.Equal(["raylab-x86-64-v2", "raylab-x86-64-v3", "raylab-x86-64-v4"], siblings);
            byte[][] builds = [.. siblings.Select(s => File.ReadAllBytes(Path.Combine(folder, s)))];
            foreach (byte[] build in builds)
            {
                Assert.Equal(head, build.AsSpan(0, 4).ToArray());
                Assert.Single(builds, other => other.AsSpan().SequenceEqual(build)); // three different compilations
            }

            // The launcher holds no renderer: a fraction of a console build's size.
            long launcher = new FileInfo(target.FullName).Length;
            Assert.True(launcher * 3 < builds.Min(b => b.Length),
                $"the installed raylab ({launcher:N0} bytes) is not the small launcher beside console builds of {string.Join(", ", builds.Select(b => $"{b.Length:N0}"))} bytes");
        }
        else
        {
            Assert.Equal(["raylab.tool.any"], packageFolders);
            Assert.Single(assemblies);
        }
    }

    /// <summary>
    /// <c>raylab scenes</c> lists the scenes the tool carries, and <c>raylab render two-spheres</c> renders one of them
    /// by name in <paramref name="work"/>, a folder without scene files; the PNG decodes. Neither build makes a warm-up
    /// render without <c>--warmup</c> (the <c>--stats</c> have no <c>warmupMs</c>).
    /// </summary>
    private static async Task AssertCarriedScenesAsync(string work, string packages, string raylab, bool native)
    {
        string list = await PackedFeed.RunChildAsync(work, packages, null, raylab, "scenes");
        foreach (string scene in new[] { "two-spheres", "off-axis", "low-contrast", "sphere-field" })
        {
            Assert.True(list.Contains(scene, StringComparison.Ordinal), $"`raylab scenes` ({raylab}) does not list {scene}:\n{list}");
        }

        string png = Path.Combine(work, native ? "by-name-native.png" : "by-name-jit.png");
        string stats = Path.ChangeExtension(png, ".json");
        await PackedFeed.RunChildAsync(work, packages, null, raylab, "render", "two-spheres", "-o", png, "--width", "96", "--height", "72",
            "--stats", stats);
        SkiaDecode.Result decoded = SkiaDecode.Load(png);
        Assert.Equal((96, 72, SKEncodedImageFormat.Png), (decoded.Width, decoded.Height, decoded.Format));
        Assert.Contains(decoded.Rgb, b => b != decoded.Rgb[0]); // a picture, not one flat colour
        Assert.DoesNotContain("\"warmupMs\"", File.ReadAllText(stats), StringComparison.Ordinal);
    }

    /// <summary>
    /// The installed native tool takes the widest render kernel this CPU runs: its launcher execs the v3 (AVX2) or v4
    /// (AVX-512) build beside it when the CPU has that level, which <c>--stats</c> shows as the kernel; with
    /// <see cref="NoDispatchVariable"/> set it execs the x86-64-v2 build, the <c>vector128</c> kernel, which writes the
    /// same PNG bytes. The build it takes has lost its execute permission first (as a package extractor may leave it):
    /// the launcher gives it back and still takes it.
    /// </summary>
    private static async Task AssertDispatchAsync(string work, string packages, string raylab)
    {
        string expected = ExpectedNativeKernel();
        string? widest = expected switch
        {
            "vector512" => "raylab-x86-64-v4",
            "vector256" => "raylab-x86-64-v3",
            _ => null,
        };
        string? widestPath = widest is null ? null : Path.Combine(Path.GetDirectoryName(new FileInfo(raylab).ResolveLinkTarget(returnFinalTarget: true)!.FullName)!, widest);
        if (widestPath is not null && !OperatingSystem.IsWindows())
        {
            File.SetUnixFileMode(widestPath, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead | UnixFileMode.OtherRead);
        }

        string[] render = ["render", "two-spheres", "--width", "96", "--height", "72", "--stats"];
        string widestPng = Path.Combine(work, "dispatch-widest.png");
        string entryPng = Path.Combine(work, "dispatch-entry.png");
        await PackedFeed.RunChildAsync(work, packages, null, raylab, [.. render, "widest.json", "-o", widestPng]);
        if (widestPath is not null && !OperatingSystem.IsWindows())
        {
            Assert.True(File.GetUnixFileMode(widestPath).HasFlag(UnixFileMode.UserExecute), $"{widestPath} was not made executable");
        }

        await PackedFeed.RunChildAsync(work, packages, NoDispatchVariable, raylab, [.. render, "entry.json", "-o", entryPng]);

        Assert.Equal(expected, Kernel(Path.Combine(work, "widest.json")));
        Assert.Equal("vector128", Kernel(Path.Combine(work, "entry.json")));
        Assert.True(File.ReadAllBytes(widestPng).AsSpan().SequenceEqual(File.ReadAllBytes(entryPng)),
            "the native tool's widest build and its x86-64-v2 build (RAYLAB_NO_DISPATCH) wrote different PNG bytes");

        static string Kernel(string stats)
        {
            using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
            return json.RootElement.GetProperty("kernel").GetString()!;
        }
    }

    /// <summary>
    /// The kernel of the build the native tool's dispatch should land in on this CPU: x86-64-v4 (AVX-512 F, BW, CD, DQ,
    /// VL) renders with vector512, x86-64-v3 (AVX2, FMA, BMI1, BMI2) with vector256, anything older with vector128.
    /// </summary>
    private static string ExpectedNativeKernel()
    {
        bool v3 = Avx2.IsSupported && Fma.IsSupported && Bmi1.IsSupported && Bmi2.IsSupported;
        bool v4 = v3 && Avx512F.IsSupported && Avx512F.VL.IsSupported && Avx512BW.IsSupported && Avx512CD.IsSupported && Avx512DQ.IsSupported;
        return v4 ? "vector512" : v3 ? "vector256" : "vector128";
    }

    /// <summary>C# block number <paramref name="block"/> (0 the first) under the README's "## The library in ten lines" heading.</summary>
    private static string ReadmeLibraryExample(string repo, int block = 0)
    {
        string readme = File.ReadAllText(Path.Combine(repo, "README.md")).ReplaceLineEndings("\n");
        Match m = ReadmeExample().Match(readme);
        Assert.True(m.Success, "README.md has no \"## The library in ten lines\" section");
        MatchCollection blocks = CsharpBlock().Matches(m.Groups["section"].Value);
        Assert.True(blocks.Count > block, $"README.md's \"## The library in ten lines\" has {blocks.Count} ```csharp blocks, not {block + 1}");
        return blocks[block].Groups["code"].Value;
    }

    /// <summary>The project file docs/getting-started.md writes under "## Your own test project" (<c>cat &gt; RayLabTests.csproj &lt;&lt;'EOF'</c>).</summary>
    private static string GettingStartedTestProject(string repo)
    {
        string guide = File.ReadAllText(Path.Combine(repo, "docs", "getting-started.md")).ReplaceLineEndings("\n");
        Match m = GuideTestProjectFile().Match(guide);
        Assert.True(m.Success, "docs/getting-started.md has no \"cat > RayLabTests.csproj <<'EOF'\" block under \"## Your own test project\"");
        return m.Groups["project"].Value;
    }

    [GeneratedRegex(@"^## Your own test project\n(?:(?!^## ).)*?cat > RayLabTests\.csproj <<'EOF'\n(?<project>.*?)^EOF$", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex GuideTestProjectFile();

    [GeneratedRegex(@"^## The library in ten lines\n(?<section>(?:(?!^## ).)*)", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex ReadmeExample();

    [GeneratedRegex(@"^```csharp\n(?<code>.*?)^```", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex CsharpBlock();

    /// <summary>A package row of <c>dotnet list package</c>: "   &gt; Id   requested   resolved" or "   &gt; Id   resolved".</summary>
    [GeneratedRegex(@"^\s*>\s+(?<id>[A-Za-z0-9_.\-]+)\s", RegexOptions.Multiline)]
    private static partial Regex PackageLine();

    /// <summary>VSTest's summary of a run with no failure: "Passed!  - Failed:     0, Passed:    N".</summary>
    [GeneratedRegex(@"Passed!\s+-\s+Failed:\s+0,\s+Passed:\s+[1-9]")]
    private static partial Regex PassedLine();

    private static void AssertPng(string path, int width, int height)
    {
        Assert.True(File.Exists(path), $"{path} was not written");
        byte[] png = File.ReadAllBytes(path);
        byte[] signature = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];
        Assert.True(png.Length > 24 && png.AsSpan(0, 8).SequenceEqual(signature), $"{path} is not a PNG");
        Assert.Equal("IHDR", Encoding.ASCII.GetString(png, 12, 4));
        (int w, int h) = (BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(16)), BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(20)));
        Assert.True((w, h) == (width, height), $"{path} is {w}x{h}, not {width}x{height}");
    }
}
