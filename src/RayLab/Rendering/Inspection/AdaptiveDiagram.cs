using RayLab.Sampling;
using RayLab.Cameras;
using RayLab.Rendering.Exact;

namespace RayLab.Rendering.Inspection;

/// <summary>A point the lab's adaptive recursion traced in one pixel, labelled as the lab labels them.</summary>
/// <param name="Label">A, B, C, D (the corners), E (the centre), then F, G, H, J, … in trace order (the lab skips I and O).</param>
/// <param name="X">Offset to the right inside the pixel, 0 … 1.</param>
/// <param name="Y">Offset downward inside the pixel, 0 … 1.</param>
/// <param name="Value">What the ray saw.</param>
/// <param name="Weight">The point's share of the pixel's value under the lab's combination rule (the shares add up to 1).</param>
public sealed record AdaptivePoint(string Label, double X, double Y, Intensity Value, double Weight);

/// <summary>A square of the recursion, in pixel units (x right, y down).</summary>
/// <param name="X">Left edge.</param>
/// <param name="Y">Top edge.</param>
/// <param name="Size">Side.</param>
/// <param name="Depth">0 for the pixel, 1 for its quadrants, ….</param>
/// <param name="Refined">True when the recursion went into this square (it traced its centre).</param>
public sealed record AdaptiveSquare(double X, double Y, double Size, int Depth, bool Refined);

/// <summary>
/// The lab's adaptive antialiasing diagram (section 4.1.4) for one pixel of a real scene: the squares the recursion
/// made, each traced point labelled in trace order, the weight the combination rule gives it, and the pixel's value
/// against its exact area-weighted colour. It runs the renderer's own recursion (<see cref="AdaptiveSampler"/>), traced as <see cref="Renderer.TracePixel"/> traces it (<see cref="AdaptiveTrace"/>).
/// </summary>
public sealed class AdaptiveDiagram
{
    private AdaptiveDiagram(int px, int py, AdaptiveSampler sampler, IReadOnlyList<AdaptivePoint> points, IReadOnlyList<AdaptiveSquare> squares, Intensity value, Intensity exact)
    {
        PixelX = px;
        PixelY = py;
        Sampler = sampler;
        Points = points;
        Squares = squares;
        Value = value;
        Exact = exact;
    }

    /// <summary>The pixel's column.</summary>
    public int PixelX { get; }

    /// <summary>The pixel's row (0 at the top).</summary>
    public int PixelY { get; }

    /// <summary>The settings the recursion ran with.</summary>
    public AdaptiveSampler Sampler { get; }

    /// <summary>The traced points, in trace order.</summary>
    public IReadOnlyList<AdaptivePoint> Points { get; }

    /// <summary>Every square the recursion looked at: the pixel, and the quadrants of each refined square.</summary>
    public IReadOnlyList<AdaptiveSquare> Squares { get; }

    /// <summary>The pixel's value by the lab's rule: Σ weight × value.</summary>
    public Intensity Value { get; }

    /// <summary>The pixel's exact area-weighted colour (<see cref="RenderMethod.Exact"/>).</summary>
    public Intensity Exact { get; }

    /// <summary>The scene inside this diagram's pixel, traced at <paramref name="resolution"/>² points (cell centres): the diagram's background.</summary>
    /// <param name="scene">The scene the diagram was made from.</param>
    /// <param name="camera">Its camera.</param>
    /// <param name="width">The render's W.</param>
    /// <param name="height">The render's H.</param>
    /// <param name="resolution">Points per side, 1 to 4096.</param>
    /// <returns>A <paramref name="resolution"/>² image of the pixel.</returns>
    public Image TraceInside(Scene scene, Camera camera, int width, int height, int resolution)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentOutOfRangeException.ThrowIfLessThan(resolution, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(resolution, 4096);
        ImagePlane plane = camera.GetImagePlane(width, height);
        var image = new Image(resolution, resolution);
        for (int j = 0; j < resolution; j++)
        {
            for (int i = 0; i < resolution; i++)
            {
                double sx = (i + 0.5) / resolution, sy = (j + 0.5) / resolution;
                image.SetPixel(i, j, plane.Trace(scene, plane.GetRay(plane.Alpha(PixelX, sx), WindowMapping.Beta(PixelY + sy, height))));
            }
        }

        return image;
    }

