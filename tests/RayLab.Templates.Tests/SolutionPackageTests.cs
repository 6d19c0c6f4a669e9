using System.IO.Compression;
using System.Text.Json;

namespace RayLab.Templates.Tests;

/// <summary>
/// The two template packages of the shared <see cref="TemplateFeed"/> (packed from this checkout and installed side by
/// side in its DOTNET_CLI_HOME): the students' <c>RayLab.Templates</c> holds no text of the reference
/// solution and refuses <c>--solution</c>; the instructor's <c>RayLab.Templates.Instructor</c> holds the solution and
/// installs beside it as <c>raylab-lab-solution</c>.
/// </summary>
[Trait("Category", "Templates")]
[Collection(TemplateFeedSharing.Name)]
public sealed class SolutionPackageTests(TemplateFeed packages)
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
        foreach ((string name, string text) in Entries(packages.StudentPackage))
        {
            Assert.False(text.Contains("#if (solution)", StringComparison.Ordinal), $"{name} in {Path.GetFileName(packages.StudentPackage)} holds #if (solution)");
            Assert.DoesNotMatch(@"(?m)^\s*#\s*(if|elif)\b.*\bsolution\b", text);
        }

        string template = Entries(packages.StudentPackage).Single(e => e.Name == "content/raylab-lab/.template.config/template.json").Text;
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

        Assert.DoesNotContain(Entries(packages.StudentPackage), e => e.Text.Contains(line, StringComparison.Ordinal));
        Assert.Contains(Entries(packages.InstructorPackage), e => e.Text.Contains(line, StringComparison.Ordinal));
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
