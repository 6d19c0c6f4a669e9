using System.Buffers.Binary;
using System.Diagnostics;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics.X86;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;
using RayLab.Tests.Imaging;
using SkiaSharp;

namespace RayLab.Tests.Packaging;

/// <summary>
/// What a new user does, end to end, with child <c>dotnet</c> processes: pack the library (<c>RayLab</c>) and the
/// tool (<c>RayLab.Tool</c>) into a folder feed; build and run a fresh console app whose Program.cs is the README's
/// "The library in ten lines" example, referencing the package; build and run the guide's own-method sample
/// (samples/RayLab.OwnMethod) outside the repository against the package; build and run the README's test project, a copy of
/// tests/RayLab.Tests/Examples, against the package; install the tool from the feed and run it (the native build on
/// linux-x64, and the framework-dependent fallback through a pointer package that names no package for this platform).
/// The children get an empty NUGET_PACKAGES folder, so no cached copy of an older RayLab package can stand in.
/// </summary>
[Trait("Category", "Packaging")]
public sealed partial class PackageTests : IDisposable
{
    /// <summary>The environment variable that keeps the native tool in the binary that was started (NativeDispatch).</summary>
    private const string NoDispatchVariable = "RAYLAB_NO_DISPATCH";

    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(5);

    private readonly string _dir = Directory.CreateTempSubdirectory("raylab-packaging-").FullName;

    public void Dispose()
    {
        try
        {
            Directory.Delete(_dir, recursive: true);
        }
        catch (IOException)
        {
            // A child that was killed on timeout may still hold a file; the temp folder is not worth failing for.
        }
    }

