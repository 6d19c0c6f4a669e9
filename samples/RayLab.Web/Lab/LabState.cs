using System.Globalization;
using System.Text;
using RayLab.Scenes;

namespace RayLab.Web.Lab;

/// <summary>
/// Everything the page shows, in one value that the URL holds: the scene (a preset, or edited JSON), the image size,
/// the camera, the method, the view and the inspected pixel. A teacher shares a view by sharing the URL.
/// </summary>
internal sealed record LabState
{
    /// <summary>The preset's name, or <see cref="Custom"/> for JSON typed into the editor.</summary>
    public required string Preset { get; init; }

    /// <summary>The edited scene's JSON when <see cref="Preset"/> is <see cref="Custom"/>, else null.</summary>
    public string? Json { get; init; }

    /// <summary>The image's width in pixels.</summary>
    public required int Width { get; init; }

    /// <summary>The image's height in pixels.</summary>
    public required int Height { get; init; }

    /// <summary>The camera (the scene file's settings: both projections' fields).</summary>
    public required CameraSettings Camera { get; init; }

    /// <summary>The method: a sampler with its count and seed, adaptive with its settings, or exact.</summary>
    public required SamplerSettings Sampler { get; init; }

    /// <summary>Which picture the canvas shows: <c>picture</c>, <c>rays</c> (rays per pixel) or <c>error</c> (against exact).</summary>
    public string View { get; init; } = "picture";

    /// <summary>The loop that renders point samples: <c>Auto</c> (the library's choice), <c>Scalar</c> or <c>Vector128</c>.</summary>
    public RenderKernel Kernel { get; init; } = RenderKernel.Auto;

    /// <summary>The kernels the page offers (the browser's SIMD is 128 bits wide).</summary>
    public static IReadOnlyList<RenderKernel> Kernels { get; } = [RenderKernel.Auto, RenderKernel.Scalar, RenderKernel.Vector128];

    /// <summary>The inspected pixel, if any.</summary>
    public (int X, int Y)? Pick { get; init; }

    /// <summary>The name of an edited scene.</summary>
    public const string Custom = "custom";

    /// <summary>The views, in the order the page lists them.</summary>
    public static IReadOnlyList<string> Views { get; } = ["picture", "rays", "error"];

    /// <summary>The size the page renders unless the URL or an edited scene says otherwise.</summary>
    public const int DefaultWidth = 640, DefaultHeight = 360;

    /// <summary>The scene's JSON text: the preset's or the edited one.</summary>
    public string SceneText => Preset == Custom ? Json ?? "" : Presets.Text(Preset) ?? "";

    /// <summary>The state a preset starts with: its own camera and method at the given size.</summary>
    public static LabState FromPreset(string preset, int width = DefaultWidth, int height = DefaultHeight)
    {
        SceneDescription file = SceneFile.Parse(Presets.Text(preset) ?? throw new ArgumentException($"Unknown preset '{preset}'.", nameof(preset)), preset);
        return new LabState { Preset = preset, Width = width, Height = height, Camera = file.Camera, Sampler = file.Sampler };
    }

    /// <summary>The scene description this state renders (the library checks it in <see cref="SceneDescription.Prepare"/>).</summary>
    public SceneDescription Describe() =>
        SceneFile.Parse(SceneText, Source) with { Width = Width, Height = Height, Camera = Camera, Sampler = Sampler };

    /// <summary>
    /// The scene, camera and method this state renders, checked by the library (<see cref="SceneDescription.Prepare"/>);
    /// the sample project's own methods are checked by their own constructors.
    /// </summary>
    /// <exception cref="SceneFileException">The state is not a scene the library renders: the message names the field.</exception>
    public PreparedScene Prepare()
    {
        try
        {
            if (OwnMethods.IsOwn(Sampler.Type))
            {
                // The library checks everything but the method, which is the sample project's.
                RenderMethod own = OwnMethods.Create(Sampler);
                return (this with { Sampler = SamplerSettings.Default }).Describe().Prepare() with { Method = own };
            }

            return Describe().Prepare();
        }
        catch (ArgumentOutOfRangeException e)
        {
            throw new SceneFileException(Source, "sampler.samples", e.Message.Split('(')[0].Trim());
        }
    }

