using System.Runtime.CompilerServices;
using RayLab.Simd;

namespace RayLab.Cameras;

/// <summary>
/// Pixel coordinates to the window (section 3.2), the one place for it: a point (X, Y) of the image, X to the
/// right and Y down, pixel (x, row) covering [x, x + 1] × [row, row + 1], lies at window point
/// <c>α = X/W</c>, <c>β = 1 − Y/H</c>. The scalar form (double) and the lane form (float, for the packet
/// kernel) side by side.
/// </summary>
/// <remarks>
/// A sample (sx, sy) ∈ [0, 1)² inside pixel (x, row) is at X = x + sx, Y = row + sy; the pixel centre is
/// sx = sy = 0.5. The lane form computes the same map as one multiply-add per sample:
/// <c>α = sx/W + x/W</c> and <c>β = (1 − row/H) − sy/H</c>, the second terms fixed for the packet.
/// </remarks>
internal static class WindowMapping
{
    /// <summary>α = X/W.</summary>
    /// <param name="x">X, in pixels from the image's left edge.</param>
    /// <param name="width">The image width W.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Alpha(double x, int width) => Alpha(x, (double)width);

    /// <summary>β = 1 − Y/H.</summary>
    /// <param name="y">Y, in pixels from the image's top edge.</param>
    /// <param name="height">The image height H.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Beta(double y, int height) => Beta(y, (double)height);

    /// <summary>α = X/W for a grid finer than the pixels: X and W counted in steps of a power of two of a pixel (exactly the α of X/step, W/step).</summary>
    /// <param name="x">X, in steps from the image's left edge.</param>
    /// <param name="width">The image width W, in steps.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Alpha(double x, double width) => x / width;

    /// <summary>β = 1 − Y/H for a grid finer than the pixels: Y and H counted in steps of a power of two of a pixel.</summary>
    /// <param name="y">Y, in steps from the image's top edge.</param>
    /// <param name="height">The image height H, in steps.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Beta(double y, double height) => 1.0 - (y / height);

    /// <summary>The lane form's per-packet α term x/W for lanes x0, x0 + 1, …; <paramref name="inverseWidth"/> is 1/W.</summary>
    /// <param name="x0">The packet's first pixel column.</param>
    /// <param name="inverseWidth">1/W in every lane.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL PacketLeft<TL>(int x0, TL inverseWidth)
        where TL : struct, ILanes<TL> => (TL.Broadcast(x0) + TL.Indices) * inverseWidth;

    /// <summary>The lane form's per-row β term 1 − row/H (the scalar <see cref="Beta(double, int)"/> of the row's top edge).</summary>
    /// <param name="row">The pixel row, 0 at the top.</param>
    /// <param name="height">The image height H.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL RowTop<TL>(int row, int height)
        where TL : struct, ILanes<TL> => TL.Broadcast((float)Beta(row, height));

    /// <summary>α per lane: sx/W + x/W.</summary>
    /// <param name="sx">The sample's offset inside its pixel, per lane.</param>
    /// <param name="inverseWidth">1/W.</param>
    /// <param name="left">x/W from <see cref="PacketLeft{TL}"/>.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Alpha<TL>(TL sx, TL inverseWidth, TL left)
        where TL : struct, ILanes<TL> => TL.MultiplyAdd(sx, inverseWidth, left);

    /// <summary>β per lane: (1 − row/H) − sy/H.</summary>
    /// <param name="sy">The sample's offset inside its pixel, per lane.</param>
    /// <param name="inverseHeight">1/H.</param>
    /// <param name="rowTop">1 − row/H from <see cref="RowTop{TL}"/>.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static TL Beta<TL>(TL sy, TL inverseHeight, TL rowTop)
        where TL : struct, ILanes<TL> => TL.NegatedMultiplyAdd(sy, inverseHeight, rowTop);
}
