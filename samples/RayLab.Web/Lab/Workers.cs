using System.Runtime.InteropServices;
using System.Runtime.InteropServices.JavaScript;
using System.Runtime.Versioning;

namespace RayLab.Web.Lab;

/// <summary>
/// The page's Web Workers (js/raylab.js starts them, js/worker.js runs in each): one .NET runtime a worker, each
/// rendering bands of rows of a picture through <see cref="WorkerRows"/>. The page starts them once its first picture is
/// done, and renders every full picture on them once they are up; the page's own thread paints and listens.
/// </summary>
[SupportedOSPlatform("browser")]
internal static partial class Workers
{
    private static int _pictures;

    /// <summary>Starts <c>navigator.hardwareConcurrency − 1</c> workers (at least 1) and waits until each is up or has failed.</summary>
    /// <returns>How many are up, and the first failure's message (<c>off</c> when none were wanted).</returns>
    public static async Task<(int Up, string Message, double Milliseconds)> StartAsync()
    {
        await JSHost.ImportAsync("raylab", "../js/raylab.js");
        using JSObject result = await Start();
        return (result.GetPropertyAsInt32("up"), result.GetPropertyAsString("message") ?? "", result.GetPropertyAsDouble("ms"));
    }

    /// <summary>
    /// Renders the picture of <paramref name="state"/> (with <paramref name="exact"/>, its exact picture) on the workers
    /// into <paramref name="image"/> and <paramref name="rays"/>, painting each band as it arrives when
    /// <paramref name="paint"/>; <paramref name="cancel"/> drops the bands still to come.
    /// </summary>
    /// <returns>The rows and their statistics with the number of workers that rendered, or the workers' message when they failed.</returns>
    /// <exception cref="OperationCanceledException"><paramref name="cancel"/> was cancelled.</exception>
    public static async Task<WorkerPicture> RenderAsync(LabState state, string method, bool exact, Image image, float[] rays, bool paint, CancellationToken cancel)
    {
        cancel.ThrowIfCancellationRequested();
        int id = ++_pictures;
        Task<JSObject> job = Render(id, state.ToQuery(), exact, image.Width, image.Height, method, paint);
        using JSObject result = await WhenDone(id, job, cancel);
        cancel.ThrowIfCancellationRequested();
        if (result.HasProperty("cancelled"))
        {
            throw new OperationCanceledException(cancel);
        }

        if (result.HasProperty("failed"))
        {
            return new WorkerPicture(null, 0, result.GetPropertyAsString("message") ?? "", result.GetPropertyAsInt32("left"), "", 0, "");
        }

        Take(image.PixelBytes, MemoryMarshal.AsBytes(rays.AsSpan()));
        var done = new BandProgress(
            result.GetPropertyAsInt32("rows"), (long)result.GetPropertyAsDouble("primaryRays"),
            TimeSpan.FromMilliseconds(result.GetPropertyAsDouble("renderMs")), (RenderKernel)result.GetPropertyAsInt32("kernel"));
        return new WorkerPicture(
            done, result.GetPropertyAsInt32("workers"), null, result.GetPropertyAsInt32("left"), result.GetPropertyAsString("bands") ?? "", result.GetPropertyAsDouble("pageMs"),
            $"{result.GetPropertyAsInt32("late")}/{result.GetPropertyAsInt32("dropped")}");
    }

    /// <summary>Waits for picture <paramref name="id"/>; a cancellation cancels it on the workers at once (its promise then resolves).</summary>
    private static async Task<JSObject> WhenDone(int id, Task<JSObject> job, CancellationToken cancel)
    {
        using CancellationTokenRegistration registration = cancel.Register(() => Cancel(id));
        return await job;
    }

    /// <summary>Ends the workers.</summary>
    [JSImport("stopWorkers", "raylab")]
    public static partial void Stop();

    [JSImport("startWorkers", "raylab")]
    [return: JSMarshalAs<JSType.Promise<JSType.Object>>]
    private static partial Task<JSObject> Start();

    [JSImport("renderOnWorkers", "raylab")]
    [return: JSMarshalAs<JSType.Promise<JSType.Object>>]
    private static partial Task<JSObject> Render(int id, string query, bool exact, int width, int height, string method, bool paint);

    [JSImport("cancelWorkers", "raylab")]
    private static partial void Cancel(int id);

    [JSImport("takeRows", "raylab")]
    private static partial bool Take([JSMarshalAs<JSType.MemoryView>] Span<byte> rgb, [JSMarshalAs<JSType.MemoryView>] Span<byte> rays);
}

/// <summary>A picture rendered on the workers, or why they could not.</summary>
/// <param name="Done">The rows and their statistics; null when the workers failed.</param>
/// <param name="Workers">How many workers rendered bands of it.</param>
/// <param name="Failure">The workers' message when they failed.</param>
/// <param name="Left">The workers still up.</param>
/// <param name="Bands">The bands each worker rendered and its whole time on them, such as <c>31+29 in 452+447 ms</c> (for the figures).</param>
/// <param name="PageMilliseconds">The page's own time on the bands: copying and painting them (for the figures).</param>
/// <param name="Cancelled">The bands of pictures cancelled since the last one: come back late and dropped by the page,
/// then those the workers dropped unrendered, such as <c>2/2</c> (for the tests).</param>
internal sealed record WorkerPicture(BandProgress? Done, int Workers, string? Failure, int Left, string Bands, double PageMilliseconds, string Cancelled);