    [Fact]
    public async Task PackagedLibraryRunsTheReadmeExampleAndTestProjectAndTheInstalledToolRenders()
    {
        string repo = FindRepoRoot();
        string feed = Path.Combine(_dir, "feed");
        string packages = Path.Combine(_dir, "nuget-packages");
        string artifacts = Path.Combine(_dir, "artifacts");

        // 1. Pack both projects into the feed (bin/obj under the temp folder, not the repository's). The tool is .NET 10's
        // RID-specific tool: RayLab.Tool points to RayLab.Tool.linux-x64 (Native AOT, packed where it can be compiled:
        // on linux-x64) and RayLab.Tool.any (the framework-dependent build for every other platform).
        string console = Path.Combine(repo, "samples", "RayLab.Console", "RayLab.Console.csproj");
        await RunAsync(_dir, packages, "dotnet", "pack", Path.Combine(repo, "src", "RayLab", "RayLab.csproj"), "-c", "Release",
            "-o", feed, "--artifacts-path", artifacts);
        await RunAsync(_dir, packages, "dotnet", "pack", console, "-c", "Release", "-o", feed, "--artifacts-path", artifacts);
        await RunAsync(_dir, packages, "dotnet", "pack", console, "-c", "Release", "-r", "any", "-o", feed, "--artifacts-path", artifacts);
        if (NativeToolHere)
        {
            await RunAsync(_dir, packages, "dotnet", "pack", console, "-c", "Release", "-r", "linux-x64", "-o", feed,
                "--artifacts-path", artifacts);
        }

        string libraryPackage = Assert.Single(Directory.GetFiles(feed, "RayLab.*.nupkg"),
            f => !Path.GetFileName(f).StartsWith("RayLab.Tool.", StringComparison.OrdinalIgnoreCase));
        string version = Path.GetFileNameWithoutExtension(libraryPackage)["RayLab.".Length..];
        Assert.True(File.Exists(Path.Combine(feed, $"RayLab.{version}.snupkg")), "the symbols package is missing");
        Assert.True(File.Exists(Path.Combine(feed, $"RayLab.Tool.{version}.nupkg")), "the tool package is missing");
        Assert.True(File.Exists(Path.Combine(feed, $"RayLab.Tool.any.{version}.nupkg")), "the framework-dependent tool package is missing");

        // 2. A fresh console app, outside the repository, whose Program.cs is exactly the README's example.
        string app = Directory.CreateDirectory(Path.Combine(_dir, "app")).FullName;
        File.WriteAllText(Path.Combine(app, "app.csproj"), $"""
            <Project Sdk="Microsoft.NET.Sdk">
              <PropertyGroup>
                <OutputType>Exe</OutputType>
                <TargetFramework>net10.0</TargetFramework>
                <ImplicitUsings>enable</ImplicitUsings>
                <Nullable>enable</Nullable>
                <ManagePackageVersionsCentrally>false</ManagePackageVersionsCentrally>
              </PropertyGroup>
              <ItemGroup>
                <PackageReference Include="RayLab" Version="{version}" />
              </ItemGroup>
            </Project>
            """);
        // The feed is added to the sources the machine already has (no <clear/>): the user and machine configs still apply.
        File.WriteAllText(Path.Combine(app, "nuget.config"), $"""
            <?xml version="1.0" encoding="utf-8"?>
            <configuration>
              <packageSources>
                <add key="raylab-test-feed" value="{feed}" />
              </packageSources>
            </configuration>
            """);
        File.WriteAllText(Path.Combine(app, "Program.cs"), ReadmeLibraryExample(repo));

        await RunAsync(app, packages, "dotnet", "run", "-c", "Release");
        AssertPng(Path.Combine(app, "two-spheres.png"), 800, 600);
        // Image.Save("….jpg") and ("….webp") through SkiaSharp, which came with the package alone.
        foreach ((string file, SKEncodedImageFormat format) in new[] { ("two-spheres.jpg", SKEncodedImageFormat.Jpeg), ("two-spheres.webp", SKEncodedImageFormat.Webp) })
        {
            string path = Path.Combine(app, file);
            Assert.True(File.Exists(path), $"{path} was not written");
            SkiaDecode.Result decoded = SkiaDecode.Load(path);
            Assert.Equal((800, 600, format), (decoded.Width, decoded.Height, decoded.Format));
        }

        // 2b. The README's guide "Your own antialiasing method": the sources of samples/RayLab.OwnMethod (a point
        // sampler and a pixel method of the student's own) beside the same project file and the lab's scene,
        // built against the package alone; it renders each method beside jittered into out/ and writes the compare report into out/report.
        string own = Directory.CreateDirectory(Path.Combine(_dir, "own")).FullName;
        foreach (string file in Directory.GetFiles(Path.Combine(repo, "samples", "RayLab.OwnMethod"), "*.cs"))
        {
            File.Copy(file, Path.Combine(own, Path.GetFileName(file)));
        }

        File.WriteAllText(Path.Combine(own, "own.csproj"), File.ReadAllText(Path.Combine(app, "app.csproj")).Replace(
            "</Project>",
            "  <ItemGroup>\n    <None Include=\"scenes/two-spheres.json\" CopyToOutputDirectory=\"PreserveNewest\" />\n  </ItemGroup>\n</Project>"));
        Directory.CreateDirectory(Path.Combine(own, "scenes"));
        File.Copy(Path.Combine(repo, "samples", "scenes", "two-spheres.json"), Path.Combine(own, "scenes", "two-spheres.json"));
        File.Copy(Path.Combine(app, "nuget.config"), Path.Combine(own, "nuget.config"));
        await RunAsync(own, packages, "dotnet", "run", "-c", "Release");
        AssertPng(Path.Combine(own, "out", "rotated-grid-16.png"), 800, 600);
        AssertPng(Path.Combine(own, "out", "mitchell.png"), 800, 600);
        // ... and writes the speed-against-error report with both methods through the library's compare API.
        string report = Path.Combine(own, "out", "report");
        Assert.True(File.Exists(Path.Combine(report, "index.html")), "the own-method sample wrote no index.html");
        AssertPng(Path.Combine(report, "error-vs-time.png"), 900, 540); // ScottPlot's chart, from the package too
        string[] series = [.. File.ReadAllLines(Path.Combine(report, "results.csv")).Skip(1).Select(line => line.Split(',')[0]).Distinct()];
        Assert.Equal(["jittered", "rotated-grid", "mitchell"], series);
        AssertPng(Path.Combine(report, "images", "mitchell-4---16.png"), 200, 150);

        // 3. The README's own test project (quick start, part 3): the Examples folder copied beside its project file,
        // so the examples a student starts from build against the package alone and pass.
        string tests = Directory.CreateDirectory(Path.Combine(_dir, "tests")).FullName;
        foreach (string file in Directory.GetFiles(Path.Combine(repo, "tests", "RayLab.Tests", "Examples"), "*.cs"))
        {
            File.Copy(file, Path.Combine(tests, Path.GetFileName(file)));
        }

        File.WriteAllText(Path.Combine(tests, "RayLabTests.csproj"), ReadmeTestProject(repo));
        File.Copy(Path.Combine(app, "nuget.config"), Path.Combine(tests, "nuget.config"));
        await RunAsync(tests, packages, "dotnet", "test", "-c", "Release");

        // 4. The tool, installed from the feed: on linux-x64 the native build, elsewhere the framework-dependent one.
        string tools = Path.Combine(_dir, "tools");
        await RunAsync(_dir, packages, "dotnet", "tool", "install", "RayLab.Tool", "--tool-path", tools,
            "--add-source", feed, "--version", version);
        string raylab = Path.Combine(tools, OperatingSystem.IsWindows() ? "raylab.exe" : "raylab");
        AssertInstalledBuild(tools, raylab, native: NativeToolHere);

        string rendered = Path.Combine(_dir, "t.png");
        await RunAsync(_dir, packages, raylab, "render", Path.Combine(repo, "samples", "scenes", "two-spheres.json"),
            "-o", rendered, "--width", "64", "--height", "48");
        AssertPng(rendered, 64, 48);

        // With no arguments it renders the scene shipped inside the tool package into out/ of the working folder.
        string work = Directory.CreateDirectory(Path.Combine(_dir, "work")).FullName;
        await RunAsync(work, packages, raylab);
        AssertPng(Path.Combine(work, "out", "two-spheres-perspective.png"), 800, 600);

        // The scenes it carries, listed and rendered by name from a folder outside the repository.
        await AssertCarriedScenesAsync(work, packages, raylab, native: NativeToolHere);
        if (NativeToolHere)
        {
            await AssertDispatchAsync(work, packages, raylab);
        }

        // 5. The fallback: a pointer package that names a native package for another platform only (as RayLab.Tool
        // does for linux-x64 on every other platform) installs RayLab.Tool.any, which renders with the JIT.
        string otherFeed = Directory.CreateDirectory(Path.Combine(_dir, "feed-other")).FullName;
        string otherPackages = Path.Combine(_dir, "nuget-packages-other"); // the first pointer package must not be reused
        string otherRid = NativeToolHere ? "win-arm64" : "linux-x64";
        await RunAsync(_dir, otherPackages, "dotnet", "pack", console, "-c", "Release", "-o", otherFeed,
            "--artifacts-path", Path.Combine(_dir, "artifacts-other"), $"-p:RayLabNativeRid={otherRid}");
        File.Copy(Path.Combine(feed, $"RayLab.Tool.any.{version}.nupkg"), Path.Combine(otherFeed, $"RayLab.Tool.any.{version}.nupkg"));
        string fallbackTools = Path.Combine(_dir, "tools-fallback");
        await RunAsync(_dir, otherPackages, "dotnet", "tool", "install", "RayLab.Tool", "--tool-path", fallbackTools,
            "--add-source", otherFeed, "--version", version);
        string fallback = Path.Combine(fallbackTools, OperatingSystem.IsWindows() ? "raylab.exe" : "raylab");
        AssertInstalledBuild(fallbackTools, fallback, native: false);
        await AssertCarriedScenesAsync(work, otherPackages, fallback, native: false);
    }

