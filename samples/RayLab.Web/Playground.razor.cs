using System.Diagnostics;
using System.Globalization;
using System.Reflection;
using Microsoft.AspNetCore.Components;
using Microsoft.JSInterop;
using RayLab.Cameras;
using RayLab.Rendering.Inspection;
using RayLab.Sampling;
using RayLab.Scenes;
using RayLab.Web.Lab;

namespace RayLab.Web;

/// <summary>
/// The playground page: the scene, camera and method on the left, the picture in the middle, the pixel inspector and
/// the error-against-time chart on the right. Every render goes through the library's public API. A camera move shows
/// an exact preview at a reduced size on the page's thread; the full render that follows runs in row bands, cancelled by
/// the next move: on the page's Web Workers once they are up (<see cref="Workers"/>), else on the page's thread, yielding
/// to the browser between bands.
/// </summary>
public sealed partial class Playground : IDisposable
{
    [Inject]
    private NavigationManager Navigation { get; set; } = default!;

    [Inject]
    private IJSRuntime JS { get; set; } = default!;

    private LabState _state = LabState.FromPreset(Presets.Names[0]);
    private string _editorText = "";
    private string? _editorError;
    private string? _error;
    private string _status = "loading";
    private int _frames;
    private Frame? _frame;
    private Inspection? _inspection;
    private PreparedScene? _prepared;
    private ImagePlane? _plane;
    private double? _previewMs;
    private int _previews;
    private string _previewCollections = "0/0"; // the garbage collections during the last preview: nursery/major
    private int _previewStep = 4;
    private DragWarmUp _dragWarm;
    private double _longestGap;
    private double? _firstMs;
    private double? _startMs;
    private double? _firstBandMs;
    private double? _firstPreviewMs;
    private int? _firstRows;
    private (bool Exact, int Width, int Height)? _preview; // the preview on the canvas, until the full render replaces it
    private Texts _t = Texts.English;
    private readonly List<Trial> _trials = [];
    private IJSInProcessObjectReference? _module;
    private DotNetObjectReference<Playground>? _self;
    private CancellationTokenSource? _cancel;
    private (string Key, Image Image)? _exact;
    private readonly Dictionary<(int Width, int Height), (Image Image, byte[] Bytes)> _previewImages = [];
    private WorkerState _workers = WorkerState.NotStarted;
    private int _workersUp;
    private string? _workersMessage; // why the workers could not start, or why they failed on a picture
    private double? _workersMs;
    private int _frameWorkers; // the workers that rendered the last full picture (0: the page's thread)
    private string _frameBands = ""; // the bands each worker rendered of it, and the page's time on them (for the figures)
    private double _frameBandsMs;
    private string _frameCancelled = ""; // the bands of cancelled pictures before it: late/dropped by the workers

    /// <summary>The RayLab version the page runs (the core assembly's informational version).</summary>
    private static string Version { get; } =
        typeof(Scene).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion.Split('+')[0] ?? "unknown";

    private static readonly Renderer OneThread = new() { MaxDegreeOfParallelism = 1 };

    protected override void OnInitialized()
    {
        // index.html's script chose the language before .NET started: the session's choice, else the browser's.
        _t = Texts.For(OperatingSystem.IsBrowser() ? PageLanguage.Get() : null);
        _state = LabState.FromQuery(new Uri(Navigation.Uri).Query);
        _editorText = _state.SceneText;
        Prepare();
    }

    protected override async Task OnAfterRenderAsync(bool firstRender)
    {
        if (!firstRender)
        {
            return;
        }

        _module = await JS.InvokeAsync<IJSInProcessObjectReference>("import", "./js/raylab.js");
        _startMs = _module.Invoke<double>("now");
        _self = DotNetObjectReference.Create(this);
        _module.InvokeVoid("attach", "view", _self);
        if (FirstPicture.Take(_state) is Handoff first)
        {
            // Program rendered the picture before the controls started: take it over, and render the rows left once the
            // controls' own first render is painted.
            _firstBandMs = first.FirstBandMs;
            _firstRows = first.Done.Rows;
            await Task.Delay(1);
            await RenderFullAsync(first);
            return;
        }

        // The first picture at once: the exact picture at a reduced size, as while dragging; the full render refines it.
        // The interpreter prepares the exact renderer's code on a strip of 8 pixels first, so that input waits for two
        // short blocks rather than one long one.
        if (Prepare() && WarmUpPreview())
        {
            await Task.Delay(1);
            if (PaintPreview(FirstPreviewStep))
            {
                _firstPreviewMs = _module.Invoke<double>("now");
            }
        }

        await RenderFullAsync();
    }

