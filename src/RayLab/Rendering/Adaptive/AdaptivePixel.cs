using System.Runtime.CompilerServices;
using RayLab.Sampling;

namespace RayLab.Rendering.Adaptive;

/// <summary>Gives the value at a point of the adaptive lattice; the lattice has 2^(MaxDepth+1) steps per pixel.</summary>
internal interface ILatticeSource
{
    /// <summary>The value at lattice point (lx, ly), x to the right and y downward from the image's top-left corner.</summary>
    /// <param name="lx">Lattice column.</param>
    /// <param name="ly">Lattice row.</param>
    /// <param name="weight">The share of this point's ray that the asking pixel is charged (for the heat map).</param>
    Intensity At(long lx, long ly, out double weight);

    /// <summary>The value at the centre of a square: asked for once only, so it needs no cache (weight 1).</summary>
    /// <param name="lx">Lattice column.</param>
    /// <param name="ly">Lattice row.</param>
    Intensity Centre(long lx, long ly);

    /// <summary>True when a sphere's silhouette may pass through the square of <paramref name="size"/> steps at (x0, y0) (<see cref="AdaptiveSampler.Guard"/>).</summary>
    /// <param name="x0">The square's left lattice column.</param>
    /// <param name="y0">The square's top lattice row.</param>
    /// <param name="size">The square's side in lattice steps.</param>
    bool MayCross(long x0, long y0, long size);
}

/// <summary>The lab's adaptive recursion for one pixel (see <see cref="AdaptiveSampler"/>), its values combined by <see cref="CombinationRule"/>.</summary>
internal static class AdaptivePixel
{
    /// <summary>The pixel's value; <paramref name="samples"/> receives the rays charged to it (corners ¼, edge points ½).</summary>
    public static Intensity Evaluate<TSource>(AdaptiveSampler sampler, ref TSource source, int px, int py, out double samples)
        where TSource : ILatticeSource
    {
        long size = 1L << (sampler.MaxDepth + 1);
        long x0 = px * size, y0 = py * size;
        samples = 0;
        Intensity tl = Take(ref source, x0, y0, ref samples);
        Intensity tr = Take(ref source, x0 + size, y0, ref samples);
        Intensity bl = Take(ref source, x0, y0 + size, ref samples);
        Intensity br = Take(ref source, x0 + size, y0 + size, ref samples);
        if (!sampler.Quincunx && sampler.MinDepth == 0 && !CornersDiffer(sampler, tl, tr, bl, br)
            && !(sampler.Guard && source.MayCross(x0, y0, size)))
        {
            // A flat pixel: the mean of its corners, which is what the combination rule gives for any centre that
            // agrees (exactly the corners' value when they are equal, as AdaptiveRenderer's runs of flat pixels take it).
            return tl == tr && tl == bl && tl == br ? tl : CombinationRule.Mean(tl, tr, bl, br);
        }

        Intensity centre = Centre(ref source, x0 + (size / 2), y0 + (size / 2), ref samples);
        return Square(sampler, ref source, x0, y0, size, 0, tl, tr, bl, br, centre, ref samples);
    }

