using RayLab.Cameras;

namespace RayLab.Rendering.Exact;

/// <summary>What the ray at a point of the image, in pixel coordinates (X right, Y down), hits and shows.</summary>
/// <param name="scene">The scene.</param>
/// <param name="plane">The frame's image plane.</param>
internal readonly struct PixelRays(Scene scene, ImagePlane plane)
{
    /// <summary>What the ray at pixel coordinates (X, Y) hits: a sphere's index, or −1.</summary>
    /// <param name="x">X.</param>
    /// <param name="y">Y.</param>
    public int Hit(double x, double y) => plane.Nearest(scene, plane.GetRayAt(x, y));

    /// <summary>The colour at pixel coordinates (X, Y): the <see cref="Scene.ColourOf"/> what the ray there hits (flat shading).</summary>
    /// <param name="x">X.</param>
    /// <param name="y">Y.</param>
    public Intensity Colour(double x, double y) => scene.ColourOf(Hit(x, y));

    /// <summary>The colour of a hit (<see cref="Scene.ColourOf"/>).</summary>
    /// <param name="hit">A sphere's index, or −1.</param>
    public Intensity ColourOf(int hit) => scene.ColourOf(hit);
}
