namespace RayLab.Package.Tests;

/// <summary>
/// The folder feed every packaging test uses, packed once per run (<see cref="PackedPackages"/>, shared with the
/// template tests when .ci/run runs both): the core (<c>RayLab</c>), the reports
/// (<c>RayLab.Reports</c>), the ImageSharp adapter (<c>RayLab.ImageSharp</c>), and the tool as .NET 10's RID-specific tool — the pointer package <c>RayLab.Tool</c>,
/// <c>RayLab.Tool.any</c> (framework-dependent) and, where it can be compiled (linux-x64), <c>RayLab.Tool.linux-x64</c>
/// (Native AOT). bin/obj of the packs go under a temp folder, not the repository's; every child gets
/// <see cref="Packages"/>, an NUGET_PACKAGES folder that starts empty.
/// </summary>
public sealed class PackedFeed : IAsyncLifetime
{
    private static readonly TimeSpan ChildTimeout = TimeSpan.FromMinutes(5);

    /// <summary>The temp folder that holds the feed, the NuGet cache and every fresh project.</summary>
    public string Root { get; } = Directory.CreateTempSubdirectory("raylab-packaging-").FullName;

    /// <summary>The repository's folder (the one with RayLab.sln).</summary>
    public string Repo { get; } = RepoPaths.Root();

    /// <summary>The folder feed.</summary>
    public string Feed => Path.Combine(Root, "feed");

    /// <summary>The children's NUGET_PACKAGES.</summary>
    public string Packages => Path.Combine(Root, "nuget-packages");

    /// <summary>The console's project file (the tool).</summary>
    public string ConsoleProject => Path.Combine(Repo, "samples", "RayLab.Console", "RayLab.Console.csproj");

    /// <summary>The packages' version (MinVer: changes with each commit).</summary>
    public string Version { get; private set; } = "";

    /// <summary>Whether this machine gets the native tool package: RayLab.Tool has one for linux-x64 only.</summary>
    public static bool NativeToolHere => PackedPackages.NativeToolHere;

    public async ValueTask InitializeAsync()
    {
        // Packed once for the run (PackedPackages), copied into this fixture's own feed. Packed for this process alone,
        // the two sets pack side by side, each in its own artifacts folder; packed for the run, one after the other.
        Task<PackedSet> packingLibraries = PackedPackages.LibrariesAsync(), packingTool = PackedPackages.ToolAsync();
        PackedSet libraries = await packingLibraries, tool = await packingTool;
        Assert.True(libraries.Version == tool.Version, $"the libraries were packed at {libraries.Version}, the tool at {tool.Version} (a commit during the packing?)");
        Version = libraries.Version;
        libraries.CopyTo(Feed, "RayLab", "RayLab.Reports", "RayLab.ImageSharp");
        tool.CopyTo(Feed, NativeToolHere ? ["RayLab.Tool", "RayLab.Tool.any", "RayLab.Tool.linux-x64"] : ["RayLab.Tool", "RayLab.Tool.any"]);
        foreach (string expected in new[] { $"RayLab.{Version}.nupkg", $"RayLab.{Version}.snupkg", $"RayLab.Reports.{Version}.nupkg", $"RayLab.ImageSharp.{Version}.nupkg", $"RayLab.Tool.{Version}.nupkg", $"RayLab.Tool.any.{Version}.nupkg" })
        {
            if (!File.Exists(Path.Combine(Feed, expected)))
            {
                throw new InvalidOperationException($"the feed lacks {expected}: {string.Join(", ", Directory.GetFiles(Feed).Select(Path.GetFileName))}");
            }
        }
    }

    public ValueTask DisposeAsync()
    {
        try
        {
            Directory.Delete(Root, recursive: true);
        }
        catch (IOException)
        {
            // A child that was killed on timeout may still hold a file; the temp folder is not worth failing for.
        }

        return ValueTask.CompletedTask;
    }

    /// <summary>A fresh console app in <see cref="Root"/>/<paramref name="name"/> on <paramref name="packages"/> from the feed.</summary>
    /// <returns>Its folder.</returns>
    public string NewProject(string name, string[] packages, string extraItems = "")
    {
        string dir = Directory.CreateDirectory(Path.Combine(Root, name)).FullName;
        string references = string.Join("\n", packages.Select(p => $"    <PackageReference Include=\"{p}\" Version=\"{Version}\" />"));
        File.WriteAllText(Path.Combine(dir, name + ".csproj"), $"""
            <Project Sdk="Microsoft.NET.Sdk">
              <PropertyGroup>
                <OutputType>Exe</OutputType>
                <TargetFramework>net10.0</TargetFramework>
                <ImplicitUsings>enable</ImplicitUsings>
                <Nullable>enable</Nullable>
              </PropertyGroup>
              <ItemGroup>
            {references}
              </ItemGroup>
              {extraItems}
            </Project>
            """);
        WriteNugetConfig(dir);
        return dir;
    }

    /// <summary>A nuget.config that adds the feed to the sources the machine already has (no &lt;clear/&gt;).</summary>
    public void WriteNugetConfig(string dir) => File.WriteAllText(Path.Combine(dir, "nuget.config"), $"""
        <?xml version="1.0" encoding="utf-8"?>
        <configuration>
          <packageSources>
            <add key="raylab-test-feed" value="{Feed}" />
          </packageSources>
        </configuration>
        """);

    /// <summary>Runs a child with <see cref="Packages"/> as its NuGet cache (see <see cref="RunChildAsync"/>).</summary>
    /// <returns>What the child wrote to stdout.</returns>
    public Task<string> RunAsync(string workingDirectory, string fileName, params string[] args) =>
        RunChildAsync(workingDirectory, Packages, null, fileName, args);

    /// <summary>Runs a child process to completion; fails with its command line, stdout and stderr unless it exits 0.</summary>
    /// <param name="workingDirectory">Where it runs.</param>
    /// <param name="nugetPackages">Its NUGET_PACKAGES.</param>
    /// <param name="setVariable">An environment variable set to 1 for it, or null.</param>
    /// <param name="fileName">The program.</param>
    /// <param name="args">Its arguments.</param>
    /// <returns>What the child wrote to stdout.</returns>
    public static Task<string> RunChildAsync(string workingDirectory, string nugetPackages, string? setVariable, string fileName, params string[] args)
    {
        var environment = new Dictionary<string, string?>
        {
            ["NUGET_PACKAGES"] = nugetPackages,
            ["RAYLAB_NO_DISPATCH"] = null, // the native tool chooses its build unless a test asks it not to
        };
        if (setVariable is not null)
        {
            environment[setVariable] = "1";
        }

        return ChildProcess.RunCheckedAsync(workingDirectory, environment, ChildTimeout, fileName, args);
    }
}
