using System.Text.Json;
using RayLab.Reports.Output;
using RayLab.Scenes;

namespace RayLab.Grading;

/// <summary>
/// <c>raylab grade</c>'s checked input: the submissions (one folder each, by name, or a Moodle download's folder or
/// zip, by full name), the pinned checks' lab and its grading.json (which pictures to score, which method's rays and
/// time to show, the points), the feed, the report folder, Moodle's grading worksheet.
/// Every problem is a <see cref="UsageException"/> naming the option and what is wrong, before anything runs.
/// </summary>
internal sealed class GradeSetup
{
    private GradeSetup(GradeRequest request, string submissions, ClassSubmission[] submitted, string checks, string feed, string output)
    {
        Request = request;
        Submissions = submissions;
        Submitted = submitted;
        Students = [.. submitted.Select(s => s.Folder)];
        Checks = checks;
        Feed = feed;
        Output = output;
    }

    public GradeRequest Request { get; }

    public string Submissions { get; }

    /// <summary>Each submission's folder, in ordinal order of the names.</summary>
    public string[] Students { get; }

    /// <summary>Each submission's row name, folder and Moodle participant id, in the order of <see cref="Students"/>.</summary>
    public ClassSubmission[] Submitted { get; }

    /// <summary>How the grade is counted (grading.json's points and picture thresholds).</summary>
    public GradingScheme Scheme { get; private set; } = GradingScheme.Default;

    /// <summary>Moodle's grading worksheet to fill (<c>--moodle-worksheet</c>), or null.</summary>
    public MoodleWorksheet? Worksheet { get; private set; }

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

    /// <summary>Checks the request; a Moodle download's zip is unpacked into <paramref name="work"/>.</summary>
    // Long: every input check, in the order their messages take precedence.
    public static GradeSetup Check(GradeRequest request, string work)
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

        string submissions = SubmissionsFolder(request.Submissions, work);
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

        if ((Directory.Exists(request.Submissions) && IsInside(output, submissions)) || IsInside(output, checks))
        {
            throw new UsageException($"--out: '{request.Output}' is inside the {(IsInside(output, checks) ? "checks" : "submissions")} folder; write the report elsewhere");
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

        ClassSubmission[] students = [.. ClassSubmissions.Read(submissions)];
        if (students.Length == 0)
        {
            throw new UsageException(Directory.EnumerateFiles(submissions).Any(f => f.Contains("_assignsubmission_", StringComparison.Ordinal))
                ? $"submissions: {request.Submissions} holds Moodle's files without their folders; download them again with \"Download submissions in folders\""
                : $"submissions: {request.Submissions} has no folders; it holds one folder per student, each a lab or the zip of one");
        }

        var setup = new GradeSetup(request, submissions, students, checks, feed, output);
        setup.ReadGrading();
        setup.Worksheet = ReadWorksheet(request.MoodleWorksheet);
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

    /// <summary>
    /// grading.json (written by tools/class-kit.sh): kind, raylabVersion, pictures (camera → path), timedMethod, points
    /// (section → points), picturePoints, pictureThresholds (rmse, flip); each optional.
    /// </summary>
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

            Scheme = GradingScheme.Read(root, path);
        }
        catch (GradingFileException e)
        {
            throw new UsageException($"--checks: {e.Message}");
        }
        catch (Exception e) when (e is JsonException or InvalidOperationException)
        {
            throw new UsageException($"--checks: {path}: {e.Message}");
        }
    }

    /// <summary>The submissions' folder: the folder given, or a Moodle download's zip unpacked safely into the grader's work.</summary>
    private static string SubmissionsFolder(string path, string work)
    {
        if (!File.Exists(path) || !path.EndsWith(".zip", StringComparison.OrdinalIgnoreCase))
        {
            return Folder(path, "submissions");
        }

        string download = Path.Combine(work, "download");
        try
        {
            SafeZip.Extract(path, download, DownloadLimits);
        }
        catch (ZipRefusedException e)
        {
            throw new UsageException($"submissions: {path}: zip refused: {e.Message}");
        }

        return download;
    }

    /// <summary>The most a class's download may unpack to: 8 GiB, 500 000 entries (each student's zip is unpacked later, with its own limits).</summary>
    private static readonly ZipLimits DownloadLimits = new(8L << 30, 500_000);

    private static MoodleWorksheet? ReadWorksheet(string? path)
    {
        if (path is null)
        {
            return null;
        }

        if (!File.Exists(path))
        {
            throw new UsageException(Directory.Exists(path) ? $"--moodle-worksheet: '{path}' is a folder; give the worksheet's CSV file" : $"--moodle-worksheet: no such file '{path}'");
        }

        try
        {
            return MoodleWorksheet.Read(path);
        }
        catch (MoodleWorksheetException e)
        {
            throw new UsageException($"--moodle-worksheet: {e.Message}");
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
