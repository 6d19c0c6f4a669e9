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
        : base(field.Length == 0 ? $"{file}: {problem}" : $"{file}: {field}: {problem}", inner)
    {
        File = file;
        Field = field;
        Problem = problem;
    }

    /// <summary>The scene file.</summary>
    public string File { get; }

    /// <summary>The JSON path of the field (empty for the file as a whole).</summary>
    public string Field { get; }

    /// <summary>What was wrong.</summary>
    public string Problem { get; }
}
