using System.Runtime.CompilerServices;
using RayLab.Geometry;

namespace RayLab.Cameras;

/// <summary>
/// A camera's view of a W×H image, checked and precomputed by <see cref="Camera.GetImagePlane"/>: the lab's
/// frame u, v, w, the window (u0, v0, u1, v1), the vectors a, b, c of section 3.2, and the mapping from a
/// pixel sample to a ray.
/// </summary>
/// <remarks>
/// Pixel to window: a sample at (sx, sy) ∈ [0, 1)² inside pixel (x, row) has
/// <c>α = (x + sx)/W</c> and <c>β = 1 − (row + sy)/H</c>; row 0 is the top row and the pixel centre is
/// sx = sy = 0.5. Each α is computed from the integer pixel index, never by accumulating steps.
/// </remarks>
public sealed class ImagePlane
{
    internal ImagePlane(int width, int height, Double3 eye, Double3 u, Double3 v, Double3 w, Window window,
        double distance, bool orthographic, double near, double far)
    {
        Width = width;
        Height = height;
        Eye = eye;
        U = u;
        V = v;
        W = w;
        Window = window;
        Distance = distance;
        IsOrthographic = orthographic;
        A = window.Width * u;
        B = window.Height * v;
        C = (window.U0 * u) + (window.V0 * v) - (orthographic ? Double3.Zero : distance * w);
        // A hit is visible when its depth along the gaze lies in [near, far]. The gaze component of every
        // direction this plane makes is the same: s for the perspective ray p − e, 1 for the orthographic −w.
        double depthPerT = orthographic ? 1 : distance;
        TMin = near / depthPerT;
        TMax = far / depthPerT;
    }

    /// <summary>The image width W in pixels.</summary>
    public int Width { get; }

    /// <summary>The image height H in pixels.</summary>
    public int Height { get; }

    /// <summary>The eye e (the camera's Position).</summary>
    public Double3 Eye { get; }

    /// <summary>Camera right, u (image right).</summary>
    public Double3 U { get; }

    /// <summary>Camera up, v (image up).</summary>
    public Double3 V { get; }

    /// <summary>Camera backward, w = −gaze/|gaze|.</summary>
    public Double3 W { get; }

    /// <summary>The window corners u0, v0, u1, v1.</summary>
    public Window Window { get; }

    /// <summary>The plane distance s (perspective).</summary>
    public double Distance { get; }

    /// <summary>True when rays are parallel (orthographic camera).</summary>
    public bool IsOrthographic { get; }

    /// <summary>The lab's a = (u1 − u0) u: the window's horizontal edge.</summary>
    public Double3 A { get; }

    /// <summary>The lab's b = (v1 − v0) v: the window's vertical edge.</summary>
    public Double3 B { get; }

    /// <summary>
    /// The lab's c = u0 u + v0 v − s w: the window's lower-left corner relative to e (orthographic: without the
    /// −s w term, since the rays start on the plane through e).
    /// </summary>
    public Double3 C { get; }

    /// <summary>The smallest visible ray parameter: the near plane's depth in units of t.</summary>
    public double TMin { get; }

    /// <summary>The largest visible ray parameter: the far plane's depth in units of t.</summary>
    public double TMax { get; }

    /// <summary>α = (x + sx)/W for a sample sx ∈ [0, 1) inside pixel column x.</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="sx">The sample's offset inside the pixel, left to right.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Alpha(int x, double sx) => (x + sx) / Width;

    /// <summary>β = 1 − (row + sy)/H for a sample sy ∈ [0, 1) inside pixel row <paramref name="row"/> (row 0 on top).</summary>
    /// <param name="row">The pixel row, 0 at the top.</param>
    /// <param name="sy">The sample's offset inside the pixel, top to bottom.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public double Beta(int row, double sy) => 1.0 - ((row + sy) / Height);

    /// <summary>
    /// The ray through window point (α, β) ∈ [0, 1]², α left to right and β bottom to top. Perspective: the
    /// lab's <c>e + t (p − e)</c> with <c>p = e + c + α a + β b</c>. Orthographic: from the point
    /// <c>e + c + α a + β b</c> on the plane through e, along the gaze −w.
    /// </summary>
    /// <param name="alpha">α, the horizontal window coordinate.</param>
    /// <param name="beta">β, the vertical window coordinate.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Ray GetRay(double alpha, double beta)
    {
        Double3 onWindow = C + (alpha * A) + (beta * B);
        return IsOrthographic
            ? new Ray(Eye + onWindow, -W)
            : new Ray(Eye, onWindow);
    }

    /// <summary>The ray through the sample (sx, sy) of pixel (x, row).</summary>
    /// <param name="x">The pixel column.</param>
    /// <param name="row">The pixel row, 0 at the top.</param>
    /// <param name="sx">Offset inside the pixel, 0..1 left to right.</param>
    /// <param name="sy">Offset inside the pixel, 0..1 top to bottom.</param>
    public Ray GetPixelRay(int x, int row, double sx, double sy) => GetRay(Alpha(x, sx), Beta(row, sy));
}
