using System.Text.Json;
using RayLab.Grading;
using RayLab.Scenes;

namespace RayLab.Cli;

/// <summary>
/// <c>raylab grade</c>'s checked input: the submissions (one folder each, by name), the pinned checks' lab and its
/// grading.json (which pictures to score, which method's rays and time to show), the feed, the report folder.
/// Every problem is a <see cref="UsageException"/> naming the option and what is wrong, before anything runs.
/// </summary>
internal sealed class GradeSetup
{
    private GradeSetup(GradeRequest request, string submissions, string[] students, string checks, string feed, string output)
    {
        Request = request;
        Submissions = submissions;
        Students = students;
        Checks = checks;
        Feed = feed;
        Output = output;
    }

    public GradeRequest Request { get; }

    public string Submissions { get; }

    /// <summary>Each submission's folder, in ordinal order of the names.</summary>
    public string[] Students { get; }

    /// <summary>How many submissions are built and checked at once: <c>--jobs</c>, at most one per submission.</summary>
    public int Jobs => Math.Min(Request.Jobs, Students.Length);

    public string Checks { get; }

    public string Feed { get; }

    public string Output { get; }

    /// <summary>The lab kind the checks are for (grading.json's kind): exercise or method.</summary>
    public string Kind { get; private set; } = "exercise";

    /// <summary>The RayLab version the checks were made with.</summary>
    public string Version { get; private set; } = "";

    /// <summary>Each camera's picture, relative to the lab's root.</summary>
    public Dictionary<string, string> Pictures { get; } = new(StringComparer.Ordinal)
    {
        ["orthographic"] = "out/two-spheres-orthographic.png",
        ["perspective"] = "out/two-spheres-perspective.png",
    };

    /// <summary>The method whose rays per pixel the program's lines report, shown as its own report (adaptive, or the method lab's mymethod).</summary>
    public string TimedMethod { get; private set; } = "adaptive";

    /// <summary>The checks' root namespace (the template's lab name).</summary>
    public string ChecksNamespace { get; private set; } = "MyLab";

    /// <summary>
    /// What a lab may use from other assemblies (the checks' tests/Lab.Tests/uses.json, the list the student's own lab
    /// checks with), or null where the checks carry none: then nothing is refused.
    /// </summary>
    public UseList? Uses { get; private set; }

    /// <summary>The lab's scene (the checks' scenes/two-spheres.json).</summary>
    public SceneDescription Scene { get; private set; } = null!;

    public static GradeSetup Check(GradeRequest request)
    {
        foreach ((string option, TimeSpan value) in new[] { ("--check-timeout", request.CheckTimeout), ("--run-timeout", request.RunTimeout), ("--submission-timeout", request.SubmissionTimeout) })
        {
            if (value <= TimeSpan.Zero)
            {
                throw new UsageException($"{option}: expected a number of seconds ≥ 1, got {value.TotalSeconds:0}");
            }
        }

        if (request.Jobs < 1)
        {
            throw new UsageException($"--jobs: expected a count ≥ 1, got {request.Jobs}");
        }

        if (request.MemoryLimitMegabytes < 256)
        {
            throw new UsageException($"--memory-limit: expected megabytes ≥ 256, got {request.MemoryLimitMegabytes}");
        }

        foreach ((string option, int value, int least, string unit) in new[] { ("--process-limit", request.ProcessLimit, 64, "a count"), ("--disk-limit", request.DiskLimitMegabytes, 64, "megabytes"), ("--cpu-limit", request.CpuLimitSeconds, 10, "seconds") })
        {
            if (value < least)
            {
                throw new UsageException($"{option}: expected {unit} ≥ {least}, got {value}");
            }
        }

        foreach (string limit in request.UnsafeNoLimit)
        {
            if (!GradeRequest.LimitNames.Contains(limit))
            {
                throw new UsageException($"--unsafe-no-limit: expected {string.Join(", ", GradeRequest.LimitNames)}, got '{limit}'");
            }
        }

        string submissions = Folder(request.Submissions, "submissions");
        string checks = Folder(request.Checks, "--checks");
        string feed = request.Feed is null
            ? Path.GetFullPath(Path.Combine(checks, "..", "..", "feed"))
            : Path.GetFullPath(request.Feed);
        if (!Directory.Exists(feed) || !Directory.EnumerateFiles(feed, "*.nupkg").Any())
        {
            throw new UsageException(request.Feed is null
                ? $"--feed: no packages in {feed} (the kit's feed/ beside checks/); give the feed with --feed"
                : Directory.Exists(feed) ? $"--feed: no packages (*.nupkg) in {feed}" : File.Exists(feed) ? $"--feed: {feed} is a file, not the feed's folder" : $"--feed: no such folder: {feed}");
        }

        if (string.IsNullOrWhiteSpace(request.Output))
        {
            throw new UsageException("--out: the path is empty");
        }

        string output = Path.GetFullPath(request.Output);
        if (File.Exists(output))
        {
            throw new UsageException($"--out: '{request.Output}' is a file; the report is a folder");
        }

        if (IsInside(output, submissions) || IsInside(output, checks))
        {
            throw new UsageException($"--out: '{request.Output}' is inside the {(IsInside(output, submissions) ? "submissions" : "checks")} folder; write the report elsewhere");
        }

        OutputFolders.Probe("--out", request.Output); // now, not after every lab is graded

        foreach (string needed in new[] { Path.Combine("tests", "Lab.Tests"), Path.Combine("src", "Lab") })
        {
            if (!Directory.Exists(Path.Combine(checks, needed)))
            {
                throw new UsageException($"--checks: {checks} has no {needed}; give a kit's checks/exercise or checks/method");
            }
        }

        foreach (string needed in new[] { "Directory.Build.props", Path.Combine("scenes", "two-spheres.json") })
        {
            if (!File.Exists(Path.Combine(checks, needed)))
            {
                throw new UsageException($"--checks: {checks} has no {needed}; give a kit's checks/exercise or checks/method");
            }
        }

        string[] students = [.. Directory.EnumerateDirectories(submissions)
            .Where(d => !Path.GetFileName(d).StartsWith('.'))
            .Order(StringComparer.Ordinal)];
        if (students.Length == 0)
        {
            throw new UsageException($"submissions: {request.Submissions} has no folders; it holds one folder per student, each a lab");
        }

        var setup = new GradeSetup(request, submissions, students, checks, feed, output);
        setup.ReadGrading();
        setup.Scene = SceneFile.Load(Path.Combine(checks, "scenes", "two-spheres.json"));
        string? project = Directory.EnumerateFiles(Path.Combine(checks, "src", "Lab"), "*.csproj").FirstOrDefault();
        if (project is not null && System.Text.RegularExpressions.Regex.Match(File.ReadAllText(project), @"<RootNamespace>\s*([^<]+?)\s*</RootNamespace>") is { Success: true } m)
        {
            setup.ChecksNamespace = m.Groups[1].Value;
        }

        string uses = Path.Combine(checks, "tests", "Lab.Tests", "uses.json");
        if (File.Exists(uses))
        {
            try
            {
                setup.Uses = UseList.Load(uses);
            }
            catch (FormatException e)
            {
                throw new UsageException($"--checks: {e.Message}");
            }
        }

        return setup;
    }

