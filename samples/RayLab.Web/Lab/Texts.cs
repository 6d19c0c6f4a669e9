using System.Globalization;

namespace RayLab.Web.Lab;

/// <summary>
/// Every word the page shows, in Polish and in English side by side, Polish in the lab's own terms (natężenie, kamera
/// ortogonalna and perspektywiczna, próbkowanie regularne, losowe, losowe nieregularne, adaptacyjne). The library's own
/// messages (a refused scene or setting) are not here: they stay the library's English text, inside this page's words.
/// The loading page's few words, shown before .NET starts, are in wwwroot/index.html and js/raylab.js.
/// </summary>
public sealed class Texts
{
    private readonly bool _pl;

    private Texts(bool polish) => _pl = polish;

    /// <summary>The Polish page.</summary>
    public static Texts Polish { get; } = new(polish: true);

    /// <summary>The English page.</summary>
    public static Texts English { get; } = new(polish: false);

    /// <summary>The texts for an html <c>lang</c> value: Polish for <c>pl</c> and <c>pl-…</c>, English otherwise.</summary>
    /// <param name="lang">A language tag such as the browser's <c>navigator.language</c>.</param>
    public static Texts For(string? lang) =>
        lang is not null && (lang.Equals("pl", StringComparison.OrdinalIgnoreCase) || lang.StartsWith("pl-", StringComparison.OrdinalIgnoreCase))
            ? Polish : English;

    /// <summary>The html <c>lang</c> value: <c>pl</c> or <c>en</c>.</summary>
    public string Lang => _pl ? "pl" : "en";

    private string T(string pl, string en) => _pl ? pl : en;

    /// <summary>The language switch's label for the other language's button.</summary>
    public string SwitchTitle => T("Język strony", "The page's language");

    /// <summary>The page's heading.</summary>
    public string Title => T("Plac zabaw RayLab", "RayLab playground");

    /// <summary>The header's runtime note: one thread, or the page's thread and its workers.</summary>
    /// <param name="workers">The workers up (0: the page renders on its own thread).</param>
    public string Runtime(int workers) => workers == 0
        ? T(".NET WebAssembly, jeden wątek", ".NET WebAssembly, one thread")
        : T($".NET WebAssembly, wątek strony i {WorkersPl(workers)}", $".NET WebAssembly, the page's thread and {WorkersEn(workers)}");

    /// <summary>The header's hint.</summary>
    public string Hint => T(
        "Przeciągnij, by obrócić kamerę; kółko lub szczypanie przybliża; kliknij piksel, by go obejrzeć. Adres strony zapisuje widok: udostępnij go.",
        "Drag to orbit, wheel or pinch to zoom, click a pixel to inspect it. The URL holds the view: share it.");

    /// <summary>The scene section's heading.</summary>
    public string Scene => T("Scena", "Scene");

    /// <summary>The JSON editor's summary, with the preset's name or the edited mark.</summary>
    /// <param name="preset">The preset's name, or null for an edited scene.</param>
    public string Editor(string? preset) => T("Edytor JSON", "JSON editor") + " (" + (preset ?? T("zmieniona", "edited")) + ")";

    /// <summary>The editor's button.</summary>
    public string Apply => T("Zastosuj", "Apply");

    /// <summary>The editor's hint.</summary>
    public string EditorHint => T("Rozmiar obrazu z pliku staje się rozmiarem strony.", "The file's image size becomes the page's.");

    /// <summary>The words before the library's message about a refused scene in the editor.</summary>
    public string SceneRefused => T("Biblioteka odrzuciła scenę:", "The library refused the scene:");

    /// <summary>The words before the library's message about a refused setting.</summary>
    public string SettingRefused => T("Biblioteka odrzuciła ustawienia:", "The library refused the settings:");

    /// <summary>The image size's label.</summary>
    public string Size => T("Rozmiar obrazu", "Size");

    /// <summary>The camera section's heading.</summary>
    public string Camera => T("Kamera", "Camera");

