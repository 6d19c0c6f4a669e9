using System.Runtime.CompilerServices;
using RayLab.Cameras;

namespace RayLab.Rendering.Exact;

/// <summary>
/// The exact reference's work for one pixel row (one per thread, reused row after row): the row's exact
/// linear pixel values, R, G, B for each pixel, in <see cref="Values"/>.
/// </summary>
/// <remarks>
/// <para>1. Cut the row [row, row + 1] at every height where an outline starts or ends, turns left or right,
/// crosses a pixel's left or right edge (X = k), or crosses another outline. Between two cuts — a strip — each
/// outline that is present has a left and a right branch, no branch meets another or a pixel edge, so the branches
/// split the strip into pieces of one colour, found with one ray through the middle of each piece.</para>
/// <para>2. A piece between branches L(Y) and R(Y) covers pixel x by ∫ (min(R, x + 1) − max(L, x)) dY over the
/// strip, and inside a strip the min and max pick the same side everywhere: each pixel gets an exact integral
/// of a branch (<see cref="Outline.Integral"/>) or of a pixel edge. Pixels wholly inside a piece are added as one
/// span (a difference array summed once per row), so they cost nothing per pixel.</para>
/// <para>3. The sweep: the strips are not cut afresh. The branches are kept in their left-to-right
/// order down the row, and at a cut only the outlines with something there (their own break, or a crossing of
/// theirs: <see cref="OutlineSet.Crossings"/> names the pair) are found, taken out and put back; a piece's area
/// is added once for the whole height over which its two branches stay neighbours, and its colour is traced
/// once, or carried when the same two branches are neighbours again just below a cut (not where both their
/// outlines cross or touch at that cut: the two sides of a touching point need not share a colour). So a row costs about
/// O(log n) per event and one ray per piece that really begins, not a ray per piece per strip (on a field of
/// spheres, tens of thousands of rays instead of millions). The pictures are the same bytes as cutting every strip afresh
/// (golden set, <c>SphereHierarchyTests</c>, <c>ExactSweepTests</c>), which the row still does with fewer than
/// eight outlines (where the sweep does not pay) and where the sweep cannot be trusted: a
/// horizontal segment (a circle seen edge-on, which changes the colour without a branch), or branches found
/// out of order by more than rounding (a crossing missed).</para>
/// </remarks>
internal sealed class ExactRow
{
    // The fewest outlines in a row for the sweep (below, strip by strip).
    private const int SweepFrom = 8;

    private readonly Scene _scene;
    private readonly ImagePlane _plane;
    private readonly OutlineSet _outlines;
    private readonly int _width;
    private readonly double[] _values;
    private readonly double[] _spans;
    private readonly List<double> _cuts = [];
    private readonly List<int> _present = [];
    private readonly List<(double Y, int Outline, bool Crossing)> _events = [];
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
    private Branch[] _branches = new Branch[8];
    private Entry[] _entries = new Entry[16];
    private int _count;
    private int _pendingStarts;
    private readonly bool _sweep;
    private bool _broken;

    public ExactRow(Scene scene, ImagePlane plane, OutlineSet outlines, bool sweep = true)
    {
        _sweep = sweep;
        _scene = scene;
        _plane = plane;
        _outlines = outlines;
        _width = plane.Width;
        _values = new double[3 * _width];
        _spans = new double[3 * (_width + 1)];
        _dirty = new bool[outlines.Outlines.Length];
        _stays = new bool[outlines.Outlines.Length];
        _position = new int[2 * outlines.Outlines.Length];
        _x = new double[2 * outlines.Outlines.Length];
        _xAt = new double[2 * outlines.Outlines.Length];
        _xAt.AsSpan().Fill(double.NaN);
    }

    /// <summary>
    /// The last row's pixel values, R, G, B of pixel 0, then of pixel 1, and so on (linear intensity); not filled
    /// when the row <see cref="IsUniform"/>.
    /// </summary>
    public double[] Values => _values;

    /// <summary>True when no outline reaches into the last row: every pixel is <see cref="UniformColor"/>.</summary>
    public bool IsUniform { get; private set; }

    /// <summary>The colour of every pixel of a uniform row.</summary>
    public Intensity UniformColor { get; private set; }

