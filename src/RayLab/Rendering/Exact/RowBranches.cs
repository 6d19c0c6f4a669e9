using System.Runtime.CompilerServices;

namespace RayLab.Rendering.Exact;

/// <summary>One branch of an outline at some height: its X there, its outline's index, −1 for the left branch and +1 for the right.</summary>
/// <param name="X">The branch's X (pixel units).</param>
/// <param name="Outline">The outline's index in <see cref="OutlineSet.Outlines"/>.</param>
/// <param name="Sign">−1 for the left branch, +1 for the right.</param>
internal readonly record struct Branch(double X, int Outline, int Sign)
{
    /// <summary>By X; equal X by outline index, then left before right (the order a sort of the whole strip gives).</summary>
    /// <param name="p">One branch.</param>
    /// <param name="q">The other.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int Compare(Branch p, Branch q) =>
        p.X != q.X ? p.X.CompareTo(q.X) : (p.Outline != q.Outline ? p.Outline.CompareTo(q.Outline) : p.Sign.CompareTo(q.Sign));

    /// <summary>The X of branch <paramref name="sign"/> of <paramref name="o"/> at height <paramref name="y"/>.</summary>
    /// <param name="o">The outline.</param>
    /// <param name="sign">−1 for the left branch, +1 for the right.</param>
    /// <param name="y">The height.</param>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double XOf(Outline o, int sign, double y)
    {
        (double left, double right) = o.At(y);
        return sign < 0 ? left : right;
    }
}

/// <summary>The outlines present in one pixel row, and their branches at a height sorted left to right.</summary>
internal sealed class RowBranches(Outline[] outlines)
{
    private Branch[] _branches = new Branch[8];

    /// <summary>The indices of the outlines that reach into the row, in index order.</summary>
    public List<int> Present { get; } = [];

    /// <summary>
    /// The two branches (left and right) of every present outline that spans height <paramref name="ym"/>, sorted by
    /// x; equal x in the order they were added (outline index, then left before right), as insertion one by one
    /// would leave them: O(n log n) where a row of a field of spheres meets hundreds.
    /// </summary>
    /// <param name="ym">The height.</param>
    /// <returns>The branches, valid until the next call.</returns>
    public Span<Branch> At(double ym)
    {
        int n = 0;
        foreach (int i in Present)
        {
            Outline o = outlines[i];
            if (o.Hy > 0 && Math.Abs(ym - o.Yc) < o.Hy)
            {
                if (n + 2 > _branches.Length)
                {
                    Array.Resize(ref _branches, 2 * _branches.Length);
                }

                (double left, double right) = o.At(ym);
                _branches[n++] = new Branch(left, i, -1);
                _branches[n++] = new Branch(right, i, +1);
            }
        }

        Span<Branch> branches = _branches.AsSpan(0, n);
        branches.Sort(static (p, q) => Branch.Compare(p, q));
        return branches;
    }
}
