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

/// <summary>
/// The lab's adaptive rule's settings as unmanaged values (<see cref="AdaptiveSampler"/>'s), so that a device
/// compiler takes <see cref="AdaptivePixel"/> as it is.
/// </summary>
internal readonly struct AdaptiveRule
{
    /// <summary>Every pixel is subdivided at least this deep.</summary>
    public readonly int MinDepth;

    /// <summary>No square is subdivided below this depth.</summary>
    public readonly int MaxDepth;

    /// <summary>The spatial contrast per channel.</summary>
    public readonly double Contrast;

    private readonly int _quincunx;
    private readonly int _guard;

    /// <summary>The rule of <paramref name="sampler"/>.</summary>
    /// <param name="sampler">The sampler.</param>
    public AdaptiveRule(AdaptiveSampler sampler)
    {
        MinDepth = sampler.MinDepth;
        MaxDepth = sampler.MaxDepth;
        Contrast = sampler.Contrast;
        _quincunx = sampler.Quincunx ? 1 : 0;
        _guard = sampler.Guard ? 1 : 0;
    }

    /// <summary><see cref="AdaptiveSampler.Quincunx"/>.</summary>
    public bool Quincunx => _quincunx != 0;

    /// <summary><see cref="AdaptiveSampler.Guard"/>.</summary>
    public bool Guard => _guard != 0;

    /// <summary><see cref="AdaptiveSampler.Differ"/>: some channel differs by more than <see cref="Contrast"/>.</summary>
    /// <param name="a">One value.</param>
    /// <param name="b">The other.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool Differ(Intensity a, Intensity b) =>
        Math.Abs(a.R - b.R) > Contrast || Math.Abs(a.G - b.G) > Contrast || Math.Abs(a.B - b.B) > Contrast;
}

/// <summary>
/// One square of <see cref="AdaptivePixel"/>'s explicit stack: where it is, its 3 × 3 points (corners, the edge
/// midpoints its refined quadrants need, centre; in rows from the top-left), which quadrants are refined (bits 1
/// top-left, 2 top-right, 4 bottom-left, 8 bottom-right), the next quadrant to take and the sum of the values of those
/// taken (<see cref="CombinationRule.Sum"/>, in quadrant order).
/// </summary>
internal struct AdaptiveSquare
{
    public long X0, Y0, Size;
    public int Depth, Refine, Next;
    public Intensity Tl, Top, Tr;
    public Intensity Left, X, Right;
    public Intensity Bl, Bottom, Br;
    public Intensity Sum;
}

/// <summary>The squares of <see cref="AdaptivePixel"/>'s explicit stack: <see cref="AdaptiveRule.MaxDepth"/> + 1 entries.</summary>
internal interface ISquareStack
{
    /// <summary>Entry <paramref name="index"/>.</summary>
    /// <param name="index">The entry, 0 the pixel's square.</param>
    ref AdaptiveSquare this[int index] { get; }
}

/// <summary>
/// The lab's adaptive rule for one pixel (see <see cref="AdaptiveSampler"/>), its values combined by
/// <see cref="CombinationRule"/>. Written once, static and generic over where the lattice's values come from and
/// where the squares' stack lives, with no recursion: the CPU renderer runs it on its lattice with a stack on the
/// CPU's stack, the device kernel of <c>RayLab.Gpu</c> on the points it traces with a stack in its local memory. The
/// squares are taken depth first, quadrants in the order top-left, top-right, bottom-left, bottom-right, and the
/// points asked for in the order of the rule's recursive form.
/// </summary>
internal static class AdaptivePixel
{
    /// <summary>The pixel's value; <paramref name="samples"/> receives the rays charged to it (corners ¼, edge points ½).</summary>
    /// <remarks>
    /// The stack is not cleared (<see cref="SkipLocalsInitAttribute"/>): every field of a square is written before it
    /// is read (a square's place, corners and centre are written as it is started, <c>Enter</c> writes the edge points
    /// its refined quadrants read, and its first quadrant's value sets its sum before the others add to theirs).
    /// Cleared, the stack cost the CPU's adaptive render of the bench scene about 6 % on one thread.
    /// </remarks>
    [SkipLocalsInit]
    public static Intensity Evaluate<TSource>(AdaptiveSampler sampler, ref TSource source, int px, int py, out double samples)
        where TSource : ILatticeSource
    {
        var rule = new AdaptiveRule(sampler);
        var stack = new SpanStack(stackalloc AdaptiveSquare[rule.MaxDepth + 1]);
        return Evaluate(rule, ref source, ref stack, px, py, out samples);
    }

