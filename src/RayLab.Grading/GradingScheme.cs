using System.Globalization;
using System.Text.Json;

namespace RayLab.Grading;

/// <summary>A value of the checks' grading.json that is wrong: the file, the field and what is wrong, in one line.</summary>
public sealed class GradingFileException : Exception
{
    /// <summary>A bad value.</summary>
    /// <param name="file">The file.</param>
    /// <param name="field">The field, as a path (<c>points.3.1</c>).</param>
    /// <param name="problem">What is wrong.</param>
    public GradingFileException(string file, string field, string problem)
        : base($"{file}: {field}: {problem}")
    {
        File = file;
        Field = field;
    }

    /// <summary>A bad file.</summary>
    public GradingFileException()
        : this("grading.json", "(root)", "not valid")
    {
    }

    /// <summary>A bad file, with a message of its own.</summary>
    /// <param name="message">What is wrong.</param>
    public GradingFileException(string message)
        : base(message)
    {
        File = "grading.json";
        Field = "(root)";
    }

    /// <summary>A bad file, with a message of its own and its cause.</summary>
    /// <param name="message">What is wrong.</param>
    /// <param name="innerException">The cause.</param>
    public GradingFileException(string message, Exception innerException)
        : base(message, innerException)
    {
        File = "grading.json";
        Field = "(root)";
    }

    /// <summary>The file.</summary>
    public string File { get; }

    /// <summary>The field.</summary>
    public string Field { get; }
}

/// <summary>
/// How a submission's grade is counted, from grading.json: <c>points</c> (section → points; without it every section
/// is worth 1), <c>picturePoints</c> (points for each picture that meets both thresholds; 0 without it) and
/// <c>pictureThresholds</c> (<c>rmse</c> in 8-bit levels, default 2; <c>flip</c>, the mean FLIP, default 0.05). The
/// grade is the sum of the points of the sections that pass and of the pictures that meet the thresholds.
/// </summary>
public sealed record GradingScheme
{
    /// <summary>Every section worth 1 point, the pictures none.</summary>
    public static GradingScheme Default { get; } = new(null, 0, 2, 0.05);

    /// <summary>A scheme.</summary>
    /// <param name="sectionPoints">Each section's points (≥ 0), or null for 1 each.</param>
    /// <param name="picturePoints">The points of each picture that meets both thresholds, ≥ 0.</param>
    /// <param name="maxRmse">The most RMSE (8-bit levels) a picture may have, &gt; 0.</param>
    /// <param name="maxFlip">The most mean FLIP a picture may have, in (0, 1].</param>
    /// <exception cref="ArgumentOutOfRangeException">A value out of its range.</exception>
    public GradingScheme(IReadOnlyDictionary<string, double>? sectionPoints, double picturePoints, double maxRmse, double maxFlip)
    {
        if (sectionPoints is not null)
        {
            foreach ((string section, double points) in sectionPoints)
            {
                if (!double.IsFinite(points) || points < 0)
                {
                    throw new ArgumentOutOfRangeException(nameof(sectionPoints), points, $"section {section}: expected points ≥ 0");
                }
            }
        }

        if (!double.IsFinite(picturePoints) || picturePoints < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(picturePoints), picturePoints, "expected points ≥ 0");
        }

        if (!double.IsFinite(maxRmse) || maxRmse <= 0)
        {
            throw new ArgumentOutOfRangeException(nameof(maxRmse), maxRmse, "expected levels > 0");
        }

        if (!double.IsFinite(maxFlip) || maxFlip <= 0 || maxFlip > 1)
        {
            throw new ArgumentOutOfRangeException(nameof(maxFlip), maxFlip, "expected a mean FLIP in (0, 1]");
        }

