
namespace RayLab.PrecisionReport;

/// <summary>
/// One hard case: a single white sphere and a camera whose window frames the hard part. The camera's near
/// plane is 0 and its far plane well beyond the sphere, so the visible hits are exactly the exact decision's
/// hits (<see cref="ExactSphere.Hit"/>: the line meets the ball and the sphere is ahead).
/// </summary>
/// <param name="Name">A short name for the table.</param>
/// <param name="Sphere">The sphere.</param>
/// <param name="Camera">The camera (an explicit window, so any image size frames the same view).</param>
/// <param name="Size">A fixed image side for cases built around their pixel lattice; null: the report's size.</param>
public sealed record HardCase(string Name, Sphere Sphere, Camera Camera, int? Size = null)
{
    /// <summary>The image side of <see cref="Grazing"/>: 64 pixels, centres at half-odd offsets from the window's centre.</summary>
    public const int GrazingSize = 64;

    /// <summary>Every case of the report, in table order.</summary>
    public static IReadOnlyList<HardCase> All { get; } =
    [
        .. from type in new[] { "perspective", "orthographic" }
           from edge in new[] { false, true }
           from ratio in new[] { 1e-4, 1e-5, 1e-6 }
           select TinyFarSphere(type, ratio, edge),
        Horizon(1.0),
        Horizon(0.01),
        FarCentre(1e19),
        FarCentre(1e100),
        .. from type in new[] { "perspective", "orthographic" }
           from inside in new[] { true, false }
           select Grazing(type, inside),
    ];

    /// <summary>
    /// An ordinary frame — a sphere of radius ~0.37 ten units away, generic gaze, 64×64 — that a float packet
    /// renderer accepts, but whose silhouette passes 10⁻⁹ (relative) inside or outside 24 pixel centres: the
    /// sphere is on the gaze axis and the window centred on it, so pixel centres lie at half-odd multiples of the
    /// pixel size from the axis, and the circle of radius √650/2 pixels goes through 24 of them
    /// (25² + 5² = 23² + 11² = 19² + 17² = 650). Float cannot decide those pixels; double can.
    /// </summary>
    /// <param name="type"><c>perspective</c> or <c>orthographic</c>.</param>
    /// <param name="inside">True: the 24 centres are just inside the silhouette (hits); false: just outside.</param>
    public static HardCase Grazing(string type, bool inside)
    {
        var centre = new Double3(3.25, -1.75, 2.5);
        var toEye = new Double3(0.36, -0.48, 0.8);
        const double distance = 10;
        Double3 eye = centre + (distance * toEye);
        double silhouette = Math.Sqrt(650) / 2; // in pixels
        bool perspective = type == "perspective";
        const double pixel = 0.0029; // window units per pixel
        double rho = silhouette * pixel; // silhouette radius on the window
        // Perspective (s = 1): ρ = r/√(D² − r²), so r = Dρ/√(1 + ρ²). Orthographic: r = ρ.
        double radius = (perspective ? distance * rho / Math.Sqrt(1 + (rho * rho)) : rho) * (inside ? 1 + 1e-9 : 1 - 1e-9);
        double half = GrazingSize / 2 * pixel;
        var window = new Window(-half, -half, half, half);
        var up = new Double3(0.1, 1, 0.2);
        Camera camera = perspective
            ? new PerspectiveCamera { Position = eye, Target = centre, Up = up, NearPlane = 0.5, FarPlane = 10 * distance, Window = window }
            : new OrthoCamera { Position = eye, Target = centre, Up = up, NearPlane = 0.5, FarPlane = 10 * distance, Window = window };
        string name = $"{type}, 24 centres 1e-9 {(inside ? "inside" : "outside")} the silhouette";
        return new HardCase(name, new Sphere(centre, radius, Intensity.White), camera, GrazingSize);
    }

