using RayLab.Scenes;
using RayLab.Reports.Output;

namespace RayLab.Cli;

/// <summary>
/// The console options that override scene-file fields (<c>--width</c> overrides <c>image.width</c>, …), for
/// <c>raylab render</c> and <c>raylab compare</c> alike; null means "as the scene file says". It applies them and
/// maps a problem in an overridden field back to the option, the one place that knows which option sets which field.
/// </summary>
/// <param name="Width"><c>--width</c>: <c>image.width</c>.</param>
/// <param name="Height"><c>--height</c>: <c>image.height</c>.</param>
/// <param name="Camera"><c>--camera</c>: <c>camera.type</c>.</param>
/// <param name="Sampler"><c>--sampler</c>: <c>sampler.type</c>.</param>
/// <param name="Samples"><c>--samples</c>: <c>sampler.samples</c>.</param>
/// <param name="Seed"><c>--seed</c>: <c>sampler.seed</c>.</param>
/// <param name="MinDepth"><c>--min-depth</c>: <c>sampler.minDepth</c>.</param>
/// <param name="MaxDepth"><c>--max-depth</c>: <c>sampler.maxDepth</c>.</param>
/// <param name="Contrast"><c>--contrast</c>: <c>sampler.contrast</c>.</param>
/// <param name="Quincunx"><c>--quincunx</c>: <c>sampler.quincunx</c> (only ever turns it on).</param>
/// <param name="Guard"><c>--guard</c>: <c>sampler.guard</c> (only ever turns it on).</param>
internal sealed record SceneOverrides(
    int? Width = null, int? Height = null, string? Camera = null, string? Sampler = null, int? Samples = null,
    uint? Seed = null, int? MinDepth = null, int? MaxDepth = null, double? Contrast = null, bool Quincunx = false, bool Guard = false)
{
    /// <summary>The scene with the options applied.</summary>
    public SceneDescription Apply(SceneDescription d)
    {
        SamplerSettings s = d.Sampler;
        return d with
        {
            Width = Width ?? d.Width,
            Height = Height ?? d.Height,
            Camera = d.Camera with { Type = Camera ?? d.Camera.Type },
            Sampler = s with
            {
                Type = Sampler ?? s.Type,
                Samples = Samples ?? s.Samples,
                Seed = Seed ?? s.Seed,
                MinDepth = MinDepth ?? s.MinDepth,
                MaxDepth = MaxDepth ?? s.MaxDepth,
                Contrast = Contrast ?? s.Contrast,
                Quincunx = Quincunx || s.Quincunx,
                Guard = Guard || s.Guard,
            },
        };
    }

    /// <summary>
    /// Applies the options and prepares the scene; a problem in a field an option set is reported as the
    /// option's (<c>--width: …</c>), any other as the scene file's.
    /// </summary>
    /// <exception cref="UsageException">An option's value is out of range or does not fit the scene.</exception>
    /// <exception cref="SceneFileException">A field the options left alone is wrong.</exception>
    public PreparedScene Prepare(SceneDescription d)
    {
        try
        {
            return Apply(d).Prepare();
        }
        catch (SceneFileException e) when (OptionFor(e.Field) is { } option)
        {
            throw new UsageException($"{option}: {e.Problem}");
        }
    }

    /// <summary>
    /// The option that set <paramref name="field"/>; for a whole object (<c>image</c>, whose W·H is too large),
    /// the options that set its fields (<c>--width/--height</c>); null when no option touched it.
    /// </summary>
    public string? OptionFor(string field)
    {
        (string Field, string Option)[] given = [.. Given()];
        if (given.FirstOrDefault(g => g.Field == field).Option is { } option)
        {
            return option;
        }

        string[] inside = [.. given.Where(g => g.Field.StartsWith(field + ".", StringComparison.Ordinal)).Select(g => g.Option)];
        return inside.Length > 0 ? string.Join('/', inside) : null;
    }

    private IEnumerable<(string Field, string Option)> Given()
    {
        if (Width is not null)
        {
            yield return ("image.width", "--width");
        }

        if (Height is not null)
        {
            yield return ("image.height", "--height");
        }

        if (Camera is not null)
        {
            yield return ("camera.type", "--camera");
        }

        if (Sampler is not null)
        {
            yield return ("sampler.type", "--sampler");
        }

        // A sampler chosen on the command line meets the file's sample count: a count it cannot use is fixed with --samples.
        if (Samples is not null || Sampler is not null)
        {
            yield return ("sampler.samples", "--samples");
        }

        if (Seed is not null)
        {
            yield return ("sampler.seed", "--seed");
        }

        if (MinDepth is not null)
        {
            yield return ("sampler.minDepth", "--min-depth");
        }

        if (MaxDepth is not null)
        {
            yield return ("sampler.maxDepth", "--max-depth");
        }

        if (Contrast is not null)
        {
            yield return ("sampler.contrast", "--contrast");
        }

        if (Quincunx)
        {
            yield return ("sampler.quincunx", "--quincunx");
        }

        if (Guard)
        {
            yield return ("sampler.guard", "--guard");
        }
    }
}