    /// <summary>Checks the state with the library (<see cref="LabState.Prepare"/>); a problem becomes the page's error line.</summary>
    private bool Prepare()
    {
        try
        {
            _prepared = _state.Prepare();
            _plane = _prepared.Camera.GetImagePlane(_state.Width, _state.Height);
            _error = null;
            return true;
        }
        catch (SceneFileException e)
        {
            _error = e.Message;
            return false;
        }
    }

    /// <summary>A key for everything the exact picture depends on: scene, camera and size.</summary>
    private string ExactKey => $"{_state.SceneText.GetHashCode(StringComparison.Ordinal)}|{_state.Camera}|{_state.Width}x{_state.Height}";

    /// <summary>
    /// Renders the current state at full size in row bands, yielding to the browser between bands, then the exact picture
    /// (cached per view) for the error; a new move or setting cancels it. With <paramref name="first"/>, it goes on from
    /// the rows the first picture finished before the controls started.
    /// </summary>
    private async Task RenderFullAsync(Handoff? first = null)
    {
        CancellationTokenSource cancel = Restart();
        if (!Prepare())
        {
            _status = "error";
            StateHasChanged();
            return;
        }

        PreparedScene prepared = _prepared!;
        _module?.Invoke<double>("longestFrameGap");
        _status = "rendering";
        StateHasChanged();
        try
        {
            var clock = Stopwatch.StartNew();
            var image = first?.Image ?? new Image(_state.Width, _state.Height);
            var rays = first?.Rays ?? new float[image.Width * image.Height];
            BandProgress from = first?.Done ?? BandProgress.None;
            if (first is not null)
            {
                Paint(image.PixelBytes.ToArray(), image.Width, image.Height);
            }

            if (!OnWorkers(from))
            {
                // The status painted before this thread blocks on its first band; the workers' bands leave it free.
                await Task.Delay(1, cancel.Token);
            }

            bool paint = _state.View == "picture";
            (BandProgress done, WorkerPicture? workers) = await RenderBandsAsync(prepared, exact: false, image, rays, from, paint, cancel.Token);
            RenderStatistics stats = done.Statistics(prepared.Method.Name, rays);
            double wall = (first?.WallMs ?? 0) + clock.Elapsed.TotalMilliseconds;
            Paint(image.PixelBytes.ToArray(), image.Width, image.Height);
            _firstMs ??= first?.DoneMs ?? _module?.Invoke<double>("now");
            await Task.Delay(1, cancel.Token);
            string key = ExactKey;
            Image exact;
            if (prepared.IsExact)
            {
                exact = image;
            }
            else if (_exact is (string k, Image cached) && k == key)
            {
                exact = cached;
            }
            else
            {
                exact = new Image(image.Width, image.Height);
                await RenderBandsAsync(prepared with { Method = RenderMethod.Exact }, exact: true, exact, null, BandProgress.None, paint: false, cancel.Token);
            }

            _exact = (key, exact);
            ImageError error = ImageError.Measure(image, exact);
            _frame = new Frame(image, rays, exact, stats, wall, error, prepared.SamplerDescription);
            _trials.Add(new Trial(prepared.SamplerDescription, prepared.SamplerName, stats.RenderTime.TotalMilliseconds, error.Rmse));
            if (_state.View != "picture")
            {
                PaintView();
            }

            if (_state.Pick is (int px, int py))
            {
                Inspect(px, py);
            }

            _longestGap = _module?.Invoke<double>("longestFrameGap") ?? 0;
            _preview = null;
            _frameWorkers = workers?.Workers ?? 0;
            _frameBands = workers?.Bands ?? "";
            _frameBandsMs = workers?.PageMilliseconds ?? 0;
            _frameCancelled = workers?.Cancelled ?? "";
            _frames++;
            _status = "ready";
            UpdateUrl();
            StateHasChanged();
            if (_workers == WorkerState.NotStarted && OperatingSystem.IsBrowser())
            {
                // In the background: the workers' runtimes start on their own threads while the page warms a drag up.
                _ = StartWorkersAsync();
            }

            if (_dragWarm == DragWarmUp.NotStarted)
            {
                await WarmUpDragAsync(cancel.Token);
            }
        }
        catch (OperationCanceledException)
        {
            // A newer render took over.
        }
        catch (ArgumentException e)
        {
            // What the scene check does not catch, e.g. a scene the exact reference cannot take: a message, the page stays.
            _error = SceneFileException.OneLine(e.Message);
            _status = "error";
            StateHasChanged();
        }
    }