    /// <summary>
    /// A sphere of radius 0.37 at distance r/<paramref name="ratio"/>, seen along a generic (not axis-aligned)
    /// gaze. <paramref name="edge"/> false: the window frames the whole sphere. True: the window is zoomed onto
    /// the right-hand silhouette, 2·10⁻⁸ of the silhouette radius wide, so pixel centres straddle it at
    /// relative distances from 10⁻⁸ down to the pixel spacing (10⁻¹⁰ at 100×100).
    /// </summary>
    /// <param name="type"><c>perspective</c> or <c>orthographic</c>.</param>
    /// <param name="ratio">Radius over distance, r/D.</param>
    /// <param name="edge">Zoom onto the silhouette.</param>
    public static HardCase TinyFarSphere(string type, double ratio, bool edge)
    {
        const double r = 0.37;
        double distance = r / ratio;
        var centre = new Double3(3.25, -1.75, 2.5);
        var toEye = new Double3(0.36, -0.48, 0.8); // a unit vector, not axis-aligned
        Double3 eye = centre + (distance * toEye);
        bool perspective = type == "perspective";
        double rho = perspective ? ratio / Math.Sqrt(1 - (ratio * ratio)) : r; // silhouette radius on the window
        Window window = edge
            ? new Window(rho * (1 - 1e-8), rho * -1.1e-8, rho * (1 + 1e-8), rho * 0.9e-8)
            : new Window(-1.5 * rho, -1.3 * rho, 1.4 * rho, 1.6 * rho);
        var up = new Double3(0.1, 1, 0.2);
        Camera camera = perspective
            ? new PerspectiveCamera { Position = eye, Target = centre, Up = up, NearPlane = 0, FarPlane = 10 * distance, Window = window }
            : new OrthoCamera { Position = eye, Target = centre, Up = up, NearPlane = 0, FarPlane = 10 * distance, Window = window };
        string name = FormattableString.Invariant($"{type}, r/D = {ratio:0e0}, {(edge ? "silhouette ±1e-8" : "whole sphere")}");
        return new HardCase(name, new Sphere(centre, r, Intensity.White), camera);
    }

    /// <summary>
    /// A sphere of radius 10⁶ with the eye <paramref name="height"/> above its top, looking at the horizon
    /// along a generic azimuth; the window spans three horizon dips above and below it.
    /// </summary>
    /// <param name="height">The eye's height above the surface.</param>
    public static HardCase Horizon(double height)
    {
        const double R = 1e6;
        var sphere = new Sphere(new Double3(0, -R, 0), R, Intensity.White);
        var eye = new Double3(0, height, 0);
        double dip = Math.Acos(R / (R + height)); // the horizon lies this far below the horizontal
        const double phi = 0.7;
        var gaze = new Double3(Math.Cos(phi) * Math.Cos(dip), -Math.Sin(dip), Math.Sin(phi) * Math.Cos(dip));
        double k = 3 * Math.Tan(dip);
        var camera = new PerspectiveCamera
        {
            Position = eye, Target = eye + gaze, Up = Double3.UnitY, NearPlane = 0, FarPlane = 1e8,
            Window = new Window(-k, -1.1 * k, 0.9 * k, k),
        };
        return new HardCase(FormattableString.Invariant($"R = 1e6, eye {height:G} above, horizon"), sphere, camera);
    }

    /// <summary>
    /// A sphere whose centre is <paramref name="scale"/> away along a generic direction, with radius a quarter
    /// of that distance, seen from the origin: squares of the distances overflow float (and, near 10¹⁵⁴, double).
    /// </summary>
    /// <param name="scale">The distance scale of the centre.</param>
    public static HardCase FarCentre(double scale)
    {
        var centre = new Double3(0.36 * scale, -0.48 * scale, 0.8 * scale);
        double distance = Math.Sqrt(ExactSphere.LengthSquared(centre));
        const double ratio = 0.25;
        double rho = ratio / Math.Sqrt(1 - (ratio * ratio));
        var camera = new PerspectiveCamera
        {
            Position = Double3.Zero, Target = centre, Up = new Double3(0.1, 1, 0.2), NearPlane = 0, FarPlane = 10 * distance,
            Window = new Window(-1.5 * rho, -1.3 * rho, 1.4 * rho, 1.6 * rho),
        };
        return new HardCase(FormattableString.Invariant($"centre at {scale:0e0}, r/D = 0.25"), new Sphere(centre, ratio * distance, Intensity.White), camera);
    }
}
