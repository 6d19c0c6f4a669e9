namespace RayLab.Web.Lab;

/// <summary>The repository's scene files (samples/scenes), embedded in the assembly as they are.</summary>
internal static class Presets
{
    /// <summary>The presets' names, in the order the page lists them.</summary>
    public static IReadOnlyList<string> Names { get; } = ["two-spheres", "off-axis", "low-contrast", "sphere-field"];

    /// <summary>The preset's JSON text, or null for an unknown name.</summary>
    public static string? Text(string name)
    {
        if (!Names.Contains(name))
        {
            return null;
        }

        using Stream? stream = typeof(Presets).Assembly.GetManifestResourceStream($"scenes/{name}.json");
        if (stream is null)
        {
            return null;
        }

        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }
}
