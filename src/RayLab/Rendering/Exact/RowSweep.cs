using System.Runtime.CompilerServices;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The exact row by a sweep down it: the branches are kept in their left-to-right order, and at each cut only the
/// outlines with something there (their own break, or a crossing of theirs) are taken out and put back. A gap
/// between two neighbouring branches is a piece of one colour for as long as both stay its neighbours and no pixel
/// edge is crossed; its area is added once, over that whole height, and its colour is traced once, or carried when
/// the same two branches are neighbours again just below the cut. The same bytes as <see cref="StripCutter"/>,
/// for O(log n) per event and one ray per piece that really begins.
/// </summary>
internal sealed class RowSweep
{
    private readonly Outline[] _outlines;
    private readonly int _width;
    private readonly RowBranches _branches;
    private readonly PixelRays _rays;
    private readonly RowPixels _pixels;
    private readonly List<int> _crossed = [];
    private readonly List<Carried> _carried = [];
    private readonly List<int> _moved = [];
    private readonly List<int> _found = [];
    private readonly List<int> _removed = [];
    private readonly bool[] _stays;
    private readonly List<(int Outline, int Sign)> _restart = [];
    private readonly bool[] _dirty;
    // Per branch Id (2·outline for the left branch, 2·outline + 1 for the right): its index in the order, valid for
    // indices below _positionsValid (the entries from there on have shifted since), and its X at height _xAt[id].
    private readonly int[] _position;
    private readonly double[] _x;
    private readonly double[] _xAt;
    private int _positionsValid;
    private Entry[] _entries = new Entry[16];
    private int _count;
    private int _pendingStarts;
    private bool _broken;

    /// <summary>Creates the sweep for one thread's rows.</summary>
    /// <param name="outlines">The frame's outlines.</param>
    /// <param name="width">W.</param>
    /// <param name="branches">The row's present outlines.</param>
    /// <param name="rays">The rays that find a piece's colour.</param>
    /// <param name="pixels">The row's sums, which the pieces are added to.</param>
    public RowSweep(Outline[] outlines, int width, RowBranches branches, PixelRays rays, RowPixels pixels)
    {
        _outlines = outlines;
        _width = width;
        _branches = branches;
        _rays = rays;
        _pixels = pixels;
        _dirty = new bool[outlines.Length];
        _stays = new bool[outlines.Length];
        _position = new int[2 * outlines.Length];
        _x = new double[2 * outlines.Length];
        _xAt = new double[2 * outlines.Length];
        _xAt.AsSpan().Fill(double.NaN);
    }

    /// <summary>
    /// Sweeps the row down its <paramref name="cuts"/>, adding every piece to the row's pixels; false when the sweep
    /// cannot be trusted (branches found out of order by more than rounding: a crossing missed), and the row must be
    /// cut afresh.
    /// </summary>
    /// <param name="cuts">The row's cuts, sorted, its top and bottom included; made distinct in place.</param>
    /// <param name="events">What happens at each cut, sorted by height: an outline's own break, or one of a crossing's two outlines.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public bool Run(List<double> cuts, List<(double Y, int Outline, bool Crossing)> events)
    {
        _broken = false;
        int m = Distinct(cuts);
        double ym = 0.5 * (cuts[0] + cuts[1]);
        Start(cuts[0], ym);
        int e = 0;
        _moved.Clear();
        for (int k = 1; k + 1 < m; k++)
        {
            double cut = cuts[k];
            e = MarkMoved(events, e, cut);
            double below = 0.5 * (cut + cuts[k + 1]);
            Update(cut, ym, below);
            ym = below;
            if (_broken)
            {
                return false;
            }

            // Below a strip so thin that its middle is hardly apart from the cut (two events a few ulps apart),
            // the order just found may be the crossing's own tie: put the same branches back again at the next cut.
            if (cuts[k + 1] - cut > 1e-7)
            {
                _moved.Clear();
            }
        }

        for (int k = 0; k < _count; k++)
        {
            Flush(k, cuts[m - 1]);
        }

        return !_broken;
    }

    // Removes repeated cuts from the sorted list; returns how many remain.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static int Distinct(List<double> cuts)
    {
        int m = 1;
        for (int k = 1; k < cuts.Count; k++)
        {
            if (cuts[k] > cuts[m - 1])
            {
                cuts[m++] = cuts[k];
            }
        }

        cuts.RemoveRange(m, cuts.Count - m);
        return m;
    }