    private static Intensity Square<TSource>(AdaptiveSampler s, ref TSource source, long x0, long y0, long size, int depth,
        Intensity tl, Intensity tr, Intensity bl, Intensity br, Intensity x, ref double samples)
        where TSource : ILatticeSource
    {
        (bool refineTl, bool refineTr, bool refineBl, bool refineBr) = Refinements(s, ref source, x0, y0, size, depth, tl, tr, bl, br, x);
        if (!(refineTl || refineTr || refineBl || refineBr))
        {
            return CombinationRule.Mean(
                CombinationRule.Quadrant(tl, x), CombinationRule.Quadrant(tr, x), CombinationRule.Quadrant(bl, x), CombinationRule.Quadrant(br, x));
        }

        long h = size / 2, q = size / 4;
        // The edge midpoints a refined quadrant needs; each is traced once and shared by the two quadrants beside it.
        Intensity top = default, left = default, right = default, bottom = default;
        if (refineTl || refineTr) { top = Take(ref source, x0 + h, y0, ref samples); }
        if (refineTl || refineBl) { left = Take(ref source, x0, y0 + h, ref samples); }
        if (refineTr || refineBr) { right = Take(ref source, x0 + size, y0 + h, ref samples); }
        if (refineBl || refineBr) { bottom = Take(ref source, x0 + h, y0 + size, ref samples); }

        Intensity vTl = refineTl
            ? Square(s, ref source, x0, y0, h, depth + 1, tl, top, left, x, Centre(ref source, x0 + q, y0 + q, ref samples), ref samples)
            : CombinationRule.Quadrant(tl, x);
        Intensity vTr = refineTr
            ? Square(s, ref source, x0 + h, y0, h, depth + 1, top, tr, x, right, Centre(ref source, x0 + h + q, y0 + q, ref samples), ref samples)
            : CombinationRule.Quadrant(tr, x);
        Intensity vBl = refineBl
            ? Square(s, ref source, x0, y0 + h, h, depth + 1, left, x, bl, bottom, Centre(ref source, x0 + q, y0 + h + q, ref samples), ref samples)
            : CombinationRule.Quadrant(bl, x);
        Intensity vBr = refineBr
            ? Square(s, ref source, x0 + h, y0 + h, h, depth + 1, x, right, bottom, br, Centre(ref source, x0 + h + q, y0 + h + q, ref samples), ref samples)
            : CombinationRule.Quadrant(br, x);
        return CombinationRule.Mean(vTl, vTr, vBl, vBr);
    }

    // Which quadrants of the square the recursion goes into: all of them above MinDepth, none at MaxDepth, otherwise
    // those whose corner differs from the centre (all when the corners differ among themselves), and with the guard
    // those a silhouette may cross.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static (bool Tl, bool Tr, bool Bl, bool Br) Refinements<TSource>(AdaptiveSampler s, ref TSource source, long x0, long y0, long size, int depth,
        Intensity tl, Intensity tr, Intensity bl, Intensity br, Intensity x)
        where TSource : ILatticeSource
    {
        if (depth >= s.MaxDepth)
        {
            return (false, false, false, false);
        }

        if (depth < s.MinDepth)
        {
            return (true, true, true, true);
        }

        bool refineTl = s.Differ(tl, x), refineTr = s.Differ(tr, x), refineBl = s.Differ(bl, x), refineBr = s.Differ(br, x);
        if (!(refineTl || refineTr || refineBl || refineBr) && CornersDiffer(s, tl, tr, bl, br))
        {
            // The corners disagree although each agrees with the centre: refine them all.
            refineTl = refineTr = refineBl = refineBr = true;
        }

        if (s.Guard)
        {
            // Where the values agree, a silhouette may still cross a quadrant between its traced points.
            long half = size / 2;
            refineTl = refineTl || source.MayCross(x0, y0, half);
            refineTr = refineTr || source.MayCross(x0 + half, y0, half);
            refineBl = refineBl || source.MayCross(x0, y0 + half, half);
            refineBr = refineBr || source.MayCross(x0 + half, y0 + half, half);
        }

        return (refineTl, refineTr, refineBl, refineBr);
    }

    private static bool CornersDiffer(AdaptiveSampler s, Intensity tl, Intensity tr, Intensity bl, Intensity br) =>
        s.Differ(tl, tr) || s.Differ(tl, bl) || s.Differ(tl, br) || s.Differ(tr, bl) || s.Differ(tr, br) || s.Differ(bl, br);

    private static Intensity Centre<TSource>(ref TSource source, long lx, long ly, ref double samples)
        where TSource : ILatticeSource
    {
        samples += 1;
        return source.Centre(lx, ly);
    }

    private static Intensity Take<TSource>(ref TSource source, long lx, long ly, ref double samples)
        where TSource : ILatticeSource
    {
        Intensity value = source.At(lx, ly, out double weight);
        samples += weight;
        return value;
    }
}
