using System.Runtime.InteropServices;
using SixLabors.ImageSharp.Advanced;
using Bitmap = SixLabors.ImageSharp.Image<SixLabors.ImageSharp.PixelFormats.Rgb24>;

namespace RayLab.ImageSharp;

/// <summary>
/// An ImageSharp <c>Image&lt;Rgb24&gt;</c> as the rows a renderer fills: each row is the bitmap's own pixel memory
/// (ImageSharp keeps every row contiguous, even when a large frame spans several buffers), seen as RayLab's
/// <see cref="RayLab.Rgb24"/>, which has ImageSharp's layout (R, G, B in 3 bytes). Nothing is copied.
/// </summary>
internal sealed class BitmapRows : IPixelRows
{
    private readonly Bitmap _bitmap;

    public BitmapRows(Bitmap bitmap)
    {
        ArgumentNullException.ThrowIfNull(bitmap, nameof(bitmap));
        _bitmap = bitmap;
        Width = bitmap.Width;
        Height = bitmap.Height;
    }

    public int Width { get; }

    public int Height { get; }

    public Span<RayLab.Rgb24> GetRowSpan(int y)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(y);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, Height);
        return MemoryMarshal.Cast<SixLabors.ImageSharp.PixelFormats.Rgb24, RayLab.Rgb24>(_bitmap.DangerousGetPixelRowMemory(y).Span);
    }
}
