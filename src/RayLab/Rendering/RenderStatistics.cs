namespace RayLab.Rendering;

/// <summary>What a render did: primary rays traced and the time spent rendering (not loading or encoding).</summary>
/// <param name="PrimaryRays">Primary rays traced.</param>
/// <param name="RenderTime">Wall-clock time of the render loop.</param>
public readonly record struct RenderStatistics(long PrimaryRays, TimeSpan RenderTime)
{
    /// <summary>Primary rays per second (0 for an instant render).</summary>
    public double RaysPerSecond => RenderTime > TimeSpan.Zero ? PrimaryRays / RenderTime.TotalSeconds : 0;
}
