using Bitmap = SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>;

namespace RayLab.ImageSharp;

/// <summary>RayLab's <see cref="Image"/> to an ImageSharp <c>Image&lt;Rgb24&gt;</c> and back: one copy of the pixels each way.</summary>
public static class ImageConversions
{
    /// <summary>A new ImageSharp bitmap with <paramref name="image"/>'s pixels (one copy).</summary>
    /// <param name="image">RayLab's image.</param>
    /// <returns>The bitmap; dispose it when done.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="image"/> is null.</exception>
    public static Bitmap ToImageSharp(this Image image)
    {
        ArgumentNullException.ThrowIfNull(image);
        return SixLabors.ImageSharp.Image.LoadPixelData<SixLabors.ImageSharp.PixelFormats.Rgb24>(image.PixelBytes, image.Width, image.Height);
    }

    /// <summary>A new RayLab image with <paramref name="bitmap"/>'s pixels (one copy; the first frame of an animation).</summary>
    /// <param name="bitmap">The ImageSharp bitmap.</param>
    /// <returns>RayLab's image.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="bitmap"/> is null.</exception>
    public static Image ToRayLabImage(this Bitmap bitmap)
    {
        ArgumentNullException.ThrowIfNull(bitmap);
        var image = new Image(bitmap.Width, bitmap.Height);
        bitmap.CopyPixelDataTo(image.PixelBytes);
        return image;
    }
}
