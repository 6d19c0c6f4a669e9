using System.Text;
using System.Text.Json;

namespace RayLab.Scenes;

/// <summary>
/// Reads scene files: JSON (comments and trailing commas allowed) with the fields <c>image</c>,
/// <c>background</c>, <c>ambient</c>, <c>camera</c>, <c>spheres</c>, <c>sampler</c> and <c>acceleration</c>; see the README.
/// Strict: a missing required field, a wrong type, a non-finite or out-of-range number and an unknown field
/// are all errors that name the file and the field.
/// </summary>
public static class SceneFile
{
    /// <summary>The largest image width or height a scene (or an override of it) may ask for: 1 048 576.</summary>
    public const int MaxImageSide = 1 << 20;

    /// <summary>The most samples per pixel a scene (or an override of it) may ask for: 65 536.</summary>
    public const int MaxSamples = 1 << 16;

    /// <summary>The values of the optional <c>acceleration</c> field (<see cref="SceneAcceleration"/> in lower case).</summary>
    private static readonly string[] AccelerationNames = [.. Enum.GetNames<SceneAcceleration>().Select(n => n.ToLowerInvariant())];

    private static readonly JsonDocumentOptions Options = new()
    {
        CommentHandling = JsonCommentHandling.Skip,
        AllowTrailingCommas = true,
        MaxDepth = 16,
    };

    private static readonly UTF8Encoding StrictUtf8 = new(encoderShouldEmitUTF8Identifier: false, throwOnInvalidBytes: true);

