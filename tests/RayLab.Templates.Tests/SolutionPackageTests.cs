using System.IO.Compression;
using System.Text.Json;

namespace RayLab.Templates.Tests;

/// <summary>
/// The two template packages, packed from this checkout (alone: no RayLab package is needed to look inside them or to
/// create a lab with <c>--skipRestore</c>): the students' <c>RayLab.Templates</c> holds no text of the reference
/// solution and refuses <c>--solution</c>; the instructor's <c>RayLab.Templates.Instructor</c> holds the solution and
/// installs beside it as <c>raylab-lab-solution</c>.
/// </summary>
[Trait("Category", "Templates")]
public sealed class SolutionPackageTests(TemplatePackages packages) : IClassFixture<TemplatePackages>
{
    /// <summary>
    /// Lines of the solution branches of the exercise skeletons: the perspective camera's ray origin, the adaptive
    /// method's contrast test, the 8-bit rule, the intensity's clamp.
    /// </summary>
    public static TheoryData<string> SolutionLines => new()
    {
        "c = (u0 * u) + (v0 * v) - (S * w)",
        "Math.Abs(a.R - b.R) > Contrast",
        "(byte)(int)scaled",
        "R = r > 0 ? r : 0;",
    };

    [Fact]
    public void NoFileOfTheStudentsPackageHoldsASolutionConditionOrTheSolutionSymbol()
    {
        foreach ((string name, string text) in Entries(packages.Student))
        {
            Assert.False(text.Contains("#if (solution)", StringComparison.Ordinal), $"{name} in {Path.GetFileName(packages.Student)} holds #if (solution)");
            Assert.DoesNotMatch(@"(?m)^\s*#\s*(if|elif)\b.*\bsolution\b", text);
        }

        string template = Entries(packages.Student).Single(e => e.Name == "content/raylab-lab/.template.config/template.json").Text;
        using JsonDocument json = JsonDocument.Parse(template);
        Assert.False(json.RootElement.GetProperty("symbols").TryGetProperty("solution", out _), "the students' template.json has the symbol solution");
        Assert.DoesNotContain("--solution", template, StringComparison.Ordinal);
    }

    [Theory]
    [MemberData(nameof(SolutionLines))]
    public void TheStudentsPackageLacksTheSolutionLineAndTheInstructorsHasIt(string line)
    {
        // The line is in the repository's content, inside an #if (solution) block.
        string content = Path.Combine(RepoPaths.Root(), "templates", "RayLab.Templates", "content", "raylab-lab");
        Assert.Contains(Directory.GetFiles(content, "*.cs", SearchOption.AllDirectories), f => File.ReadAllText(f).Contains(line, StringComparison.Ordinal));

        Assert.DoesNotContain(Entries(packages.Student), e => e.Text.Contains(line, StringComparison.Ordinal));
        Assert.Contains(Entries(packages.Instructor), e => e.Text.Contains(line, StringComparison.Ordinal));
    }

    [Fact]
    public async Task TheStudentsTemplateRefusesSolutionAndTheInstructorsMakesTheSolutionLab()
    {
        string work = Directory.CreateDirectory(Path.Combine(packages.Root, "labs")).FullName;

        (int exit, string output) = await packages.RunUncheckedAsync(work, "dotnet", "new", "raylab-lab", "-o", Path.Combine(work, "refused"), "--solution", "--skipRestore");
        Assert.True(exit != 0, $"dotnet new raylab-lab --solution was accepted:\n{output}");
        Assert.False(Directory.Exists(Path.Combine(work, "refused", "src")), "dotnet new raylab-lab --solution made a lab");

        string student = Path.Combine(work, "student");
        await packages.RunAsync(work, "dotnet", "new", "raylab-lab", "-o", student, "--skipRestore");
        Assert.Contains("throw ToWrite.Section(\"3.2\"", File.ReadAllText(Path.Combine(student, "src", "Lab", "LabPerspectiveCamera.cs")), StringComparison.Ordinal);

        string solution = Path.Combine(work, "solution");
        await packages.RunAsync(work, "dotnet", "new", "raylab-lab-solution", "-o", solution, "--lang", "en", "--skipRestore");
        string camera = File.ReadAllText(Path.Combine(solution, "src", "Lab", "LabPerspectiveCamera.cs"));
        Assert.Contains("c = (u0 * u) + (v0 * v) - (S * w)", camera, StringComparison.Ordinal);
        Assert.DoesNotContain("ToWrite.Section", camera, StringComparison.Ordinal);
        Assert.DoesNotContain("#if (", camera, StringComparison.Ordinal);
        Assert.Contains("2.1 Intensity:", File.ReadAllText(Path.Combine(solution, "src", "Lab", "LightIntensity.cs")), StringComparison.Ordinal); // --lang still works
    }

