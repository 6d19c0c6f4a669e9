using System.Diagnostics;
using System.Runtime.InteropServices.JavaScript;
using System.Runtime.Versioning;
using RayLab.Scenes;

namespace RayLab.Web.Lab;

/// <summary>
/// The picture the URL asks for, rendered before the page's controls start. The browser runs .NET's Main about 2 s after
/// navigation, and Blazor's own start (host, services, the first render of the controls) takes about 1.3 s more on the
/// interpreter; the library needs none of it. So <c>Program</c> calls <see cref="RenderAsync"/> first: it renders the
/// state's picture in bands, painting each over the loading page, for at most <see cref="Budget"/>. The page then takes
/// the picture over (<see cref="Take"/>) and renders the rows left, if any.
/// </summary>
internal static partial class FirstPicture
{
    private static Handoff? _handoff;

    /// <summary>How long the first picture may hold the controls back; the page renders any rows left after it.</summary>
    public static TimeSpan Budget { get; } = TimeSpan.FromMilliseconds(1500);

    /// <summary>
    /// Renders the picture of the state in the page's URL onto the loading page's canvas. It does nothing for a view
    /// other than the picture, and for a state the library refuses: the page shows that message once it is up.
    /// </summary>
    [SupportedOSPlatform("browser")]
    public static async Task RenderAsync()
    {
        try
        {
            await JSHost.ImportAsync("raylab", "../js/raylab.js");
            LabState state = LabState.FromQuery(Search());
            if (state.View != "picture")
            {
                return;
            }

            PreparedScene prepared = state.Prepare();
            var clock = Stopwatch.StartNew();
            var image = new Image(state.Width, state.Height);
            var rays = new float[image.Width * image.Height];
            // Bands of 100 ms and no warm-up strip: nothing waits for input yet, and the browser paints between bands.
            var bands = new Bands(100, warmUp: false);
            var renderer = new Renderer { MaxDegreeOfParallelism = 1, Kernel = state.Kernel };
            double? firstBand = null;
            BandProgress done = await bands.RenderAsync(renderer, prepared, image, rays, BandProgress.None, (first, count) =>
            {
                PaintRows(Bands.RowBytes(image, first, count), image.Width, image.Height, first, prepared.SamplerDescription);
                firstBand ??= Now();
            }, () => clock.Elapsed >= Budget, CancellationToken.None);
            _handoff = new Handoff(state.ToQuery(), image, rays, done, clock.Elapsed.TotalMilliseconds, firstBand, done.Rows == image.Height ? Now() : null);
        }
        catch (SceneFileException)
        {
            // The page shows the library's message once its controls are up.
        }
        catch (ArgumentException)
        {
            // What the scene check does not catch (a scene the method cannot take): the page shows it too.
        }
    }

    /// <summary>The first picture of this state, once: null when there is none or it is of another state.</summary>
    public static Handoff? Take(LabState state)
    {
        Handoff? handoff = _handoff;
        _handoff = null;
        return handoff is not null && handoff.Query == state.ToQuery() ? handoff : null;
    }

    [SupportedOSPlatform("browser")]
    private static string Search() => JSHost.GlobalThis.GetPropertyAsJSObject("location")?.GetPropertyAsString("search") ?? "";

    [SupportedOSPlatform("browser")]
    [JSImport("now", "raylab")]
    private static partial double Now();

    [SupportedOSPlatform("browser")]
    [JSImport("paintFirstRows", "raylab")]
    private static partial void PaintRows([JSMarshalAs<JSType.MemoryView>] Span<byte> rgb, int width, int height, int firstRow, string method);
}

/// <summary>The first picture, as far as it got before the controls started.</summary>
/// <param name="Query">The state it is of, as a query string.</param>
/// <param name="Image">The picture; rows from <paramref name="Done"/>.Rows on are not rendered yet.</param>
/// <param name="Rays">Rays per pixel of the rows done.</param>
/// <param name="Done">The rows done and their statistics.</param>
/// <param name="WallMs">Its render's time from start to the last band, yields to the browser included.</param>
/// <param name="FirstBandMs">When its first band was painted, in ms after navigation.</param>
/// <param name="DoneMs">When its last row was painted, or null when rows are left.</param>
internal sealed record Handoff(string Query, Image Image, float[] Rays, BandProgress Done, double WallMs, double? FirstBandMs, double? DoneMs);