    /// <summary>Whether this machine gets the native tool package: RayLab.Tool has one for linux-x64 only.</summary>
    private static bool NativeToolHere => OperatingSystem.IsLinux() && RuntimeInformation.OSArchitecture == Architecture.X64;

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

            // The entry is the x86-64-v2 build; the wider builds it execs on a CPU that runs them lie beside it.
            string folder = Path.GetDirectoryName(target.FullName)!;
            string[] siblings = [.. Directory.GetFiles(folder, "raylab-*").Select(f => Path.GetFileName(f)!).Order(StringComparer.Ordinal)];
            Assert.Equal(["raylab-x86-64-v3", "raylab-x86-64-v4"], siblings);
            byte[][] builds = [File.ReadAllBytes(target.FullName), .. siblings.Select(s => File.ReadAllBytes(Path.Combine(folder, s)))];
            foreach (byte[] build in builds)
            {
                Assert.Equal(head, build.AsSpan(0, 4).ToArray());
                Assert.Single(builds, other => other.AsSpan().SequenceEqual(build)); // three different compilations
            }
        }
        else
        {
            Assert.Equal(["raylab.tool.any"], packageFolders);
            Assert.Single(assemblies);
        }
    }

    /// <summary>
    /// <c>raylab scenes</c> lists the scenes the tool carries, and <c>raylab render two-spheres</c> renders one of them
    /// by name in <paramref name="work"/>, a folder without scene files; the PNG decodes. The native build makes no
    /// warm-up render (its <c>--stats</c> has no <c>warmupMs</c>), the JIT build does.
    /// </summary>
    private static async Task AssertCarriedScenesAsync(string work, string packages, string raylab, bool native)
    {
        string list = await RunAsync(work, packages, raylab, "scenes");
        foreach (string scene in new[] { "two-spheres", "off-axis", "low-contrast", "sphere-field" })
        {
            Assert.Contains(scene, list, StringComparison.Ordinal);
        }

        string png = Path.Combine(work, native ? "by-name-native.png" : "by-name-jit.png");
        string stats = Path.ChangeExtension(png, ".json");
        await RunAsync(work, packages, raylab, "render", "two-spheres", "-o", png, "--width", "96", "--height", "72",
            "--stats", stats);
        SkiaDecode.Result decoded = SkiaDecode.Load(png);
        Assert.Equal((96, 72, SKEncodedImageFormat.Png), (decoded.Width, decoded.Height, decoded.Format));
        Assert.Contains(decoded.Rgb, b => b != decoded.Rgb[0]); // a picture, not one flat colour
        Assert.Equal(native, !File.ReadAllText(stats).Contains("\"warmupMs\"", StringComparison.Ordinal));
    }

    /// <summary>
    /// The installed native tool takes the widest render kernel this CPU runs: its x86-64-v2 entry execs the v3 (AVX2)
    /// or v4 (AVX-512) build beside it when the CPU has that level, which <c>--stats</c> shows as the kernel
    /// (expected from this test process's own checks of the same instruction sets); with
    /// <see cref="NoDispatchVariable"/> set it stays in the entry, the <c>vector128</c> kernel, and writes the same PNG bytes.
    /// The build it takes has lost its execute permission first (as a package extractor may leave it): the entry
    /// gives it back and still takes it.
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
        await RunAsync(work, packages, raylab, [.. render, "widest.json", "-o", widestPng]);
        if (widestPath is not null && !OperatingSystem.IsWindows())
        {
            Assert.True(File.GetUnixFileMode(widestPath).HasFlag(UnixFileMode.UserExecute), $"{widestPath} was not made executable");
        }
        await RunWithVariableAsync(work, packages, NoDispatchVariable, raylab, [.. render, "entry.json", "-o", entryPng]);

        Assert.Equal(expected, Kernel(Path.Combine(work, "widest.json")));
        Assert.Equal("vector128", Kernel(Path.Combine(work, "entry.json")));
        Assert.Equal(File.ReadAllBytes(widestPng), File.ReadAllBytes(entryPng));

        static string Kernel(string stats)
        {
            using JsonDocument json = JsonDocument.Parse(File.ReadAllText(stats));
            return json.RootElement.GetProperty("kernel").GetString()!;
        }
    }

    /// <summary>
    /// The kernel of the build the native tool's dispatch should land in on this CPU, from the same instruction sets
    /// this (JIT) process sees: x86-64-v4 (AVX-512 F, BW, CD, DQ, VL) renders with vector512, x86-64-v3 (AVX2, FMA,
    /// BMI1, BMI2) with vector256, anything older with the entry's vector128.
    /// </summary>
    private static string ExpectedNativeKernel()
    {
        bool v3 = Avx2.IsSupported && Fma.IsSupported && Bmi1.IsSupported && Bmi2.IsSupported;
        bool v4 = v3 && Avx512F.IsSupported && Avx512F.VL.IsSupported && Avx512BW.IsSupported && Avx512CD.IsSupported && Avx512DQ.IsSupported;
        return v4 ? "vector512" : v3 ? "vector256" : "vector128";
    }

    /// <summary>The C# block under the README's "## The library in ten lines" heading.</summary>
    private static string ReadmeLibraryExample(string repo)
    {
        string readme = File.ReadAllText(Path.Combine(repo, "README.md")).ReplaceLineEndings("\n");
        Match m = ReadmeExample().Match(readme);
        Assert.True(m.Success, "README.md has no ```csharp block under \"## The library in ten lines\"");
        return m.Groups["code"].Value;
    }

    /// <summary>The project file the README's quick start writes with <c>cat &gt; RayLabTests.csproj &lt;&lt;'EOF'</c>.</summary>
    private static string ReadmeTestProject(string repo)
    {
        string readme = File.ReadAllText(Path.Combine(repo, "README.md")).ReplaceLineEndings("\n");
        Match m = ReadmeTestProjectFile().Match(readme);
        Assert.True(m.Success, "README.md has no \"cat > RayLabTests.csproj <<'EOF'\" block under \"### 3. Tests\"");
        return m.Groups["project"].Value;
    }

    [GeneratedRegex(@"^### 3\. Tests\n(?:(?!^##).)*?^cat > RayLabTests\.csproj <<'EOF'\n(?<project>.*?)^EOF$", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex ReadmeTestProjectFile();

    [GeneratedRegex(@"^## The library in ten lines\n(?:(?!^## ).)*?^```csharp\n(?<code>.*?)^```", RegexOptions.Multiline | RegexOptions.Singleline)]
    private static partial Regex ReadmeExample();

    private static void AssertPng(string path, int width, int height)
    {
        Assert.True(File.Exists(path), $"{path} was not written");
        byte[] png = File.ReadAllBytes(path);
        byte[] signature = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];
        Assert.True(png.Length > 24 && png.AsSpan(0, 8).SequenceEqual(signature), $"{path} is not a PNG");
        Assert.Equal("IHDR", Encoding.ASCII.GetString(png, 12, 4));
        Assert.Equal(width, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(16)));
        Assert.Equal(height, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(20)));
    }

    private static string FindRepoRoot()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "RayLab.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException($"RayLab.sln not found above {AppContext.BaseDirectory}");
    }

    /// <summary>Runs a child process to completion; fails with its command line, stdout and stderr unless it exits 0.</summary>
    /// <returns>What the child wrote to stdout.</returns>
    private static Task<string> RunAsync(string workingDirectory, string nugetPackages, string fileName, params string[] args) =>
        RunWithVariableAsync(workingDirectory, nugetPackages, null, fileName, args);

    /// <summary>As <see cref="RunAsync(string, string, string, string[])"/>, with <paramref name="setVariable"/> (when not null) set to 1 in the child's environment.</summary>
    /// <returns>What the child wrote to stdout.</returns>
    private static async Task<string> RunWithVariableAsync(string workingDirectory, string nugetPackages, string? setVariable, string fileName, string[] args)
    {
        var psi = new ProcessStartInfo(fileName)
        {
            WorkingDirectory = workingDirectory,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string arg in args)
        {
            psi.ArgumentList.Add(arg);
        }

        // What the test host inherited from the outer `dotnet test` build must not steer the child builds.
        foreach (string key in psi.Environment.Keys.Where(k => k.StartsWith("MSBuild", StringComparison.OrdinalIgnoreCase)).ToList())
        {
            psi.Environment.Remove(key);
        }

        psi.Environment["NUGET_PACKAGES"] = nugetPackages;
        psi.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        psi.Environment["DOTNET_NOLOGO"] = "1";
        psi.Environment["DOTNET_SKIP_FIRST_TIME_EXPERIENCE"] = "1";
        psi.Environment.Remove(NoDispatchVariable); // the native tool chooses its build unless a test asks it not to
        if (setVariable is not null)
        {
            psi.Environment[setVariable] = "1";
        }

        using var process = new Process { StartInfo = psi };
        var stdout = new StringBuilder();
        var stderr = new StringBuilder();
        process.OutputDataReceived += (_, e) => { if (e.Data is not null) { lock (stdout) { stdout.AppendLine(e.Data); } } };
        process.ErrorDataReceived += (_, e) => { if (e.Data is not null) { lock (stderr) { stderr.AppendLine(e.Data); } } };
        process.Start();
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();

        string command = $"{fileName} {string.Join(' ', args)} (in {workingDirectory})";
        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(TestContext.Current.CancellationToken);
        timeout.CancelAfter(ChildTimeout);
        try
        {
            await process.WaitForExitAsync(timeout.Token);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"timed out after {ChildTimeout} or cancelled: {command}\n--- stdout\n{stdout}\n--- stderr\n{stderr}");
        }

        process.WaitForExit(); // drains the redirected streams
        Assert.True(process.ExitCode == 0,
            $"exit code {process.ExitCode}: {command}\n--- stdout\n{stdout}\n--- stderr\n{stderr}");
        return stdout.ToString();
    }
}
