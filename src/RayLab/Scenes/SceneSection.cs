namespace RayLab.Scenes;

/// <summary>
/// One object of a scene file (<c>image</c>, <c>camera</c>, <c>sampler</c>, <c>spheres[i]</c>): its JSON path, its
/// fields, and which of them a type's <see cref="ArgumentException"/> is about. The types check their own
/// arguments; the reader builds each object inside its section, so an error names the JSON path it came from.
/// </summary>
/// <param name="path">The section's JSON path.</param>
/// <param name="fields">The JSON fields the section allows.</param>
/// <param name="alias">
/// The field a parameter name stands for where the two are spelled differently (a camera's <c>NearPlane</c> is
/// <c>near</c>), or null; a parameter spelled like a field (ignoring case) needs none.
/// </param>
internal sealed class SceneSection(string path, IReadOnlyList<string> fields, Func<string, string?>? alias = null)
{
    /// <summary>The top-level fields of a scene file.</summary>
    public static IReadOnlyList<string> RootFields { get; } = ["image", "background", "ambient", "camera", "spheres", "sampler", "acceleration"];

    /// <summary>The <c>image</c> object: <see cref="RayLab.Image.CheckSize"/> names <c>width</c> and <c>height</c>.</summary>
    public static SceneSection Image { get; } = new("image", ["width", "height"]);

    /// <summary>The <c>camera</c> object, whose errors name camera properties (<see cref="CameraSettings.FieldOf"/>).</summary>
    public static SceneSection Camera { get; } = new("camera", CameraSettings.Fields, CameraSettings.FieldOf);

    /// <summary>The <c>sampler</c> object, whose errors name parameters of the samplers' constructors.</summary>
    public static SceneSection Sampler { get; } = new("sampler", SamplerSettings.Fields, SamplerSettings.FieldOf);

    /// <summary>The JSON path, e.g. <c>camera</c> or <c>spheres[2]</c>.</summary>
    public string Path => path;

    /// <summary>The JSON fields the section allows.</summary>
    public IReadOnlyList<string> Fields => fields;

    /// <summary>Sphere <paramref name="index"/> of the <c>spheres</c> array (its constructor names <c>center</c> and <c>radius</c>).</summary>
    /// <param name="index">The sphere's index in the file.</param>
    public static SceneSection Sphere(int index) => new($"spheres[{index}]", ["center", "radius", "color"]);

    /// <summary>
    /// The JSON path of the field <paramref name="parameterName"/> stands for: through the alias, else the field
    /// spelled the same (ignoring case); the section itself when neither, never a guess at another field.
    /// </summary>
    /// <param name="parameterName">An exception's <see cref="ArgumentException.ParamName"/>, or null.</param>
    public string FieldOf(string? parameterName)
    {
        if (parameterName is null)
        {
            return path;
        }

        string? field = alias?.Invoke(parameterName) ?? fields.FirstOrDefault(f => string.Equals(f, parameterName, StringComparison.OrdinalIgnoreCase));
        return field is null || !fields.Contains(field, StringComparer.Ordinal) ? path : Join(path, field);
    }

    /// <summary>Runs <paramref name="create"/>, reporting a type's <see cref="ArgumentException"/> as an error in this section.</summary>
    /// <typeparam name="T">What is built.</typeparam>
    /// <param name="source">The scene file, for the message.</param>
    /// <param name="create">Builds (and so checks) the section's object.</param>
    /// <returns>What <paramref name="create"/> returned.</returns>
    /// <exception cref="SceneFileException">The type rejected an argument: naming the file, the field and the type's message.</exception>
    public T Build<T>(string source, Func<T> create)
    {
        try
        {
            return create();
        }
        catch (ArgumentException e)
        {
            throw Error(source, e);
        }
    }

    /// <summary>Runs <paramref name="check"/>, reporting a type's <see cref="ArgumentException"/> as an error in this section.</summary>
    /// <param name="source">The scene file, for the message.</param>
    /// <param name="check">Builds (and so checks) the section's objects.</param>
    /// <exception cref="SceneFileException">The type rejected an argument: naming the file, the field and the type's message.</exception>
    public void Build(string source, Action check) => Build(source, () =>
    {
        check();
        return true;
    });

    /// <summary>A type's <see cref="ArgumentException"/> as an error naming the file and the field its parameter stands for.</summary>
    /// <param name="source">The scene file.</param>
    /// <param name="e">The type's exception.</param>
    public SceneFileException Error(string source, ArgumentException e) => new(source, FieldOf(e.ParamName), FirstLine(e.Message), e);

    /// <summary>A child path: <c>camera</c> + <c>fov</c> → <c>camera.fov</c>; the root's children are bare names.</summary>
    /// <param name="parent">The parent's path, empty for the root.</param>
    /// <param name="name">The field.</param>
    public static string Join(string parent, string name) => parent.Length == 0 ? name : $"{parent}.{name}";

    // ArgumentException appends " (Parameter 'x')" and an out-of-range one "Actual value was …" on a new line:
    // the field name already says the first, the type's own message the second.
    private static string FirstLine(string message)
    {
        int end = message.IndexOfAny(['\r', '\n']);
        string line = end >= 0 ? message[..end] : message;
        int at = line.IndexOf(" (Parameter '", StringComparison.Ordinal);
        return at >= 0 ? line[..at] : line;
    }
}