    /// <summary>
    /// Renders a full picture in bands from <paramref name="from"/>.Rows on, painting each band when
    /// <paramref name="paint"/>: on the workers when they are up (and nothing was begun here), else on this thread. A
    /// picture the workers fail on is rendered here (a state the library refuses then shows its message).
    /// </summary>
    /// <returns>The rows and their statistics, and the workers' picture (null: this thread rendered it).</returns>
    private async Task<(BandProgress Done, WorkerPicture? Workers)> RenderBandsAsync(
        PreparedScene prepared, bool exact, Image image, float[]? rays, BandProgress from, bool paint, CancellationToken cancel)
    {
        if (OnWorkers(from))
        {
            WorkerPicture picture = await Workers.RenderAsync(_state, prepared.SamplerDescription, exact, image, rays ?? new float[image.Width * image.Height], paint, cancel);
            if (picture.Done is BandProgress done)
            {
                _workersMessage = null;
                return (done, picture);
            }

            _workersMessage = picture.Failure;
            if (picture.Left == 0)
            {
                _workers = WorkerState.Failed;
                _workersUp = 0;
            }
        }

        return (await _bands.RenderAsync(PageRenderer(cancel), prepared, image, rays, from, paint ? PaintRows(image) : null, null, cancel), null);
    }

    /// <summary>Whether a picture begun at <paramref name="from"/> renders on the workers: they are up, and nothing of it was rendered here.</summary>
    [System.Runtime.Versioning.SupportedOSPlatformGuard("browser")]
    private bool OnWorkers(BandProgress from) => _workers == WorkerState.Up && from.Rows == 0 && OperatingSystem.IsBrowser();

    /// <summary>Starts the workers once a page, after its first picture; until they are up, full pictures render on this thread.</summary>
    [System.Runtime.Versioning.SupportedOSPlatform("browser")]
    private async Task StartWorkersAsync()
    {
        _workers = WorkerState.Starting;
        StateHasChanged();
        (int up, string message, double ms) = await Workers.StartAsync();
        _workersUp = up;
        _workersMs = ms;
        _workersMessage = message.Length == 0 ? null : message;
        _workers = up > 0 ? WorkerState.Up : message == "off" ? WorkerState.Off : WorkerState.Failed;
        StateHasChanged();
    }

    /// <summary>Where the page's workers are.</summary>
    private enum WorkerState
    {
        NotStarted,
        Starting,
        Up,
        Failed,
        Off,
    }

    /// <summary>The live numbers' words for who rendered the last full picture.</summary>
    private string RenderedBy => _frameWorkers > 0 ? _t.Workers(_frameWorkers) : _t.PageThread(_workers switch
    {
        WorkerState.Starting => _t.WorkersStarting,
        WorkerState.Failed => _t.WorkersFailed(_workersMessage ?? ""),
        WorkerState.Off => _t.WorkersOff,
        WorkerState.Up when _workersMessage is not null => _t.WorkersFailedOnPicture(_workersMessage),
        _ => null,
    });

    /// <summary>Cancels the render under way and returns the source for the next one.</summary>
    private CancellationTokenSource Restart()
    {
        _cancel?.Cancel();
        _cancel?.Dispose();
        _cancel = new CancellationTokenSource();
        return _cancel;
    }

    /// <summary>The renderer of the page's full renders: one thread (the page's), the state's kernel, cancelled by the next change.</summary>
    private Renderer PageRenderer(CancellationToken cancel) => new() { MaxDegreeOfParallelism = 1, CancellationToken = cancel, Kernel = _state.Kernel };

