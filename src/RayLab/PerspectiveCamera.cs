using RayLab.Cameras;

namespace RayLab;

/// <summary>
/// The lab's perspective camera (section 3.2): rays from the eye e through the window on a plane at distance
/// s in front of it. The window follows from <see cref="Camera.Fov"/> and the image's aspect ratio (square
/// pixels, centred), unless <see cref="Camera.Window"/> sets it explicitly (an off-axis view) on the plane at
/// <see cref="Distance"/>.
/// </summary>
public sealed record PerspectiveCamera : Camera
{
    private readonly double _distance = 1;

    /// <summary>The plane distance s, &gt; 0. Default 1.</summary>
    /// <exception cref="ArgumentException">The value is not positive or not finite.</exception>
    public double Distance
    {
        get => _distance;
        init => _distance = value > 0 && double.IsFinite(value)
            ? value
            : throw new ArgumentException($"Distance must be a finite number > 0, got {value}.", nameof(Distance));
    }

    /// <inheritdoc />
    public override bool IsOrthographic => false;

    /// <summary>The plane with the perspective projection (<see cref="PerspectiveProjection"/>) at distance <see cref="Distance"/>.</summary>
    private protected override ImagePlane CreatePlane(int width, int height, Double3 u, Double3 v, Double3 w, Window window) =>
        new ImagePlane<PerspectiveProjection>(width, height, Position, u, v, w, window, Distance, NearPlane, FarPlane);

    /// <summary>
    /// The explicit window, or the centred one with <c>(v1 − v0)/(2 s) = tan(Fov/2)</c> and
    /// <c>(u1 − u0)/(v1 − v0) = W/H</c>.
    /// </summary>
    /// <param name="aspectRatio">Image width / height.</param>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2208:Instantiate argument exceptions correctly", Justification = "The exception names the camera property to change.")]
    protected override Window GetWindow(double aspectRatio)
    {
        if (Window is { } window)
        {
            return window;
        }

        double v1 = Distance * Math.Tan(Fov * Math.PI / 360.0);
        if (!double.IsFinite(2 * v1 * aspectRatio) || !double.IsFinite(2 * v1))
        {
            throw new ArgumentException($"Distance {Distance} × tan(Fov/2) × W/H overflows: the window would be infinite.", nameof(Distance));
        }

        return new Window(-v1 * aspectRatio, -v1, v1 * aspectRatio, v1);
    }

    /// <inheritdoc />
    protected override string WindowSource => nameof(Distance);
}
