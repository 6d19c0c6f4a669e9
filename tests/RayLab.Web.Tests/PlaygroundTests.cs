using System.Globalization;
using System.Security.Cryptography;
using Microsoft.Playwright;
using Microsoft.Playwright.Xunit.v3;
using RayLab.Rendering.Inspection;
using RayLab.Sampling;
using RayLab.Scenes;

namespace RayLab.Web.Tests;

/// <summary>
/// The playground in Debian's headless Chromium. One browser serves every test (<see cref="BrowserTest"/> launches it
/// once and closes each test's contexts after it); each page opens in a fresh browser context (a cold cache), waits on
/// the page's gates (#lab's data-state and data-frame), never on a clock, and fails on any console error.
/// </summary>
public sealed class PlaygroundTests(StaticSite site, ITestOutputHelper output) : BrowserTest, IClassFixture<StaticSite>
{
    private static readonly string Chromium = Environment.GetEnvironmentVariable("CHROMIUM") is { Length: > 0 } c ? c : "/usr/bin/chromium";

    /// <summary>A page with its console errors collected.</summary>
    private sealed record Session(IBrowserContext Context, IPage Page, List<string> Errors) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync() => await Context.CloseAsync();
    }

    /// <summary>
    /// Debian's Chromium, headless, for the one browser of the run. Without the omnibox popup: headless Chromium builds
    /// that browser UI (a WebUI renderer, 2.9 s of main-thread work in a trace) for each new window, on the same 2 cores
    /// as the page; a user's browser has it built long before.
    /// </summary>
    public override Task<BrowserTypeLaunchOptions?> LaunchOptionsAsync() => Task.FromResult<BrowserTypeLaunchOptions?>(new()
    {
        ExecutablePath = Chromium, Headless = true, Args = ["--no-sandbox", "--disable-features=PreloadTopChromeWebUI,WebUIOmniboxPopup"],
    });

    /// <summary>
    /// Opens the page at <paramref name="query"/>. <paramref name="workers"/>, when given, is the number of Web Workers the
    /// page starts (<c>globalThis.raylabWorkers</c>; 0: none, the page renders on its own thread); else the page's own
    /// choice, <c>navigator.hardwareConcurrency − 1</c>. <paramref name="initScript"/> runs before the page's scripts.
    /// </summary>
    private async Task<Session> OpenAsync(string query = "", string? locale = null, int? workers = null, string? initScript = null)
    {
        IBrowserContext context = await NewContext(new() { ViewportSize = new() { Width = 1400, Height = 1000 }, Locale = locale });
        if (workers is int count)
        {
            await context.AddInitScriptAsync($"globalThis.raylabWorkers = {count};");
        }

        if (initScript is not null)
        {
            await context.AddInitScriptAsync(initScript);
        }

        // Long tasks (50 ms or more on the main thread, Chromium's measure of blocked input), kept for the figures.
        await context.AddInitScriptAsync(
            "window.longTasks = []; new PerformanceObserver(l => { for (const e of l.getEntries()) window.longTasks.push([e.startTime, e.duration]); }).observe({ type: 'longtask', buffered: true });");
        IPage page = await context.NewPageAsync();
        var errors = new List<string>();
        page.Console += (_, m) =>
        {
            if (m.Type == "error")
            {
                errors.Add($"{m.Text} ({m.Location})");
            }
        };
        page.PageError += (_, e) => errors.Add(e);
        await page.GotoAsync(site.Address + query);
        await WaitForFrame(page, 1);
        return new Session(context, page, errors);
    }

    /// <summary>Waits until the page has finished <paramref name="frame"/> full renders and is ready.</summary>
    private static async Task WaitForFrame(IPage page, int frame) => await page.WaitForFunctionAsync(
        $"() => {{ const l = document.getElementById('lab'); return l && l.dataset.state === 'ready' && Number(l.dataset.frame) >= {frame}; }}",
        null, new() { Timeout = 120_000 });

    /// <summary>Waits until the page's workers are up (or have failed, or are off), and returns the state.</summary>
    private static async Task<string> WaitForWorkers(IPage page)
    {
        await page.WaitForFunctionAsync(
            "() => ['up', 'failed', 'off'].includes(document.getElementById('lab').dataset.workersState)", null, new() { Timeout = 120_000 });
        return await page.GetAttributeAsync("#lab", "data-workers-state") ?? "";
    }

    /// <summary>Renders the page's picture again and waits for it.</summary>
    private static async Task RenderAgain(IPage page)
    {
        int frame = await Frame(page);
        await page.ClickAsync("#rerender");
        await WaitForFrame(page, frame + 1);
    }

    /// <summary>The page's time now, in ms after navigation.</summary>
    private static Task<double> Now(IPage page) => page.EvaluateAsync<double>("() => performance.now()");

    /// <summary>The longest task that started at or after <paramref name="since"/>, in ms (0 for none of 50 ms or more), after a frame.</summary>
    private static async Task<string> LongestTask(IPage page, double since) => (await page.EvaluateAsync<double>(
        "async since => { await new Promise(r => requestAnimationFrame(() => setTimeout(r, 0))); return Math.max(0, ...window.longTasks.filter(t => t[0] >= since).map(t => t[1])); }",
        since)).ToString("0", CultureInfo.InvariantCulture);

    private static async Task<int> Frame(IPage page) => int.Parse(await page.GetAttributeAsync("#lab", "data-frame") ?? "0", CultureInfo.InvariantCulture);

    /// <summary>SHA-256 of the canvas as RGB24 bytes, row 0 first (the layout of Image.PixelBytes).</summary>
    private static Task<string> CanvasHash(IPage page) => page.EvaluateAsync<string>("""
        async () => {
          const c = document.getElementById('view');
          const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
          const rgb = new Uint8Array(c.width * c.height * 3);
          for (let i = 0, j = 0; i < d.length; i += 4, j += 3) { rgb[j] = d[i]; rgb[j + 1] = d[i + 1]; rgb[j + 2] = d[i + 2]; }
          const h = new Uint8Array(await crypto.subtle.digest('SHA-256', rgb));
          return [...h].map(b => b.toString(16).padStart(2, '0')).join('');
        }
        """);

    private static SceneDescription Scene(string preset, int width = 640, int height = 360) =>
        SceneFile.Load(Path.Combine(StaticSite.RepositoryRoot, "samples", "scenes", preset + ".json")) with { Width = width, Height = height };

    /// <summary>The library's picture of the same scene, method and size, with the kernel the page reports, as a SHA-256.</summary>
    private static async Task<string> LibraryHash(IPage page, SceneDescription description, RenderMethod? method = null)
    {
        RenderKernel kernel = Enum.Parse<RenderKernel>(await page.GetAttributeAsync("#lab", "data-kernel") ?? "Auto");
        PreparedScene prepared = description.Prepare();
        prepared = method is null ? prepared : prepared with { Method = method };
        Image image = prepared.CreateImage();
        prepared.Render(new Renderer { Kernel = kernel }, image);
        return Convert.ToHexStringLower(SHA256.HashData(image.PixelBytes));
    }

    private static async Task ClickPixel(IPage page, int x, int y)
    {
        ILocator canvas = page.Locator("#view");
        LocatorBoundingBoxResult box = (await canvas.BoundingBoxAsync())!;
        int w = int.Parse((await canvas.GetAttributeAsync("data-width"))!, CultureInfo.InvariantCulture);
        int h = int.Parse((await canvas.GetAttributeAsync("data-height"))!, CultureInfo.InvariantCulture);
        await canvas.ClickAsync(new() { Position = new() { X = (float)((x + 0.5) * box.Width / w), Y = (float)((y + 0.5) * box.Height / h) } });
    }

    private static async Task Change(IPage page, string selector, string value)
    {
        await page.FillAsync(selector, value);
        await page.DispatchEventAsync(selector, "change");
    }

    [Fact]
    public async Task The_first_picture_equals_the_librarys_render_of_the_same_scene_method_and_size()
    {
        await using Session s = await OpenAsync();
        Assert.Equal("adaptive", await s.Page.GetAttributeAsync("#lab", "data-method"));
        Assert.Equal(await LibraryHash(s.Page, Scene("two-spheres")), await CanvasHash(s.Page));
        TestContext.Current.SendDiagnosticMessage($"figure: first picture {await s.Page.GetAttributeAsync("#lab", "data-first-ms")} ms after navigation (cold cache)");

        await using Session jittered = await OpenAsync("?scene=two-spheres&m=jittered&n=4&seed=1");
        Assert.Equal(await LibraryHash(jittered.Page, Scene("two-spheres") with { Sampler = new SamplerSettings("jittered", 4, 1) }), await CanvasHash(jittered.Page));
        Assert.Empty(s.Errors);
        Assert.Empty(jittered.Errors);
    }

    [Fact]
    public async Task A_picture_begun_before_the_controls_started_is_finished_by_the_page_with_the_librarys_bytes()
    {
        // 1280x720 at 16 spp takes seconds on the interpreter, beyond the first picture's budget: the page renders the rest.
        const string query = "?scene=two-spheres&w=1280&h=720&m=jittered&n=16&seed=3";
        await using Session s = await OpenAsync(query);
        int rows = int.Parse(await s.Page.GetAttributeAsync("#lab", "data-first-rows") ?? "", CultureInfo.InvariantCulture);
        TestContext.Current.SendDiagnosticMessage($"figure: {query}: {rows} of 720 rows painted before the controls started");
        Assert.InRange(rows, 1, 719);
        Assert.NotEqual("", await s.Page.GetAttributeAsync("#lab", "data-first-band-ms"));
        Assert.Equal(await LibraryHash(s.Page, Scene("two-spheres", 1280, 720) with { Sampler = new SamplerSettings("jittered", 16, 3) }), await CanvasHash(s.Page));
        Assert.Empty(s.Errors);
    }

    [Theory]
    [InlineData("?scene=two-spheres&m=jittered&n=16&seed=5")]
    [InlineData("?scene=two-spheres")]
    [InlineData("?scene=off-axis&m=mitchell")]
    public async Task A_picture_rendered_by_two_workers_equals_the_picture_of_the_pages_own_thread_byte_for_byte(string query)
    {
        await using Session one = await OpenAsync(query, workers: 0);
        Assert.Equal("off", await WaitForWorkers(one.Page));
        await RenderAgain(one.Page);
        Assert.Equal("0", await one.Page.GetAttributeAsync("#lab", "data-workers"));
        string oneThread = await CanvasHash(one.Page);
        string oneRmse = await one.Page.InnerTextAsync("#rmse");

        await using Session two = await OpenAsync(query, workers: 2);
        // The first picture is the page's own; the workers start after it.
        Assert.Equal("0", await two.Page.GetAttributeAsync("#lab", "data-workers"));
        Assert.Equal("up", await WaitForWorkers(two.Page));
        Assert.Equal("2", await two.Page.GetAttributeAsync("#lab", "data-workers-up"));
        await RenderAgain(two.Page);
        Assert.Equal("2", await two.Page.GetAttributeAsync("#lab", "data-workers"));
        Assert.Equal("2 workers", (await two.Page.InnerTextAsync("#workers")).Trim());
        Assert.Equal(oneThread, await CanvasHash(two.Page));
        // The error against exact: the exact picture was rendered by the workers too.
        Assert.Equal(oneRmse, await two.Page.InnerTextAsync("#rmse"));
        Assert.Empty(one.Errors);
        Assert.Empty(two.Errors);
    }

    [Fact]
    public async Task Workers_pictures_equal_the_librarys_and_a_change_under_way_cancels_their_bands()
    {
        // 1280x720 at 16 spp: seconds on the workers, so the change comes while their bands are under way.
        const string query = "?scene=two-spheres&w=1280&h=720&m=jittered&n=16&seed=3";
        await using Session s = await OpenAsync(query, workers: 2);
        Assert.Equal("up", await WaitForWorkers(s.Page));
        await RenderAgain(s.Page);
        Assert.Equal("2", await s.Page.GetAttributeAsync("#lab", "data-workers"));
        SceneDescription scene = Scene("two-spheres", 1280, 720);
        Assert.Equal(await LibraryHash(s.Page, scene with { Sampler = new SamplerSettings("jittered", 16, 3) }), await CanvasHash(s.Page));

        int frame = await Frame(s.Page);
        await s.Page.ClickAsync("#rerender");
        // The change comes once the workers' first bands of the picture are in, with the rest in flight or to come.
        await s.Page.WaitForFunctionAsync("() => document.getElementById('lab').dataset.state === 'rendering' && globalThis.raylabWorkerRows > 0");
        await Change(s.Page, "#seed", "4");
        await WaitForFrame(s.Page, frame + 1);
        // One frame: the cancelled picture never finished. The workers were told: a band queued behind the one a worker
        // renders is dropped unrendered (at most one per worker and one more each on its way); the bands under way come
        // back late and are dropped by the page. Which of the two a band meets depends on where the workers were when
        // the change came, so the test holds that some band of the cancelled picture was cancelled, and none was painted
        // over the new picture.
        Assert.Equal(frame + 1, await Frame(s.Page));
        string[] cancelled = (await s.Page.GetAttributeAsync("#lab", "data-bands-cancelled") ?? "").Split('/');
        TestContext.Current.SendDiagnosticMessage($"figure: cancelled picture's bands: {cancelled[0]} came back late, {cancelled[1]} dropped by the workers");
        int late = int.Parse(cancelled[0], CultureInfo.InvariantCulture), dropped = int.Parse(cancelled[1], CultureInfo.InvariantCulture);
        Assert.InRange(dropped, 0, 4);
        Assert.True(late + dropped >= 1, $"no band of the cancelled picture came back late or was dropped: {late}/{dropped}");
        Assert.Equal("2", await s.Page.GetAttributeAsync("#lab", "data-workers"));
        Assert.Equal(await LibraryHash(s.Page, scene with { Sampler = new SamplerSettings("jittered", 16, 4) }), await CanvasHash(s.Page));
        Assert.Empty(s.Errors);
    }

    [Theory]
    [InlineData("en-US", "the page's thread (workers could not start: no Web Workers)")]
    [InlineData("pl-PL", "wątek strony (wątki robocze nie wystartowały: no Web Workers)")]
    public async Task Where_workers_cannot_start_the_page_renders_on_its_own_thread_and_says_so(string locale, string words)
    {
        await using Session s = await OpenAsync("?scene=two-spheres&m=jittered&n=4&seed=1", locale, initScript: "delete globalThis.Worker;");
        Assert.Equal("failed", await WaitForWorkers(s.Page));
        await RenderAgain(s.Page);
        Assert.Equal("0", await s.Page.GetAttributeAsync("#lab", "data-workers"));
        Assert.Equal(words, (await s.Page.InnerTextAsync("#workers")).Trim());
        Assert.Equal(await LibraryHash(s.Page, Scene("two-spheres") with { Sampler = new SamplerSettings("jittered", 4, 1) }), await CanvasHash(s.Page));
        Assert.Empty(s.Errors);
    }

    [Fact]
    public void The_published_site_is_at_most_4_5_MB_with_brotli()
    {
        long bytes = site.BrotliBytes();
        TestContext.Current.SendDiagnosticMessage($"figure: site {bytes / 1e6:0.00} MB with brotli");
        Assert.InRange(bytes, 1, 4_500_000);
    }

    [Fact]
    public async Task The_sample_projects_own_methods_render_the_librarys_picture()
    {
        await using Session grid = await OpenAsync("?scene=off-axis&m=rotated-grid&n=4");
        Assert.Equal(await LibraryHash(grid.Page, Scene("off-axis"), RenderMethod.Sampled(new RayLab.OwnMethod.RotatedGridSampler(4))), await CanvasHash(grid.Page));
        await ClickPixel(grid.Page, 100, 100);
        await grid.Page.WaitForSelectorAsync("#inspector[data-points='4']");

        await using Session mitchell = await OpenAsync("?scene=off-axis&m=mitchell");
        Assert.Equal(await LibraryHash(mitchell.Page, Scene("off-axis"), RenderMethod.Custom(new RayLab.OwnMethod.MitchellMethod())), await CanvasHash(mitchell.Page));
        Assert.Empty(grid.Errors);
        Assert.Empty(mitchell.Errors);
    }

    [Fact]
    public async Task For_mitchell_the_inspector_shows_the_points_its_own_code_traced()
    {
        SceneDescription description = Scene("off-axis");
        PreparedScene prepared = description.Prepare();
        RenderMethod method = RenderMethod.Custom(new RayLab.OwnMethod.MitchellMethod());
        // A pixel where the contrast test passes (4 points) and one on an edge where it adds 12 more (16), in reading order.
        PixelTrace Find(int count) => Enumerable.Range(0, 360).SelectMany(y => Enumerable.Range(0, 640).Select(x => (x, y)))
            .Where(p => p.x % 7 == 0 && p.y % 5 == 0)
            .Select(p => Renderer.TracePixel(prepared.Scene, prepared.Camera, 640, 360, method, p.x, p.y))
            .First(t => t.Points.Count == count);

        await using Session s = await OpenAsync("?scene=off-axis&m=mitchell");
        foreach (PixelTrace expected in new[] { Find(4), Find(16) })
        {
            await ClickPixel(s.Page, expected.X, expected.Y);
            await s.Page.WaitForSelectorAsync($"#inspector[data-points='{expected.Points.Count}']");
            IReadOnlyList<ILocator> circles = await s.Page.Locator("#inspector circle.sample").AllAsync();
            string[] shown = [.. await Task.WhenAll(circles.Select(async c => $"{await c.GetAttributeAsync("data-x")},{await c.GetAttributeAsync("data-y")}"))];
            Assert.Equal(expected.Points.Select(p => $"{R(p.X)},{R(p.Y)}"), shown);
        }

        Assert.Empty(s.Errors);
    }

    [Fact]
    public async Task Changing_the_sampler_or_the_sample_count_renders_again()
    {
        await using Session s = await OpenAsync();
        string adaptive = await CanvasHash(s.Page);
        await s.Page.SelectOptionAsync("#method", "jittered");
        await WaitForFrame(s.Page, 2);
        Assert.Equal("jittered", await s.Page.GetAttributeAsync("#lab", "data-method"));
        int samples = int.Parse(await s.Page.InputValueAsync("#samples"), CultureInfo.InvariantCulture);
        string first = await CanvasHash(s.Page);
        Assert.NotEqual(adaptive, first);

        await Change(s.Page, "#samples", "9");
        await WaitForFrame(s.Page, 3);
        string nine = await CanvasHash(s.Page);
        Assert.NotEqual(first, nine);
        Assert.Equal(await LibraryHash(s.Page, Scene("two-spheres") with { Sampler = new SamplerSettings("jittered", 9, 1) }), nine);
        Assert.NotEqual(9, samples);
        Assert.Empty(s.Errors);
    }

    [Fact]
    public async Task Clicking_a_pixel_shows_as_many_sample_points_as_the_count()
    {
        await using Session s = await OpenAsync("?scene=two-spheres&m=jittered&n=9&seed=3");
        await ClickPixel(s.Page, 200, 150);
        await s.Page.WaitForSelectorAsync("#inspector[data-points='9']");
        IReadOnlyList<ILocator> circles = await s.Page.Locator("#inspector circle.sample").AllAsync();
        Assert.Equal(9, circles.Count);
        var expected = new SamplePoint[9];
        ((IPixelSampler)new JitteredSampler(9, 3)).GetSamples(200, 150, expected);
        string[] shown = [.. await Task.WhenAll(circles.Select(async c => $"{await c.GetAttributeAsync("data-x")},{await c.GetAttributeAsync("data-y")}"))];
        Assert.Equal(expected.Select(p => $"{R(p.X)},{R(p.Y)}"), shown);
        Assert.Empty(s.Errors);
    }

    [Fact]
    public async Task For_adaptive_the_inspector_shows_the_same_points_as_the_librarys_diagram()
    {
        await using Session s = await OpenAsync();
        SceneDescription description = Scene("two-spheres");
        PreparedScene prepared = description.Prepare();
        AdaptiveSampler sampler = description.Sampler.CreateAdaptive();
        AdaptiveDiagram edge = AdaptiveDiagram.FindEdgePixel(prepared.Scene, prepared.Camera, 640, 360, sampler);
        await ClickPixel(s.Page, edge.PixelX, edge.PixelY);
        await s.Page.WaitForSelectorAsync($"#inspector[data-points='{edge.Points.Count}']");
        IReadOnlyList<ILocator> circles = await s.Page.Locator("#inspector circle.sample").AllAsync();
        string[] shown = [.. await Task.WhenAll(circles.Select(async c =>
            $"{await c.GetAttributeAsync("data-label")} {await c.GetAttributeAsync("data-x")},{await c.GetAttributeAsync("data-y")} {await c.GetAttributeAsync("data-weight")}"))];
        Assert.Equal(edge.Points.Select(p => $"{p.Label} {R(p.X)},{R(p.Y)} {R(p.Weight)}"), shown);
        Assert.True(edge.Points.Count > 5, "an edge pixel is subdivided");
        // The README's screenshot, when asked for: RAYLAB_WEB_SCREENSHOT=docs/playground.png dotnet test tests/RayLab.Web.Tests.
        if (Environment.GetEnvironmentVariable("RAYLAB_WEB_SCREENSHOT") is { Length: > 0 } screenshot)
        {
            await s.Page.SetViewportSizeAsync(1280, 800);
            await s.Page.ScreenshotAsync(new() { Path = Path.GetFullPath(screenshot, StaticSite.RepositoryRoot) });
        }

        Assert.Empty(s.Errors);
    }

    [Fact]
    public async Task A_bad_scene_shows_the_librarys_validation_text_and_the_page_still_works()
    {
        const string bad = """{ "spheres": [ { "center": [0, 0, 0], "radius": -1, "color": [1, 1, 1] } ] }""";
        string expected = Assert.Throws<SceneFileException>(() => SceneFile.Parse(bad, "editor").Prepare()).Message;
        await using Session s = await OpenAsync();
        await s.Page.ClickAsync("summary");
        await Change(s.Page, "#editor", bad);
        await s.Page.ClickAsync("#apply");
        await s.Page.WaitForSelectorAsync("#editor-error");
        Assert.Equal(expected, (await s.Page.TextContentAsync("#editor-error"))?.Trim());

        await Change(s.Page, "#editor", "{ not json");
        await s.Page.ClickAsync("#apply");
        await s.Page.WaitForSelectorAsync("#editor-error:has-text('not valid JSON')");

        int frame = await Frame(s.Page);
        await s.Page.SelectOptionAsync("#method", "exact");
        await WaitForFrame(s.Page, frame + 1);
        Assert.Equal("exact", await s.Page.GetAttributeAsync("#lab", "data-method"));
        Assert.Empty(s.Errors);
    }

    /// <summary>A .NET resource key such as <c>Arg_ParamName_Name</c>, which a trimmed site shows in place of the framework's text.</summary>
    private static readonly System.Text.RegularExpressions.Regex ResourceKey = new(@"\b[A-Z][a-z]+_[A-Za-z_]+\b");

    /// <summary>The page's words that the language switch changes: the heading, the section headings, the sample count's label.</summary>
    private static async Task<string[]> Words(IPage page)
    {
        string[] words =
        [
            await page.GetAttributeAsync("html", "lang") ?? "",
            await page.TitleAsync(),
            .. await page.Locator("h1, h2").AllInnerTextsAsync(),
            await page.InnerTextAsync("label:has(#samples)"),
            await page.InnerTextAsync("#status"),
        ];
        return [.. words.Select(w => System.Text.RegularExpressions.Regex.Replace(w, @"\s+", " ").Trim())];
    }

    [Theory]
    [InlineData("pl-PL", "pl", "Plac zabaw RayLab")]
    [InlineData("en-US", "en", "RayLab playground")]
    public async Task The_page_opens_in_the_browsers_language(string locale, string lang, string title)
    {
        await using Session s = await OpenAsync("?scene=two-spheres&m=jittered&n=4", locale);
        Assert.Equal(lang, await s.Page.GetAttributeAsync("html", "lang"));
        Assert.Equal(title, await s.Page.InnerTextAsync("h1"));
        Assert.Equal(title, await s.Page.TitleAsync());
        Assert.Equal("on", await s.Page.GetAttributeAsync($"#lang-{lang}", "class"));
        string[] words = await Words(s.Page);
        Assert.Equal(lang == "pl"
            ? ["pl", title, title, "Scena", "Kamera", "Metoda", "Liczby na żywo Renderuj ponownie", "Inspektor piksela", "Błąd a czas (ta wizyta)", "Promienie na piksel", "gotowe"]
            : ["en", title, title, "Scene", "Camera", "Method", "Live numbers Render again", "Pixel inspector", "Error against time (this visit)", "Samples per pixel", "ready"],
            words);
        Assert.Empty(s.Errors);
    }

    [Fact]
    public async Task The_language_switch_changes_the_pages_words_and_stays_for_the_session()
    {
        await using Session s = await OpenAsync("?scene=two-spheres&m=jittered&n=4", "en-US");
        string[] english = await Words(s.Page);
        await s.Page.ClickAsync("#lang-pl");
        await s.Page.WaitForSelectorAsync("html[lang='pl']");
        string[] polish = await Words(s.Page);
        TestContext.Current.SendDiagnosticMessage($"EN: {string.Join(" | ", english)}");
        TestContext.Current.SendDiagnosticMessage($"PL: {string.Join(" | ", polish)}");
        Assert.All(english.Zip(polish), p => Assert.NotEqual(p.First, p.Second));
        Assert.Equal("Plac zabaw RayLab", await s.Page.InnerTextAsync("h1"));
        Assert.Equal("perspektywiczna", (await s.Page.InnerTextAsync("#camera option[value='perspective']")).Trim());
        Assert.Equal("losowe nieregularne", (await s.Page.InnerTextAsync("#method option[value='jittered']")).Trim());

        // A reload in the same tab keeps the choice; the other button takes it back.
        await s.Page.ReloadAsync();
        await WaitForFrame(s.Page, 1);
        Assert.Equal(polish, await Words(s.Page));
        await s.Page.ClickAsync("#lang-en");
        await s.Page.WaitForSelectorAsync("html[lang='en']");
        Assert.Equal(english, await Words(s.Page));
        Assert.Empty(s.Errors);
    }

    [Theory]
    [InlineData("pl-PL", "Biblioteka odrzuciła ustawienia:", "Biblioteka odrzuciła scenę:")]
    [InlineData("en-US", "The library refused the settings:", "The library refused the scene:")]
    public async Task A_refused_setting_or_scene_shows_the_librarys_text_with_no_resource_key(string locale, string settingPrefix, string scenePrefix)
    {
        // A 3-sample grid: the sampler's own ArgumentException, whose parameter name the framework appends; no samples at
        // all: the framework's own message (ArgumentOutOfRangeException.ThrowIfLessThan), passed on by the library.
        string twoSpheres = File.ReadAllText(Path.Combine(StaticSite.RepositoryRoot, "samples", "scenes", "two-spheres.json"));
        SceneFileException Refused(SamplerSettings sampler) => Assert.Throws<SceneFileException>(() =>
            (SceneFile.Parse(twoSpheres, "two-spheres") with { Width = 640, Height = 360, Sampler = sampler }).Prepare());
        SceneFileException setting = Refused(new SamplerSettings("jittered", 3, 1));
        SceneFileException none = Refused(new SamplerSettings("random", 0, 1));
        // The same grid in the editor: the two-spheres file with its sampler made jittered with 3 samples.
        string bad = twoSpheres.Replace("\"type\": \"adaptive\"", "\"type\": \"jittered\"", StringComparison.Ordinal)
            .Replace("\"samples\": 16", "\"samples\": 3", StringComparison.Ordinal);
        SceneFileException scene = Assert.Throws<SceneFileException>(() => SceneFile.Parse(bad, "editor").Prepare());
        Assert.Equal(("sampler.samples", "sampler.samples", "sampler.samples"), (setting.Field, none.Field, scene.Field));
        Assert.Contains("got 3", scene.Problem, StringComparison.Ordinal);

        await using Session s = await OpenAsync(locale: locale);
        await s.Page.SelectOptionAsync("#method", "jittered");
        await WaitForFrame(s.Page, 2);
        await Change(s.Page, "#samples", "3");
        await s.Page.WaitForSelectorAsync("#lab[data-state='error']");
        string message = (await s.Page.InnerTextAsync("#error")).Trim();
        TestContext.Current.SendDiagnosticMessage($"{locale} setting: {message}");
        Assert.DoesNotMatch(ResourceKey, message);
        Assert.Equal(setting.Message, message);
        Assert.Equal($"{settingPrefix} {setting.Message}", (await s.Page.InnerTextAsync("p.error:has(#error)")).Trim());

        await s.Page.SelectOptionAsync("#method", "random");
        await s.Page.WaitForSelectorAsync("#lab[data-state='ready']");
        await Change(s.Page, "#samples", "0");
        await s.Page.WaitForSelectorAsync("#lab[data-state='error']");
        message = (await s.Page.InnerTextAsync("#error")).Trim();
        TestContext.Current.SendDiagnosticMessage($"{locale} setting: {message}");
        Assert.DoesNotMatch(ResourceKey, message);
        Assert.Equal(none.Message, message);

        await s.Page.ClickAsync("summary");
        await Change(s.Page, "#editor", bad);
        await s.Page.ClickAsync("#apply");
        await s.Page.WaitForSelectorAsync("#editor-error");
        message = (await s.Page.InnerTextAsync("#editor-error")).Trim();
        TestContext.Current.SendDiagnosticMessage($"{locale} scene: {message}");
        Assert.DoesNotMatch(ResourceKey, message);
        Assert.Equal(scene.Message, message);
        Assert.Equal($"{scenePrefix} {scene.Message}", (await s.Page.InnerTextAsync("p.error:has(#editor-error)")).Trim());

        // The page still works: a sample count the sampler takes renders again.
        int frame = await Frame(s.Page);
        await Change(s.Page, "#samples", "4");
        await WaitForFrame(s.Page, frame + 1);
        Assert.Empty(s.Errors);
    }

    [Fact]
    public async Task Dragging_changes_the_camera_and_the_url_follows_and_reopens_the_same_picture()
    {
        await using Session s = await OpenAsync("?scene=two-spheres&m=exact");
        string before = s.Page.Url;
        string beforeHash = await CanvasHash(s.Page);
        LocatorBoundingBoxResult box = (await s.Page.Locator("#view").BoundingBoxAsync())!;
        float cx = box.X + (box.Width / 2), cy = box.Y + (box.Height / 2);
        await s.Page.Mouse.MoveAsync(cx, cy);
        await s.Page.Mouse.DownAsync();
        await s.Page.Mouse.MoveAsync(cx + 90, cy + 30, new() { Steps = 10 });
        await s.Page.Mouse.UpAsync();
        await WaitForFrame(s.Page, 2);
        await s.Page.WaitForFunctionAsync($"() => location.href !== {System.Text.Json.JsonSerializer.Serialize(before)}");
        string after = s.Page.Url;
        Assert.NotEqual(Query(before)["pos"], Query(after)["pos"]);
        string afterHash = await CanvasHash(s.Page);
        Assert.NotEqual(beforeHash, afterHash);
        TestContext.Current.SendDiagnosticMessage($"figure: drag preview (exact, reduced size) {await s.Page.GetAttributeAsync("#lab", "data-preview-ms")} ms");

        await using Session shared = await OpenAsync(new Uri(after).Query);
        Assert.Equal(afterHash, await CanvasHash(shared.Page));
        Assert.Empty(s.Errors);
        Assert.Empty(shared.Errors);
    }

    /// <summary>
    /// The figures of docs/performance.md's browser section, printed, not asserted (speed lives in figures, not tests):
    /// a measurement, not a check, so it is in the Figures category, which <c>dotnet test</c> and CI leave out
    /// (tests/Directory.Build.props); <c>--filter Category=Figures</c> runs it.
    /// </summary>
    [Fact]
    [Trait("Category", "Figures")]
    public async Task Timings_are_printed_as_figures()
    {
        var lines = new List<string> { site.PublishNote, $"site: {site.BrotliBytes() / 1e6:0.00} MB with brotli (each file's .br copy, else the file)" };
        // A page opened and closed first, so that the test's own start (Playwright's driver, the browser, the local server,
        // the JIT of them) does not share the 2 cores with the measured page; every session is a new browser context,
        // with an empty cache.
        await (await OpenAsync("?scene=two-spheres&m=exact")).DisposeAsync();
        await using (Session cold = await OpenAsync())
        {
            lines.Add($"first picture (two-spheres adaptive 640x360), ms after navigation, cold cache: first rows painted {await cold.Page.GetAttributeAsync("#lab", "data-first-band-ms")}, "
                + $"whole picture {await cold.Page.GetAttributeAsync("#lab", "data-first-ms")}, controls up {await cold.Page.GetAttributeAsync("#lab", "data-start-ms")}; "
                + $"rows painted before the controls {await cold.Page.GetAttributeAsync("#lab", "data-first-rows")} of 360");
        }

        await using (Session exact = await OpenAsync("?scene=two-spheres&m=exact"))
        {
            // A method's first render in the page, started from the controls: the interpreter prepares its code as it runs.
            int frame = await Frame(exact.Page);
            double since = await Now(exact.Page);
            await exact.Page.SelectOptionAsync("#method", "jittered");
            await WaitForFrame(exact.Page, frame + 1);
            lines.Add($"first switch from exact to jittered 16 spp 640x360: render {await exact.Page.GetAttributeAsync("#lab", "data-render-ms")} ms, "
                + $"longest frame gap {await exact.Page.GetAttributeAsync("#lab", "data-gap-ms")} ms, longest task {await LongestTask(exact.Page, since)} ms");
            Assert.Empty(exact.Errors);
        }

        foreach ((string name, string query) in new[]
        {
            ("exact 640x360", "m=exact"), ("jittered 4 spp 640x360", "m=jittered&n=4&seed=1"),
            ("jittered 4 spp 640x360, scalar kernel", "m=jittered&n=4&seed=1&k=scalar"), ("adaptive (scene's) 640x360", ""),
        })
        {
            await using Session s = await OpenAsync("?scene=two-spheres&" + query);
            var ms = new List<string> { await s.Page.GetAttributeAsync("#lab", "data-render-ms") ?? "" };
            var gaps = new List<string> { await s.Page.GetAttributeAsync("#lab", "data-gap-ms") ?? "" };
            // The first render's tasks from the controls' start on (before it, the page has no input to block).
            var tasks = new List<string> { await LongestTask(s.Page, double.Parse(await s.Page.GetAttributeAsync("#lab", "data-start-ms") ?? "0", CultureInfo.InvariantCulture)) };
            for (int i = 0; i < 3; i++)
            {
                int frame = await Frame(s.Page);
                double since = await Now(s.Page);
                await s.Page.ClickAsync("#rerender");
                await WaitForFrame(s.Page, frame + 1);
                ms.Add(await s.Page.GetAttributeAsync("#lab", "data-render-ms") ?? "");
                gaps.Add(await s.Page.GetAttributeAsync("#lab", "data-gap-ms") ?? "");
                tasks.Add(await LongestTask(s.Page, since));
            }

            lines.Add($"{name}: render {string.Join(", ", ms)} ms (first, then again); longest frame gap {string.Join(", ", gaps)} ms; longest task {string.Join(", ", tasks)} ms");
            Assert.Empty(s.Errors);
        }

        // Jittered 16 spp 640x360 on the page's thread (no workers) and on two workers, both pages open, renders taken in
        // turn (so the machine's load falls on both alike), each after its page's first picture and one more (warm-up).
        await using (Session one = await OpenAsync("?scene=two-spheres&m=jittered&n=16&seed=1", workers: 0))
        await using (Session two = await OpenAsync("?scene=two-spheres&m=jittered&n=16&seed=1", workers: 2))
        {
            await WaitForWorkers(one.Page);
            string state = await WaitForWorkers(two.Page);
            lines.Add($"2 workers {state} {await two.Page.GetAttributeAsync("#lab", "data-workers-ms")} ms after their start (the first picture's end)");
            await RenderAgain(one.Page);
            await RenderAgain(two.Page);
            var walls = new Dictionary<Session, List<double>> { [one] = [], [two] = [] };
            var renders = new Dictionary<Session, List<double>> { [one] = [], [two] = [] };
            var tasks = new Dictionary<Session, List<string>> { [one] = [], [two] = [] };
            var bands = new List<string>();
            for (int i = 0; i < 7; i++)
            {
                foreach (Session s in new[] { one, two })
                {
                    double since = await Now(s.Page);
                    await RenderAgain(s.Page);
                    walls[s].Add(double.Parse(await s.Page.GetAttributeAsync("#lab", "data-wall-ms") ?? "", CultureInfo.InvariantCulture));
                    renders[s].Add(double.Parse(await s.Page.GetAttributeAsync("#lab", "data-render-ms") ?? "", CultureInfo.InvariantCulture));
                    tasks[s].Add(await LongestTask(s.Page, since));
                    if (s == two)
                    {
                        bands.Add($"{await s.Page.GetAttributeAsync("#lab", "data-bands")} ({await s.Page.GetAttributeAsync("#lab", "data-bands-page-ms")} ms)");
                        Assert.Equal("2", await s.Page.GetAttributeAsync("#lab", "data-workers"));
                    }
                }
            }

            double oneMedian = Median(walls[one]), twoMedian = Median(walls[two]);
            lines.Add($"jittered 16 spp 640x360, the page's thread: wall {string.Join(", ", walls[one])} ms (median {oneMedian:0}), render {string.Join(", ", renders[one])} ms; longest task {string.Join(", ", tasks[one])} ms");
            lines.Add($"jittered 16 spp 640x360, 2 workers: wall {string.Join(", ", walls[two])} ms (median {twoMedian:0}), render (summed over the workers) {string.Join(", ", renders[two])} ms; longest task {string.Join(", ", tasks[two])} ms");
            lines.Add($"jittered 16 spp 640x360, 2 workers: bands per worker (the page's time on them) {string.Join(", ", bands)}");
            lines.Add($"jittered 16 spp 640x360: 2 workers {oneMedian / twoMedian:0.00}x the page's thread (medians of wall times)");
            Assert.Empty(one.Errors);
            Assert.Empty(two.Errors);
        }

        // A drag on the page a student opens first (its picture adaptive, begun before the controls), on the exact one,
        // and on the first page with two workers up (3 threads on the 2 cores when a move comes during a picture).
        foreach ((string query, int? workers) in new[] { ("", (int?)null), ("?scene=two-spheres&m=exact", null), ("", 2) })
        {
            await using Session drag = await OpenAsync(query, workers: workers);
            // The page warms a drag up with previews when idle after its first picture; a user's hand takes longer than that.
            await drag.Page.WaitForFunctionAsync("() => document.getElementById('lab').dataset.dragWarm === 'done'");
            string up = await WaitForWorkers(drag.Page);
            LocatorBoundingBoxResult box = (await drag.Page.Locator("#view").BoundingBoxAsync())!;
            float cx = box.X + (box.Width / 2), cy = box.Y + (box.Height / 2);
            var previews = new List<string>();
            await drag.Page.Mouse.MoveAsync(cx, cy);
            await drag.Page.Mouse.DownAsync();
            for (int i = 1; i <= 12; i++)
            {
                // Each move's own preview: the count of previews painted goes up by one (a move that arrives while one
                // renders is summed into the next, but these wait for each).
                int painted = int.Parse(await drag.Page.GetAttributeAsync("#lab", "data-previews") ?? "0", CultureInfo.InvariantCulture);
                await drag.Page.Mouse.MoveAsync(cx + (i * 12), cy);
                await drag.Page.WaitForFunctionAsync($"() => Number(document.getElementById('lab').dataset.previews) > {painted}");
                // With the garbage collections that ran during the preview, if any (nursery/major).
                string gc = await drag.Page.GetAttributeAsync("#lab", "data-preview-gc") ?? "0/0";
                previews.Add((await drag.Page.GetAttributeAsync("#lab", "data-preview-ms") ?? "") + (gc == "0/0" ? "" : $" (GC {gc})"));
            }

            await drag.Page.Mouse.UpAsync();
            await WaitForFrame(drag.Page, 2);
            lines.Add($"drag previews (exact at a reduced size) on {(query.Length == 0 ? "the first page" : query)}, workers {up} "
                + $"({await drag.Page.GetAttributeAsync("#lab", "data-workers-up")}), the picture after it on {await drag.Page.GetAttributeAsync("#lab", "data-workers")} workers: {string.Join(", ", previews)} ms");
        }

        // Diagnostic messages (xunit.runner.json) reach the console at any verbosity; the file keeps them for docs/performance.md.
        string file = Path.Combine(AppContext.BaseDirectory, "web-figures.txt");
        await File.WriteAllLinesAsync(file, lines, TestContext.Current.CancellationToken);
        foreach (string line in lines)
        {
            output.WriteLine(line);
            TestContext.Current.SendDiagnosticMessage("figure: " + line);
        }
    }

    private static string R(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static double Median(List<double> values)
    {
        double[] sorted = [.. values.Order()];
        return sorted.Length % 2 == 1 ? sorted[sorted.Length / 2] : (sorted[(sorted.Length / 2) - 1] + sorted[sorted.Length / 2]) / 2;
    }

    private static Dictionary<string, string> Query(string url) => new Uri(url).Query.TrimStart('?').Split('&')
        .Select(p => p.Split('=', 2)).ToDictionary(p => p[0], p => Uri.UnescapeDataString(p[1]));
}
