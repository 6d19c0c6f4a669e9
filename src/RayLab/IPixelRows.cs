namespace RayLab;

/// <summary>
/// An 8-bit RGB picture that a renderer fills row by row: RayLab's own <see cref="Image"/>, or, with the
/// <c>RayLab.ImageSharp</c> package, an ImageSharp <c>Image&lt;Rgb24&gt;</c> (the lab's bitmap, "obraz", section 2.2).
/// The renderer writes each row straight into the memory this returns, from whichever thread renders that row,
/// so rows must be independent: writing one row never touches another.
/// </summary>
public interface IPixelRows
{
    /// <summary>The width W in pixels, ≥ 1.</summary>
    int Width { get; }

    /// <summary>The height H in pixels, ≥ 1.</summary>
    int Height { get; }

    /// <summary>Row <paramref name="y"/> (0 at the top) as W pixels, the picture's own memory (no copy).</summary>
    /// <param name="y">The row, 0 ≤ y &lt; H.</param>
    /// <returns>The row's pixels.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The row is outside the picture.</exception>
    Span<Rgb24> GetRowSpan(int y);
}