    /// <summary>Paints a band of <paramref name="image"/>'s rows onto the canvas as it is finished.</summary>
    private Action<int, int> PaintRows(Image image) => (first, count) =>
    {
        _module?.InvokeVoid("paintRows", "view", Bands.RowBytes(image, first, count).ToArray(), image.Width, first);
        _firstBandMs ??= _module?.Invoke<double>("now");
    };

    private readonly Bands _bands = new();

    /// <summary>A camera move from the pointer: an exact preview at a reduced size, sized to stay near <see cref="PreviewMilliseconds"/>.</summary>
    [JSInvokable]
    public async Task Move(double dx, double dy, double zoom)
    {
        Restart();
        CameraSettings camera = Orbit.Rotate(_state.Camera, dx * Orbit.RadiansPerPixel, dy * Orbit.RadiansPerPixel);
        if (zoom != 1)
        {
            camera = Orbit.Zoom(camera, zoom);
        }

        _state = _state with { Camera = camera };
        if (!Prepare())
        {
            _status = "error";
            StateHasChanged();
            return;
        }

        if (!PaintPreview(null))
        {
            StateHasChanged();
            return;
        }

        _status = "preview";
        StateHasChanged();
        await Task.Yield();
    }

    /// <summary>What a preview frame while dragging aims to take (the target is 50 ms: the margin is for the frame that runs long).</summary>
    private const double PreviewMilliseconds = 25;

    /// <summary>
    /// The first picture's preview step (a quarter of the width and height), since its time is mostly the interpreter's
    /// first calls (the half-size one blocked input 100-190 ms).
    /// </summary>
    private const int FirstPreviewStep = 8;

    /// <summary>The preview sizes: step k scales the width and height by 2^(-k/4), from the full size (0) down to 0.15 (11).</summary>
    private static double PreviewScale(int step) => Math.Pow(2, -step / 4.0);

    private const int SmallestPreviewStep = 11;

    /// <summary>
    /// Renders the exact picture at a reduced size and paints it scaled up over the canvas: at <paramref name="step"/>, or
    /// (null) at the drag's step, which follows the measured time, aiming at <see cref="PreviewMilliseconds"/> a frame.
    /// False (and the error line) when the library refuses.
    /// </summary>
    private bool PaintPreview(int? step)
    {
        int at = step ?? _previewStep;
        if (RenderPreview(at) is not (Image preview, byte[] bytes, RenderMethod method, double renderMs))
        {
            return false;
        }

        var clock = Stopwatch.StartNew();
        _module?.InvokeVoid("paintPreview", "view", bytes, preview.Width, preview.Height, _state.Width, _state.Height);
        double ms = renderMs + clock.Elapsed.TotalMilliseconds;
        _previewMs = ms;
        _previews++;
        if (step is null)
        {
            // A step up is 1.41 times the pixels, so it grows by one step a move at most, and only when the frame would
            // stay under the aim: one fast frame followed by a larger step overshot to 51-58 ms on one move in eight.
            double wanted = PreviewScale(at) * Math.Sqrt(PreviewMilliseconds / Math.Max(ms, 1));
            int next = at - 1;
            while (next < SmallestPreviewStep && PreviewScale(next) > wanted)
            {
                next++;
            }

            _previewStep = next;
        }

        _preview = (method == RenderMethod.Exact, preview.Width, preview.Height);
        return true;
    }

    /// <summary>
    /// Renders the preview's method at <paramref name="step"/> into that size's image and byte copy, which are kept: the
    /// steps are few, so a drag reuses them and makes no large objects for the collector. With its time in ms; null (and
    /// the error line) when the library refuses.
    /// </summary>
    private (Image Image, byte[] Bytes, RenderMethod Method, double Ms)? RenderPreview(int step)
    {
        double s = PreviewScale(step);
        int w = Math.Max(1, (int)(_state.Width * s)), h = Math.Max(1, (int)(_state.Height * s));
        if (!_previewImages.TryGetValue((w, h), out (Image Image, byte[] Bytes) kept))
        {
            if (_previewImages.Count > SmallestPreviewStep)
            {
                _previewImages.Clear(); // the page's size changed: the old sizes will not come back soon
            }

            kept = (new Image(w, h), new byte[w * h * 3]);
            _previewImages[(w, h)] = kept;
        }

        var clock = Stopwatch.StartNew();
        int minor = GC.CollectionCount(0), major = GC.CollectionCount(GC.MaxGeneration);
        RenderMethod method;
        try
        {
            method = PreviewMethod();
            OneThread.Render(_prepared!.Scene, _prepared.Camera, method, kept.Image);
        }
        catch (ArgumentException e)
        {
            _error = SceneFileException.OneLine(e.Message);
            return null;
        }

        kept.Image.PixelBytes.CopyTo(kept.Bytes);
        _previewCollections = $"{GC.CollectionCount(0) - minor}/{GC.CollectionCount(GC.MaxGeneration) - major}";
        return (kept.Image, kept.Bytes, method, clock.Elapsed.TotalMilliseconds);
    }

