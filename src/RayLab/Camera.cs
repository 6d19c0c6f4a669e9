using RayLab.Cameras;

namespace RayLab;

/// <summary>
/// The lab's abstract camera (section 3): <see cref="Position"/>, <see cref="Target"/>, <see cref="Up"/>,
/// <see cref="NearPlane"/>, <see cref="FarPlane"/> and <see cref="Fov"/>, with the defaults the lab gives
/// (at the origin, looking at (0, 0, 1), up (0, 1, 0), near 1, far 1000).
/// </summary>
/// <remarks>
/// The frame is the lab's: <c>w = −g/|g|</c> with gaze <c>g = Target − Position</c>,
/// <c>u = (up × w)/|up × w|</c>, <c>v = w × u</c>. The lab prints a minus sign in front of u; with it the
/// picture comes out mirrored, so RayLab leaves it out: camera right is image right, camera up is image up.
/// A camera is an immutable record: move it between two renders with a <c>with</c> expression
/// (<c>camera with { Position = new Double3(0, 2, 6) }</c>), which checks each property it sets as the
/// initialiser does and leaves the original as it was. Each render takes its own snapshot of the view
/// (<see cref="GetImagePlane"/> checks the combination of the properties and precomputes everything a renderer
/// needs), so no render sees a camera change under it.
/// </remarks>
public abstract record Camera
{
    private readonly Double3 _position = Double3.Zero;
    private readonly Double3 _target = new(0, 0, 1);
    private readonly Double3 _up = Double3.UnitY;
    private readonly double _near = 1;
    private readonly double _far = 1000;
    private readonly double _fov = 60;
    private readonly Window? _window;

    /// <summary>The eye point e (the centre of projection for a perspective camera). Default (0, 0, 0).</summary>
    /// <exception cref="ArgumentException">A component is not finite.</exception>
    public Double3 Position { get => _position; init => _position = Finite(value, nameof(Position)); }

    /// <summary>The point looked at (a point, as in <c>Matrix4x4.CreateLookAt</c>, not a direction). Default (0, 0, 1).</summary>
    /// <exception cref="ArgumentException">A component is not finite.</exception>
    public Double3 Target { get => _target; init => _target = Finite(value, nameof(Target)); }

    /// <summary>The up vector; it need not be perpendicular to the gaze, only not parallel. Default (0, 1, 0).</summary>
    /// <exception cref="ArgumentException">A component is not finite.</exception>
    public Double3 Up { get => _up; init => _up = Finite(value, nameof(Up)); }

    /// <summary>
    /// The near clipping plane: the smallest visible depth, measured along the gaze from <see cref="Position"/>.
    /// Default 1; must be ≥ 0.
    /// </summary>
    /// <exception cref="ArgumentException">The value is negative or not finite.</exception>
    public double NearPlane
    {
        get => _near;
        init => _near = value >= 0 && double.IsFinite(value)
            ? value
            : throw new ArgumentException($"NearPlane must be a finite number ≥ 0, got {value}.", nameof(NearPlane));
    }

    /// <summary>The far clipping plane: the largest visible depth along the gaze. Default 1000; must exceed <see cref="NearPlane"/>.</summary>
    /// <exception cref="ArgumentException">The value is not positive or not finite.</exception>
    public double FarPlane
    {
        get => _far;
        init => _far = value > 0 && double.IsFinite(value)
            ? value
            : throw new ArgumentException($"FarPlane must be a finite number > 0, got {value}.", nameof(FarPlane));
    }

    /// <summary>
    /// The vertical field of view in degrees, strictly between 0 and 180 (the lab calls it horizontal; v is
    /// the vertical axis, so it is the vertical one). Used by <see cref="PerspectiveCamera"/>. Default 60.
    /// </summary>
    /// <exception cref="ArgumentException">The value is not in (0, 180) or is NaN.</exception>
    public double Fov
    {
        get => _fov;
        init => _fov = value > 0 && value < 180
            ? value
            : throw new ArgumentException($"Fov must be in (0, 180) degrees, got {value}.", nameof(Fov));
    }

    /// <summary>
    /// An explicit window (u0, v0, u1, v1) on the projection plane, or null (the default) for the centred window
    /// with square pixels that the projection's own setting gives (<see cref="Fov"/> for a perspective camera,
    /// <see cref="OrthoCamera.ViewHeight"/> for an orthographic one). A window with u0 ≠ −u1 is off-axis.
    /// </summary>
    /// <exception cref="ArgumentException">The window is empty, inverted or not finite.</exception>
    public Window? Window
    {
        get => _window;
        init
        {
            value?.Validate(nameof(Window));
            _window = value;
        }
    }

    /// <summary>A name for messages and file names (the lab lets a camera carry one).</summary>
    public string Name { get; init; } = "camera";

    /// <summary>True for a camera whose rays are parallel.</summary>
    public abstract bool IsOrthographic { get; }