    /// <summary>Computes the exact pixel values of pixel row <paramref name="row"/> (0 at the top) into <see cref="Values"/>.</summary>
    /// <param name="row">The row.</param>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void Integrate(int row)
    {
        double y0 = row, y1 = row + 1;
        _cuts.Clear();
        _present.Clear();
        _events.Clear();
        _broken = false;
        bool segment = false;
        Outline[] outlines = _outlines.Outlines;
        for (int i = 0; i < outlines.Length; i++)
        {
            if (outlines[i].Bottom >= y0 && outlines[i].Top <= y1)
            {
                _present.Add(i);
                segment |= outlines[i].Hy == 0;
                int before = _cuts.Count;
                outlines[i].AddBreaks(y0, y1, _width, _cuts);
                for (int k = before; k < _cuts.Count; k++)
                {
                    _events.Add((_cuts[k], i, false));
                }
            }
        }

        IsUniform = _present.Count == 0;
        if (IsUniform)
        {
            UniformColor = Probe(_width / 2.0, row + 0.5);
            return;
        }

        OutlineSet.Crossing[] crossings = _outlines.Crossings;
        int at = FirstCrossingFrom(crossings, y0);
        for (; at < crossings.Length && crossings[at].Y < y1; at++)
        {
            if (crossings[at].Y > y0)
            {
                _cuts.Add(crossings[at].Y);
                _events.Add((crossings[at].Y, crossings[at].First, true));
                _events.Add((crossings[at].Y, crossings[at].Second, true));
            }
        }

        _cuts.Add(y0);
        _cuts.Add(y1);
        _cuts.Sort();
        Array.Clear(_values);
        Array.Clear(_spans);
        // A row of a few outlines is cut strip by strip: there the sweep's bookkeeping costs more than it saves.
        bool sweep = _sweep && !segment && _present.Count >= SweepFrom;
        if (sweep)
        {
            _events.Sort(static (p, q) => p.Y.CompareTo(q.Y));
            Sweep();
        }

        if (!sweep || _broken)
        {
            // A horizontal segment (a circle seen edge-on) can change the colour without a branch, and a broken
            // order means a crossing was missed: cut every strip afresh, as the sweep's reference does.
            Array.Clear(_values);
            Array.Clear(_spans);
            for (int k = 0; k + 1 < _cuts.Count; k++)
            {
                if (_cuts[k + 1] > _cuts[k])
                {
                    Strip(_cuts[k], _cuts[k + 1]);
                }
            }
        }

        double r = 0, g = 0, b = 0;
        for (int x = 0; x < _width; x++)
        {
            r += _spans[3 * x];
            g += _spans[(3 * x) + 1];
            b += _spans[(3 * x) + 2];
            _values[3 * x] += r;
            _values[(3 * x) + 1] += g;
            _values[(3 * x) + 2] += b;
        }
    }

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Strip(double ya, double yb)
    {
        double ym = 0.5 * (ya + yb), h = yb - ya;
        Outline[] outlines = _outlines.Outlines;
        Span<Branch> branches = BranchesAt(ym);
        int n = branches.Length;

        // Walk the pieces left to right; a branch outside the image stands for the image's edge.
        double leftX = 0, leftIntegral = 0;
        for (int k = 0; k <= n; k++)
        {
            double rightX = _width, rightIntegral = _width * h;
            if (k < n)
            {
                Branch branch = branches[k];
                if (branch.X <= 0)
                {
                    continue;
                }

                if (branch.X < _width)
                {
                    rightX = branch.X;
                    rightIntegral = outlines[branch.Outline].Integral(branch.Sign, ya, yb);
                }
            }

            if (rightX > leftX)
            {
                Piece(leftX, leftIntegral, rightX, rightIntegral, h, Probe(0.5 * (leftX + rightX), ym));
                leftX = rightX;
                leftIntegral = rightIntegral;
            }

            if (rightX >= _width)
            {
                break;
            }
        }
    }