    /// <summary>The projection's label.</summary>
    public string Projection => T("Rodzaj kamery", "Projection");

    /// <summary>A camera type's name in the list (English: the scene file's word).</summary>
    /// <param name="type">The scene file's camera type.</param>
    public string CameraType(string type) => !_pl ? type : type switch
    {
        "perspective" => "perspektywiczna",
        "orthographic" => "ortogonalna",
        _ => type,
    };

    /// <summary>The camera's position label.</summary>
    public string Position => T("Położenie (e)", "Position");

    /// <summary>The camera's target label.</summary>
    public string Target => T("Cel", "Target");

    /// <summary>The camera's up vector label.</summary>
    public string Up => T("Wektor do góry", "Up");

    /// <summary>The perspective camera's field of view label.</summary>
    public string Fov => T("Pole widzenia (°)", "Fov (°)");

    /// <summary>The window's distance label.</summary>
    public string Distance => T("Odległość okna (s)", "Distance (window)");

    /// <summary>The orthographic camera's view height label.</summary>
    public string ViewHeight => T("Wysokość widoku", "View height");

    /// <summary>The near plane's label.</summary>
    public string Near => T("Przednia płaszczyzna obcinania", "Near");

    /// <summary>The far plane's label.</summary>
    public string Far => T("Tylna płaszczyzna obcinania", "Far");

    /// <summary>The window's first corner label.</summary>
    public string Window0 => T("Okno u0 v0", "Window u0 v0");

    /// <summary>The window's second corner label.</summary>
    public string Window1 => T("Okno u1 v1", "Window u1 v1");

    /// <summary>The button that centres the window.</summary>
    public string CentredWindow => T("Okno wyśrodkowane", "Centred window");

    /// <summary>The method section's heading.</summary>
    public string Method => T("Metoda", "Method");

    /// <summary>The sampler's label.</summary>
    public string Sampler => T("Próbkowanie", "Sampler");

    /// <summary>The sample project's group in the sampler list.</summary>
    public string OwnMethods => T("Własne metody projektu przykładowego (samples/RayLab.OwnMethod)", "The sample project's own (samples/RayLab.OwnMethod)");

    /// <summary>A sampler's name in the list (English, and the methods the lab does not name: the scene file's word).</summary>
    /// <param name="type">The scene file's sampler type.</param>
    public string SamplerType(string type) => !_pl ? type : type switch
    {
        "regular" => "regularne",
        "random" => "losowe",
        "jittered" => "losowe nieregularne",
        "adaptive" => "adaptacyjne",
        "exact" => "obraz dokładny",
        _ => type,
    };

    /// <summary>The adaptive minimum depth's label.</summary>
    public string MinDepth => T("Głębokość minimalna", "Min depth");

    /// <summary>The adaptive maximum depth's label.</summary>
    public string MaxDepth => T("Głębokość maksymalna", "Max depth");

    /// <summary>The adaptive contrast's label.</summary>
    public string Contrast => T("Kontrast", "Contrast");

    /// <summary>The quincunx's label.</summary>
    public string Quincunx => T("Kwinkunks (środek)", "Quincunx (centre)");

    /// <summary>The silhouette guard's label.</summary>
    public string Guard => T("Ochrona konturów", "Silhouette guard");

    /// <summary>The render kernel's label.</summary>
    public string Kernel => T("Jądro renderowania", "Kernel");

    /// <summary>The sample count's label.</summary>
    public string Samples => T("Promienie na piksel", "Samples per pixel");

    /// <summary>The seed's label.</summary>
    public string Seed => T("Ziarno", "Seed");

    /// <summary>A view's button.</summary>
    /// <param name="view">The view: <c>picture</c>, <c>rays</c> or <c>error</c>.</param>
    public string View(string view) => view switch
    {
        "rays" => T("Promienie na piksel", "Rays per pixel"),
        "error" => T("Błąd względem dokładnego", "Error against exact"),
        _ => T("Obraz", "Picture"),
    };

