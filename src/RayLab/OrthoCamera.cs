using RayLab.Cameras;

namespace RayLab;

/// <summary>
/// The lab's orthographic camera (section 3.1): parallel rays along the gaze, one per sample, starting on the
/// plane through <see cref="Camera.Position"/>. The window is <see cref="ViewHeight"/> world units high
/// (default 2: the lab's [−1, 1]) and as wide as the aspect ratio makes it, unless <see cref="Camera.Window"/> sets it
/// (in world units, on the plane through the position).
/// </summary>
/// <remarks>
/// The lab's own loop starts every ray at one point, which is a perspective projection; here each ray starts
/// at its own point on the plane. The lab's pixel size 2/resolution uses the right resolution for each axis.
/// </remarks>
public sealed record OrthoCamera : Camera
{
    private readonly double _height = 2;

    /// <summary>The view height in world units, &gt; 0. Default 2.</summary>
    /// <exception cref="ArgumentException">The value is not positive or not finite.</exception>
    public double ViewHeight
    {
        get => _height;
        init => _height = value > 0 && double.IsFinite(value)
            ? value
            : throw new ArgumentException($"ViewHeight must be a finite number > 0, got {value}.", nameof(ViewHeight));
    }

    /// <inheritdoc />
    public override bool IsOrthographic => true;

    /// <summary>The explicit window, or the centred one <see cref="ViewHeight"/> high with square pixels.</summary>
    /// <param name="aspectRatio">Image width / height.</param>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2208:Instantiate argument exceptions correctly", Justification = "The exception names the camera property to change.")]
    protected override Window GetWindow(double aspectRatio)
    {
        if (Window is { } window)
        {
            return window;
        }

        if (!double.IsFinite(ViewHeight * aspectRatio))
        {
            throw new ArgumentException($"ViewHeight {ViewHeight} × W/H overflows: the window would be infinite.", nameof(ViewHeight));
        }

        return RayLab.Window.Centered(ViewHeight * aspectRatio, ViewHeight);
    }

    /// <summary>The plane with the orthographic projection (<see cref="OrthographicProjection"/>); its distance s is 1 (unused).</summary>
    private protected override ImagePlane CreatePlane(int width, int height, Double3 u, Double3 v, Double3 w, Window window) =>
        new ImagePlane<OrthographicProjection>(width, height, Position, u, v, w, window, 1, NearPlane, FarPlane);

    /// <inheritdoc />
    protected override string WindowSource => nameof(ViewHeight);
}