    // The piece of colour c between boundaries at xl and xr (at mid-height), with ∫X dY of each over its height h.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Piece(double xl, double il, double xr, double ir, double h, Intensity c)
    {
        int a = Math.Min((int)xl, _width - 1), b = Math.Min((int)xr, _width - 1);
        if (a == b)
        {
            Add(a, c, ir - il);
            return;
        }

        Add(a, c, ((a + 1) * h) - il);
        Add(b, c, ir - (b * h));
        if (b > a + 1)
        {
            _spans[3 * (a + 1)] += c.R * h;
            _spans[(3 * (a + 1)) + 1] += c.G * h;
            _spans[(3 * (a + 1)) + 2] += c.B * h;
            _spans[3 * b] -= c.R * h;
            _spans[(3 * b) + 1] -= c.G * h;
            _spans[(3 * b) + 2] -= c.B * h;
        }
    }

    // The sweep down the row: the branches are kept in their order left to right, and at each cut only the outlines
    // with something there (their own breaks, or a crossing of theirs) are taken out and put back. A gap between two
    // neighbouring branches is a piece of one colour for as long as both stay its neighbours and no pixel edge is
    // crossed; its area is added once, over that whole height (Flush), and its colour is traced once, or carried
    // when the same two branches are neighbours again just below the cut (nothing between them changed there).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Sweep()
    {
        List<double> cuts = _cuts;
        int m = 1;
        for (int k = 1; k < cuts.Count; k++)
        {
            if (cuts[k] > cuts[m - 1])
            {
                cuts[m++] = cuts[k];
            }
        }

        cuts.RemoveRange(m, cuts.Count - m);
        double ym = 0.5 * (cuts[0] + cuts[1]);
        Span<Branch> branches = BranchesAt(ym);
        int n = branches.Length;
        EnsureRoom(n + 1);
        _entries[0] = new Entry { Outline = -1, GapStart = cuts[0] };
        for (int k = 0; k < n; k++)
        {
            _entries[k + 1] = new Entry { Outline = branches[k].Outline, Sign = branches[k].Sign, GapStart = cuts[0] };
        }

        _count = n + 1;
        _positionsValid = 1;
        _pendingStarts = 0;
        int e = 0;
        _moved.Clear();
        for (int k = 1; k + 1 < m; k++)
        {
            double cut = cuts[k];
            foreach (int i in _moved)
            {
                _dirty[i] = true;
            }

            _crossed.Clear();
            while (e < _events.Count && _events[e].Y <= cut)
            {
                if (_events[e].Crossing)
                {
                    _crossed.Add(_events[e].Outline);
                }

                if (!_dirty[_events[e].Outline])
                {
                    _dirty[_events[e].Outline] = true;
                    _moved.Add(_events[e].Outline);
                }

                e++;
            }

            double below = 0.5 * (cut + cuts[k + 1]);
            Update(cut, ym, below);
            ym = below;
            if (_broken)
            {
                return;
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
        Outline[] outlines = _outlines.Outlines;
        foreach (int i in _moved)
        {
            Outline o = outlines[i];
            _stays[i] = false; // set for every outline moved, so that none is left over from a row given up
            if (o.Hy > 0 && Math.Abs(above - o.Yc) < o.Hy)
            {
                int left = Find(i, -1), right = Find(i, +1);
                if (left < 0 || right < 0)
                {
                    _broken = true;
                    return;
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

        // Take the entries that move out, shifting each run between them left.
        if (_removed.Count > 0)
        {
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

        foreach (int i in _moved)
        {
            _dirty[i] = false;
            Outline o = outlines[i];
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

        foreach ((int outline, int sign) in _restart)
        {
            int k = outline < 0 ? 0 : Find(outline, sign);
            if (k < 0)
            {
                _broken = true; // cannot happen: every branch restarted is in the order
                return;
            }

            ref Entry entry = ref _entries[k];
            if (double.IsNaN(entry.GapStart))
            {
                entry.GapStart = cut;
                entry.Known = false;
                _pendingStarts--;
                int left = Id(k), right = RightId(k);
                foreach (Carried c in _carried)
                {
                    if (c.Left == left && c.Right == right && !(Crossed(left) && Crossed(right)))
                    {
                        entry.Hit = c.Hit;
                        entry.Known = c.Known;
                        break;
                    }
                }
            }
        }

        // Every gap that ended has begun again (or left with its branch): otherwise the order is not what it seems.
        _broken |= _pendingStarts != 0;
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

        Outline[] outlines = _outlines.Outlines;
        double xl = CachedX(outlines, i, -1, below), xr = CachedX(outlines, i, +1, below);
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

            double d = side * (CachedX(outlines, other.Outline, other.Sign, below) - x);
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

    // Puts a branch back at its place in the order at height ym (the same order as Compare on every branch's X there).
    private void Insert(Branch branch, double ym, double cut)
    {
        Outline[] outlines = _outlines.Outlines;
        int lo = 1, hi = _count;
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            Entry other = _entries[mid];
            double x = CachedX(outlines, other.Outline, other.Sign, ym);
            if (Compare(branch, new Branch(x, other.Outline, other.Sign)) > 0)
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

        Outline[] outlines = _outlines.Outlines;
        double h = end - ys, ym = 0.5 * (ys + end);
        double xl = 0, il = 0;
        if (k > 0)
        {
            Outline o = outlines[entry.Outline];
            double x = BranchX(o, entry.Sign, ym);
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
            Outline o = outlines[next.Outline];
            double x = BranchX(o, next.Sign, ym);
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

        if (!entry.Known)
        {
            // Traced in a piece of some size, the colour is the piece's for sure and may be carried on; in a sliver
            // (at a crossing, its two branches a few ulps apart) it may be a neighbour's, which matters for its
            // own tiny area only.
            entry.Hit = Hit(0.5 * (xl + xr), ym);
            entry.Known = h > 1e-7 && xr - xl > 1e-7;
        }

        Piece(xl, il, xr, ir, h, _scene.ColourOf(entry.Hit));
    }

    // BranchX of branch (outline, sign) at height y, remembered per branch for the last height asked (the insertions
    // at a cut all search the order at the same height).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private double CachedX(Outline[] outlines, int outline, int sign, double y)
    {
        int id = (2 * outline) + (sign > 0 ? 1 : 0);
        if (_xAt[id] != y)
        {
            _x[id] = BranchX(outlines[outline], sign, y);
            _xAt[id] = y;
        }

        return _x[id];
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static double BranchX(Outline o, int sign, double y)
    {
        (double left, double right) = o.At(y);
        return sign < 0 ? left : right;
    }

    private void EnsureRoom(int count)
    {
        if (count > _entries.Length)
        {
            Array.Resize(ref _entries, Math.Max(count, 2 * _entries.Length));
        }
    }

    // By X; equal X by outline index, then left before right (the order a sort of the whole strip gives).
    /// <summary>
    /// The two branches (left and right) of every present outline that spans height <paramref name="ym"/>, sorted by
    /// x; equal x in the order they were added (outline index, then left before right), as insertion one by one
    /// would leave them: O(n log n) where a row of a field of spheres meets hundreds.
    /// </summary>
    private Span<Branch> BranchesAt(double ym)
    {
        Outline[] outlines = _outlines.Outlines;
        int n = 0;
        foreach (int i in _present)
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
        branches.Sort(static (p, q) => Compare(p, q));
        return branches;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Compare(Branch p, Branch q) =>
        p.X != q.X ? p.X.CompareTo(q.X) : (p.Outline != q.Outline ? p.Outline.CompareTo(q.Outline) : p.Sign.CompareTo(q.Sign));

    private static int FirstCrossingFrom(OutlineSet.Crossing[] crossings, double y)
    {
        int lo = 0, hi = crossings.Length;
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            if (crossings[mid].Y < y)
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        return lo;
    }

    private void Add(int x, Intensity c, double area)
    {
        _values[3 * x] += c.R * area;
        _values[(3 * x) + 1] += c.G * area;
        _values[(3 * x) + 2] += c.B * area;
    }

    // What the ray at pixel coordinates (X, Y) hits: a sphere's index, or −1.
    private int Hit(double x, double y)
    {
        Ray ray = _plane.GetRayAt(x, y);
        return _scene.Nearest(ray, _plane.TMin, _plane.TMax);
    }

    // The colour at pixel coordinates (X, Y): the ColourOf what the ray there hits (flat shading).
    private Intensity Probe(double x, double y)
    {
        Ray ray = _plane.GetRayAt(x, y);
        return _scene.ColourOf(_scene.Nearest(ray, _plane.TMin, _plane.TMax));
    }

    private readonly record struct Branch(double X, int Outline, int Sign);

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