    /// <summary>Reads and checks a scene file.</summary>
    /// <param name="path">The file.</param>
    /// <exception cref="SceneFileException">The file cannot be read, is not valid JSON, or a field is wrong.</exception>
    public static SceneDescription Load(string path)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new SceneFileException(path, "", $"cannot read the file: {e.Message}", e);
        }

        return Parse(Decode(bytes, path), path);
    }

    /// <summary>
    /// The file's text: UTF-8 (with or without its byte order mark), or UTF-16 after its byte order mark. Bytes that are
    /// not UTF-8 are an error naming the first and where it is, not a JSON error about the replacement character they
    /// would decode to.
    /// </summary>
    private static string Decode(byte[] bytes, string path)
    {
        ReadOnlySpan<byte> b = bytes;
        if (b.StartsWith((ReadOnlySpan<byte>)[0xFF, 0xFE]) || b.StartsWith((ReadOnlySpan<byte>)[0xFE, 0xFF]))
        {
            return (b[0] == 0xFF ? Encoding.Unicode : Encoding.BigEndianUnicode).GetString(b[2..]);
        }

        int skip = b.StartsWith((ReadOnlySpan<byte>)[0xEF, 0xBB, 0xBF]) ? 3 : 0;
        try
        {
            return StrictUtf8.GetString(b[skip..]);
        }
        catch (DecoderFallbackException e)
        {
            string first = e.BytesUnknown is [byte x, ..] ? $"0x{x:X2}" : "a byte";
            throw new SceneFileException(path, "", FormattableString.Invariant(
                $"is not UTF-8 text: {first} at byte {skip + e.Index} cannot be decoded (save the file as UTF-8)"), e);
        }
    }

    /// <summary>Parses and checks scene JSON.</summary>
    /// <param name="json">The JSON text.</param>
    /// <param name="source">A name for the source in messages (a file name).</param>
    /// <exception cref="SceneFileException">The text is not valid JSON, or a field is wrong.</exception>
    public static SceneDescription Parse(string json, string source = "scene")
    {
        ArgumentNullException.ThrowIfNull(json);
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json, Options);
        }
        catch (JsonException e)
        {
            throw new SceneFileException(source, "", $"not valid JSON: {Describe(e, json)}", e);
        }

        using (document)
        {
            var reader = new Reader(source);
            SceneDescription description = reader.ReadRoot(document.RootElement);
            description.Prepare(); // cross-field checks (position = target, near ≥ far, …) with field names
            return description;
        }
    }

    /// <summary>
    /// The parser's message with its position one-based, as an editor shows it: "line 6, column 13" where
    /// System.Text.Json says "LineNumber: 5 | BytePositionInLine: 12" (zero-based, and counted in UTF-8 bytes).
    /// </summary>
    private static string Describe(JsonException e, string json)
    {
        string message = e.Message;
        int at = message.IndexOf(" Path: ", StringComparison.Ordinal);
        at = at >= 0 ? at : message.IndexOf(" LineNumber: ", StringComparison.Ordinal);
        message = (at >= 0 ? message[..at] : message).TrimEnd();
        if (e.LineNumber is not { } line || e.BytePositionInLine is not { } position)
        {
            return message;
        }

        string[] lines = json.Split('\n');
        long column = position;
        if (line < lines.Length)
        {
            byte[] bytes = System.Text.Encoding.UTF8.GetBytes(lines[line].TrimEnd('\r'));
            column = System.Text.Encoding.UTF8.GetCharCount(bytes, 0, (int)Math.Min(position, bytes.Length));
        }

        return string.Create(System.Globalization.CultureInfo.InvariantCulture, $"{message} (line {line + 1}, column {column + 1})");
    }

    /// <summary>Walks the JSON, keeping the path of the current field for messages.</summary>
    private sealed class Reader(string source)
    {
        public SceneDescription ReadRoot(JsonElement root)
        {
            CheckText(root, "");
            JsonElement obj = Object(root, "(root)");
            Only(obj, "", SceneSection.RootFields);

            JsonElement image = Object(Required(obj, "", "image"), "image");
            Only(image, SceneSection.Image);
            int width = Int(Required(image, "image", "width"), "image.width", 1, MaxImageSide);
            int height = Int(Required(image, "image", "height"), "image.height", 1, MaxImageSide);

            Intensity background = Optional(obj, "background") is { } bg ? Color(bg, "background") : Intensity.Black;
            Intensity ambient = Optional(obj, "ambient") is { } am ? Color(am, "ambient") : Intensity.White;
            CameraSettings camera = ReadCamera(Object(Required(obj, "", "camera"), "camera"));

            JsonElement spheresJson = Required(obj, "", "spheres");
            if (spheresJson.ValueKind != JsonValueKind.Array)
            {
                throw Error("spheres", $"must be an array of spheres, got {Describe(spheresJson)}");
            }

            var spheres = new List<Sphere>();
            int index = 0;
            foreach (JsonElement item in spheresJson.EnumerateArray())
            {
                spheres.Add(ReadSphere(item, SceneSection.Sphere(index++)));
            }

            SamplerSettings sampler = Optional(obj, "sampler") is { } s ? ReadSampler(Object(s, "sampler")) : SamplerSettings.Default;
            SceneAcceleration acceleration = Optional(obj, "acceleration") is { } a
                ? Enum.Parse<SceneAcceleration>(Name(a, "acceleration", AccelerationNames), ignoreCase: true)
                : SceneAcceleration.Auto;
            return new SceneDescription(source, width, height, new Scene(spheres, background, ambient) { Acceleration = acceleration }, camera, sampler);
        }

        // The numbers are read as JSON (kind, finiteness); their ranges are the camera's own checks.
        private CameraSettings ReadCamera(JsonElement camera)
        {
            SceneSection section = SceneSection.Camera;
            Only(camera, section);
            string type = Name(Required(camera, "camera", "type"), "camera.type", CameraSettings.Types);
            Double3 position = Vector(Required(camera, "camera", "position"), "camera.position");
            Double3 target = Vector(Required(camera, "camera", "target"), "camera.target");
            Double3 up = Optional(camera, "up") is { } u ? Vector(u, "camera.up") : Double3.UnitY;
            double fov = Optional(camera, "fov") is { } f ? Number(f, "camera.fov") : 60;
            double height = Optional(camera, "height") is { } h ? Number(h, "camera.height") : 2;
            double near = Optional(camera, "near") is { } n ? Number(n, "camera.near") : 1;
            double far = Optional(camera, "far") is { } fa ? Number(fa, "camera.far") : 1000;
            double distance = Optional(camera, "distance") is { } d ? Number(d, "camera.distance") : 1;
            Window? window = null;
            if (Optional(camera, "window") is { } w)
            {
                double[] c = Numbers(w, "camera.window", 4);
                window = new Window(c[0], c[1], c[2], c[3]);
            }

            var settings = new CameraSettings(type, position, target, up, fov, height, near, far, distance, window);
            section.Build(source, settings.Check);
            return settings;
        }

        private Sphere ReadSphere(JsonElement element, SceneSection section)
        {
            string path = section.Path;
            JsonElement sphere = Object(element, path);
            Only(sphere, section);
            Double3 center = Vector(Required(sphere, path, "center"), path + ".center");
            double radius = Number(Required(sphere, path, "radius"), path + ".radius");
            Intensity color = Color(Required(sphere, path, "color"), path + ".color");
            return section.Build(source, () => new Sphere(center, radius, color));
        }

        // The file's own limit on samples is checked here; the depths, the contrast and whether the sampler can
        // use the sample count are the samplers' own checks.
        private SamplerSettings ReadSampler(JsonElement sampler)
        {
            SceneSection section = SceneSection.Sampler;
            Only(sampler, section);
            string type = Name(Required(sampler, "sampler", "type"), "sampler.type", SamplerSettings.Types);
            int samples = Optional(sampler, "samples") is { } s ? Int(s, "sampler.samples", 1, MaxSamples) : 1;
            uint seed = 0;
            if (Optional(sampler, "seed") is { } seedJson)
            {
                if (seedJson.ValueKind != JsonValueKind.Number || !seedJson.TryGetUInt32(out seed))
                {
                    throw Error("sampler.seed", $"must be an integer from 0 to {uint.MaxValue}, got {Describe(seedJson)}");
                }
            }

            int maxDepth = Optional(sampler, "maxDepth") is { } max ? Int(max, "sampler.maxDepth") : 3;
            int minDepth = Optional(sampler, "minDepth") is { } min ? Int(min, "sampler.minDepth") : 0;
            double contrast = Optional(sampler, "contrast") is { } c ? Number(c, "sampler.contrast") : 0.1;
            bool quincunx = Optional(sampler, "quincunx") is { } q
                && (q.ValueKind is JsonValueKind.True or JsonValueKind.False ? q.GetBoolean() : throw Error("sampler.quincunx", $"must be true or false, got {Describe(q)}"));
            bool guard = Optional(sampler, "guard") is { } g
                && (g.ValueKind is JsonValueKind.True or JsonValueKind.False ? g.GetBoolean() : throw Error("sampler.guard", $"must be true or false, got {Describe(g)}"));
            var settings = new SamplerSettings(type, samples, seed, minDepth, maxDepth, contrast, quincunx, guard);
            section.Build(source, settings.Check);
            return settings;
        }

        // JSON allows "\ud800" (an unpaired surrogate escape), but System.Text.Json cannot turn it into a .NET
        // string and throws InvalidOperationException wherever it is read (a field name, TryGetProperty, a
        // value). Find it first, with its path.
        private void CheckText(JsonElement element, string path)
        {
            const string Unpaired = "holds an unpaired UTF-16 surrogate escape (\\uD800 to \\uDFFF alone)";
            switch (element.ValueKind)
            {
                case JsonValueKind.Object:
                    foreach (JsonProperty property in element.EnumerateObject())
                    {
                        string name;
                        try
                        {
                            name = property.Name;
                        }
                        catch (InvalidOperationException)
                        {
                            throw Error(path.Length == 0 ? "(root)" : path, $"a field name {Unpaired}");
                        }

                        CheckText(property.Value, Join(path, name));
                    }

                    break;
                case JsonValueKind.Array:
                    int index = 0;
                    foreach (JsonElement item in element.EnumerateArray())
                    {
                        CheckText(item, $"{path}[{index++}]");
                    }

                    break;
                case JsonValueKind.String:
                    try
                    {
                        _ = element.GetString();
                    }
                    catch (InvalidOperationException)
                    {
                        throw Error(path.Length == 0 ? "(root)" : path, $"the string {Unpaired}");
                    }

                    break;
            }
        }

        private JsonElement Object(JsonElement element, string path) =>
            element.ValueKind == JsonValueKind.Object ? element : throw Error(path, $"must be an object, got {Describe(element)}");

        private JsonElement Required(JsonElement obj, string parent, string name) =>
            obj.TryGetProperty(name, out JsonElement value) ? value : throw Error(Join(parent, name), "is required but missing");

        private static JsonElement? Optional(JsonElement obj, string name) =>
            obj.TryGetProperty(name, out JsonElement value) && value.ValueKind != JsonValueKind.Null ? value : null;

        private void Only(JsonElement obj, SceneSection section) => Only(obj, section.Path, section.Fields);

        private void Only(JsonElement obj, string parent, IReadOnlyList<string> allowed)
        {
            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (JsonProperty property in obj.EnumerateObject())
            {
                if (!allowed.Contains(property.Name, StringComparer.Ordinal))
                {
                    throw Error(Join(parent, property.Name), $"unknown field; expected one of: {string.Join(", ", allowed)}");
                }

                if (!seen.Add(property.Name))
                {
                    throw Error(Join(parent, property.Name), "appears more than once");
                }
            }
        }

        private double Number(JsonElement element, string path)
        {
            if (element.ValueKind != JsonValueKind.Number)
            {
                throw Error(path, $"must be a number, got {Describe(element)}");
            }

            if (!element.TryGetDouble(out double value) || !double.IsFinite(value))
            {
                throw Error(path, $"must be a finite number, got {element.GetRawText()}");
            }

            return value;
        }

        // An integer in [min, max]; without bounds, any that fits an int (the type that reads it checks its range).
        private int Int(JsonElement element, string path, int min = int.MinValue, int max = int.MaxValue)
        {
            bool bounded = min != int.MinValue || max != int.MaxValue;
            if (element.ValueKind != JsonValueKind.Number)
            {
                throw Error(path, $"must be an integer, got {Describe(element)}");
            }

            if (!element.TryGetInt64(out long value))
            {
                throw Error(path, bounded ? $"must be an integer from {min} to {max}, got {element.GetRawText()}" : $"must be an integer, got {element.GetRawText()}");
            }

            return value >= min && value <= max
                ? (int)value
                : throw Error(path, $"must be an integer from {min} to {max}, got {value}");
        }

        private double[] Numbers(JsonElement element, string path, int count)
        {
            if (element.ValueKind != JsonValueKind.Array || element.GetArrayLength() != count)
            {
                throw Error(path, $"must be an array of {count} numbers, got {Describe(element)}");
            }

            var values = new double[count];
            for (int i = 0; i < count; i++)
            {
                values[i] = Number(element[i], $"{path}[{i}]");
            }

            return values;
        }

        private Double3 Vector(JsonElement element, string path)
        {
            double[] v = Numbers(element, path, 3);
            return new Double3(v[0], v[1], v[2]);
        }

        private Intensity Color(JsonElement element, string path)
        {
            double[] v = Numbers(element, path, 3);
            for (int i = 0; i < 3; i++)
            {
                if (v[i] < 0)
                {
                    throw Error($"{path}[{i}]", $"must be ≥ 0, got {v[i]}");
                }
            }

            return new Intensity(v[0], v[1], v[2]);
        }

        private string Name(JsonElement element, string path, IReadOnlyList<string> allowed)
        {
            if (element.ValueKind != JsonValueKind.String)
            {
                throw Error(path, $"must be a string, one of: {string.Join(", ", allowed)}; got {Describe(element)}");
            }

            string value = element.GetString()!;
            return allowed.Contains(value, StringComparer.Ordinal)
                ? value
                : throw Error(path, $"unknown value '{value}'; expected one of: {string.Join(", ", allowed)}");
        }

        private SceneFileException Error(string path, string problem) => new(source, path, problem);

        private static string Join(string parent, string name) => SceneSection.Join(parent, name);

        private static string Describe(JsonElement element) => element.ValueKind switch
        {
            JsonValueKind.Array => $"an array of {element.GetArrayLength()}",
            JsonValueKind.Object => "an object",
            JsonValueKind.String => $"the string \"{Truncate(element.GetString()!)}\"",
            JsonValueKind.Number => $"the number {element.GetRawText()}",
            JsonValueKind.True or JsonValueKind.False => element.GetRawText(),
            _ => "null",
        };

        private static string Truncate(string s) => s.Length <= 40 ? s : s[..40] + "…";
    }
}
