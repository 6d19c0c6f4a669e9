namespace RayLab.Scenes;

/// <summary>
/// A scene file could not be used: which file, which field (a JSON path such as <c>camera.fov</c> or
/// <c>spheres[1].radius</c>), and what was wrong. <see cref="Exception.Message"/> is one line:
/// <c>FILE: FIELD: PROBLEM</c>.
/// </summary>
public sealed class SceneFileException : Exception
{
    /// <summary>Creates the exception.</summary>
    /// <param name="file">The scene file.</param>
    /// <param name="field">The JSON path of the field, or an empty string for the file as a whole.</param>
    /// <param name="problem">What was wrong.</param>
    /// <param name="inner">The underlying exception, if any.</param>
    public SceneFileException(string file, string field, string problem, Exception? inner = null)
        : base(Compose(file, field, problem), inner)
    {
        File = file;
        Field = OneLine(field);
        Problem = OneLine(problem);
    }

    /// <summary>The scene file.</summary>
    public string File { get; }

    /// <summary>The JSON path of the field (empty for the file as a whole).</summary>
    public string Field { get; }

    /// <summary>What was wrong.</summary>
    public string Problem { get; }

    /// <summary>
    /// The text with line breaks and other control characters written as escapes (<c>\n</c>, <c>\u0000</c>),
    /// so that a field name or a quoted piece of a broken file cannot split the message over several lines.
    /// </summary>
    /// <param name="text">Any text.</param>
    public static string OneLine(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        if (!text.Any(NeedsEscape))
        {
            return text;
        }

        var s = new System.Text.StringBuilder(text.Length + 8);
        foreach (char c in text)
        {
            _ = c switch
            {
                '\n' => s.Append("\\n"),
                '\r' => s.Append("\\r"),
                '\t' => s.Append("\\t"),
                _ when NeedsEscape(c) => s.Append(System.Globalization.CultureInfo.InvariantCulture, $"\\u{(int)c:X4}"),
                _ => s.Append(c),
            };
        }

        return s.ToString();
    }

    private static bool NeedsEscape(char c) => char.IsControl(c) || c is '\u2028' or '\u2029';

    private static string Compose(string file, string field, string problem)
    {
        ArgumentNullException.ThrowIfNull(file);
        ArgumentNullException.ThrowIfNull(field);
        ArgumentNullException.ThrowIfNull(problem);
        return OneLine(field.Length == 0 ? $"{file}: {problem}" : $"{file}: {field}: {problem}");
    }
}
