using RayLab.Scenes;

namespace RayLab.Web.Lab;

/// <summary>
/// Renders an image a band of rows at a time (<see cref="Renderer.RenderRows(Scene, Camera, RenderMethod, Image, int, int, float[])"/>) on the page's one thread, yielding to
/// the browser between bands so that input and painting go on. The band height follows the measured speed, aiming at
/// <see cref="Milliseconds"/> a band, and is remembered per method for its next render.
/// </summary>
/// <param name="milliseconds">What one band aims to take.</param>
/// <param name="warmUp">Whether a method's first render starts on a strip of 8 pixels, so that input between the bands
/// waits for two short blocks rather than one long one (not needed before the page has controls).</param>
internal sealed class Bands(double milliseconds = Bands.Milliseconds, bool warmUp = true)
{
    private readonly Dictionary<string, int> _rows = [];

    /// <summary>What one band aims to take unless told: short enough for input and painting to go on between bands.</summary>
    public const double Milliseconds = 30;

    /// <summary>
    /// Renders rows <paramref name="from"/>.Rows to the bottom of <paramref name="image"/>, or until <paramref name="stop"/>
    /// says so after a band; <paramref name="painted"/> gets each band's first row and row count as it is finished.
    /// </summary>
    /// <returns>The rows finished so far (all rows from the top) and their statistics, added to <paramref name="from"/>'s.</returns>
    public async Task<BandProgress> RenderAsync(
        Renderer renderer, PreparedScene prepared, Image image, float[]? rays, BandProgress from,
        Action<int, int>? painted, Func<bool>? stop, CancellationToken cancel)
    {
        RenderMethod method = prepared.Method;
        bool first = !_rows.TryGetValue(method.Name, out int rows);
        // A method's first render aims at half the band time: the interpreter compiles its hot loops during a band
        // (60-90 ms at once), and the band's own time comes on top.
        double aim = first ? milliseconds / 2 : milliseconds;
        if (first && warmUp && from.Rows < image.Height)
        {
            // A method's first call in the page: the interpreter prepares its code on a strip of 8 pixels (20-40 ms), apart
            // from the first band, which then starts at one row.
            renderer.Render(prepared.Scene, prepared.Camera, method, new Image(8, 1));
            await Task.Delay(1, cancel);
        }

        // A method's first band is one row; the next follow its measured speed.
        rows = Math.Max(rows, 1);
        BandProgress done = from;
        while (done.Rows < image.Height && !(stop?.Invoke() ?? false))
        {
            int count = Math.Min(rows, image.Height - done.Rows);
            RenderStatistics band = renderer.RenderRows(prepared.Scene, prepared.Camera, method, image, done.Rows, count, rays);
            painted?.Invoke(done.Rows, count);
            done = new BandProgress(done.Rows + count, done.PrimaryRays + band.PrimaryRays, done.RenderTime + band.RenderTime, band.Kernel);
            rows = Next(count, band.RenderTime.TotalMilliseconds, image.Height, aim);
            _rows[method.Name] = rows;
            await Task.Delay(1, cancel);
        }

        return done;
    }

    /// <summary>The RGB24 bytes of <paramref name="count"/> rows of <paramref name="image"/> from row <paramref name="first"/>.</summary>
    public static Span<byte> RowBytes(Image image, int first, int count) => image.PixelBytes.Slice(first * image.Width * 3, count * image.Width * 3);

    /// <summary>
    /// The next band's height: the rows that take <paramref name="aim"/> at the last band's speed, at most twice the
    /// last band, since rows differ in cost (the background is cheap, a sphere's edge is not: a 66-row band of sky in 7 ms
    /// was followed by 292 rows in 229 ms before this limit).
    /// </summary>
    private static int Next(int rows, double took, int height, double aim) =>
        Math.Clamp((int)(rows * aim / Math.Max(took, 0.5)), 1, Math.Clamp(2 * rows, 1, height));
}

/// <summary>How far a render in bands has come: the rows finished from the top, and their statistics.</summary>
/// <param name="Rows">Rows finished, from row 0.</param>
/// <param name="PrimaryRays">The library's primary rays over those rows.</param>
/// <param name="RenderTime">The library's render time over those rows.</param>
/// <param name="Kernel">The kernel the last band ran.</param>
internal sealed record BandProgress(int Rows, long PrimaryRays, TimeSpan RenderTime, RenderKernel Kernel)
{
    /// <summary>Nothing rendered yet.</summary>
    public static BandProgress None { get; } = new(0, 0, TimeSpan.Zero, RenderKernel.Scalar);

    /// <summary>
    /// The whole render's statistics. Adaptive bands each count the whole image's pixel corners, so for adaptive the rays
    /// charged to the pixels (<paramref name="rays"/>) are the cost.
    /// </summary>
    public RenderStatistics Statistics(string method, float[]? rays) =>
        new(rays is not null && method == "adaptive" ? (long)Math.Round(rays.Sum(r => (double)r)) : PrimaryRays, RenderTime) { Kernel = Kernel };
}
