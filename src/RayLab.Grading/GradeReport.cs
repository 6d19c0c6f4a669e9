using System.Globalization;
using System.Net;
using System.Text;
using System.Text.Json;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Grading;

/// <summary>
/// What every submission is measured against, computed once by RayLab from the checks' scene file (the lab's
/// scenes/two-spheres.json, which holds both cameras' settings and the lab's adaptive rule, depth 0–3, contrast 0.05):
/// each camera's exact image and the rays per pixel the lab's adaptive rule takes on it: for the exercise lab as its
/// students write it (every pixel on its own, with its centre), for the method lab as RayLab renders it (corners shared).
/// </summary>
internal sealed class GradeReference
{
    public Dictionary<string, Image> Exact { get; } = new(StringComparer.Ordinal);

    public Dictionary<string, double> AdaptiveRaysPerPixel { get; } = new(StringComparer.Ordinal);

    public static GradeReference Create(GradeSetup setup)
    {
        var reference = new GradeReference();
        SceneDescription d = setup.Scene;
        var renderer = new Renderer();
        foreach (string camera in setup.Pictures.Keys)
        {
            PreparedScene prepared = (d with { Camera = d.Camera with { Type = camera } }).Prepare();
            var exact = new Image(d.Width, d.Height);
            renderer.Render(d.Scene, prepared.Camera, RenderMethod.Exact, exact);
            reference.Exact[camera] = exact;
            reference.AdaptiveRaysPerPixel[camera] = setup.Kind == "exercise" && d.Sampler.IsAdaptive
                ? RaysPerPixelAlone(d, prepared.Camera, new AdaptiveSampler(d.Sampler.MinDepth, d.Sampler.MaxDepth, d.Sampler.Contrast, quincunx: true, d.Sampler.Guard))
                : (double)renderer.Render(d.Scene, prepared.Camera, prepared.Method, new Image(d.Width, d.Height)).PrimaryRays / (d.Width * d.Height);
        }

        return reference;
    }

    /// <summary>
    /// The rays per pixel of the lab's rule as the exercise lab writes it (its check 4.1.4): each pixel traced on its own,
    /// with its centre (the quincunx A, B, C, D, E), sharing no point with its neighbours, where RayLab's adaptive
    /// renderer shares the pixels' corners and traces a centre only where they disagree.
    /// </summary>
    private static double RaysPerPixelAlone(SceneDescription d, Camera camera, AdaptiveSampler rule)
    {
        RenderMethod method = RenderMethod.Adaptive(rule);
        long rays = 0;
        Parallel.For(0, d.Height, () => 0L, (y, _, sum) =>
        {
            for (int x = 0; x < d.Width; x++)
            {
                sum += Renderer.TracePixel(d.Scene, camera, d.Width, d.Height, method, x, y).Points.Count;
            }

            return sum;
        }, sum => Interlocked.Add(ref rays, sum));
        return (double)rays / (d.Width * d.Height);
    }

    public void Save(string staging)
    {
        Directory.CreateDirectory(Path.Combine(staging, "exact"));
        foreach ((string camera, Image image) in Exact)
        {
            image.Save(Path.Combine(staging, "exact", $"{camera}.png"));
        }
    }
}