    // The order at the row's top: every branch at the first strip's middle ym, each gap beginning at `top`.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Start(double top, double ym)
    {
        Span<Branch> branches = _branches.At(ym);
        int n = branches.Length;
        EnsureRoom(n + 1);
        _entries[0] = new Entry { Outline = -1, GapStart = top };
        for (int k = 0; k < n; k++)
        {
            _entries[k + 1] = new Entry { Outline = branches[k].Outline, Sign = branches[k].Sign, GapStart = top };
        }

        _count = n + 1;
        _positionsValid = 1;
        _pendingStarts = 0;
    }

    // Marks the outlines with an event at or above `cut` (from event e on) as moved, and those of a crossing as
    // crossed; the outlines still listed as moved from a thin strip above stay moved. Returns the next event.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int MarkMoved(List<(double Y, int Outline, bool Crossing)> events, int e, double cut)
    {
        foreach (int i in _moved)
        {
            _dirty[i] = true;
        }

        _crossed.Clear();
        while (e < events.Count && events[e].Y <= cut)
        {
            if (events[e].Crossing)
            {
                _crossed.Add(events[e].Outline);
            }

            if (!_dirty[events[e].Outline])
            {
                _dirty[events[e].Outline] = true;
                _moved.Add(events[e].Outline);
            }

            e++;
        }

        return e;
    }

    // At a cut: the branches of the outlines marked dirty are found in the order (as it was just above, at `above`),
    // the gaps beside them end, they are taken out and put back at their places just below (at `below`), and the
    // gaps that begin get their colour carried or left to be traced. Work: O(log n) per branch moved, plus the
    // shifting of the entries after it. An outline whose event is its own (a pixel edge or a turn, not a crossing)
    // and whose branches stay clearly between the same neighbours below the cut is left where it is: taking it
    // out and putting it back would give the same order (StaysInPlace).
    private void Update(double cut, double above, double below)
    {
        _carried.Clear();
        _restart.Clear();
        _found.Clear();
        _removed.Clear();
        if (!FindMoved(above, below))
        {
            _broken = true;
            return;
        }

        EndGapsBesideFound(cut);
        TakeOutRemoved();
        PutBack(cut, below);
        if (!BeginGaps(cut))
        {
            _broken = true; // cannot happen: every branch restarted is in the order
            return;
        }

        // Every gap that ended has begun again (or left with its branch): otherwise the order is not what it seems.
        _broken |= _pendingStarts != 0;
    }

    // Finds in the order the branches of each moved outline that spans `above` (into _found), and lists those of
    // the outlines that do not stay in place to be taken out (_removed). False when a branch is not in the order.
    private bool FindMoved(double above, double below)
    {
        foreach (int i in _moved)
        {
            Outline o = _outlines[i];
            _stays[i] = false; // set for every outline moved, so that none is left over from a row given up
            if (o.Hy > 0 && Math.Abs(above - o.Yc) < o.Hy)
            {
                int left = Find(i, -1), right = Find(i, +1);
                if (left < 0 || right < 0)
                {
                    return false;
                }

                _found.Add(left);
                _found.Add(right);
                _stays[i] = Math.Abs(below - o.Yc) < o.Hy && !_crossed.Contains(i) && StaysInPlace(i, left, right, below);
                if (!_stays[i])
                {
                    _removed.Add(left);
                    _removed.Add(right);
                }
            }
        }

        return true;
    }

    // Ends at the cut the gaps on both sides of every branch found, each gap once.
    private void EndGapsBesideFound(double cut)
    {
        _found.Sort();
        for (int f = 0; f < _found.Count; f++)
        {
            int k = _found[f];
            if (f == 0 || _found[f - 1] != k - 1)
            {
                End(k - 1, cut);
            }

            End(k, cut);
        }
    }

    // Takes the entries that move out of the order, shifting each run between them left.
    private void TakeOutRemoved()
    {
        if (_removed.Count == 0)
        {
            return;
        }

        _removed.Sort();
        int w = _removed[0];
        _positionsValid = Math.Min(_positionsValid, w);
        for (int f = 0; f < _removed.Count; f++)
        {
            int from = _removed[f] + 1, to = f + 1 < _removed.Count ? _removed[f + 1] : _count;
            if (!double.IsNaN(_entries[_removed[f]].GapStart))
            {
                _broken = true; // cannot happen: every found entry's gap was just ended
            }

            _pendingStarts--;
            Array.Copy(_entries, from, _entries, w, to - from);
            w += to - from;
        }

        _count = w;
    }