    /// <summary>
    /// Renders <see cref="DragWarmUpPreviews"/> drag previews, unpainted, one a task, while the page is idle after its
    /// first picture. The interpreter compiles a loop's faster code once it has run many times: without this, that
    /// compile fell in the second or the eighth frame of a drag (43-82 ms); with two previews, in its seventh (up to
    /// 76 ms), and with eight mostly in its second (up to 64 ms): each time at about the tenth preview rendered.
    /// </summary>
    private async Task WarmUpDragAsync(CancellationToken cancel)
    {
        _dragWarm = DragWarmUp.Started;
        try
        {
            for (int i = 0; i < DragWarmUpPreviews; i++)
            {
                // The drag's step and the steps either side, where its first moves go, so each size's image is made too.
                await Task.Delay(1, cancel);
                if (RenderPreview(Math.Clamp(_previewStep + (i % 3) - 1, 0, SmallestPreviewStep)) is null)
                {
                    return;
                }
            }
        }
        finally
        {
            _dragWarm = DragWarmUp.Done;
            StateHasChanged();
        }
    }

    private const int DragWarmUpPreviews = 12;

    /// <summary>Where the drag's warm-up is: it runs once a page, after the first picture (a new move cancels it).</summary>
    private enum DragWarmUp
    {
        NotStarted,
        Started,
        Done,
    }

    /// <summary>Renders the preview's method on a strip of 8 pixels; false when the library refuses the scene.</summary>
    private bool WarmUpPreview()
    {
        try
        {
            OneThread.Render(_prepared!.Scene, _prepared.Camera, PreviewMethod(), new Image(8, 1));
            return true;
        }
        catch (ArgumentException)
        {
            return false;
        }
    }

    /// <summary>The exact picture, or one ray per pixel for a scene the exact reference cannot take.</summary>
    private RenderMethod PreviewMethod()
    {
        try
        {
            RenderMethod.Exact.Check(_prepared!.Scene, _prepared.Camera, _state.Width, _state.Height);
            return RenderMethod.Exact;
        }
        catch (UnsupportedSceneException)
        {
            return RenderMethod.Sampled(new RegularSampler(1));
        }
    }

    /// <summary>The pointer let go (or the wheel stopped): the full render, and the URL follows the camera.</summary>
    [JSInvokable]
    public async Task MoveEnd()
    {
        UpdateUrl();
        await RenderFullAsync();
    }

    /// <summary>A click on the picture: the pixel inspector shows that pixel.</summary>
    [JSInvokable]
    public void Pick(int x, int y)
    {
        if (x < 0 || y < 0 || x >= _state.Width || y >= _state.Height)
        {
            return;
        }

        _state = _state with { Pick = (x, y) };
        try
        {
            Inspect(x, y);
        }
        catch (ArgumentException e)
        {
            _inspection = null;
            _error = SceneFileException.OneLine(e.Message);
        }

        UpdateUrl();
        StateHasChanged();
    }