        SectionPoints = sectionPoints is null ? null : new SortedDictionary<string, double>(sectionPoints.ToDictionary(), StringComparer.Ordinal);
        PicturePoints = picturePoints;
        MaxRmse = maxRmse;
        MaxFlip = maxFlip;
    }

    /// <summary>Each section's points, or null for 1 each.</summary>
    public IReadOnlyDictionary<string, double>? SectionPoints { get; }

    /// <summary>The points of each picture that meets both thresholds.</summary>
    public double PicturePoints { get; }

    /// <summary>The most RMSE (8-bit levels) a picture may have.</summary>
    public double MaxRmse { get; }

    /// <summary>The most mean FLIP a picture may have.</summary>
    public double MaxFlip { get; }

    /// <summary>Reads the scheme from grading.json's root object; every key is optional.</summary>
    /// <param name="root">The file's root.</param>
    /// <param name="file">The file's path, for the errors.</param>
    /// <returns>The scheme.</returns>
    /// <exception cref="GradingFileException">A value of the wrong type or out of its range, naming the file and the field.</exception>
    public static GradingScheme Read(JsonElement root, string file)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(file);
        if (root.ValueKind != JsonValueKind.Object)
        {
            throw new GradingFileException(file, "(root)", $"expected an object, got {Kind(root)}");
        }

        Dictionary<string, double>? sections = null;
        if (root.TryGetProperty("points", out JsonElement points))
        {
            if (points.ValueKind != JsonValueKind.Object)
            {
                throw new GradingFileException(file, "points", $"expected an object of section → points, got {Kind(points)}");
            }

            sections = new Dictionary<string, double>(StringComparer.Ordinal);
            foreach (JsonProperty section in points.EnumerateObject())
            {
                sections[section.Name] = Number(section.Value, file, $"points.{section.Name}", "points ≥ 0", v => v >= 0);
            }
        }

        double picturePoints = root.TryGetProperty("picturePoints", out JsonElement pp)
            ? Number(pp, file, "picturePoints", "points ≥ 0", v => v >= 0)
            : Default.PicturePoints;
        double maxRmse = Default.MaxRmse, maxFlip = Default.MaxFlip;
        if (root.TryGetProperty("pictureThresholds", out JsonElement thresholds))
        {
            if (thresholds.ValueKind != JsonValueKind.Object)
            {
                throw new GradingFileException(file, "pictureThresholds", $"expected an object with rmse and flip, got {Kind(thresholds)}");
            }

            foreach (JsonProperty t in thresholds.EnumerateObject())
            {
                switch (t.Name)
                {
                    case "rmse":
                        maxRmse = Number(t.Value, file, "pictureThresholds.rmse", "8-bit levels > 0", v => v > 0);
                        break;
                    case "flip":
                        maxFlip = Number(t.Value, file, "pictureThresholds.flip", "a mean FLIP in (0, 1]", v => v is > 0 and <= 1);
                        break;
                    default:
                        throw new GradingFileException(file, $"pictureThresholds.{t.Name}", "expected rmse or flip");
                }
            }
        }

        return new GradingScheme(sections, picturePoints, maxRmse, maxFlip);
    }

    /// <summary>The points of a section: its own, or 1 without a <c>points</c> list.</summary>
    /// <param name="section">The section.</param>
    /// <returns>Its points.</returns>
    public double PointsOf(string section)
    {
        ArgumentNullException.ThrowIfNull(section);
        return SectionPoints is null ? 1 : SectionPoints.GetValueOrDefault(section);
    }

    /// <summary>Whether a picture meets both thresholds.</summary>
    /// <param name="rmse">Its RMSE in 8-bit levels (NaN: none).</param>
    /// <param name="flip">Its mean FLIP (NaN: none).</param>
    /// <returns>Whether both are finite and within the thresholds.</returns>
    public bool Meets(double rmse, double flip) =>
        double.IsFinite(rmse) && double.IsFinite(flip) && rmse <= MaxRmse && flip <= MaxFlip;

    /// <summary>The most a submission can get: every section's points (the list's, or 1 for each of <paramref name="sections"/>) and every picture's.</summary>
    /// <param name="sections">The checks' sections.</param>
    /// <param name="pictures">How many pictures are scored.</param>
    /// <returns>The full grade.</returns>
    public double MaxGrade(IEnumerable<string> sections, int pictures)
    {
        ArgumentNullException.ThrowIfNull(sections);
        ArgumentOutOfRangeException.ThrowIfNegative(pictures);
        double sum = SectionPoints is null ? sections.Distinct(StringComparer.Ordinal).Count() : SectionPoints.Values.Sum();
        return sum + (pictures * PicturePoints);
    }

    /// <summary>A submission's grade: the points of the sections that pass, and of the pictures that meet the thresholds.</summary>
    /// <param name="sections">Each section's result (<c>pass</c>, <c>fail</c>, …).</param>
    /// <param name="pictures">Each scored picture's RMSE and mean FLIP (NaN where it has none).</param>
    /// <returns>The grade.</returns>
    public double Grade(IReadOnlyDictionary<string, string> sections, IEnumerable<(double Rmse, double Flip)> pictures)
    {
        ArgumentNullException.ThrowIfNull(sections);
        ArgumentNullException.ThrowIfNull(pictures);
        double sum = sections.Where(s => s.Value == "pass").Sum(s => PointsOf(s.Key));
        return sum + (pictures.Count(p => Meets(p.Rmse, p.Flip)) * PicturePoints);
    }

    private static double Number(JsonElement value, string file, string field, string expected, Func<double, bool> valid)
    {
        if (value.ValueKind != JsonValueKind.Number || !value.TryGetDouble(out double v) || !double.IsFinite(v) || !valid(v))
        {
            throw new GradingFileException(file, field, $"expected {expected}, got {(value.ValueKind == JsonValueKind.Number ? value.GetRawText() : Kind(value))}");
        }

        return v;
    }

    private static string Kind(JsonElement value) => value.ValueKind switch
    {
        JsonValueKind.String => $"the string \"{value.GetString()}\"",
        JsonValueKind.Number => value.GetRawText(),
        _ => value.ValueKind.ToString().ToLower(CultureInfo.InvariantCulture),
    };
}