    /// <summary>
    /// The camera's view of a <paramref name="width"/>×<paramref name="height"/> image: its frame, window
    /// and ray generation, checked and precomputed.
    /// </summary>
    /// <param name="width">The image width in pixels, ≥ 1.</param>
    /// <param name="height">The image height in pixels, ≥ 1.</param>
    /// <exception cref="ArgumentException">
    /// The size is not positive; <see cref="Position"/> equals <see cref="Target"/>; <see cref="Up"/> is
    /// parallel to the gaze; <see cref="NearPlane"/> ≥ <see cref="FarPlane"/>; the window is invalid; or the
    /// numbers are so large or small that the rays overflow double (their directions must square to a finite,
    /// normal double). The exception names the property to change.
    /// </exception>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2208:Instantiate argument exceptions correctly", Justification = "A combination of the camera's properties is wrong: the exception names the property to change, not the method's parameter.")]
    public ImagePlane GetImagePlane(int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        if (!(NearPlane < FarPlane))
        {
            throw new ArgumentException($"NearPlane ({NearPlane}) must be less than FarPlane ({FarPlane}).", nameof(NearPlane));
        }

        Double3 gaze = Target - Position;
        if (!gaze.IsFinite)
        {
            throw new ArgumentException($"Target − Position overflows: the gaze from {Position} to {Target} is not finite.", nameof(Target));
        }

        if (gaze == Double3.Zero)
        {
            throw new ArgumentException($"Position and Target are the same point {Position}: there is no gaze direction.", nameof(Target));
        }

        // Gaze and up scaled by a power of two (exact, so the frame is the same) to keep their squares in range.
        Double3 w = -Double3.Normalize(ScaleToUnit(gaze));
        Double3 up = ScaleToUnit(Up);
        double upLength = up.Length;
        Double3 upCrossW = Double3.Cross(up, w);
        // |up × w| = |up| sin(angle): reject an up vector within ~1e-10 rad of the gaze axis.
        if (!(upLength > 0) || !(upCrossW.Length > 1e-10 * upLength))
        {
            throw new ArgumentException($"Up {Up} is zero or parallel to the gaze {gaze}: the camera frame is undefined.", nameof(Up));
        }

        Double3 u = Double3.Normalize(upCrossW);
        Double3 v = Double3.Cross(w, u);
        Window window = GetWindow((double)width / height);
        window.Validate(Window is null ? WindowSource : nameof(Window));
        ImagePlane plane = CreatePlane(width, height, u, v, w, window);
        CheckRays(plane);
        return plane;
    }

    /// <summary>The window for an image of the given aspect ratio (width / height).</summary>
    /// <param name="aspectRatio">Image width divided by image height.</param>
    protected abstract Window GetWindow(double aspectRatio);

    /// <summary>The property the window comes from when <see cref="Window"/> is null (for error messages).</summary>
    protected abstract string WindowSource { get; }

    /// <summary>
    /// The image plane with this camera's projection: the frame u, v, w at <see cref="Position"/>, the window,
    /// and the near and far planes.
    /// </summary>
    /// <param name="width">The image width.</param>
    /// <param name="height">The image height.</param>
    /// <param name="u">Camera right.</param>
    /// <param name="v">Camera up.</param>
    /// <param name="w">Camera backward.</param>
    /// <param name="window">The checked window.</param>
    private protected abstract ImagePlane CreatePlane(int width, int height, Double3 u, Double3 v, Double3 w, Window window);

    // Every ray must be usable: origin finite and |d|² a finite, normal double (a sphere test squares d). |d|² is
    // convex over the window, so its corners bound it from above; from below, d·w = −s bounds it by s².
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2208:Instantiate argument exceptions correctly", Justification = "The exception names the camera property to change.")]
    private void CheckRays(ImagePlane plane)
    {
        string source = Window is null ? WindowSource : nameof(Window);
        if (!plane.IsOrthographic && !(plane.Distance * plane.Distance >= SmallestNormal))
        {
            throw new ArgumentException($"Distance {plane.Distance} is too small: ray directions would underflow (s² must be at least {SmallestNormal:G3}).", nameof(PerspectiveCamera.Distance));
        }

        foreach ((double alpha, double beta) in new[] { (0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0) })
        {
            Ray ray = plane.GetRay(alpha, beta);
            double d2 = ray.Direction.LengthSquared;
            if (!double.IsFinite(d2))
            {
                throw new ArgumentException($"The view is too large for double: a corner ray's direction {ray.Direction} squares to infinity (keep Distance and the window within about 1e154).", source);
            }

            if (!ray.Origin.IsFinite)
            {
                throw new ArgumentException($"Position {Position} plus the window overflows: the corner ray starts at {ray.Origin}.", Window is null && IsOrthographic ? nameof(Position) : source);
            }
        }
    }

    private const double SmallestNormal = 2.2250738585072014E-308; // 2^−1022

    private static Double3 ScaleToUnit(Double3 v)
    {
        double max = Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));
        return max > 0 ? v * Math.ScaleB(1.0, -Math.ILogB(max)) : v;
    }

    private static Double3 Finite(Double3 value, string name) =>
        value.IsFinite ? value : throw new ArgumentException($"{name} must be finite, got {value}.", name);
}
