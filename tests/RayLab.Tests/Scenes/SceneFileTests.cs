using System.Text;
using RayLab.Scenes;

namespace RayLab.Tests.Scenes;

public sealed class SceneFileTests : IDisposable
{
    private const string Source = "test-scene.json";

    // A valid scene, one line per top-level field so that a row below can change or remove one piece.
    private const string ImageLine = """  "image": { "width": 40, "height": 30 },""" + "\n";
    private const string BackgroundLine = """  "background": [0.1, 0.1, 0.1],""" + "\n";
    private const string AmbientLine = """  "ambient": [1, 1, 1],""" + "\n";
    private const string CameraLine =
        """  "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 40, "height": 2.5, "near": 0.1, "far": 100, "distance": 1 },"""
        + "\n";
    private const string SpheresLine = """  "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": [0.5, 0.25, 1] } ],""" + "\n";
    private const string SamplerLine = """  "sampler": { "type": "regular", "samples": 1, "seed": 0 }""" + "\n";
    // The sampler's settings, for rows that make it adaptive.
    private const string Adaptive = "\"type\": \"regular\", \"samples\": 1, \"seed\": 0";
    private const string Base = "{\n" + ImageLine + BackgroundLine + AmbientLine + CameraLine + SpheresLine + SamplerLine + "}\n";

    private readonly string _dir = Path.Combine(Path.GetTempPath(), "raylab-tests-" + Guid.NewGuid().ToString("N"));

    public SceneFileTests() => Directory.CreateDirectory(_dir);

    public void Dispose()
    {
        if (Directory.Exists(_dir))
        {
            Directory.Delete(_dir, recursive: true);
        }
    }

    [Fact]
    public void TheShippedTwoSpheresSceneLoads()
    {
        string path = Path.Combine(AppContext.BaseDirectory, "scenes", "two-spheres.json");

        SceneDescription scene = SceneFile.Load(path);

        Assert.Equal(path, scene.Source);
        Assert.Equal(800, scene.Width);
        Assert.Equal(600, scene.Height);
        Assert.Equal(2, scene.Scene.Spheres.Count);
        Assert.Equal(new SamplerSettings("adaptive", 16, 1, MinDepth: 0, MaxDepth: 3, Contrast: 0.05), scene.Sampler);
        Assert.Equal("perspective", scene.Camera.Type);
        Assert.Equal(40, scene.Camera.Fov);
        Assert.Equal(new Intensity(0.1, 0.1, 0.15), scene.Scene.Background);
    }

    [Fact]
    public void TheBaseSceneOfTheBadInputRowsIsValid()
    {
        SceneDescription scene = SceneFile.Parse(Base, Source);

        Assert.Equal(Source, scene.Source);
        Assert.Equal(40, scene.Width);
        Assert.Equal(30, scene.Height);
        Sphere sphere = Assert.Single(scene.Scene.Spheres);
        Assert.Equal(new Double3(0, 0, 0), sphere.Center);
        Assert.Equal(1, sphere.Radius);
        Assert.Equal(new Intensity(0.5, 0.25, 1), sphere.Color);
        Assert.Equal(new CameraSettings("perspective", new(0, 0, 5), new(0, 0, 0), new(0, 1, 0), 40, 2.5, 0.1, 100, 1, null), scene.Camera);
        Assert.Equal(new SamplerSettings("regular", 1, 0), scene.Sampler);
    }

    [Fact]
    public void CommentsAndTrailingCommasAreAccepted()
    {
        const string json = """
            // a line comment before the root
            {
              /* a block comment */
              "image": { "width": 4, "height": 3, },
              "camera": { "type": "orthographic", "position": [0, 0, 5], "target": [0, 0, 0], }, // trailing
              "spheres": [ { "center": [0, 0, 0], "radius": 1, "color": [1, 0, 0], }, ],
            }
            """;

        SceneDescription scene = SceneFile.Parse(json, Source);

        Assert.Equal(4, scene.Width);
        Assert.Equal(3, scene.Height);
        Assert.Equal("orthographic", scene.Camera.Type);
        Assert.Equal(new Intensity(1, 0, 0), Assert.Single(scene.Scene.Spheres).Color);
    }