    // Puts the branches of each moved outline that spans `below` back at their places there; one left in place
    // has its gaps begun again instead.
    private void PutBack(double cut, double below)
    {
        foreach (int i in _moved)
        {
            _dirty[i] = false;
            Outline o = _outlines[i];
            if (_stays[i])
            {
                // Left in place: its gaps ended above, and begin again as if it had been put back.
                _stays[i] = false;
                _restart.Add((i, -1));
                _restart.Add((i, +1));
            }
            else if (o.Hy > 0 && Math.Abs(below - o.Yc) < o.Hy)
            {
                (double left, double right) = o.At(below);
                Insert(new Branch(left, i, -1), below, cut);
                Insert(new Branch(right, i, +1), below, cut);
            }
        }
    }

    // Begins at the cut the gap right of every branch restarted, its colour carried from a gap that ended there
    // between the same two branches. False when a branch restarted is not in the order.
    private bool BeginGaps(double cut)
    {
        foreach ((int outline, int sign) in _restart)
        {
            int k = outline < 0 ? 0 : Find(outline, sign);
            if (k < 0)
            {
                return false;
            }

            ref Entry entry = ref _entries[k];
            if (double.IsNaN(entry.GapStart))
            {
                entry.GapStart = cut;
                entry.Known = false;
                _pendingStarts--;
                Carry(ref entry, Id(k), RightId(k));
            }
        }

        return true;
    }

    // Gives a gap that begins between branches `left` and `right` the colour of the gap that ended between the same
    // two at this cut, if any (not where both their outlines cross or touch at the cut: see Crossed).
    private void Carry(ref Entry entry, int left, int right)
    {
        foreach (Carried c in _carried)
        {
            if (c.Left == left && c.Right == right && !(Crossed(left) && Crossed(right)))
            {
                entry.Hit = c.Hit;
                entry.Known = c.Known;
                return;
            }
        }
    }

    // True when outline i's branches, at indices left < right, keep their places at height `below` with a margin:
    // each of their neighbours in the order is a branch that does not move at this cut (or the image's edge, or the
    // outline's other branch) and lies clearly on its side (more than 1e-9 pixel, relative). Then the order is sorted
    // around them, and taking them out and putting them back by search would put them exactly there.
    private bool StaysInPlace(int i, int left, int right, double below)
    {
        if (right <= left)
        {
            return false;
        }

        double xl = CachedX(i, -1, below), xr = CachedX(i, +1, below);
        return Clear(left - 1, xl, -1) && (left + 1 == right || Clear(left + 1, xl, +1))
            && (right - 1 == left || Clear(right - 1, xr, -1)) && Clear(right + 1, xr, +1);

        // Entry k, on side `side` of a branch at x, is the image's edge or a branch that stays, clearly on that side.
        bool Clear(int k, double x, int side)
        {
            if (k <= 0 || k >= _count)
            {
                return true;
            }

            Entry other = _entries[k];
            if (_dirty[other.Outline])
            {
                return false;
            }

            double d = side * (CachedX(other.Outline, other.Sign, below) - x);
            return d > 1e-9 * (1 + Math.Abs(x));
        }
    }

    // The index of branch (outline, sign) in the order, or −1 when it is not there. Each branch's index is kept per
    // Id and brought up to date (from the first entry that shifted) only when asked for: the same index that a search
    // by X finds, as every branch is in the order once, without evaluating any outline.
    private int Find(int outline, int sign)
    {
        int id = (2 * outline) + (sign > 0 ? 1 : 0);
        int k = _position[id];
        if (k < 1 || k >= _positionsValid || _entries[k].Outline != outline || _entries[k].Sign != sign)
        {
            for (int j = _positionsValid; j < _count; j++)
            {
                _position[(2 * _entries[j].Outline) + (_entries[j].Sign > 0 ? 1 : 0)] = j;
            }

            _positionsValid = _count;
            k = _position[id];
            if (k < 1 || k >= _count || _entries[k].Outline != outline || _entries[k].Sign != sign)
            {
                return -1;
            }
        }

        return k;
    }

    // True when the branch with this Id belongs to an outline that crosses or touches another at the current cut. Two
    // such branches that are neighbours above and below the cut may touch there, and the two sides of a touching
    // point need not have one colour (a meeting circle's picture touches a sphere's outline where the circle passes
    // behind the sphere: on one side it is a border, on the other not), so their gap's colour is traced again.
    private bool Crossed(int id) => id >= 0 && _crossed.Contains(id >> 1);

    // 2·outline for a left branch, 2·outline + 1 for a right one; the image's left and right edge.
    private int Id(int k) => k == 0 ? -1 : (2 * _entries[k].Outline) + (_entries[k].Sign > 0 ? 1 : 0);

    private int RightId(int k) => k + 1 < _count ? Id(k + 1) : -2;

