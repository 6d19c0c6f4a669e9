using System.Runtime.InteropServices;
using System.Runtime.InteropServices.JavaScript;
using System.Runtime.Versioning;
using RayLab.Scenes;

namespace RayLab.Web.Lab;

/// <summary>
/// What a Web Worker of the page calls (js/worker.js, on its own .NET runtime, one thread): bands of rows of the picture
/// a state describes, rendered by the library's <see cref="Renderer.RenderRows(Scene, Camera, RenderMethod, Image, int, int, float[])"/>
/// as the page renders them on its own thread. A pixel's value does not depend on the rows rendered with it, so the
/// bands of any number of workers give the bytes of one render. The last state's scene, picture and rays are kept, so
/// a picture's bands reuse them.
/// </summary>
[SupportedOSPlatform("browser")]
internal static partial class WorkerRows
{
    private static (string Key, PreparedScene Prepared, RenderKernel Kernel, Image Image, float[] Rays)? _kept;
    private static RenderStatistics? _last;

    /// <summary>
    /// Renders rows <paramref name="firstRow"/> to <paramref name="firstRow"/> + <paramref name="rowCount"/> − 1 of the
    /// state <paramref name="query"/> describes at <paramref name="width"/>×<paramref name="height"/> (with
    /// <paramref name="exact"/>, its exact picture).
    /// </summary>
    /// <returns>The band's rays per pixel (4-byte floats, W·rowCount of them), then its RGB24 bytes, row by row.</returns>
    /// <exception cref="SceneFileException">The state is not a scene the library renders.</exception>
    /// <exception cref="ArgumentException">The library refuses the scene for the method (the page shows its message).</exception>
    [JSExport]
    internal static byte[] Render(string query, bool exact, int width, int height, int firstRow, int rowCount)
    {
        string key = $"{width}x{height}|{(exact ? "exact" : "method")}|{query}";
        if (_kept is not { } kept || kept.Key != key)
        {
            LabState state = LabState.FromQuery(query) with { Width = width, Height = height };
            PreparedScene prepared = state.Prepare();
            kept = (key, exact ? prepared with { Method = RenderMethod.Exact } : prepared, state.Kernel, new Image(width, height), new float[width * height]);
            _kept = kept;
        }

        var renderer = new Renderer { MaxDegreeOfParallelism = 1, Kernel = kept.Kernel };
        _last = renderer.RenderRows(kept.Prepared.Scene, kept.Prepared.Camera, kept.Prepared.Method, kept.Image, firstRow, rowCount, kept.Rays);
        int pixels = width * rowCount;
        byte[] band = new byte[(pixels * sizeof(float)) + (pixels * 3)];
        MemoryMarshal.AsBytes(kept.Rays.AsSpan(firstRow * width, pixels)).CopyTo(band);
        Bands.RowBytes(kept.Image, firstRow, rowCount).CopyTo(band.AsSpan(pixels * sizeof(float)));
        return band;
    }

    /// <summary>The last band's statistics: its primary rays, its render time in ms, and the kernel that ran (as its number).</summary>
    [JSExport]
    internal static double[] LastBand() =>
        _last is { } s ? [s.PrimaryRays, s.RenderTime.TotalMilliseconds, (int)s.Kernel] : [0, 0, 0];
}