    /// <summary>The pixel's value under <paramref name="rule"/>; <paramref name="samples"/> receives the rays charged to it (corners ¼, edge points ½).</summary>
    /// <param name="rule">The rule's settings.</param>
    /// <param name="source">The lattice's values.</param>
    /// <param name="stack">At least <see cref="AdaptiveRule.MaxDepth"/> + 1 squares.</param>
    /// <param name="px">The pixel's column.</param>
    /// <param name="py">The pixel's row.</param>
    /// <param name="samples">The rays charged to the pixel.</param>
    /// <typeparam name="TSource">Where the values come from.</typeparam>
    /// <typeparam name="TStack">Where the stack lives.</typeparam>
    public static Intensity Evaluate<TSource, TStack>(in AdaptiveRule rule, ref TSource source, ref TStack stack, int px, int py, out double samples)
        where TSource : ILatticeSource
        where TStack : ISquareStack, allows ref struct
    {
        long size = 1L << (rule.MaxDepth + 1);
        long x0 = px * size, y0 = py * size;
        samples = 0;
        Intensity tl = Take(ref source, x0, y0, ref samples);
        Intensity tr = Take(ref source, x0 + size, y0, ref samples);
        Intensity bl = Take(ref source, x0, y0 + size, ref samples);
        Intensity br = Take(ref source, x0 + size, y0 + size, ref samples);
        if (!rule.Quincunx && rule.MinDepth == 0 && !CornersDiffer(rule, tl, tr, bl, br)
            && !(rule.Guard && source.MayCross(x0, y0, size)))
        {
            // A flat pixel: the mean of its corners, which is what the combination rule gives for any centre that
            // agrees (exactly the corners' value when they are equal, as AdaptiveRenderer's runs of flat pixels take it).
            return tl == tr && tl == bl && tl == br ? tl : CombinationRule.Mean(tl, tr, bl, br);
        }

        ref AdaptiveSquare pixel = ref stack[0];
        (pixel.X0, pixel.Y0, pixel.Size, pixel.Depth) = (x0, y0, size, 0);
        (pixel.Tl, pixel.Tr, pixel.Bl, pixel.Br) = (tl, tr, bl, br);
        pixel.X = Centre(ref source, x0 + (size / 2), y0 + (size / 2), ref samples);
        return Squares(rule, ref source, ref stack, ref samples);
    }

    /// <summary>The value of the square at the bottom of the stack (its place, corners and centre set): its quadrants depth first, each refined one a square on the stack.</summary>
    private static Intensity Squares<TSource, TStack>(in AdaptiveRule rule, ref TSource source, ref TStack stack, ref double samples)
        where TSource : ILatticeSource
        where TStack : ISquareStack, allows ref struct
    {
        if (!Enter(rule, ref source, ref stack[0], ref samples, out Intensity value))
        {
            return value;
        }

        int top = 0;
        while (true)
        {
            ref AdaptiveSquare square = ref stack[top];
            int q = square.Next;
            if (q == 4)
            {
                value = CombinationRule.MeanOfSum(square.Sum);
                if (top == 0)
                {
                    return value;
                }

                top--;
                Add(ref stack[top], value);
                continue;
            }

            square.Next = q + 1;
            if ((square.Refine & (1 << q)) == 0)
            {
                Add(ref square, CombinationRule.Quadrant(Corner(square, q), square.X));
                continue;
            }

            // The quadrant is the square above on the stack: its place, centre and corners (the square's points).
            ref AdaptiveSquare quadrant = ref stack[top + 1];
            long h = square.Size / 2;
            quadrant.X0 = square.X0 + ((q & 1) * h);
            quadrant.Y0 = square.Y0 + ((q >> 1) * h);
            quadrant.Size = h;
            quadrant.Depth = square.Depth + 1;
            quadrant.X = Centre(ref source, quadrant.X0 + (h / 2), quadrant.Y0 + (h / 2), ref samples);
            Corners(square, q, ref quadrant);
            if (Enter(rule, ref source, ref quadrant, ref samples, out value))
            {
                top++;
            }
            else
            {
                Add(ref square, value);
            }
        }
    }

    /// <summary>
    /// Starts a square whose place, corners and centre are set: its refined quadrants and the edge midpoints they
    /// need. None refined: false, and <paramref name="value"/> the square's value (the combination rule over its
    /// corners and centre); else true, the square ready on the stack.
    /// </summary>
    private static bool Enter<TSource>(in AdaptiveRule rule, ref TSource source, ref AdaptiveSquare square, ref double samples, out Intensity value)
        where TSource : ILatticeSource
    {
        int refine = Refinements(rule, ref source, square);
        if (refine == 0)
        {
            Intensity x = square.X;
            value = CombinationRule.Mean(
                CombinationRule.Quadrant(square.Tl, x), CombinationRule.Quadrant(square.Tr, x),
                CombinationRule.Quadrant(square.Bl, x), CombinationRule.Quadrant(square.Br, x));
            return false;
        }

        long x0 = square.X0, y0 = square.Y0, size = square.Size, h = size / 2;
        square.Refine = refine;
        square.Next = 0;
        // The edge midpoints a refined quadrant needs; each is traced once and shared by the two quadrants beside it.
        if ((refine & 3) != 0) { square.Top = Take(ref source, x0 + h, y0, ref samples); }
        if ((refine & 5) != 0) { square.Left = Take(ref source, x0, y0 + h, ref samples); }
        if ((refine & 10) != 0) { square.Right = Take(ref source, x0 + size, y0 + h, ref samples); }
        if ((refine & 12) != 0) { square.Bottom = Take(ref source, x0 + h, y0 + size, ref samples); }
        value = default;
        return true;
    }