    /// <summary>Fills the inspector for pixel (<paramref name="x"/>, <paramref name="y"/>) with the points the current method traced there.</summary>
    private void Inspect(int x, int y)
    {
        if (_prepared is null || _plane is null || _frame is null)
        {
            return;
        }

        PreparedScene prepared = _prepared;
        Rgb24 rendered = _frame.Picture.GetPixel(x, y);
        string inside = InsideDataUrl(prepared.Scene, _plane, x, y);
        PixelTrace traced = Renderer.TracePixel(prepared.Scene, prepared.Camera, _state.Width, _state.Height, prepared.Method, x, y);
        Intensity exact = prepared.IsExact ? traced.Value : ExactValue(x, y);

        // The adaptive points carry the lab's letters (A, B, C, D the corners, E the centre, …); the others their number.
        bool adaptive = _state.Sampler.IsAdaptive;
        InspectedPoint[] points = [.. traced.Points.Select((p, i) => new InspectedPoint(
            adaptive ? AdaptiveDiagram.Label(i) : (i + 1).ToString(CultureInfo.InvariantCulture), p.X, p.Y, p.Value, p.Weight))];
        string method = prepared.IsExact ? "exact" : prepared.SamplerDescription;
        _inspection = new Inspection(x, y, method, points, traced.Squares, traced.Value, exact, rendered, inside);
    }

    /// <summary>The exact value of pixel (<paramref name="x"/>, <paramref name="y"/>): its row of the exact picture, traced alone.</summary>
    private Intensity ExactValue(int x, int y) =>
        Renderer.TracePixel(_prepared!.Scene, _prepared.Camera, _state.Width, _state.Height, RenderMethod.Exact, x, y).Value;

    /// <summary>What lies inside the pixel, traced at 24×24 points, as a PNG data URL for the inspector's background.</summary>
    private static string InsideDataUrl(Scene scene, ImagePlane plane, int x, int y)
    {
        const int n = 24;
        var inside = new Image(n, n);
        for (int j = 0; j < n; j++)
        {
            for (int i = 0; i < n; i++)
            {
                inside.SetPixel(i, j, scene.Trace(plane.GetPixelRay(x, y, (i + 0.5) / n, (j + 0.5) / n), plane.TMin, plane.TMax));
            }
        }

        using var png = new MemoryStream();
        inside.Save(png, ImageFormat.Png);
        return "data:image/png;base64," + Convert.ToBase64String(png.ToArray());
    }

    /// <summary>Paints the current view (picture, rays per pixel or error) of the last full frame.</summary>
    private void PaintView()
    {
        if (_frame is not Frame f)
        {
            return;
        }

        switch (_state.View)
        {
            case "rays":
                Paint(ColourMap.Paint(f.Rays, RaysMax), f.Picture.Width, f.Picture.Height);
                break;
            case "error":
                Paint(ColourMap.Paint(ImageError.PerPixel(f.Picture, f.Exact), ErrorMax), f.Picture.Width, f.Picture.Height);
                break;
            default:
                Paint(f.Picture.PixelBytes.ToArray(), f.Picture.Width, f.Picture.Height);
                break;
        }
    }

    private double RaysMax => _frame is null || _frame.Rays.Length == 0 ? 1 : Math.Max(1, _frame.Rays.Max());

    private double ErrorMax => _frame is null ? 1 : Math.Max(1, _frame.Error.Max);

    private void Paint(byte[] rgb, int width, int height) => _module?.InvokeVoid("paint", "view", rgb, width, height);

    private void UpdateUrl()
    {
        string url = Navigation.BaseUri + "?" + _state.ToQuery();
        if (url != Navigation.Uri)
        {
            Navigation.NavigateTo(url, forceLoad: false, replace: true);
        }
    }

    /// <summary>Applies a change from a control, then renders.</summary>
    private async Task Change(Func<LabState, LabState> change)
    {
        _state = change(_state);
        await RenderFullAsync();
    }

    private async Task SetView(string view)
    {
        _state = _state with { View = view };
        PaintView();
        UpdateUrl();
        await Task.CompletedTask;
    }

    private async Task LoadPreset(string preset)
    {
        LabState fresh = LabState.FromPreset(preset, _state.Width, _state.Height);
        _editorText = fresh.SceneText;
        _editorError = null;
        _exact = null;
        await Change(_ => fresh with { View = _state.View });
    }

    /// <summary>The editor's Apply: the library parses and checks the text; its message is shown, and the last good scene stays.</summary>
    private async Task ApplyEditor()
    {
        try
        {
            SceneDescription file = SceneFile.Parse(_editorText, "editor");
            file.Prepare();
            _editorError = null;
            _exact = null;
            await Change(s => s with { Preset = LabState.Custom, Json = _editorText, Width = file.Width, Height = file.Height, Camera = file.Camera, Sampler = file.Sampler, Pick = null });
        }
        catch (SceneFileException e)
        {
            _editorError = e.Message;
        }
    }