/// <summary>The class table: grades.csv, grades.json (for a gradebook) and index.html (with the pictures).</summary>
internal static class GradeReport
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>The outcomes the CSV counts, in the order of its columns "checks passed" … "checks not run".</summary>
    private static readonly string[] CountedOutcomes = ["Passed", "Failed", "Timeout", "Crashed", "NotRun", "Skipped"];

    public static void Write(string staging, GradeSetup setup, GradeReference reference, IReadOnlyList<StudentRow> rows, bool sandboxed)
    {
        string[] sections = [.. rows.SelectMany(r => r.Checks.Keys).Select(GradeJob.SectionOf).Distinct().Order(SectionOrder.Instance)];
        string[] cameras = [.. setup.Pictures.Keys];
        foreach (StudentRow row in rows)
        {
            row.Grade = GradeMarks.Grade(setup, row, sections, cameras);
        }

        File.WriteAllText(Path.Combine(staging, "grades.csv"), Csv(rows, sections, cameras, reference));
        File.WriteAllText(Path.Combine(staging, "grades.json"), Json(setup, rows, sections, cameras, reference, sandboxed));
        File.WriteAllText(Path.Combine(staging, "index.html"), Html(setup, rows, sections, cameras, reference, sandboxed));
    }

    private static string Csv(IReadOnlyList<StudentRow> rows, string[] sections, string[] cameras, GradeReference reference)
    {
        var csv = new StringBuilder();
        var header = new List<string> { "student", "status", "grade" };
        header.AddRange(sections);
        header.AddRange(["checks passed", "checks failed", "checks timed out", "checks crashed", "checks not run", "checks not written"]);
        foreach (string c in cameras)
        {
            header.AddRange([$"{c} rmse", $"{c} flip", $"{c} rays per pixel (the program's own line)", $"{c} lab adaptive rays per pixel"]);
        }

        header.AddRange(["program seconds (the grader's clock)", "seconds", "detail"]);
        csv.AppendLine(string.Join(',', header.Select(GradeCsv.Cell)));
        foreach (StudentRow row in rows)
        {
            var cells = new List<string> { row.Name, row.Status, row.Grade.ToString("0.##", Inv) };
            cells.AddRange(sections.Select(row.Section));
            cells.AddRange([.. CountedOutcomes.Select(o => row.Count(o).ToString(Inv))]);
            foreach (string c in cameras)
            {
                PictureScore? p = row.Pictures.GetValueOrDefault(c);
                cells.AddRange([Number(p?.Rmse, "F4"), Number(p?.Flip, "F6"), row.LabRaysPerPixel.TryGetValue(c, out double rpp) ? rpp.ToString("F2", Inv) : "",
                    reference.AdaptiveRaysPerPixel[c].ToString("F2", Inv)]);
            }

            cells.AddRange([ProgramSeconds(row) is double program ? program.ToString("F2", Inv) : "", row.Seconds.ToString("F0", Inv), Detail(row) ?? ""]);
            csv.AppendLine(string.Join(',', cells.Select(GradeCsv.Cell)));
        }

        return csv.ToString();
    }

    // Long: grades.json written field by field, in the file's order.
    private static string Json(GradeSetup setup, IReadOnlyList<StudentRow> rows, string[] sections, string[] cameras, GradeReference reference, bool sandboxed)
    {
        using var stream = new MemoryStream();
        using (var json = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
        {
            json.WriteStartObject();
            json.WriteString("kind", setup.Kind);
            json.WriteString("raylabVersion", setup.Version);
            json.WriteString("checks", setup.Checks);
            json.WriteBoolean("sandboxed", sandboxed);
            json.WriteNumber("jobs", setup.Jobs);
            json.WriteNumber("memoryLimitMB", setup.Request.MemoryLimitMegabytes);
            json.WriteNumber("maxGrade", GradeMarks.MaxGrade(setup, sections, cameras));
            json.WriteStartArray("sections");
            foreach (string s in sections)
            {
                json.WriteStringValue(s);
            }

            json.WriteEndArray();
            json.WriteStartObject("reference");
            foreach (string c in cameras)
            {
                json.WriteStartObject(c);
                json.WriteString("exact", $"exact/{c}.png");
                json.WriteNumber("labAdaptiveRaysPerPixel", Math.Round(reference.AdaptiveRaysPerPixel[c], 4));
                json.WriteEndObject();
            }

            json.WriteEndObject();
            json.WriteStartArray("students");
            foreach (StudentRow row in rows)
            {
                json.WriteStartObject();
                json.WriteString("name", row.Name);
                json.WriteString("status", row.Status);
                json.WriteNumber("grade", row.Grade);
                if (row.ParticipantId is not null)
                {
                    json.WriteString("moodleParticipant", row.ParticipantId);
                }

                json.WriteStartArray("problems");
                foreach (string p in row.Problems.Distinct())
                {
                    json.WriteStringValue(p);
                }

                json.WriteEndArray();
                if (Detail(row) is { } detail)
                {
                    json.WriteString("detail", detail);
                }

                // What the grader did about the machine rather than the lab: checks run again after a run that recorded nothing.
                json.WriteStartArray("notes");
                foreach (string note in row.Notes)
                {
                    json.WriteStringValue(note);
                }

                json.WriteEndArray();

                // What the lab uses that the checks' list refuses: each line fails the sections it starts with.
                json.WriteStartArray("uses");
                foreach (string use in row.Uses)
                {
                    json.WriteStringValue(use);
                }

                json.WriteEndArray();
                json.WriteStartObject("sections");
                foreach (string s in sections)
                {
                    string result = row.Section(s);
                    if (result.Length == 0)
                    {
                        json.WriteNull(s);
                    }
                    else
                    {
                        json.WriteString(s, result);
                    }
                }

                json.WriteEndObject();
                json.WriteStartArray("checks");
                foreach ((string display, string outcome) in row.Checks)
                {
                    json.WriteStartObject();
                    json.WriteString("name", display);
                    json.WriteString("section", GradeJob.SectionOf(display));
                    json.WriteString("outcome", outcome);
                    json.WriteEndObject();
                }

                json.WriteEndArray();
                json.WriteStartObject("pictures");
                foreach (string c in cameras)
                {
                    json.WritePropertyName(c);
                    if (!row.Pictures.TryGetValue(c, out PictureScore? p))
                    {
                        json.WriteNullValue();
                        continue;
                    }

                    json.WriteStartObject();
                    if (p.Problem is null)
                    {
                        json.WriteNumber("rmse", Math.Round(p.Rmse, 4));
                        json.WriteNumber("flip", Math.Round(p.Flip, 6));
                        json.WriteString("picture", $"students/{row.Folder}/{c}.png");
                        json.WriteString("flipMap", $"students/{row.Folder}/{c}-flip.png");
                    }
                    else
                    {
                        json.WriteString("problem", p.Problem);
                    }

                    json.WriteEndObject();
                }

                json.WriteEndObject();
                if (ProgramSeconds(row) is double program)
                {
                    json.WriteStartObject("program");
                    json.WriteNumber("seconds", Math.Round(program, 2));
                    json.WriteString("timedBy", row.ProgramTimedBy);
                    json.WriteEndObject();
                }

                json.WriteStartObject("labReport");
                json.WriteString("method", setup.TimedMethod);
                json.WriteString("source", LabReportSource);
                foreach ((string c, double rpp) in row.LabRaysPerPixel.OrderBy(t => t.Key, StringComparer.Ordinal))
                {
                    json.WriteStartObject(c);
                    json.WriteNumber("raysPerPixel", rpp);
                    json.WriteEndObject();
                }

                json.WriteEndObject();
                json.WriteNumber("seconds", Math.Round(row.Seconds, 1));
                json.WriteStartObject("steps");
                foreach ((string step, double seconds) in row.Steps)
                {
                    json.WriteNumber(step, Math.Round(seconds, 1));
                }

                json.WriteEndObject();
                if (row.ProgramStart is double start)
                {
                    json.WriteNumber("programStart", Math.Round(start, 1));
                }

                json.WriteString("log", $"students/{row.Folder}/log.txt");
                json.WriteEndObject();
            }

            json.WriteEndArray();
            json.WriteEndObject();
        }

        return Encoding.UTF8.GetString(stream.ToArray()) + "\n";
    }

    // Long: index.html written element by element, in the page's order.
    private static string Html(GradeSetup setup, IReadOnlyList<StudentRow> rows, string[] sections, string[] cameras, GradeReference reference, bool sandboxed)
    {
        static string E(string text) => WebUtility.HtmlEncode(text);
        var html = new StringBuilder();
        html.AppendLine("<!DOCTYPE html>");
        html.AppendLine("<html lang=\"en\"><head><meta charset=\"utf-8\"><title>RayLab grades</title><style>");
        html.AppendLine("body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.25em .5em;text-align:center}"
            + "td.pass{background:#d8f5d0}td.fail{background:#f8d0d0}td.timeout,td.crashed,td.not-run{background:#f8e8b0}td.not-written{background:#e8e8e8}td.l{text-align:left}"
            + "figure{display:inline-block;margin:.3em}figure img{width:320px;image-rendering:pixelated}figcaption{font-size:.85em}");
        html.AppendLine("</style></head><body>");
        html.AppendLine($"<h1>RayLab grades: the {E(setup.Kind)} lab</h1>");
        html.AppendLine($"<p>{rows.Count} submissions, checks from <code>{E(setup.Checks)}</code> (RayLab {E(setup.Version)}), "
            + (sandboxed ? "each run in bubblewrap (no network, read-only system)." : "<strong>run without a sandbox (--unsafe-no-sandbox)</strong>.")
            + " Pictures: RMSE in 8-bit levels and mean FLIP against the exact image, read back from each lab's copy as untrusted (no link followed, the size capped, the header checked before decoding)."
            + " Program s: the grader's own clock around the lab's built program, started directly (not through <code>dotnet run</code>)."
            + $" Rays per pixel of <code>{E(setup.TimedMethod)}</code>: as the program's own lines claim them, unchecked here (the checks count rays themselves), beside the rays of the lab's adaptive rule."
            + (setup.Jobs == 1 ? " Built, checked and run one at a time."
                : string.Create(CultureInfo.InvariantCulture, $" Built and checked {setup.Jobs} at a time; the programs ran one at a time."))
            + string.Create(CultureInfo.InvariantCulture, $" Each process held at most {setup.Request.MemoryLimitMegabytes} MB of managed memory.")
            + " The last column is each submission's own seconds.</p>");
        html.AppendLine(CultureInfo.InvariantCulture, $"<table><tr><th>student</th><th>status</th><th>grade<br>(of {GradeMarks.MaxGrade(setup, sections, cameras).ToString("0.##", Inv)})</th>");
        foreach (string s in sections)
        {
            html.Append(CultureInfo.InvariantCulture, $"<th>{E(s)}</th>");
        }

        foreach (string c in cameras)
        {
            html.Append(CultureInfo.InvariantCulture, $"<th>{E(c)}<br>RMSE / FLIP</th><th>{E(c)}<br>rays/px, the program's own line (lab rule {reference.AdaptiveRaysPerPixel[c].ToString("F2", Inv)})</th>");
        }

        html.AppendLine("<th>program s<br>(grader's clock)</th><th>s</th></tr>");
        foreach (StudentRow row in rows)
        {
            html.Append(CultureInfo.InvariantCulture, $"<tr><td class=\"l\"><a href=\"#{E(row.Folder)}\">{E(row.Name)}</a></td><td class=\"l\">{E(row.Status)}</td><td>{row.Grade.ToString("0.##", Inv)}</td>");
            foreach (string s in sections)
            {
                string r = row.Section(s);
                html.Append(CultureInfo.InvariantCulture, $"<td class=\"{r.Replace(' ', '-')}\">{(r.Length == 0 ? "—" : r)}</td>");
            }

            foreach (string c in cameras)
            {
                PictureScore? p = row.Pictures.GetValueOrDefault(c);
                string score = p is null ? "—" : p.Problem is null ? $"{p.Rmse.ToString("F3", Inv)} / {p.Flip.ToString("F4", Inv)}" : E(p.Problem);
                string rays = row.LabRaysPerPixel.TryGetValue(c, out double rpp) ? rpp.ToString("F2", Inv) : "—";
                html.Append(CultureInfo.InvariantCulture, $"<td>{score}</td><td>{rays}</td>");
            }

            string program = ProgramSeconds(row) is double seconds ? seconds.ToString("F2", Inv) : "—";
            html.AppendLine(CultureInfo.InvariantCulture, $"<td>{program}</td><td>{row.Seconds.ToString("F0", Inv)}</td></tr>");
        }

        html.AppendLine("</table>");
        foreach (StudentRow row in rows)
        {
            html.AppendLine(CultureInfo.InvariantCulture, $"<h2 id=\"{E(row.Folder)}\">{E(row.Name)}: {E(row.Status)}</h2>");
            if (Detail(row) is { } detail)
            {
                html.AppendLine(CultureInfo.InvariantCulture, $"<pre>{E(detail)}</pre>");
            }

            foreach (string note in row.Notes)
            {
                html.AppendLine(CultureInfo.InvariantCulture, $"<p>Note: {E(note)}.</p>");
            }

            if (row.ProgramTimedBy is not null)
            {
                html.AppendLine(CultureInfo.InvariantCulture, $"<p>Program: {E(row.ProgramTimedBy)}.</p>");
            }

            if (row.Uses.Count > 0)
            {
                html.AppendLine("<p>Uses what the lab may not (each fails the sections it names):</p><ul>");
                foreach (string use in row.Uses)
                {
                    html.AppendLine(CultureInfo.InvariantCulture, $"<li>{E(use)}</li>");
                }

                html.AppendLine("</ul>");
            }

            string notPassed = string.Join(", ", row.Checks.Where(c => c.Value != "Passed").Select(c => $"{E(c.Key)}: {E(c.Value)}").DefaultIfEmpty(row.Checks.Count == 0 ? "none ran" : "all passed"));
            html.AppendLine(CultureInfo.InvariantCulture, $"<p><a href=\"students/{E(row.Folder)}/log.txt\">log</a> (build, checks, program). Checks: {notPassed}</p>");
            foreach (string c in cameras)
            {
                if (row.Pictures.TryGetValue(c, out PictureScore? p) && p.Problem is null)
                {
                    html.AppendLine(CultureInfo.InvariantCulture, $"<figure><img src=\"students/{E(row.Folder)}/{c}.png\" alt=\"{E(row.Name)}, {c}\"><figcaption>{E(row.Name)}, {c}</figcaption></figure>");
                    html.AppendLine(CultureInfo.InvariantCulture, $"<figure><img src=\"students/{E(row.Folder)}/{c}-flip.png\" alt=\"FLIP map\"><figcaption>FLIP map (black: no visible difference), mean {p.Flip.ToString("F4", Inv)}</figcaption></figure>");
                    html.AppendLine(CultureInfo.InvariantCulture, $"<figure><img src=\"exact/{c}.png\" alt=\"exact, {c}\"><figcaption>exact, {c}</figcaption></figure><br>");
                }
            }
        }

        html.AppendLine("</body></html>");
        return html.ToString();
    }

    private static string Number(double? value, string format) =>
        value is { } v && double.IsFinite(v) ? v.ToString(format, Inv) : "";

    /// <summary>What the report says of the rays per pixel it shows: the lab's own words.</summary>
    private const string LabReportSource = "the program's own lines: not checked by the grader, not graded (the checks count the rays themselves)";

    /// <summary>The most characters of a row's detail (the lab's own output) the report shows.</summary>
    private const int DetailLimit = 1000;

    /// <summary>The program's seconds by the grader's clock, or null when it did not run.</summary>
    private static double? ProgramSeconds(StudentRow row) =>
        row.ProgramTimedBy is not null && row.Steps.TryGetValue("program", out double seconds) ? seconds : null;

    /// <summary>The row's detail, cut to <see cref="DetailLimit"/> characters with a note that says so.</summary>
    private static string? Detail(StudentRow row) =>
        row.Detail is not { } detail ? null
        : detail.Length <= DetailLimit ? detail
        : string.Create(Inv, $"{detail[..DetailLimit]}… ({detail.Length - DetailLimit:N0} characters more in the log)");

    /// <summary>Section numbers in numeric order (2.1, 2.2, 3, 3.1, …, 4.1.4, 5), then own, then class names.</summary>
    internal sealed class SectionOrder : IComparer<string>
    {
        public static readonly SectionOrder Instance = new();

        public int Compare(string? x, string? y)
        {
            int[]? a = Numbers(x), b = Numbers(y);
            if (a is not null && b is not null)
            {
                for (int i = 0; i < Math.Min(a.Length, b.Length); i++)
                {
                    if (a[i] != b[i])
                    {
                        return a[i].CompareTo(b[i]);
                    }
                }

                return a.Length.CompareTo(b.Length);
            }

            if (a is not null || b is not null)
            {
                return a is not null ? -1 : 1;
            }

            return (x == "own" ? 0 : 1).CompareTo(y == "own" ? 0 : 1) is var own and not 0 ? own : string.CompareOrdinal(x, y);
        }

        private static int[]? Numbers(string? s)
        {
            string[] parts = (s ?? "").Split('.');
            var numbers = new int[parts.Length];
            for (int i = 0; i < parts.Length; i++)
            {
                if (!int.TryParse(parts[i], NumberStyles.None, CultureInfo.InvariantCulture, out int n))
                {
                    return null;
                }

                numbers[i] = n;
            }

            return numbers;
        }
    }
}

/// <summary>The cells of <c>raylab grade</c>'s grades.csv, safe to open in a spreadsheet.</summary>
internal static class GradeCsv
{
    /// <summary>
    /// One cell: a text that starts with <c>=</c>, <c>+</c>, <c>-</c>, <c>@</c>, a tab or a carriage return (which a
    /// spreadsheet takes for a formula: OWASP's CSV injection rule) gets a leading <c>'</c>, then a cell with a comma,
    /// a quote or a line break is quoted as RFC 4180 asks, its quotes doubled.
    /// </summary>
    /// <param name="text">The cell's text: a student's name, a status, the lab's own error lines.</param>
    /// <returns>The cell as written in the file.</returns>
    public static string Cell(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        string cell = text.Length > 0 && text[0] is '=' or '+' or '-' or '@' or '\t' or '\r' ? "'" + text : text;
        return cell.IndexOfAny([',', '"', '\n', '\r']) >= 0 ? $"\"{cell.Replace("\"", "\"\"", StringComparison.Ordinal)}\"" : cell;
    }
}