    /// <summary>Quadrant <paramref name="q"/>'s corner that is a corner of the square.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Intensity Corner(in AdaptiveSquare square, int q) => q switch { 0 => square.Tl, 1 => square.Tr, 2 => square.Bl, _ => square.Br };

    /// <summary>Sets quadrant <paramref name="q"/>'s corners from the square's points.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Corners(in AdaptiveSquare square, int q, ref AdaptiveSquare quadrant)
    {
        switch (q)
        {
            case 0: (quadrant.Tl, quadrant.Tr, quadrant.Bl, quadrant.Br) = (square.Tl, square.Top, square.Left, square.X); break;
            case 1: (quadrant.Tl, quadrant.Tr, quadrant.Bl, quadrant.Br) = (square.Top, square.Tr, square.X, square.Right); break;
            case 2: (quadrant.Tl, quadrant.Tr, quadrant.Bl, quadrant.Br) = (square.Left, square.X, square.Bl, square.Bottom); break;
            default: (quadrant.Tl, quadrant.Tr, quadrant.Bl, quadrant.Br) = (square.X, square.Right, square.Bottom, square.Br); break;
        }
    }

    /// <summary>Adds the value of the quadrant just taken (<see cref="AdaptiveSquare.Next"/> − 1) to the square's sum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void Add(ref AdaptiveSquare square, Intensity value) =>
        square.Sum = square.Next == 1 ? value : CombinationRule.Sum(square.Sum, value);

    // Which quadrants of the square the rule goes into (bits 1 top-left, 2 top-right, 4 bottom-left, 8 bottom-right):
    // all of them above MinDepth, none at MaxDepth, otherwise those whose corner differs from the centre (all when the
    // corners differ among themselves), and with the guard those a silhouette may cross.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Refinements<TSource>(in AdaptiveRule s, ref TSource source, in AdaptiveSquare square)
        where TSource : ILatticeSource
    {
        int depth = square.Depth;
        if (depth >= s.MaxDepth)
        {
            return 0;
        }

        if (depth < s.MinDepth)
        {
            return 15;
        }

        Intensity tl = square.Tl, tr = square.Tr, bl = square.Bl, br = square.Br, x = square.X;
        int refine = (s.Differ(tl, x) ? 1 : 0) | (s.Differ(tr, x) ? 2 : 0) | (s.Differ(bl, x) ? 4 : 0) | (s.Differ(br, x) ? 8 : 0);
        if (refine == 0 && CornersDiffer(s, tl, tr, bl, br))
        {
            // The corners disagree although each agrees with the centre: refine them all.
            refine = 15;
        }

        if (s.Guard)
        {
            // Where the values agree, a silhouette may still cross a quadrant between its traced points.
            long x0 = square.X0, y0 = square.Y0, half = square.Size / 2;
            refine |= (refine & 1) == 0 && source.MayCross(x0, y0, half) ? 1 : 0;
            refine |= (refine & 2) == 0 && source.MayCross(x0 + half, y0, half) ? 2 : 0;
            refine |= (refine & 4) == 0 && source.MayCross(x0, y0 + half, half) ? 4 : 0;
            refine |= (refine & 8) == 0 && source.MayCross(x0 + half, y0 + half, half) ? 8 : 0;
        }

        return refine;
    }

    private static bool CornersDiffer(in AdaptiveRule s, Intensity tl, Intensity tr, Intensity bl, Intensity br) =>
        s.Differ(tl, tr) || s.Differ(tl, bl) || s.Differ(tl, br) || s.Differ(tr, bl) || s.Differ(tr, br) || s.Differ(bl, br);

    /// <summary>
    /// The share of lattice point (<paramref name="lx"/>, <paramref name="ly"/>)'s ray charged to a pixel that asks for it
    /// (for the heat map): ¼ for a pixel corner, ½ for a point on a pixel edge, 1 inside.
    /// </summary>
    /// <param name="lx">Lattice column.</param>
    /// <param name="ly">Lattice row.</param>
    /// <param name="size">Lattice steps per pixel side (a power of two).</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Share(long lx, long ly, long size)
    {
        bool onColumn = (lx & (size - 1)) == 0, onRow = (ly & (size - 1)) == 0;
        return onColumn && onRow ? 0.25 : onColumn || onRow ? 0.5 : 1;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Intensity Centre<TSource>(ref TSource source, long lx, long ly, ref double samples)
        where TSource : ILatticeSource
    {
        samples += 1;
        return source.Centre(lx, ly);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Intensity Take<TSource>(ref TSource source, long lx, long ly, ref double samples)
        where TSource : ILatticeSource
    {
        Intensity value = source.At(lx, ly, out double weight);
        samples += weight;
        return value;
    }

    /// <summary>The squares' stack on the CPU's stack.</summary>
    private readonly ref struct SpanStack(Span<AdaptiveSquare> squares) : ISquareStack
    {
        private readonly Span<AdaptiveSquare> _squares = squares;

        public ref AdaptiveSquare this[int index] => ref _squares[index];
    }
}
