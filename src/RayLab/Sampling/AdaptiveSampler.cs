using System.Globalization;

namespace RayLab.Sampling;

/// <summary>
/// The lab's adaptive antialiasing (section 4, after mental ray): trace the four corners of a pixel, and where
/// they disagree by more than <see cref="Contrast"/> its centre too (the quincunx), subdividing where the values
/// disagree, down to <see cref="MaxDepth"/>. Rendered by <see cref="RayLab.Renderer.Render(Scene, RayLab.Camera, AdaptiveSampler, RayLab.Image, float[])"/>.
/// </summary>
/// <remarks>
/// <para>The rule, for a square at depth d (the pixel is depth 0) with corners c₁…c₄ and centre X: quadrant q
/// (the quarter that holds corner c_q) is <em>refined</em> — its two missing corners and its centre are
/// traced and it is treated as a square at depth d + 1 — when d &lt; <see cref="MaxDepth"/> and either
/// d &lt; <see cref="MinDepth"/>, or c_q and X differ by more than <see cref="Contrast"/> in some channel, or
/// two of the square's corners differ by more than <see cref="Contrast"/> while every corner agrees with X
/// (then all four quadrants are refined). This is the lab's worked example: quadrants whose corner agrees
/// with the centre stay as they are, the others are subdivided.</para>
/// <para>A pixel whose four corners agree (and <see cref="MinDepth"/> is 0) is flat: its value is the mean of
/// its corners and its centre is not traced, so a flat image costs one ray per pixel (the corners are shared).
/// With <see cref="Quincunx"/> every pixel's centre is traced, as the lab's description lists it (A, B, C, D and
/// E), at two rays per pixel or more; the combination rule gives the same value for a flat pixel either way.</para>
/// <para>The value follows the lab's combination rule: <c>value = ¼ Σ_q v(q)</c> with
/// <c>v(q) = (c_q + X)/2</c> for a quadrant that was not refined and <c>v(q) = value(q)</c> for one that was.</para>
/// <para>No point is traced twice: pixel corners are shared by up to four pixels, sub-square corners by
/// neighbouring squares, inside a pixel and across pixel edges. The scheme is biased: a feature that lies
/// between the traced points (a sphere smaller than a pixel) can vanish; <see cref="Guard"/> prevents that.</para>
/// </remarks>
public sealed class AdaptiveSampler
{
    /// <summary>The deepest subdivision supported: squares of 1/1024 pixel.</summary>
    public const int MaxSupportedDepth = 10;

    /// <summary>Creates the sampler.</summary>
    /// <param name="minDepth">Subdivide every pixel at least this deep (0 ≤ minDepth ≤ maxDepth).</param>
    /// <param name="maxDepth">Never subdivide deeper (0 to <see cref="MaxSupportedDepth"/>).</param>
    /// <param name="contrast">The spatial contrast threshold per channel, ≥ 0 and finite.</param>
    /// <param name="quincunx">Trace every pixel's centre, even where its corners agree.</param>
    /// <param name="guard">Also refine, down to <paramref name="maxDepth"/>, every square a sphere's silhouette may cross (<see cref="Guard"/>).</param>
    /// <exception cref="ArgumentOutOfRangeException">A depth or the contrast is out of range.</exception>
    public AdaptiveSampler(int minDepth = 0, int maxDepth = 3, double contrast = 0.1, bool quincunx = false, bool guard = false)
    {
        if (maxDepth is < 0 or > MaxSupportedDepth)
        {
            throw new ArgumentOutOfRangeException(nameof(maxDepth), maxDepth, $"The maximum depth must be from 0 to {MaxSupportedDepth}.");
        }

        if (minDepth < 0 || minDepth > maxDepth)
        {
            throw new ArgumentOutOfRangeException(nameof(minDepth), minDepth, $"The minimum depth must be from 0 to the maximum depth ({maxDepth}).");
        }

        if (!(contrast >= 0) || !double.IsFinite(contrast))
        {
            throw new ArgumentOutOfRangeException(nameof(contrast), contrast, "The contrast must be a finite number ≥ 0.");
        }

        MinDepth = minDepth;
        MaxDepth = maxDepth;
        Contrast = contrast;
        Quincunx = quincunx;
        Guard = guard;
    }

    /// <summary>The name the console and scene files use.</summary>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Performance", "CA1822:Mark members as static", Justification = "An instance property, like IPixelSampler.Name, so a student reads every sampler's name the same way.")]
    public string Name => "adaptive";

    /// <summary>Every pixel is subdivided at least this deep.</summary>
    public int MinDepth { get; }

    /// <summary>No square is subdivided below this depth (the pixel is depth 0).</summary>
    public int MaxDepth { get; }

    /// <summary>The spatial contrast: two values differ when some channel differs by more than this.</summary>
    public double Contrast { get; }

    /// <summary>
    /// True: every pixel's centre is traced (the lab's quincunx, ≥ 2 rays per pixel). False (the default): only
    /// where the pixel's corners disagree (about 1 ray per pixel where the image is flat).
    /// </summary>
    public bool Quincunx { get; }

    /// <summary>
    /// True: the guard, our own addition after Whitted (1980), who subdivided where a ray passed close to an
    /// object without hitting it. A square is also refined (down to <see cref="MaxDepth"/>) when a sphere's
    /// silhouette may pass through it although its traced points agree: the ray through the square's centre passes
    /// at distance p from the sphere's centre, and no ray of the square is farther than m from it (m from the square's
    /// size: its half-diagonal on the window, turned into an angle about the eye for the perspective camera), so the
    /// square is refined when |p − r| ≤ m. Conservative — no silhouette that crosses a square is missed, whichever
    /// camera and window — and cheap away from silhouettes. False (the default): the lab's rule alone, which loses
    /// a sliver of a sphere between traced points.
    /// </summary>
    public bool Guard { get; }

    /// <summary>True when <paramref name="a"/> and <paramref name="b"/> differ by more than <see cref="Contrast"/> in some channel.</summary>
    /// <param name="a">One value.</param>
    /// <param name="b">The other.</param>
    public bool Differ(Intensity a, Intensity b) =>
        Math.Abs(a.R - b.R) > Contrast || Math.Abs(a.G - b.G) > Contrast || Math.Abs(a.B - b.B) > Contrast;

    /// <summary>Describes the settings, e.g. <c>adaptive (depth 0–3, contrast 0.1)</c>.</summary>
    public override string ToString() =>
        string.Create(CultureInfo.InvariantCulture, $"adaptive (depth {MinDepth}–{MaxDepth}, contrast {Contrast:G6}{(Quincunx ? ", quincunx" : "")}{(Guard ? ", guard" : "")})");
}