    [Fact]
    public void OptionalFieldsTakeTheirDefaults()
    {
        const string json = """
            {
              "image": { "width": 4, "height": 3 },
              "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0] },
              "spheres": []
            }
            """;

        SceneDescription scene = SceneFile.Parse(json, Source);

        Assert.Equal(Intensity.Black, scene.Scene.Background);
        Assert.Equal(Intensity.White, scene.Scene.Ambient);
        Assert.Equal(new Double3(0, 1, 0), scene.Camera.Up);
        Assert.Equal(1, scene.Camera.Near);
        Assert.Equal(1000, scene.Camera.Far);
        Assert.Equal(60, scene.Camera.Fov);
        Assert.Equal(2, scene.Camera.Height);
        Assert.Equal(1, scene.Camera.Distance);
        Assert.Null(scene.Camera.Window);
        Assert.Equal(new SamplerSettings("regular", 1, 0), scene.Sampler);
        Assert.Empty(scene.Scene.Spheres);
    }

    [Fact]
    public void AnOptionalFieldGivenAsNullTakesItsDefault()
    {
        const string omitted = """
            {
              "image": { "width": 4, "height": 3 },
              "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0] },
              "spheres": []
            }
            """;
        const string nulls = """
            {
              "image": { "width": 4, "height": 3 }, "background": null, "ambient": null,
              "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0], "up": null, "fov": null,
                          "height": null, "near": null, "far": null, "distance": null, "window": null },
              "spheres": [], "sampler": null
            }
            """;

        SceneDescription expected = SceneFile.Parse(omitted, Source), actual = SceneFile.Parse(nulls, Source);

        Assert.Equal(expected.Scene.Background, actual.Scene.Background);
        Assert.Equal(expected.Scene.Ambient, actual.Scene.Ambient);
        Assert.Equal(expected.Camera, actual.Camera);
        Assert.Equal(expected.Sampler, actual.Sampler);
    }