    // Ends the gap right of entry k at the cut, remembering its two branches and colour.
    private void End(int k, double cut)
    {
        Flush(k, cut);
        _carried.Add(new Carried(Id(k), RightId(k), _entries[k].Hit, _entries[k].Known));
        _entries[k].GapStart = double.NaN;
        _pendingStarts++;
        if (k == 0 || !_dirty[_entries[k].Outline])
        {
            _restart.Add((_entries[k].Outline, _entries[k].Sign)); // a branch being moved is restarted where it is put back
        }
    }

    // Puts a branch back at its place in the order at height ym (the same order as Branch.Compare on every branch's X there).
    private void Insert(Branch branch, double ym, double cut)
    {
        int lo = 1, hi = _count;
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            Entry other = _entries[mid];
            double x = CachedX(other.Outline, other.Sign, ym);
            if (Branch.Compare(branch, new Branch(x, other.Outline, other.Sign)) > 0)
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        if (!double.IsNaN(_entries[lo - 1].GapStart))
        {
            End(lo - 1, cut); // the gap the branch splits
        }

        EnsureRoom(_count + 1);
        _positionsValid = Math.Min(_positionsValid, lo);
        Array.Copy(_entries, lo, _entries, lo + 1, _count - lo);
        _entries[lo] = new Entry { Outline = branch.Outline, Sign = branch.Sign, GapStart = double.NaN };
        _count++;
        _restart.Add((branch.Outline, branch.Sign));
        _pendingStarts++;
    }

    // Adds the piece right of entry k from where it began to `end`, tracing its colour if not known yet.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Flush(int k, double end)
    {
        ref Entry entry = ref _entries[k];
        double ys = entry.GapStart;
        if (!(end > ys))
        {
            return;
        }

        double h = end - ys, ym = 0.5 * (ys + end);
        double xl = 0, il = 0;
        if (k > 0)
        {
            Outline o = _outlines[entry.Outline];
            double x = Branch.XOf(o, entry.Sign, ym);
            if (x >= _width)
            {
                return;
            }

            if (x > 0)
            {
                xl = x;
                il = o.Integral(entry.Sign, ys, end);
            }
        }

        double xr = _width, ir = _width * h;
        if (k + 1 < _count)
        {
            Entry next = _entries[k + 1];
            Outline o = _outlines[next.Outline];
            double x = Branch.XOf(o, next.Sign, ym);
            if (x <= 0)
            {
                return;
            }

            if (x < _width)
            {
                xr = x;
                ir = o.Integral(next.Sign, ys, end);
            }
        }

        if (!(xr > xl))
        {
            // Out of order by more than rounding: a crossing was missed, and the row is cut afresh.
            _broken |= xl - xr > 1e-9 * (1 + xl);
            return;
        }

        _pixels.Piece(xl, il, xr, ir, h, ColourOf(ref entry, xl, xr, ym, h));
    }

    // The colour of the gap right of an entry, between xl and xr at mid-height ym, traced there if not known yet.
    private Intensity ColourOf(ref Entry entry, double xl, double xr, double ym, double h)
    {
        if (!entry.Known)
        {
            // Traced in a piece of some size, the colour is the piece's for sure and may be carried on; in a sliver
            // (at a crossing, its two branches a few ulps apart) it may be a neighbour's, which matters for its
            // own tiny area only.
            entry.Hit = _rays.Hit(0.5 * (xl + xr), ym);
            entry.Known = h > 1e-7 && xr - xl > 1e-7;
        }

        return _rays.ColourOf(entry.Hit);
    }

    // Branch.XOf of branch (outline, sign) at height y, remembered per branch for the last height asked (the insertions
    // at a cut all search the order at the same height).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private double CachedX(int outline, int sign, double y)
    {
        int id = (2 * outline) + (sign > 0 ? 1 : 0);
        if (_xAt[id] != y)
        {
            _x[id] = Branch.XOf(_outlines[outline], sign, y);
            _xAt[id] = y;
        }

        return _x[id];
    }

    private void EnsureRoom(int count)
    {
        if (count > _entries.Length)
        {
            Array.Resize(ref _entries, Math.Max(count, 2 * _entries.Length));
        }
    }

    // A branch in the sweep's order and the gap (piece) right of it: where the gap began and its colour if traced.
    private struct Entry
    {
        public int Outline;
        public int Sign;
        public double GapStart;
        public int Hit;
        public bool Known;
    }

    // A gap ended at a cut: its left and right branch (Id) and its colour.
    private readonly record struct Carried(int Left, int Right, int Hit, bool Known);
}
