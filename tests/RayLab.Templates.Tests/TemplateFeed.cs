
namespace RayLab.Templates.Tests;

/// <summary>
/// Once for the test assembly's template collection (<see cref="TemplateFeedSharing"/>): a temporary folder with its own DOTNET_CLI_HOME (so the template is installed nowhere
/// else) and an empty NUGET_PACKAGES (so no cached RayLab package can stand in for the one packed here); RayLab,
/// RayLab.ImageSharp, RayLab.Reports and RayLab.Templates packed from this checkout (<see cref="PackedPackages"/>) into a folder feed, and the
/// instructor's RayLab.Templates.Instructor into a folder of its own; both template packages installed side by side
/// by their ids and version, as the student and the instructor would.
/// </summary>
public sealed class TemplateFeed : IAsyncLifetime
{
    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(10);

    /// <summary>The temporary folder everything happens in.</summary>
    public string Root { get; } = Directory.CreateTempSubdirectory("raylab-templates-").FullName;

    /// <summary>The folder feed.</summary>
    public string Feed => Path.Combine(Root, "feed");

    /// <summary>The children's NUGET_PACKAGES, empty at the start.</summary>
    public string Packages => Path.Combine(Root, "nuget-packages");

    /// <summary>The children's DOTNET_CLI_HOME (where <c>dotnet new install</c> records templates).</summary>
    public string CliHome => Path.Combine(Root, "dotnet-home");

    /// <summary>The folder with the instructor's template package (<c>dotnet new raylab-lab-solution</c>).</summary>
    public string InstructorFeed => Path.Combine(Root, "instructor");

    /// <summary>The students' template package, RayLab.Templates.<see cref="Version"/>.nupkg in <see cref="Feed"/>.</summary>
    public string StudentPackage => Path.Combine(Feed, $"RayLab.Templates.{Version}.nupkg");

    /// <summary>The instructor's template package, RayLab.Templates.Instructor.<see cref="Version"/>.nupkg in <see cref="InstructorFeed"/>.</summary>
    public string InstructorPackage => Path.Combine(InstructorFeed, $"RayLab.Templates.Instructor.{Version}.nupkg");

    /// <summary>The version the five packages were packed with (MinVer: the same for all five).</summary>
    public string Version { get; private set; } = "";

    public async ValueTask InitializeAsync()
    {
        Directory.CreateDirectory(CliHome);
        // Packed once for the run (PackedPackages, shared with the class kit and the package tests), copied here.
        PackedSet packed = await PackedPackages.LibrariesAsync();
        packed.CopyTo(Feed, "RayLab", "RayLab.ImageSharp", "RayLab.Reports", "RayLab.Grading.Uses", "RayLab.Grading", "RayLab.Templates");
        packed.CopyTo(InstructorFeed, "RayLab.Templates.Instructor");

        string template = Assert.Single(Directory.GetFiles(Feed, "RayLab.Templates.*.nupkg"));
        Version = Path.GetFileNameWithoutExtension(template)["RayLab.Templates.".Length..];
        Assert.True(File.Exists(Path.Combine(Feed, $"RayLab.{Version}.nupkg")), $"RayLab {Version} is not in the feed");
        Assert.True(File.Exists(Path.Combine(Feed, $"RayLab.Reports.{Version}.nupkg")), $"RayLab.Reports {Version} is not in the feed");
        Assert.True(File.Exists(Path.Combine(Feed, $"RayLab.ImageSharp.{Version}.nupkg")), $"RayLab.ImageSharp {Version} is not in the feed");

        await RunAsync(Root, "dotnet", "new", "install", $"RayLab.Templates::{Version}", "--add-source", Feed);
        await RunAsync(Root, "dotnet", "new", "install", $"RayLab.Templates.Instructor::{Version}", "--add-source", InstructorFeed);
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
    public Task<(int ExitCode, string Output)> RunUncheckedAsync(string workingDirectory, string fileName, params string[] args) =>
        RunUncheckedAsync(workingDirectory, new Dictionary<string, string?>(), fileName, args);

    /// <summary>Runs a child to completion, whatever its exit code, with more environment variables.</summary>
    /// <returns>Its exit code, and stdout followed by stderr.</returns>
    public async Task<(int ExitCode, string Output)> RunUncheckedAsync(string workingDirectory, IReadOnlyDictionary<string, string?> variables, string fileName, params string[] args)
    {
        Dictionary<string, string?> environment = Environment();
        foreach ((string name, string? value) in variables)
        {
            environment[name] = value;
        }

        ChildResult result = await ChildProcess.RunAsync(workingDirectory, environment, ChildTimeout, fileName, args);
        return (result.ExitCode, result.Output + result.Errors);
    }

    /// <summary>The children's own CLI home and NuGet cache, and no HTTPS certificate prompt.</summary>
    private Dictionary<string, string?> Environment() => new()
    {
        ["DOTNET_CLI_HOME"] = CliHome,
        ["NUGET_PACKAGES"] = Packages,
        ["DOTNET_GENERATE_ASPNET_CERTIFICATE"] = "false",
    };
}

/// <summary>
/// The test classes that share one <see cref="TemplateFeed"/> (one packing, one install of both templates): the lab
/// tests and the template packages' tests. They run one after the other, as their children share a DOTNET_CLI_HOME.
/// </summary>
[CollectionDefinition(Name)]
public sealed class TemplateFeedSharing : ICollectionFixture<TemplateFeed>
{
    /// <summary>The collection's name.</summary>
    public const string Name = "template feed";
}
