using System.Xml.Linq;

namespace RayLab.Grading;

/// <summary>
/// The pinned checks, apart from the lab: for each submission a folder of their own in the grader's work, which the lab's
/// build and code never see, made from the instructor's copy (the kit's checks), compiled against the lab's built
/// assembly (a reference to the file, not the lab's project: nothing of the lab's MSBuild runs) and run with their
/// folder read-only, a folder of results the only one the run writes.
/// </summary>
internal static class GradeChecks
{
    /// <summary>The folder, inside the checks' folder, the lab's assembly and its data files are copied to.</summary>
    private const string LabFolder = "lab";

    /// <summary>
    /// The built lab assembly of a lab's project: <c>src/Lab/bin/Debug/net10.0/NAME.dll</c>, NAME the project file's
    /// name (the SDK's default output), or null when the build left none there.
    /// </summary>
    /// <param name="lab">The lab's copy.</param>
    /// <returns>The assembly's path, or null.</returns>
    public static string? BuiltAssembly(string lab)
    {
        string? project = Directory.EnumerateFiles(Path.Combine(lab, "src", "Lab"), "*.csproj").Order(StringComparer.Ordinal).FirstOrDefault();
        if (project is null)
        {
            return null;
        }

        string path = Path.Combine(lab, "src", "Lab", "bin", "Debug", "net10.0", Path.GetFileNameWithoutExtension(project) + ".dll");
        return File.Exists(path) && new FileInfo(path).LinkTarget is null ? path : null;
    }

    /// <summary>Where the checks' build leaves their test assembly, relative to the checks' folder.</summary>
    public const string TestsOutput = "tests/Lab.Tests/bin/Debug/net10.0/Lab.Tests.dll";

    /// <summary>The checks' built test assembly (<see cref="TestsOutput"/>), or null when their build left none there.</summary>
    /// <param name="folder">The checks' folder, built.</param>
    /// <returns>The assembly's path, or null.</returns>
    public static string? BuiltTests(string folder)
    {
        string path = Path.Combine(folder, TestsOutput);
        return File.Exists(path) ? path : null;
    }

    /// <summary>
    /// The options the checks' project gives <c>dotnet test</c> when it is run on the project (the instructor's
    /// <c>RunSettingsFilePath</c> and <c>VSTestLogger</c>), as options for a run on the built assembly, which reads no
    /// project: <c>--settings FILE</c> and one <c>--logger</c> for each logger.
    /// </summary>
    /// <param name="folder">The checks' folder.</param>
    /// <returns>The options, none where the project sets neither.</returns>
    public static IReadOnlyList<string> ProjectTestSettings(string folder)
    {
        string directory = Path.Combine(folder, "tests", "Lab.Tests");
        XElement project = XDocument.Load(Path.Combine(directory, "Lab.Tests.csproj")).Root!;
        var options = new List<string>();
        string? settings = project.Descendants("RunSettingsFilePath").LastOrDefault()?.Value.Trim();
        if (!string.IsNullOrEmpty(settings))
        {
            string path = settings.Replace("$(MSBuildThisFileDirectory)", directory + Path.DirectorySeparatorChar, StringComparison.Ordinal);
            if (File.Exists(path))
            {
                options.AddRange(["--settings", path]);
            }
        }

        string? loggers = project.Descendants("VSTestLogger").LastOrDefault()?.Value.Trim();
        foreach (string logger in (loggers ?? "").Split(';', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            options.AddRange(["--logger", Uri.UnescapeDataString(logger)]);
        }

        return options;
    }

    /// <summary>
    /// Makes the checks' folder: the instructor's tests/Lab.Tests, Directory.Build.props and the feed's nuget.config;
    /// the lab's assembly (with its symbols, for the lines in the messages) and its scene files under lab/; the test
    /// project's reference to the lab's project replaced by one to that assembly, with the instructor's lab project's
    /// package references it does not have itself.
    /// </summary>
    /// <param name="checks">The instructor's checks (the kit's checks/KIND).</param>
    /// <param name="nugetConfig">The nuget.config text (the kit's feed as the only source).</param>
    /// <param name="assembly">The lab's built assembly.</param>
    /// <param name="labNamespace">The lab's root namespace where it differs from the checks', to bring into scope; or null.</param>
    /// <param name="folder">The checks' folder to make (new).</param>
    public static void Prepare(string checks, string nugetConfig, string assembly, string? labNamespace, string folder)
    {
        string tests = Path.Combine(folder, "tests", "Lab.Tests");
        GradeJob.CopyLab(Path.Combine(checks, "tests", "Lab.Tests"), tests);
        File.Copy(Path.Combine(checks, "Directory.Build.props"), Path.Combine(folder, "Directory.Build.props"));
        File.WriteAllText(Path.Combine(folder, "nuget.config"), nugetConfig);
        if (labNamespace is not null)
        {
            File.WriteAllText(Path.Combine(tests, "GradedLabNamespace.cs"), $"global using {labNamespace};\n");
        }

        // The lab's assembly and symbols, and its scene files (what its code reads from its own folder); no other file of
        // its output: the checks' own packages supply every library.
        string labFolder = Path.Combine(folder, LabFolder);
        Directory.CreateDirectory(labFolder);
        string name = Path.GetFileNameWithoutExtension(assembly);
        string output = Path.GetDirectoryName(assembly)!;
        File.Copy(assembly, Path.Combine(labFolder, name + ".dll"));
        if (File.Exists(Path.Combine(output, name + ".pdb")) && new FileInfo(Path.Combine(output, name + ".pdb")).LinkTarget is null)
        {
            File.Copy(Path.Combine(output, name + ".pdb"), Path.Combine(labFolder, name + ".pdb"));
        }

        string scenes = Path.Combine(output, "scenes");
        if (Directory.Exists(scenes) && new DirectoryInfo(scenes).LinkTarget is null)
        {
            foreach (FileInfo scene in new DirectoryInfo(scenes).EnumerateFiles("*.json").Where(f => f.LinkTarget is null && f.Length <= 1 << 20))
            {
                Directory.CreateDirectory(Path.Combine(labFolder, "scenes"));
                scene.CopyTo(Path.Combine(labFolder, "scenes", scene.Name));
            }
        }

        string project = Path.Combine(tests, "Lab.Tests.csproj");
        XDocument test = XDocument.Load(project);
        foreach (XElement reference in test.Descendants("ProjectReference").ToList())
        {
            reference.Remove();
        }

        string? labProject = Directory.EnumerateFiles(Path.Combine(checks, "src", "Lab"), "*.csproj").Order(StringComparer.Ordinal).FirstOrDefault();
        var own = new HashSet<string>(test.Descendants("PackageReference").Select(p => (string?)p.Attribute("Include") ?? ""), StringComparer.OrdinalIgnoreCase);
        IEnumerable<XElement> packages = labProject is null ? []
            : XDocument.Load(labProject).Descendants("PackageReference").Where(p => !own.Contains((string?)p.Attribute("Include") ?? "")).Select(p => new XElement(p));
        test.Root!.Add(new XElement("ItemGroup",
            new XElement("Reference", new XAttribute("Include", name), new XElement("HintPath", $"../../{LabFolder}/{name}.dll")),
            packages,
            new XElement("None",
                new XAttribute("Include", $"../../{LabFolder}/scenes/*.json"),
                new XAttribute("Link", "scenes/%(Filename)%(Extension)"),
                new XAttribute("CopyToOutputDirectory", "PreserveNewest"))));
        test.Save(project);
    }
}