    /// <summary>Every file of a .nupkg (a zip) with its text.</summary>
    private static List<(string Name, string Text)> Entries(string nupkg)
    {
        using ZipArchive zip = ZipFile.OpenRead(nupkg);
        var entries = new List<(string Name, string Text)>();
        foreach (ZipArchiveEntry entry in zip.Entries.Where(e => e.Length > 0))
        {
            using var reader = new StreamReader(entry.Open());
            entries.Add((entry.FullName, reader.ReadToEnd()));
        }

        return entries;
    }
}

/// <summary>
/// Once for <see cref="SolutionPackageTests"/>: RayLab.Templates and RayLab.Templates.Instructor packed from this
/// checkout into a temporary folder and both installed, side by side, in a temporary DOTNET_CLI_HOME.
/// </summary>
public sealed class TemplatePackages : IAsyncLifetime
{
    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(5);

    /// <summary>The temporary folder everything happens in.</summary>
    public string Root { get; } = Directory.CreateTempSubdirectory("raylab-template-packages-").FullName;

    /// <summary>The students' package, RayLab.Templates.*.nupkg.</summary>
    public string Student { get; private set; } = "";

    /// <summary>The instructor's package, RayLab.Templates.Instructor.*.nupkg.</summary>
    public string Instructor { get; private set; } = "";

    private string CliHome => Path.Combine(Root, "dotnet-home");

    public async ValueTask InitializeAsync()
    {
        string repo = RepoPaths.Root(), feed = Path.Combine(Root, "feed"), artifacts = Path.Combine(Root, "artifacts");
        Directory.CreateDirectory(CliHome);
        foreach (string project in new[] { "templates/RayLab.Templates/RayLab.Templates.csproj", "templates/RayLab.Templates.Instructor/RayLab.Templates.Instructor.csproj" })
        {
            await RunAsync(Root, "dotnet", "pack", Path.Combine(repo, project), "-c", "Release", "-o", feed, "--artifacts-path", artifacts);
        }

        Instructor = Assert.Single(Directory.GetFiles(feed, "RayLab.Templates.Instructor.*.nupkg"));
        Student = Assert.Single(Directory.GetFiles(feed, "RayLab.Templates.*.nupkg"), f => f != Instructor);
        await RunAsync(Root, "dotnet", "new", "install", Student);
        await RunAsync(Root, "dotnet", "new", "install", Instructor);
    }

    public ValueTask DisposeAsync()
    {
        try
        {
            Directory.Delete(Root, recursive: true);
        }
        catch (IOException)
        {
            // A child killed on timeout may still hold a file; the temporary folder is not worth failing for.
        }

        return ValueTask.CompletedTask;
    }

    /// <summary>Runs a child to completion; fails with its command line and output unless it exits 0.</summary>
    /// <returns>What the child wrote to stdout.</returns>
    public Task<string> RunAsync(string workingDirectory, string fileName, params string[] args) =>
        ChildProcess.RunCheckedAsync(workingDirectory, Environment(), ChildTimeout, fileName, args);

    /// <summary>Runs a child to completion, whatever its exit code.</summary>
    /// <returns>Its exit code, and stdout followed by stderr.</returns>
    public async Task<(int ExitCode, string Output)> RunUncheckedAsync(string workingDirectory, string fileName, params string[] args)
    {
        ChildResult result = await ChildProcess.RunAsync(workingDirectory, Environment(), ChildTimeout, fileName, args);
        return (result.ExitCode, result.Output + result.Errors);
    }

    private Dictionary<string, string?> Environment() => new()
    {
        ["DOTNET_CLI_HOME"] = CliHome,
        ["NUGET_PACKAGES"] = Path.Combine(Root, "nuget-packages"),
        ["DOTNET_GENERATE_ASPNET_CERTIFICATE"] = "false",
    };
}