    private static double? ReadNumber(ChangeEventArgs e) =>
        double.TryParse(e.Value?.ToString(), NumberStyles.Float, CultureInfo.InvariantCulture, out double d) && double.IsFinite(d) ? d : null;

    private static Double3? ReadVector(ChangeEventArgs e)
    {
        string[] parts = (e.Value?.ToString() ?? "").Split(',', StringSplitOptions.TrimEntries);
        return parts.Length == 3
            && double.TryParse(parts[0], NumberStyles.Float, CultureInfo.InvariantCulture, out double x)
            && double.TryParse(parts[1], NumberStyles.Float, CultureInfo.InvariantCulture, out double y)
            && double.TryParse(parts[2], NumberStyles.Float, CultureInfo.InvariantCulture, out double z)
            ? new Double3(x, y, z) : null;
    }

    private Task SetCamera(ChangeEventArgs e, Func<CameraSettings, double, CameraSettings> set) =>
        ReadNumber(e) is double d ? Change(s => s with { Camera = set(s.Camera, d) }) : Task.CompletedTask;

    private Task SetCameraVector(ChangeEventArgs e, Func<CameraSettings, Double3, CameraSettings> set) =>
        ReadVector(e) is Double3 v ? Change(s => s with { Camera = set(s.Camera, v) }) : Task.CompletedTask;

    private Task SetSampler(ChangeEventArgs e, Func<SamplerSettings, double, SamplerSettings> set) =>
        ReadNumber(e) is double d ? Change(s => s with { Sampler = set(s.Sampler, d) }) : Task.CompletedTask;

    private Task SetWindow(ChangeEventArgs e, int corner)
    {
        if (ReadNumber(e) is not double d)
        {
            return Task.CompletedTask;
        }

        Window w = _state.Camera.Window ?? _plane?.Window ?? new Window(-1, -1, 1, 1);
        w = corner switch
        {
            0 => w with { U0 = d },
            1 => w with { V0 = d },
            2 => w with { U1 = d },
            _ => w with { V1 = d },
        };
        return Change(s => s with { Camera = s.Camera with { Window = w } });
    }

    // (+ 0.0 turns −0 into 0; a value that rounds to zero prints as 0, not −0)
    private static string F(double value, string format = "0.###") =>
        (format != "R" && Math.Abs(value) < 5e-5 ? 0.0 : value + 0.0).ToString(format, CultureInfo.InvariantCulture);

    private static string Vec(Double3 v) => $"{F(v.X)}, {F(v.Y)}, {F(v.Z)}";

    private static string Css(Intensity i) => $"rgb({Intensity.ToLevel(i.R)},{Intensity.ToLevel(i.G)},{Intensity.ToLevel(i.B)})";

    private static string Levels(Intensity i) => $"{Intensity.ToLevel(i.R)} {Intensity.ToLevel(i.G)} {Intensity.ToLevel(i.B)}";

    private static readonly string[] Sizes = ["320x180", "640x360", "800x600", "1280x720", "1920x1080"];

    private Task SetSize(ChangeEventArgs e)
    {
        string[] parts = (e.Value?.ToString() ?? "").Split('x');
        return parts.Length == 2 && int.TryParse(parts[0], CultureInfo.InvariantCulture, out int w) && int.TryParse(parts[1], CultureInfo.InvariantCulture, out int h)
            ? Change(s => s with { Width = w, Height = h, Pick = null })
            : Task.CompletedTask;
    }

    /// <summary>The language switch: the page's words, the html <c>lang</c> and the session's choice follow.</summary>
    private void SetLanguage(Texts texts)
    {
        _t = texts;
        if (OperatingSystem.IsBrowser())
        {
            PageLanguage.Set(texts.Lang, texts.Title);
        }
    }

    private string? Showing => _preview is (bool exact, int w, int h) ? _t.Showing(exact, w, h) : null;

    private static string Hue(int index) => $"hsl({(index * 67) % 360}, 80%, 62%)";

    public void Dispose()
    {
        _cancel?.Cancel();
        _cancel?.Dispose();
        _self?.Dispose();
        _module?.Dispose();
        if (_workers == WorkerState.Up && OperatingSystem.IsBrowser())
        {
            Workers.Stop();
        }
    }
}