    /// <summary>grading.json (written by tools/class-kit.sh): kind, raylabVersion, pictures (camera → path), timedMethod; each optional.</summary>
    private void ReadGrading()
    {
        string path = Path.Combine(Checks, "grading.json");
        if (!File.Exists(path))
        {
            return;
        }

        try
        {
            using JsonDocument document = JsonDocument.Parse(File.ReadAllText(path));
            JsonElement root = document.RootElement;
            if (root.TryGetProperty("kind", out JsonElement kind))
            {
                Kind = kind.GetString() ?? Kind;
            }

            if (root.TryGetProperty("raylabVersion", out JsonElement version))
            {
                Version = version.GetString() ?? "";
            }

            if (root.TryGetProperty("timedMethod", out JsonElement timed))
            {
                TimedMethod = timed.GetString() ?? TimedMethod;
            }

            if (root.TryGetProperty("pictures", out JsonElement pictures))
            {
                foreach (JsonProperty picture in pictures.EnumerateObject())
                {
                    if (!Pictures.ContainsKey(picture.Name))
                    {
                        throw new UsageException($"--checks: {path}: pictures.{picture.Name}: expected a camera, orthographic or perspective");
                    }

                    string file = picture.Value.GetString() ?? "";
                    if (file.Length == 0 || Path.IsPathRooted(file) || file.Split('/', '\\').Contains(".."))
                    {
                        throw new UsageException($"--checks: {path}: pictures.{picture.Name}: expected a path inside the lab, got '{file}'");
                    }

                    Pictures[picture.Name] = file;
                }
            }
        }
        catch (Exception e) when (e is JsonException or InvalidOperationException)
        {
            throw new UsageException($"--checks: {path}: {e.Message}");
        }
    }

    private static string Folder(string path, string option)
    {
        if (string.IsNullOrWhiteSpace(path))
        {
            throw new UsageException($"{option}: the path is empty");
        }

        if (!Directory.Exists(path))
        {
            throw new UsageException(File.Exists(path) ? $"{option}: '{path}' is a file, not a folder" : $"{option}: no such folder '{path}'");
        }

        return Path.GetFullPath(path).TrimEnd(Path.DirectorySeparatorChar);
    }

    private static bool IsInside(string path, string folder)
    {
        string relative = Path.GetRelativePath(folder, path);
        return relative == "." || (!relative.StartsWith("..", StringComparison.Ordinal) && !Path.IsPathRooted(relative));
    }
}