    /// <summary>The name the library's messages give the scene: the preset's, or <c>editor</c>.</summary>
    public string Source => Preset == Custom ? "editor" : Preset;

    /// <summary>The state as a query string (without the leading <c>?</c>).</summary>
    public string ToQuery()
    {
        var q = new List<(string, string)>
        {
            ("scene", Preset),
            ("w", I(Width)),
            ("h", I(Height)),
            ("cam", Camera.Type),
            ("pos", V(Camera.Position)),
            ("tgt", V(Camera.Target)),
            ("up", V(Camera.Up)),
            ("fov", D(Camera.Fov)),
            ("oh", D(Camera.Height)),
            ("near", D(Camera.Near)),
            ("far", D(Camera.Far)),
            ("dist", D(Camera.Distance)),
        };
        if (Camera.Window is Window w)
        {
            q.Add(("win", string.Join(",", D(w.U0), D(w.V0), D(w.U1), D(w.V1))));
        }

        q.Add(("m", Sampler.Type));
        q.Add(("n", I(Sampler.Samples)));
        q.Add(("seed", Sampler.Seed.ToString(CultureInfo.InvariantCulture)));
        q.Add(("min", I(Sampler.MinDepth)));
        q.Add(("max", I(Sampler.MaxDepth)));
        q.Add(("c", D(Sampler.Contrast)));
        q.Add(("q", Sampler.Quincunx ? "1" : "0"));
        q.Add(("g", Sampler.Guard ? "1" : "0"));
        q.Add(("view", View));
        if (Kernel != RenderKernel.Auto)
        {
            q.Add(("k", Kernel.ToString().ToLowerInvariant()));
        }

        if (Pick is (int px, int py))
        {
            q.Add(("px", $"{I(px)},{I(py)}"));
        }

        if (Preset == Custom && Json is not null)
        {
            q.Add(("json", Convert.ToBase64String(Encoding.UTF8.GetBytes(Json)).TrimEnd('=').Replace('+', '-').Replace('/', '_')));
        }

        return string.Join("&", q.Select(p => $"{p.Item1}={Uri.EscapeDataString(p.Item2)}"));
    }

