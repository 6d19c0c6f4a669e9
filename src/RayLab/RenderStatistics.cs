namespace RayLab;

/// <summary>What a render did: primary rays traced and the time spent rendering (not loading or encoding).</summary>
/// <param name="PrimaryRays">Primary rays traced.</param>
/// <param name="RenderTime">Wall-clock time of the render loop.</param>
public readonly record struct RenderStatistics(long PrimaryRays, TimeSpan RenderTime)
{
    /// <summary>Primary rays per second (0 for an instant render).</summary>
    public double RaysPerSecond => RenderTime > TimeSpan.Zero ? PrimaryRays / RenderTime.TotalSeconds : 0;

    /// <summary>The loop that rendered the image: for adaptive renders the one that traced the pixel corners, <see cref="RenderKernel.Scalar"/> for exact renders.</summary>
    public RenderKernel Kernel { get; init; }

    /// <summary>
    /// Packet kernels: samples whose float answer was within its error bound of a silhouette or of another
    /// sphere, and were traced again in double (each still counts once in <see cref="PrimaryRays"/>).
    /// </summary>
    public long RetracedSamples { get; init; }

    /// <summary>
    /// The device that rendered, by <see cref="RenderDevice.Name"/>: null for the CPU renderers. A device's render
    /// reports the CPU kernel whose bytes it reproduces as <see cref="Kernel"/>.
    /// </summary>
    public string? Device { get; init; }

    /// <summary>Why an <see cref="RenderKernel.Auto"/> render took the scalar path, when the scene was the reason; else null.</summary>
    public string? ScalarReason { get; init; }
}