    /// <summary>Traces pixel (<paramref name="px"/>, <paramref name="py"/>) of a W×H render.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">W.</param>
    /// <param name="height">H.</param>
    /// <param name="sampler">The adaptive settings.</param>
    /// <param name="px">The pixel's column.</param>
    /// <param name="py">The pixel's row.</param>
    /// <returns>The diagram.</returns>
    /// <exception cref="ArgumentException">The pixel is outside the image, or the camera's settings are invalid.</exception>
    public static AdaptiveDiagram Trace(Scene scene, Camera camera, int width, int height, AdaptiveSampler sampler, int px, int py)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(sampler);
        ArgumentOutOfRangeException.ThrowIfNegative(px);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(px, width);
        ArgumentOutOfRangeException.ThrowIfNegative(py);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(py, height);
        ImagePlane plane = camera.GetImagePlane(width, height);
        // The pixel's row alone: a row's exact values do not depend on the rows rendered with it.
        var row = new RenderOptions(1, RenderKernel.Scalar, null, default) { FirstRow = py, EndRow = py + 1 };
        Intensity exact = ExactRenderer.RenderLinear(scene, plane, row)[px];
        return Build(scene, plane, sampler, px, py, exact);
    }

    /// <summary>
    /// Finds an edge pixel for the diagram: among the pixels an edge crosses (exact value not one flat colour),
    /// preferring those the edge cuts through the middle (two corners on each side), the one whose recursion traced
    /// a number of points closest to <paramref name="wantedPoints"/> (the lab's example has 16, A to R), the first in
    /// reading order on a tie.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="camera">The camera.</param>
    /// <param name="width">W.</param>
    /// <param name="height">H.</param>
    /// <param name="sampler">The adaptive settings.</param>
    /// <param name="wantedPoints">How many traced points the diagram should show, ≥ 4.</param>
    /// <returns>The diagram of that pixel.</returns>
    /// <exception cref="InvalidOperationException">No edge crosses the image.</exception>
    public static AdaptiveDiagram FindEdgePixel(Scene scene, Camera camera, int width, int height, AdaptiveSampler sampler, int wantedPoints = 16)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(camera);
        ArgumentNullException.ThrowIfNull(sampler);
        ImagePlane plane = camera.GetImagePlane(width, height);
        Intensity[] exact = ExactRenderer.RenderLinear(scene, plane, new RenderOptions(1, RenderKernel.Scalar, null, default));
        var colours = Enumerable.Range(-1, scene.Spheres.Count + 1).Select(scene.ColourOf).ToHashSet();
        AdaptiveDiagram? best = null;
        for (int i = 0; i < exact.Length; i++)
        {
            if (colours.Contains(exact[i]))
            {
                continue; // no edge inside this pixel
            }

            AdaptiveDiagram candidate = Build(scene, plane, sampler, i % width, i / width, exact[i]);
            if (best is null || Score(candidate) < Score(best))
            {
                best = candidate;
            }
        }

        return best ?? throw new InvalidOperationException("No edge crosses the image: the adaptive diagram needs an edge pixel.");

        int Score(AdaptiveDiagram d)
        {
            // Corners A, B, C, D split two and two (an edge through the middle), else a penalty of 1000.
            Intensity[] corners = [.. d.Points.Take(4).Select(p => p.Value)];
            bool halves = corners.Distinct().Count() == 2 && corners.Count(c => c == corners[0]) == 2;
            return (halves ? 0 : 1000) + Math.Abs(d.Points.Count - wantedPoints);
        }
    }

    private static AdaptiveDiagram Build(Scene scene, ImagePlane plane, AdaptiveSampler sampler, int px, int py, Intensity exact)
    {
        AdaptiveTrace trace = AdaptiveTrace.Run(scene, plane, sampler, px, py);
        var points = new List<AdaptivePoint>(trace.Points.Count);
        Intensity value = default;
        for (int i = 0; i < trace.Points.Count; i++)
        {
            TracedPoint p = trace.Points[i];
            value += p.Weight * p.Value;
            points.Add(new AdaptivePoint(Label(i), p.X, p.Y, p.Value, p.Weight));
        }

        return new AdaptiveDiagram(px, py, sampler, points, trace.Squares, value, exact);
    }

    /// <summary>The lab's labels: A … Z without I and O, then AA, AB, ….</summary>
    /// <param name="index">The trace order, from 0.</param>
    public static string Label(int index)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        const string Letters = "ABCDEFGHJKLMNPQRSTUVWXYZ";
        return index < Letters.Length ? Letters[index].ToString() : Label((index / Letters.Length) - 1) + Letters[index % Letters.Length];
    }
}