    /// <summary>The line under a preview.</summary>
    /// <param name="exact">Whether the preview is the exact picture (else one ray per pixel).</param>
    /// <param name="width">The preview's width.</param>
    /// <param name="height">The preview's height.</param>
    public string Showing(bool exact, int width, int height) => _pl
        ? $"Podgląd: {(exact ? "obraz dokładny" : "jeden promień na piksel")} w rozmiarze {width}×{height}, powiększony; pełny obraz za chwilę."
        : $"Showing a preview: {(exact ? "the exact picture" : "one ray per pixel")} at {width}×{height}, scaled up; the full render follows.";

    /// <summary>The rays legend's maximum.</summary>
    /// <param name="max">The maximum, formatted.</param>
    public string RaysLegend(string max) => max + T(" promieni", " rays");

    /// <summary>The error legend's maximum.</summary>
    /// <param name="max">The maximum, formatted.</param>
    public string LevelsLegend(string max) => max + T(" poziomów", " levels");

    /// <summary>The numbers section's heading.</summary>
    public string LiveNumbers => T("Liczby na żywo", "Live numbers");

    /// <summary>The render-again button.</summary>
    public string RenderAgain => T("Renderuj ponownie", "Render again");

    /// <summary>The render-again button's tooltip.</summary>
    public string RenderAgainTitle => T("Czasy różnią się między przebiegami", "Timings vary from run to run");

    /// <summary>The status's label.</summary>
    public string Status => T("Stan", "Status");

    /// <summary>A status's words.</summary>
    /// <param name="status">The page's gate: <c>loading</c>, <c>rendering</c>, <c>preview</c>, <c>ready</c> or <c>error</c>.</param>
    public string StatusName(string status) => status switch
    {
        "loading" => T("wczytywanie", "loading"),
        "rendering" => T("renderowanie", "rendering"),
        "preview" => T("podgląd", "preview"),
        "ready" => T("gotowe", "ready"),
        "error" => T("błąd", "error"),
        _ => status,
    };

    /// <summary>The render time's label.</summary>
    public string Render => T("Renderowanie", "Render");

    /// <summary>The wall time's label.</summary>
    public string Wall => T("Czas rzeczywisty (pasy, przerwy)", "Wall (bands, yields)");

    /// <summary>The ray count's label.</summary>
    public string Rays => T("Promienie", "Rays");

    /// <summary>The rays per pixel label.</summary>
    public string RaysPerPixel => T("Promienie na piksel", "Rays per pixel");

    /// <summary>The RMSE's label.</summary>
    public string Rmse => T("RMSE względem dokładnego", "RMSE against exact");

    /// <summary>The unit of the RMSE: 8-bit levels.</summary>
    public string Levels => T("poziomów", "levels");

    /// <summary>The longest frame gap's label.</summary>
    public string LongestGap => T("Najdłuższa przerwa między klatkami", "Longest frame gap");

    /// <summary>The label of who rendered the last full picture.</summary>
    public string RenderedOn => T("Renderowały", "Rendered on");

    /// <summary>The picture was rendered on <paramref name="workers"/> workers.</summary>
    /// <param name="workers">How many workers rendered bands of it.</param>
    public string Workers(int workers) => T(WorkersPl(workers), WorkersEn(workers));

    /// <summary>The picture was rendered on the page's own thread, with the reason when there is one.</summary>
    /// <param name="why">Why not on workers, or null.</param>
    public string PageThread(string? why) => T("wątek strony", "the page's thread") + (why is null ? "" : $" ({why})");

    /// <summary>The workers are starting.</summary>
    public string WorkersStarting => T("wątki robocze startują", "workers starting");

    /// <summary>The workers could not start.</summary>
    /// <param name="message">The browser's reason.</param>
    public string WorkersFailed(string message) => T($"wątki robocze nie wystartowały: {message}", $"workers could not start: {message}");