    [Fact]
    public void ARequiredFieldGivenAsNullIsAnErrorNamingIt()
    {
        const string json = """{ "image": null, "camera": { "type": "perspective", "position": [0, 0, 5], "target": [0, 0, 0] }, "spheres": [] }""";

        var e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));
        Assert.Contains("image", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void ASamplerWithOnlyItsTypeHasOneSampleAndSeedZero()
    {
        string json = Mutate(Base, SamplerLine, """  "sampler": { "type": "random" }""" + "\n");

        Assert.Equal(new SamplerSettings("random", 1, 0), SceneFile.Parse(json, Source).Sampler);
    }

    [Fact]
    public void ARadiusOfZeroIsAllowed()
    {
        string json = Mutate(Base, "\"radius\": 1", "\"radius\": 0");

        Assert.Equal(0, Assert.Single(SceneFile.Parse(json, Source).Scene.Spheres).Radius);
    }

    [Fact]
    public void AnExplicitWindowIsRead()
    {
        string json = Mutate(Base, "\"distance\": 1", "\"distance\": 1, \"window\": [-0.25, -0.2, 0.55, 0.3]");

        Assert.Equal(new Window(-0.25, -0.2, 0.55, 0.3), SceneFile.Parse(json, Source).Camera.Window);
    }

    [Theory]
    // Not a scene at all.
    [InlineData("", "", "{ this is not JSON")]
    [InlineData("(root)", "", "[1, 2, 3]")]
    // Missing required fields.
    [InlineData("image", ImageLine, "")]
    [InlineData("image.width", "\"width\": 40, ", "")]
    [InlineData("camera", CameraLine, "")]
    [InlineData("camera.type", "\"type\": \"perspective\", ", "")]
    [InlineData("camera.position", "\"position\": [0, 0, 5], ", "")]
    [InlineData("spheres", SpheresLine, "")]
    [InlineData("spheres[0].radius", "\"radius\": 1, ", "")]
    // Wrong types.
    [InlineData("image.width", "\"width\": 40", "\"width\": \"800\"")]
    [InlineData("image.width", "\"width\": 40", "\"width\": 800.5")]
    [InlineData("camera.position", "\"position\": [0, 0, 5]", "\"position\": [0, 5]")]
    [InlineData("spheres[0].color", "\"color\": [0.5, 0.25, 1]", "\"color\": \"red\"")]
    [InlineData("spheres", SpheresLine, """  "spheres": { "center": [0, 0, 0], "radius": 1, "color": [0.5, 0.25, 1] },""" + "\n")]
    [InlineData("sampler.samples", "\"samples\": 1", "\"samples\": -1")]
    [InlineData("sampler.seed", "\"seed\": 0", "\"seed\": -1")]
    [InlineData("sampler.seed", "\"seed\": 0", "\"seed\": 1.5")]
    [InlineData("image", ImageLine, """  "image": [40, 30],""" + "\n")]
    [InlineData("camera.type", "\"type\": \"perspective\"", "\"type\": 1")]
    // Out of range.
    [InlineData("image.width", "\"width\": 40", "\"width\": 0")]
    [InlineData("image.height", "\"height\": 30", "\"height\": -1")]
    [InlineData("spheres[0].radius", "\"radius\": 1", "\"radius\": -1")]
    [InlineData("spheres[0].color[1]", "\"color\": [0.5, 0.25, 1]", "\"color\": [0.5, -0.1, 1]")]
    [InlineData("background[2]", BackgroundLine, """  "background": [0, 0, -1],""" + "\n")]
    [InlineData("camera.fov", "\"fov\": 40", "\"fov\": 0")]
    [InlineData("camera.fov", "\"fov\": 40", "\"fov\": 180")]
    [InlineData("camera.fov", "\"fov\": 40", "\"fov\": 190")]
    [InlineData("camera.near", "\"near\": 0.1", "\"near\": -1")]
    // near ≥ far is the camera's combination check (Camera.GetImagePlane), which names NearPlane and both values.
    [InlineData("camera.near", "\"far\": 100", "\"far\": 0.1")]
    [InlineData("camera.near", "\"near\": 0.1, \"far\": 100", "\"near\": 10, \"far\": 5")]
    [InlineData("camera.height", "\"type\": \"perspective\"", "\"type\": \"orthographic\"", "\"height\": 2.5", "\"height\": 0")]
    [InlineData("camera.distance", "\"distance\": 1", "\"distance\": 0")]
    [InlineData("camera.window", "\"distance\": 1", "\"distance\": 1, \"window\": [1, -1, 1, 1]")]
    [InlineData("camera.window", "\"distance\": 1", "\"distance\": 1, \"window\": [1, -1, 0.5, 1]")]
    [InlineData("camera.window", "\"distance\": 1", "\"distance\": 1, \"window\": [-1, -1, 1]")]
    // Unknown and duplicate fields.
    [InlineData("spheres[0].radious", "\"radius\": 1", "\"radious\": 1")]
    [InlineData("camera.fov", "\"fov\": 40", "\"fov\": 40, \"fov\": 50")]
    [InlineData("colour", AmbientLine, """  "colour": [1, 1, 1],""" + "\n")]
    // Unknown names.
    [InlineData("camera.type", "\"type\": \"perspective\"", "\"type\": \"fisheye\"")]
    [InlineData("sampler.type", "\"type\": \"regular\"", "\"type\": \"stochastic\"")]
    // Combinations the camera or sampler rejects.
    [InlineData("sampler.samples", "\"type\": \"regular\", \"samples\": 1", "\"type\": \"jittered\", \"samples\": 5")]
    [InlineData("sampler.samples", "\"samples\": 1", "\"samples\": 2")]
    [InlineData("camera.target", "\"position\": [0, 0, 5]", "\"position\": [0, 0, 0]")]
    [InlineData("camera.up", "\"up\": [0, 1, 0]", "\"up\": [0, 0, 1]")]
    [InlineData("camera.up", "\"up\": [0, 1, 0]", "\"up\": [0, 0, 0]")]
    // Filled in by the bad-input audit: every field missing, of the wrong type, out of range or not finite.
    [InlineData("image.height", "\"height\": 30", "")]
    [InlineData("camera.target", "\"target\": [0, 0, 0], ", "")]
    [InlineData("spheres[0].center", "\"center\": [0, 0, 0], ", "")]
    [InlineData("spheres[0].color", ", \"color\": [0.5, 0.25, 1]", "")]
    [InlineData("sampler.type", "\"type\": \"regular\", ", "")]
    [InlineData("background", BackgroundLine, "  \"background\": \"grey\",\n")]
    [InlineData("ambient", AmbientLine, "  \"ambient\": [1, 1],\n")]
    [InlineData("camera", CameraLine, "  \"camera\": [],\n")]
    [InlineData("camera.up", "\"up\": [0, 1, 0]", "\"up\": 1")]
    [InlineData("camera.fov", "\"fov\": 40", "\"fov\": \"40\"")]
    [InlineData("camera.near", "\"near\": 0.1", "\"near\": true")]
    [InlineData("camera.far", "\"far\": 100", "\"far\": \"far\"")]
    [InlineData("camera.distance", "\"distance\": 1", "\"distance\": [1]")]
    [InlineData("camera.height", "\"height\": 2.5", "\"height\": \"2.5\"")]
    [InlineData("camera.window", "\"distance\": 1", "\"distance\": 1, \"window\": { \"u0\": 0 }")]
    [InlineData("camera.window[0]", "\"distance\": 1", "\"distance\": 1, \"window\": [\"a\", 0, 1, 1]")]
    [InlineData("spheres[0]", "{ \"center\": [0, 0, 0], \"radius\": 1, \"color\": [0.5, 0.25, 1] }", "3")]
    [InlineData("spheres[0].center[1]", "\"center\": [0, 0, 0]", "\"center\": [0, \"0\", 0]")]
    [InlineData("spheres[0].radius", "\"radius\": 1", "\"radius\": \"1\"")]
    [InlineData("sampler", SamplerLine, "  \"sampler\": \"regular\"\n")]
    [InlineData("sampler.type", "\"type\": \"regular\"", "\"type\": 3")]
    [InlineData("sampler.samples", "\"samples\": 1", "\"samples\": \"4\"")]
    [InlineData("sampler.samples", "\"samples\": 1", "\"samples\": 1.5")]
    [InlineData("sampler.samples", "\"samples\": 1", "\"samples\": 0")]
    [InlineData("sampler.samples", "\"samples\": 1", "\"samples\": 65537")]
    [InlineData("sampler.seed", "\"seed\": 0", "\"seed\": \"1\"")]
    [InlineData("sampler.minDepth", Adaptive, "\"type\": \"adaptive\", \"minDepth\": 0.5")]
    [InlineData("sampler.minDepth", Adaptive, "\"type\": \"adaptive\", \"minDepth\": -1")]
    [InlineData("sampler.minDepth", Adaptive, "\"type\": \"adaptive\", \"minDepth\": 4, \"maxDepth\": 3")]
    [InlineData("sampler.maxDepth", Adaptive, "\"type\": \"adaptive\", \"maxDepth\": \"3\"")]
    [InlineData("sampler.maxDepth", Adaptive, "\"type\": \"adaptive\", \"maxDepth\": 11")]
    [InlineData("sampler.contrast", Adaptive, "\"type\": \"adaptive\", \"contrast\": \"x\"")]
    [InlineData("sampler.contrast", Adaptive, "\"type\": \"adaptive\", \"contrast\": -0.1")]
    [InlineData("sampler.contrast", Adaptive, "\"type\": \"adaptive\", \"contrast\": 1e999")]
    [InlineData("image.width", "\"width\": 40", "\"width\": 1048577")]
    [InlineData("image.width", "\"width\": 40", "\"width\": 1e999")]
    [InlineData("camera.fov", "\"fov\": 40", "\"fov\": 1e999")]
    [InlineData("camera.near", "\"near\": 0.1", "\"near\": 1e999")]
    [InlineData("camera.far", "\"far\": 100", "\"far\": 1e999")]
    [InlineData("camera.height", "\"height\": 2.5", "\"height\": 1e999")]
    [InlineData("camera.distance", "\"distance\": 1", "\"distance\": 1e999")]
    [InlineData("camera.window[2]", "\"distance\": 1", "\"distance\": 1, \"window\": [-1, -1, 1e999, 1]")]
    [InlineData("camera.position[2]", "\"position\": [0, 0, 5]", "\"position\": [0, 0, 1e999]")]
    [InlineData("camera.target[0]", "\"target\": [0, 0, 0]", "\"target\": [-1e999, 0, 0]")]
    [InlineData("camera.up[1]", "\"up\": [0, 1, 0]", "\"up\": [0, 1e999, 0]")]
    [InlineData("background[1]", BackgroundLine, "  \"background\": [0, 1e999, 0],\n")]
    [InlineData("ambient[0]", AmbientLine, "  \"ambient\": [-1e999, 1, 1],\n")]
    [InlineData("spheres[0].color[0]", "\"color\": [0.5, 0.25, 1]", "\"color\": [1e999, 0.25, 1]")]
    [InlineData("sampler.seed", "\"seed\": 0", "\"seed\": 1e999")]
    // Finite numbers whose combination overflows: before the audit these rendered a blank image (exit 0).
    [InlineData("camera.window", "\"distance\": 1", "\"distance\": 1, \"window\": [-1e308, -1, 1e308, 1]")]
    [InlineData("camera.distance", "\"distance\": 1", "\"distance\": 1e308")]
    [InlineData("camera.distance", "\"distance\": 1", "\"distance\": 1e-160")]
    [InlineData("camera.height", "\"type\": \"perspective\"", "\"type\": \"orthographic\"", "\"height\": 2.5", "\"height\": 1.7e308")]
    [InlineData("camera.target", "\"position\": [0, 0, 5], \"target\": [0, 0, 0]", "\"position\": [1e308, 0, 5], \"target\": [-1e308, 0, 0]")]
    // Text the message must not break over lines, and text System.Text.Json cannot read (found by ConsoleFuzzTests).
    [InlineData("camera.line\\nbreak", "\"fov\": 40", "\"line\\nbreak\": 40")]
    [InlineData("", "", "{ \"image\": tru\ne }")]
    [InlineData("camera.type", "\"type\": \"perspective\"", "\"type\": \"\\ud800\"")]
    [InlineData("spheres[0]", "\"radius\": 1", "\"\\udc00\": 1")]
    [InlineData("(root)", AmbientLine, "  \"a\\ud83d\": [1, 1, 1],\n")]
    // Non-finite numbers.
    [InlineData("spheres[0].radius", "\"radius\": 1", "\"radius\": 1e999")]
    [InlineData("spheres[0].center[0]", "\"center\": [0, 0, 0]", "\"center\": [-1e999, 0, 0]")]
    // Finite, but out of double's reach from the camera: the ray–sphere test's squares would overflow, and the sphere vanish.
    [InlineData("spheres[0]", "\"radius\": 1", "\"radius\": 2e154")]
    [InlineData("spheres[0]", "\"center\": [0, 0, 0]", "\"center\": [0, 0, -1e153]")]
    public void BadInputNamesTheSourceAndTheField(
        string field, string find, string replace, string? find2 = null, string? replace2 = null)
    {
        string json = find.Length == 0 ? replace : Mutate(Base, find, replace);
        if (find2 is not null)
        {
            json = Mutate(json, find2, replace2!);
        }

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));

        Assert.Equal(field, e.Field);
        Assert.Equal(Source, e.File);
        Assert.False(string.IsNullOrWhiteSpace(e.Problem));
        Assert.StartsWith(Source + ": ", e.Message, StringComparison.Ordinal);
        Assert.Contains(field, e.Message, StringComparison.Ordinal);
        Assert.Equal(field.Length == 0 ? $"{Source}: {e.Problem}" : $"{Source}: {field}: {e.Problem}", e.Message);
        Assert.DoesNotContain('\n', e.Message);
    }

    [Fact]
    public void AFileThatIsNotUtf8NamesTheFirstBadByteAndWhereItIs()
    {
        // Latin-2 (ISO 8859-2) "ł" in a comment: 0xB3, which UTF-8 cannot start a character with.
        byte[] head = Encoding.UTF8.GetBytes("{ // kula\n");
        byte[] bytes = [.. head, 0xB3, .. Encoding.UTF8.GetBytes(Base[1..])];
        string path = Path.Combine(_dir, "latin2.json");
        File.WriteAllBytes(path, bytes);

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Load(path));

        Assert.Equal("", e.Field);
        Assert.Equal($"{path}: is not UTF-8 text: 0xB3 at byte {head.Length} cannot be decoded (save the file as UTF-8)", e.Message);
    }

    [Theory]
    [InlineData("utf-8 with its mark")]
    [InlineData("utf-16")]
    [InlineData("utf-16BE")]
    public void AFileInUtf8WithItsMarkOrInUtf16WithItsMarkLoads(string encoding)
    {
        Encoding e = encoding == "utf-8 with its mark" ? new UTF8Encoding(true) : Encoding.GetEncoding(encoding);
        string path = Path.Combine(_dir, "marked.json");
        File.WriteAllBytes(path, [.. e.GetPreamble(), .. e.GetBytes(Base)]);

        SceneDescription expected = SceneFile.Parse(Base, path), actual = SceneFile.Load(path);
        Assert.Equal(expected.Camera, actual.Camera);
        Assert.Equal(expected.Sampler, actual.Sampler);
        Assert.Equal(expected.Scene.Spheres.Select(x => (x.Center, x.Radius, x.Color)), actual.Scene.Spheres.Select(x => (x.Center, x.Radius, x.Color)));
    }

    [Theory]
    [InlineData("true", true)]
    [InlineData("false", false)]
    public void TheAdaptiveSamplerMayAskForTheQuincunx(string value, bool expected)
    {
        string json = Mutate(Base, SamplerLine, $$"""  "sampler": { "type": "adaptive", "quincunx": {{value}} }""" + "\n");

        SamplerSettings sampler = SceneFile.Parse(json, Source).Sampler;

        Assert.Equal(expected, sampler.Quincunx);
        Assert.Equal(expected, sampler.CreateAdaptive().Quincunx);
    }

    [Theory]
    [InlineData("true", true)]
    [InlineData("false", false)]
    [InlineData("null", false)]
    public void TheAdaptiveSamplerMayAskForTheGuard(string value, bool expected)
    {
        string json = Mutate(Base, SamplerLine, $$"""  "sampler": { "type": "adaptive", "guard": {{value}} }""" + "\n");

        SamplerSettings sampler = SceneFile.Parse(json, Source).Sampler;

        Assert.Equal(expected, sampler.Guard);
        Assert.Equal(expected, sampler.CreateAdaptive().Guard);
    }

    [Fact]
    public void AGuardThatIsNotABooleanIsReported()
    {
        string json = Mutate(Base, SamplerLine, """  "sampler": { "type": "adaptive", "guard": 1 }""" + "\n");

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));

        Assert.Equal("sampler.guard", e.Field);
        Assert.Contains("true or false", e.Problem, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("1")]
    [InlineData("\"yes\"")]
    public void AQuincunxThatIsNotABooleanIsReported(string value)
    {
        string json = Mutate(Base, SamplerLine, $$"""  "sampler": { "type": "adaptive", "quincunx": {{value}} }""" + "\n");

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));

        Assert.Equal("sampler.quincunx", e.Field);
        Assert.Contains("true or false", e.Problem, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("\"radius\": 1e999")]
    [InlineData("\"radius\": -1e999")]
    public void ANonFiniteNumberIsReportedAsSuch(string radius)
    {
        string json = Mutate(Base, "\"radius\": 1", radius);

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));

        Assert.Equal("spheres[0].radius", e.Field);
        Assert.Contains("finite", e.Problem, StringComparison.Ordinal);
    }

    [Fact]
    public void NotJsonIsReportedForTheWholeFile()
    {
        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse("{ \"image\": ", Source));

        Assert.Equal("", e.Field);
        Assert.StartsWith(Source + ": not valid JSON", e.Message, StringComparison.Ordinal);
        Assert.IsAssignableFrom<System.Text.Json.JsonException>(e.InnerException);
    }

    [Fact]
    public void AJsonErrorNamesItsLineAndColumnFromOne()
    {
        // The mistake, a missing comma, is on line 6 as an editor counts lines; "camera" starts at its column 24.
        string json = "{\n  \"image\": {\n    \"width\": 8,\n    \"height\": 6\n  },\n  \"ambient\": [1, 1, 1] \"camera\": {}\n}";

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));

        Assert.Contains("(line 6, column 24)", e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain("LineNumber", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AFileIsLoadedAndNamedByItsPath()
    {
        string path = Path.Combine(_dir, "scene.json");
        File.WriteAllText(path, Base);

        Assert.Equal(path, SceneFile.Load(path).Source);

        File.WriteAllText(path, Mutate(Base, "\"fov\": 40", "\"fov\": 190"));
        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Load(path));
        Assert.Equal(path, e.File);
        Assert.Equal("camera.fov", e.Field);
        Assert.StartsWith(path + ": camera.fov: ", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void LoadingAMissingFileNamesTheFileAndNoField()
    {
        string path = Path.Combine(_dir, "does-not-exist.json");

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Load(path));

        Assert.Equal("", e.Field);
        Assert.Equal(path, e.File);
        Assert.StartsWith(path + ": ", e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain('\n', e.Message);
        Assert.NotNull(e.InnerException);
    }

    [Fact]
    public void LoadingAFolderIsASceneFileError()
    {
        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Load(_dir));

        Assert.Equal("", e.Field);
        Assert.StartsWith(_dir + ": ", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void AnImageTooLargeToAllocateSaysWhatTheLimitIs()
    {
        string json = Mutate(Base, "\"width\": 40, \"height\": 30", "\"width\": 1048576, \"height\": 1048576");

        SceneFileException e = Assert.Throws<SceneFileException>(() => SceneFile.Parse(json, Source));

        Assert.Equal("image", e.Field);
        Assert.Contains("W·H·3 must be at most 2,147,483,591 bytes", e.Problem, StringComparison.Ordinal);
    }

    [Fact]
    public void OverridesObeyTheFilesOwnLimits()
    {
        // The console's --width, --height and --samples go through Prepare, not the reader: same limits.
        SceneDescription scene = SceneFile.Parse(Base, Source);
        const int Side = SceneFile.MaxImageSide;

        Assert.Equal("image.width", Assert.Throws<SceneFileException>(() => (scene with { Width = Side + 1, Height = 1 }).Prepare()).Field);
        Assert.Equal("image.height", Assert.Throws<SceneFileException>(() => (scene with { Width = 1, Height = Side + 1 }).Prepare()).Field);
        SceneFileException e = Assert.Throws<SceneFileException>(() => (scene with { Sampler = new SamplerSettings("random", SceneFile.MaxSamples + 1, 0) }).Prepare());
        Assert.Equal("sampler.samples", e.Field);
        Assert.Equal($"must be an integer from 1 to 65536, got {SceneFile.MaxSamples + 1}", e.Problem);
        Assert.Equal(Side, (scene with { Width = Side, Height = 1 }).Prepare().Description.Width);
        Assert.Equal(SceneFile.MaxSamples, (scene with { Sampler = new SamplerSettings("random", SceneFile.MaxSamples, 0) }).Prepare().SamplesPerPixel);
    }

    [Theory]
    [InlineData(0, 30, "image.width", "must be an integer from 1 to 1048576, got 0")]
    [InlineData(40, -3, "image.height", "must be an integer from 1 to 1048576, got -3")]
    public void AnOverrideBelowOneGetsTheReadersMessage(int width, int height, string field, string problem)
    {
        // --width 0 said "width ('0') must be greater than or equal to '1'.", a .NET parameter's words.
        SceneDescription scene = SceneFile.Parse(Base, Source);

        SceneFileException e = Assert.Throws<SceneFileException>(() => (scene with { Width = width, Height = height }).Prepare());

        Assert.Equal(field, e.Field);
        Assert.Equal(problem, e.Problem);
    }

    [Fact]
    public void ASampleCountBelowOneGetsTheReadersMessage()
    {
        // --samples 0 said "samplesPerPixel ('0') must be greater than or equal to '1'.", a constructor's parameter.
        SceneDescription scene = SceneFile.Parse(Base, Source);

        SceneFileException e = Assert.Throws<SceneFileException>(() => (scene with { Sampler = new SamplerSettings("random", 0, 0) }).Prepare());

        Assert.Equal("sampler.samples", e.Field);
        Assert.Equal("must be an integer from 1 to 65536, got 0", e.Problem);
    }

    [Fact]
    public void APreparedOverrideIsReportedWithTheFieldItReplaced()
    {
        SceneDescription scene = SceneFile.Parse(Base, Source);

        SceneFileException e = Assert.Throws<SceneFileException>(
            () => (scene with { Sampler = new SamplerSettings("jittered", 5, 0) }).Prepare());

        Assert.Equal("sampler.samples", e.Field);
        Assert.StartsWith(Source + ": sampler.samples: ", e.Message, StringComparison.Ordinal);
        Assert.DoesNotContain("(Parameter", e.Message, StringComparison.Ordinal);
    }

    /// <summary>Replaces the one occurrence of <paramref name="find"/>; a row whose text is not there fails loudly.</summary>
    private static string Mutate(string json, string find, string replace)
    {
        int at = json.IndexOf(find, StringComparison.Ordinal);
        Assert.True(at >= 0, $"the row's text {find} is not in the scene");
        Assert.True(json.IndexOf(find, at + 1, StringComparison.Ordinal) < 0, $"the row's text {find} is in the scene more than once");
        return string.Concat(json.AsSpan(0, at), replace, json.AsSpan(at + find.Length));
    }
}