    /// <summary>
    /// The state a query string describes: the preset's (or the edited scene's) own settings, each overridden by the
    /// query's value where it has a readable one. A value it cannot read is left at the scene's (never a dead page).
    /// </summary>
    public static LabState FromQuery(string query)
    {
        Dictionary<string, string> q = Parse(query);
        string preset = q.GetValueOrDefault("scene") ?? Presets.Names[0];
        LabState state;
        if (preset == Custom && q.TryGetValue("json", out string? encoded) && TryDecode(encoded) is string json)
        {
            try
            {
                SceneDescription file = SceneFile.Parse(json, "editor");
                state = new LabState { Preset = Custom, Json = json, Width = file.Width, Height = file.Height, Camera = file.Camera, Sampler = file.Sampler };
            }
            catch (SceneFileException)
            {
                state = FromPreset(Presets.Names[0]);
            }
        }
        else
        {
            state = FromPreset(Presets.Names.Contains(preset) ? preset : Presets.Names[0]);
        }

        CameraSettings c = state.Camera;
        c = c with
        {
            Type = q.GetValueOrDefault("cam") is string t && CameraSettings.Types.Contains(t) ? t : c.Type,
            Position = Vec(q, "pos") ?? c.Position,
            Target = Vec(q, "tgt") ?? c.Target,
            Up = Vec(q, "up") ?? c.Up,
            Fov = Num(q, "fov") ?? c.Fov,
            Height = Num(q, "oh") ?? c.Height,
            Near = Num(q, "near") ?? c.Near,
            Far = Num(q, "far") ?? c.Far,
            Distance = Num(q, "dist") ?? c.Distance,
            Window = q.TryGetValue("win", out string? win) ? Win(win) : (q.ContainsKey("cam") ? null : c.Window),
        };
        SamplerSettings s = state.Sampler;
        s = s with
        {
            Type = q.GetValueOrDefault("m") is string m && (SamplerSettings.Types.Contains(m) || OwnMethods.IsOwn(m)) ? m : s.Type,
            Samples = (int?)Num(q, "n") ?? s.Samples,
            Seed = q.TryGetValue("seed", out string? seed) && uint.TryParse(seed, NumberStyles.None, CultureInfo.InvariantCulture, out uint sd) ? sd : s.Seed,
            MinDepth = (int?)Num(q, "min") ?? s.MinDepth,
            MaxDepth = (int?)Num(q, "max") ?? s.MaxDepth,
            Contrast = Num(q, "c") ?? s.Contrast,
            Quincunx = q.TryGetValue("q", out string? qu) ? qu == "1" : s.Quincunx,
            Guard = q.TryGetValue("g", out string? gu) ? gu == "1" : s.Guard,
        };
        (int X, int Y)? pick = q.TryGetValue("px", out string? px) && Ints(px) is [int x, int y] ? (x, y) : null;
        int width = (int?)Num(q, "w") is int wv and >= 1 and <= 4096 ? wv : state.Width;
        int height = (int?)Num(q, "h") is int hv and >= 1 and <= 4096 ? hv : state.Height;
        return state with
        {
            Width = width,
            Height = height,
            Camera = c,
            Sampler = s,
            View = q.GetValueOrDefault("view") is string v && Views.Contains(v) ? v : "picture",
            Kernel = q.TryGetValue("k", out string? k) && Enum.TryParse(k, ignoreCase: true, out RenderKernel kernel) && Kernels.Contains(kernel) ? kernel : RenderKernel.Auto,
            Pick = pick is (int a, int b) && a < width && b < height ? pick : null,
        };
    }

    private static Dictionary<string, string> Parse(string query)
    {
        var result = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string part in query.TrimStart('?').Split('&', StringSplitOptions.RemoveEmptyEntries))
        {
            int eq = part.IndexOf('=', StringComparison.Ordinal);
            if (eq > 0)
            {
                result[Uri.UnescapeDataString(part[..eq])] = Uri.UnescapeDataString(part[(eq + 1)..].Replace('+', ' '));
            }
        }

        return result;
    }

    private static string? TryDecode(string text)
    {
        try
        {
            string b64 = text.Replace('-', '+').Replace('_', '/');
            b64 += new string('=', (4 - (b64.Length % 4)) % 4);
            return Encoding.UTF8.GetString(Convert.FromBase64String(b64));
        }
        catch (FormatException)
        {
            return null;
        }
    }

    private static double? Num(Dictionary<string, string> q, string key) =>
        q.TryGetValue(key, out string? s) && double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) && double.IsFinite(d) ? d : null;

    private static double[]? Numbers(string text)
    {
        string[] parts = text.Split(',');
        var values = new double[parts.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            if (!double.TryParse(parts[i], NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) || !double.IsFinite(values[i]))
            {
                return null;
            }
        }

        return values;
    }

    private static int[]? Ints(string text) => Numbers(text) is double[] d && d.All(v => v >= 0 && v == Math.Floor(v) && v < int.MaxValue) ? [.. d.Select(v => (int)v)] : null;

    private static Double3? Vec(Dictionary<string, string> q, string key) =>
        q.TryGetValue(key, out string? s) && Numbers(s) is [double x, double y, double z] ? new Double3(x, y, z) : null;

    private static Window? Win(string text) => Numbers(text) is [double u0, double v0, double u1, double v1] ? new Window(u0, v0, u1, v1) : null;

    internal static string D(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static string I(int value) => value.ToString(CultureInfo.InvariantCulture);

    private static string V(Double3 v) => $"{D(v.X)},{D(v.Y)},{D(v.Z)}";
}