    /// <summary>The workers failed on this picture, which the page's thread rendered.</summary>
    /// <param name="message">The workers' message.</param>
    public string WorkersFailedOnPicture(string message) => T($"wątki robocze zawiodły: {message}", $"the workers failed: {message}");

    /// <summary>No workers were asked for.</summary>
    public string WorkersOff => T("wątki robocze wyłączone", "workers off");

    // Polish counts: 1 wątek, 2–4 (22–24 …) wątki, else wątków.
    private static string WorkersPl(int n) => n == 1 ? "1 wątek roboczy"
        : n % 10 is >= 2 and <= 4 && n % 100 is < 12 or > 14 ? $"{n} wątki robocze" : $"{n} wątków roboczych";

    private static string WorkersEn(int n) => n == 1 ? "1 worker" : $"{n} workers";

    /// <summary>The last preview's label.</summary>
    public string LastPreview => T("Ostatni podgląd (dokładny)", "Last preview (exact)");

    /// <summary>The inspector's heading.</summary>
    public string Inspector => T("Inspektor piksela", "Pixel inspector");

    /// <summary>The inspector's line above its diagram.</summary>
    /// <param name="x">The pixel's column.</param>
    /// <param name="y">The pixel's row.</param>
    /// <param name="method">The method's description.</param>
    /// <param name="points">How many points.</param>
    public string Pixel(int x, int y, string method, int points) => _pl
        ? string.Create(CultureInfo.InvariantCulture, $"Piksel ({x}, {y}), {method}: punkty: {points}")
        : string.Create(CultureInfo.InvariantCulture, $"Pixel ({x}, {y}), {method}: {points} points");

    /// <summary>A point's tooltip: its label, place and weight.</summary>
    /// <param name="label">The point's label.</param>
    /// <param name="x">Its x, formatted.</param>
    /// <param name="y">Its y, formatted.</param>
    /// <param name="weight">Its weight, formatted.</param>
    public string Point(string label, string x, string y, string weight) => $"{label} ({x}, {y}) {T("waga", "weight")} {weight}";

    /// <summary>The inspector table's 8-bit column.</summary>
    public string EightBit => T("8 bitów", "8-bit");

    /// <summary>The inspector table's swatch column.</summary>
    public string Swatch => T("próbka koloru", "swatch");

    /// <summary>The rendered value's row.</summary>
    public string Rendered => T("wyrenderowane", "rendered");

    /// <summary>The method's value row.</summary>
    public string MethodsValue => T("wartość metody", "method's value");

    /// <summary>The exact value's row.</summary>
    public string Exact => T("dokładne", "exact");

    /// <summary>The note under an adaptive diagram (before the command's name).</summary>
    public string AdaptiveNote => T(
        "Podział piksela z próbkowania adaptacyjnego z instrukcji, z AdaptiveDiagram biblioteki (kod za poleceniem",
        "The lab's adaptive subdivision, from the library's AdaptiveDiagram (the code behind");

    /// <summary>The note under an adaptive diagram (after the command's name).</summary>
    public string AdaptiveNoteEnd => T("): najedź na punkt, by zobaczyć jego wagę.", "): hover a point for its weight.");

    /// <summary>The inspector's hint before a click.</summary>
    public string ClickAPixel => T("Kliknij piksel obrazu, by zobaczyć, dokąd poszły jego promienie.", "Click a pixel of the picture to see where its rays go.");

    /// <summary>The chart's heading.</summary>
    public string ErrorAgainstTime => T("Błąd a czas (ta wizyta)", "Error against time (this visit)");

    /// <summary>The chart's note.</summary>
    public string ChartNote => T(
        "RMSE w poziomach 8-bitowych względem obrazu dokładnego, czas renderowania w skali logarytmicznej. Próbuj metod i liczby promieni, by zbudować wykres do sprawozdania.",
        "RMSE in 8-bit levels against the exact picture, render time on a log scale. Try methods and counts to build the report's chart.");
}
