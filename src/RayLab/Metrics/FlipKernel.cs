using System.Buffers;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace RayLab.Metrics;

/// <summary>
/// The LDR-FLIP pipeline on planar float rows. The picture is cut into horizontal bands, one task each, and a band
/// into column tiles of 256. A tile walks the band's rows top to bottom, converting each input row (and the filters'
/// margin above, below and beside) to YCxCz, filtering it horizontally into a ring of the last 2R + 1 rows (14 planes:
/// for each image Y, Cx, Cz·h1, Cz·h2 and the feature detectors' Gaussian, first and second derivative; about 300 KB,
/// so the vertical pass reads it from the L2 cache), then filtering that ring vertically and computing the error of
/// one output row. Every output value is computed by the same operations whatever the banding, so the map and its
/// mean (rows summed in double, then the row sums in order) are the same at any thread count.
/// </summary>
internal sealed class FlipKernel
{
    private const int PlanesPerImage = 7;
    private const int TileColumns = 256;
    private const int Planes = 2 * PlanesPerImage;
    private const int PlaneY = 0, PlaneCx = 1, PlaneCz1 = 2, PlaneCz2 = 3, PlaneG = 4, PlaneD = 5, PlaneDD = 6;

    private readonly Image _reference;
    private readonly Image _test;
    private readonly FlipFilters _filters;
    private readonly bool _vectorized;
    private readonly int _width;
    private readonly int _height;
    private readonly int _stride;      // The width rounded up to whole vectors.
    private readonly int _tile;        // Columns per tile: the ring of one tile stays in the L2 cache.
    private readonly int _pad;         // Columns each side of a tile the horizontal filters read.
    private readonly int _rowLength;   // _pad + _tile + _pad.
    private readonly int _ringRows;    // 2R + 1.
    private readonly float[] _spatialWeights;   // Tap k's Y, Cx, Cz1, Cz2 weights at 4k … 4k + 3.
    private readonly float[] _featureWeights;   // Tap k's G, D, DD weights at 3k … 3k + 2.
    private readonly float[] _map;
    private readonly double[] _rowSums;

    public FlipKernel(Image reference, Image test, float pixelsPerDegree, bool vectorized)
    {
        _reference = reference;
        _test = test;
        _filters = new FlipFilters(pixelsPerDegree);
        _vectorized = vectorized;
        _width = reference.Width;
        _height = reference.Height;
        int lanes = Vector<float>.Count;
        _stride = (_width + lanes - 1) / lanes * lanes;
        _tile = Math.Min(_stride, TileColumns);
        _pad = _filters.MaxRadius;
        _rowLength = _pad + _tile + _pad;
        _ringRows = (2 * _filters.MaxRadius) + 1;
        _spatialWeights = Interleave(_filters.Y, _filters.Cx, _filters.Cz1, _filters.Cz2);
        _featureWeights = Interleave(_filters.G, _filters.D, _filters.DD);
        _map = GC.AllocateUninitializedArray<float>(_width * _height);
        _rowSums = new double[_height];
    }

    /// <summary>Computes the map and its mean on up to <paramref name="threads"/> threads (−1: the runtime's choice).</summary>
    public (float[] Map, double Mean) Run(int threads)
    {
        int workers = threads == -1 ? Environment.ProcessorCount : threads;
        // A few bands per worker balance the load; each band re-filters 2R rows of margin, so bands stay well taller than R.
        int bands = workers == 1 ? 1 : Math.Clamp(Math.Min(workers * 3, _height / Math.Max(1, 4 * _filters.MaxRadius)), 1, _height);
        int bandHeight = (_height + bands - 1) / bands;
        bands = (_height + bandHeight - 1) / bandHeight;
        if (bands == 1)
        {
            RunBand(0, _height);
        }
        else
        {
            Parallel.For(0, bands, new ParallelOptions { MaxDegreeOfParallelism = threads }, band =>
                RunBand(band * bandHeight, Math.Min(_height, (band + 1) * bandHeight)));
        }

        double sum = 0;
        foreach (double rowSum in _rowSums)
        {
            sum += rowSum;
        }

        return (_map, sum / ((double)_width * _height));
    }

    private static float[] Interleave(params float[][] filters)
    {
        var weights = new float[filters.Length * filters[0].Length];
        for (int k = 0; k < filters[0].Length; k++)
        {
            for (int j = 0; j < filters.Length; j++)
            {
                weights[(k * filters.Length) + j] = filters[j][k];
            }
        }

        return weights;
    }

    // Called once per band or row: optimised at the first call, not left to tiering's on-stack replacement.
    // Long: the band's column-tile sweep rents its ring and row buffers and returns them in one try/finally.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void RunBand(int y0, int y1)
    {
        int r = _filters.MaxRadius;
        int rowFloats = 4 * _rowLength;
        int ringFloats = _ringRows * RowFloats;
        float[] convertedReference = ArrayPool<float>.Shared.Rent(rowFloats);
        float[] convertedTest = ArrayPool<float>.Shared.Rent(rowFloats);
        float[] ring = ArrayPool<float>.Shared.Rent(ringFloats);
        float[] output = ArrayPool<float>.Shared.Rent(_tile);
        int[] spatialOffsets = new int[(2 * _filters.SpatialRadius) + 1];
        int[] featureOffsets = new int[(2 * _filters.FeatureRadius) + 1];
        try
        {
            // Column tiles, each swept top to bottom through the band with its own ring of horizontally filtered rows.
            for (int x0 = 0; x0 < _stride; x0 += _tile)
            {
                int vectorCount = Math.Min(_tile, _stride - x0);
                int valid = Math.Min(vectorCount, _width - x0);
                int count = _vectorized ? vectorCount : valid;
                int next = Math.Max(0, y0 - r);
                for (int y = y0; y < y1; y++)
                {
                    int last = Math.Min(_height - 1, y + r);
                    for (; next <= last; next++)
                    {
                        int slot = next % _ringRows;
                        Convert(_reference.PixelBytes.Slice(next * 3 * _width, 3 * _width), x0, count, convertedReference);
                        Convert(_test.PixelBytes.Slice(next * 3 * _width, 3 * _width), x0, count, convertedTest);
                        if (_vectorized)
                        {
                            HorizontalVector(convertedReference, convertedTest, ring, slot, count);
                        }
                        else
                        {
                            HorizontalScalar(convertedReference, ring, slot, 0, count);
                            HorizontalScalar(convertedTest, ring, slot, PlanesPerImage, count);
                        }
                    }

                    RowOffsets(y, _filters.SpatialRadius, spatialOffsets);
                    RowOffsets(y, _filters.FeatureRadius, featureOffsets);
                    if (_vectorized)
                    {
                        VerticalVector(ring, spatialOffsets, featureOffsets, output, count);
                    }
                    else
                    {
                        VerticalScalar(ring, spatialOffsets, featureOffsets, output, count);
                    }

                    output.AsSpan(0, valid).CopyTo(_map.AsSpan((y * _width) + x0, valid));
                }
            }

            for (int y = y0; y < y1; y++)
            {
                double rowSum = 0;
                foreach (float e in _map.AsSpan(y * _width, _width))
                {
                    rowSum += e;
                }

                _rowSums[y] = rowSum;
            }
        }
        finally
        {
            ArrayPool<float>.Shared.Return(convertedReference);
            ArrayPool<float>.Shared.Return(convertedTest);
            ArrayPool<float>.Shared.Return(ring);
            ArrayPool<float>.Shared.Return(output);
        }
    }

    // The ring offsets of rows y − radius … y + radius, clamped to the image (edge rows repeat).
    private void RowOffsets(int y, int radius, int[] offsets)
    {
        for (int k = 0; k < offsets.Length; k++)
        {
            int row = Math.Clamp(y + k - radius, 0, _height - 1);
            offsets[k] = row % _ringRows * RowFloats;
        }
    }

    // Columns x0 − pad … x0 + count + pad − 1 of one RGB24 row → four planar rows: Y, Cx, Cz and the normalised
    // luminance. Columns outside the image repeat its edge pixels.
    // Called once per band or row: optimised at the first call, not left to tiering's on-stack replacement.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Convert(ReadOnlySpan<byte> rgb, int x0, int count, float[] converted)
    {
        ref Vector128<float> table = ref Unsafe.As<float, Vector128<float>>(ref MemoryMarshal.GetArrayDataReference(FlipModel.ChannelTable));
        Span<float> y = converted.AsSpan(0, _rowLength);
        Span<float> cx = converted.AsSpan(_rowLength, _rowLength);
        Span<float> cz = converted.AsSpan(2 * _rowLength, _rowLength);
        Span<float> yn = converted.AsSpan(3 * _rowLength, _rowLength);
        int n = count + (2 * _pad);
        int first = x0 - _pad;
        int lo = Math.Max(0, -first);
        int hi = Math.Min(n, _width - first);
        ReadOnlySpan<byte> pixels = rgb.Slice(3 * (first + lo), 3 * (hi - lo));
        var minus16 = Vector128.Create(-16.0f, 0.0f, 0.0f, 0.0f);
        for (int i = lo, p = 0; i < hi; i++, p += 3)
        {
            // (Y, Cx, Cz, 0) as the sum of the three channels' table entries.
            Vector128<float> c = Unsafe.Add(ref table, pixels[p]) + Unsafe.Add(ref table, 256 + pixels[p + 1])
                + Unsafe.Add(ref table, 512 + pixels[p + 2]) + minus16;
            float yy = c.GetElement(0);
            y[i] = yy;
            cx[i] = c.GetElement(1);
            cz[i] = c.GetElement(2);
            yn[i] = FlipModel.NormalizedLuminance(yy);
        }

        Fill(y, lo, hi, n);
        Fill(cx, lo, hi, n);
        Fill(cz, lo, hi, n);
        Fill(yn, lo, hi, n);
    }

    // Columns left and right of the image repeat its first and last pixel.
    private static void Fill(Span<float> row, int lo, int hi, int n)
    {
        row[..lo].Fill(row[lo]);
        row[hi..n].Fill(row[hi - 1]);
    }

    // The ring: _ringRows rows of RowFloats floats. Within a row, each vector of columns keeps its 14 planes side by
    // side ([column vector][plane][lane]), so a filter tap reaches every plane from one address plus constants.
    private int RowFloats => Planes * _tile;

    // The ring index of (column x, plane) in a row, x counted from the tile's first column.
    private static int Index(int x, int plane)
    {
        int lanes = Vector<float>.Count;
        return (((x / lanes * Planes) + plane) * lanes) + (x % lanes);
    }

    private void HorizontalScalar(float[] converted, float[] ring, int slot, int firstPlane, int count)
    {
        FlipFilters f = _filters;
        int rs = f.SpatialRadius, rf = f.FeatureRadius;
        int row = slot * RowFloats;
        for (int x = 0; x < count; x++)
        {
            float y = 0, cx = 0, cz1 = 0, cz2 = 0;
            int start = _pad + x - rs;
            for (int k = 0; k <= 2 * rs; k++)
            {
                float vy = converted[start + k];
                float vcx = converted[_rowLength + start + k];
                float vcz = converted[(2 * _rowLength) + start + k];
                y += f.Y[k] * vy;
                cx += f.Cx[k] * vcx;
                cz1 += f.Cz1[k] * vcz;
                cz2 += f.Cz2[k] * vcz;
            }

            float g = 0, d = 0, dd = 0;
            start = (3 * _rowLength) + _pad + x - rf;
            for (int k = 0; k <= 2 * rf; k++)
            {
                float v = converted[start + k];
                g += f.G[k] * v;
                d += f.D[k] * v;
                dd += f.DD[k] * v;
            }

            ring[row + Index(x, firstPlane + PlaneY)] = y;
            ring[row + Index(x, firstPlane + PlaneCx)] = cx;
            ring[row + Index(x, firstPlane + PlaneCz1)] = cz1;
            ring[row + Index(x, firstPlane + PlaneCz2)] = cz2;
            ring[row + Index(x, firstPlane + PlaneG)] = g;
            ring[row + Index(x, firstPlane + PlaneD)] = d;
            ring[row + Index(x, firstPlane + PlaneDD)] = dd;
        }
    }

    private void VerticalScalar(float[] ring, int[] spatialOffsets, int[] featureOffsets, float[] output, int count)
    {
        FlipFilters f = _filters;
        const int Second = PlanesPerImage;
        for (int x = 0; x < count; x++)
        {
            float y1 = 0, cx1 = 0, czA1 = 0, czB1 = 0, y2 = 0, cx2 = 0, czA2 = 0, czB2 = 0;
            for (int k = 0; k < spatialOffsets.Length; k++)
            {
                int o = spatialOffsets[k];
                y1 += f.Y[k] * ring[o + Index(x, PlaneY)];
                cx1 += f.Cx[k] * ring[o + Index(x, PlaneCx)];
                czA1 += f.Cz1[k] * ring[o + Index(x, PlaneCz1)];
                czB1 += f.Cz2[k] * ring[o + Index(x, PlaneCz2)];
                y2 += f.Y[k] * ring[o + Index(x, Second + PlaneY)];
                cx2 += f.Cx[k] * ring[o + Index(x, Second + PlaneCx)];
                czA2 += f.Cz1[k] * ring[o + Index(x, Second + PlaneCz1)];
                czB2 += f.Cz2[k] * ring[o + Index(x, Second + PlaneCz2)];
            }

            float color = FlipModel.ColorError(y1, cx1, czA1 + czB1, y2, cx2, czA2 + czB2);

            float dx1 = 0, ddx1 = 0, dy1 = 0, ddy1 = 0, dx2 = 0, ddx2 = 0, dy2 = 0, ddy2 = 0;
            for (int k = 0; k < featureOffsets.Length; k++)
            {
                int o = featureOffsets[k];
                float g1 = ring[o + Index(x, PlaneG)], g2 = ring[o + Index(x, Second + PlaneG)];
                dx1 += f.G[k] * ring[o + Index(x, PlaneD)];
                ddx1 += f.G[k] * ring[o + Index(x, PlaneDD)];
                dy1 += f.D[k] * g1;
                ddy1 += f.DD[k] * g1;
                dx2 += f.G[k] * ring[o + Index(x, Second + PlaneD)];
                ddx2 += f.G[k] * ring[o + Index(x, Second + PlaneDD)];
                dy2 += f.D[k] * g2;
                ddy2 += f.DD[k] * g2;
            }

            float feature = FlipModel.FeatureError(
                MathF.Sqrt((dx1 * dx1) + (dy1 * dy1)),
                MathF.Sqrt((ddx1 * ddx1) + (ddy1 * ddy1)),
                MathF.Sqrt((dx2 * dx2) + (dy2 * dy2)),
                MathF.Sqrt((ddx2 * ddx2) + (ddy2 * ddy2)));
            output[x] = FlipModel.Combine(color, feature);
        }
    }

    // Both images at once: eight (then six) independent sums hide the multiply-add latency, and each weight is
    // broadcast once for the two images.
    // Called once per band or row: optimised at the first call, not left to tiering's on-stack replacement.
    // Long: hand-unrolled: both images' sums (eight, then six vectors) stay in registers through the tap loops; a split would spill them.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void HorizontalVector(float[] convertedReference, float[] convertedTest, float[] ring, int slot, int count)
    {
        int rs = _filters.SpatialRadius, rf = _filters.FeatureRadius;
        int lanes = Vector<float>.Count;
        ref float y1s = ref MemoryMarshal.GetArrayDataReference(convertedReference);
        ref float cx1s = ref Unsafe.Add(ref y1s, _rowLength);
        ref float cz1s = ref Unsafe.Add(ref y1s, 2 * _rowLength);
        ref float yn1s = ref Unsafe.Add(ref y1s, 3 * _rowLength);
        ref float y2s = ref MemoryMarshal.GetArrayDataReference(convertedTest);
        ref float cx2s = ref Unsafe.Add(ref y2s, _rowLength);
        ref float cz2s = ref Unsafe.Add(ref y2s, 2 * _rowLength);
        ref float yn2s = ref Unsafe.Add(ref y2s, 3 * _rowLength);
        ref float ws = ref MemoryMarshal.GetArrayDataReference(_spatialWeights);
        ref float wf = ref MemoryMarshal.GetArrayDataReference(_featureWeights);
        ref float dst = ref Unsafe.Add(ref MemoryMarshal.GetArrayDataReference(ring), slot * RowFloats);
        int taps = (2 * rs) + 1;
        int featureTaps = (2 * rf) + 1;
        const int Second = PlanesPerImage;
        int narrowFirst = rs - _filters.NarrowRadius;          // Y and Cx use taps narrowFirst … taps − narrowFirst − 1.
        int narrowTaps = (2 * _filters.NarrowRadius) + 1;
        for (int x = 0; x < count; x += lanes)
        {
            var y1 = Vector<float>.Zero;
            var cx1 = Vector<float>.Zero;
            var czA1 = Vector<float>.Zero;
            var czB1 = Vector<float>.Zero;
            var y2 = Vector<float>.Zero;
            var cx2 = Vector<float>.Zero;
            var czA2 = Vector<float>.Zero;
            var czB2 = Vector<float>.Zero;
            nuint start = (nuint)(_pad + x - rs);
            for (int k = 0; k < taps; k++)
            {
                nuint i = start + (nuint)k;
                ref float w = ref Unsafe.Add(ref ws, 4 * k);
                var wcz1 = new Vector<float>(Unsafe.Add(ref w, 2));
                var wcz2 = new Vector<float>(Unsafe.Add(ref w, 3));
                var vcz1 = Vector.LoadUnsafe(ref cz1s, i);
                var vcz2 = Vector.LoadUnsafe(ref cz2s, i);
                czA1 = Vector.MultiplyAddEstimate(vcz1, wcz1, czA1);
                czB1 = Vector.MultiplyAddEstimate(vcz1, wcz2, czB1);
                czA2 = Vector.MultiplyAddEstimate(vcz2, wcz1, czA2);
                czB2 = Vector.MultiplyAddEstimate(vcz2, wcz2, czB2);
                if ((uint)(k - narrowFirst) < (uint)narrowTaps)
                {
                    var wy = new Vector<float>(w);
                    var wcx = new Vector<float>(Unsafe.Add(ref w, 1));
                    y1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref y1s, i), wy, y1);
                    cx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref cx1s, i), wcx, cx1);
                    y2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref y2s, i), wy, y2);
                    cx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref cx2s, i), wcx, cx2);
                }
            }

            var g1 = Vector<float>.Zero;
            var d1 = Vector<float>.Zero;
            var dd1 = Vector<float>.Zero;
            var g2 = Vector<float>.Zero;
            var d2 = Vector<float>.Zero;
            var dd2 = Vector<float>.Zero;
            start = (nuint)(_pad + x - rf);
            for (int k = 0; k < featureTaps; k++)
            {
                nuint i = start + (nuint)k;
                ref float w = ref Unsafe.Add(ref wf, 3 * k);
                var wg = new Vector<float>(w);
                var wd = new Vector<float>(Unsafe.Add(ref w, 1));
                var wdd = new Vector<float>(Unsafe.Add(ref w, 2));
                var v1 = Vector.LoadUnsafe(ref yn1s, i);
                var v2 = Vector.LoadUnsafe(ref yn2s, i);
                g1 = Vector.MultiplyAddEstimate(v1, wg, g1);
                d1 = Vector.MultiplyAddEstimate(v1, wd, d1);
                dd1 = Vector.MultiplyAddEstimate(v1, wdd, dd1);
                g2 = Vector.MultiplyAddEstimate(v2, wg, g2);
                d2 = Vector.MultiplyAddEstimate(v2, wd, d2);
                dd2 = Vector.MultiplyAddEstimate(v2, wdd, dd2);
            }

            ref float o = ref Unsafe.Add(ref dst, x * Planes);
            y1.StoreUnsafe(ref o, (nuint)(PlaneY * lanes));
            cx1.StoreUnsafe(ref o, (nuint)(PlaneCx * lanes));
            czA1.StoreUnsafe(ref o, (nuint)(PlaneCz1 * lanes));
            czB1.StoreUnsafe(ref o, (nuint)(PlaneCz2 * lanes));
            g1.StoreUnsafe(ref o, (nuint)(PlaneG * lanes));
            d1.StoreUnsafe(ref o, (nuint)(PlaneD * lanes));
            dd1.StoreUnsafe(ref o, (nuint)(PlaneDD * lanes));
            y2.StoreUnsafe(ref o, (nuint)((Second + PlaneY) * lanes));
            cx2.StoreUnsafe(ref o, (nuint)((Second + PlaneCx) * lanes));
            czA2.StoreUnsafe(ref o, (nuint)((Second + PlaneCz1) * lanes));
            czB2.StoreUnsafe(ref o, (nuint)((Second + PlaneCz2) * lanes));
            g2.StoreUnsafe(ref o, (nuint)((Second + PlaneG) * lanes));
            d2.StoreUnsafe(ref o, (nuint)((Second + PlaneD) * lanes));
            dd2.StoreUnsafe(ref o, (nuint)((Second + PlaneDD) * lanes));
        }
    }

    // Called once per band or row: optimised at the first call, not left to tiering's on-stack replacement.
    // Long: hand-unrolled: both images' spatial, then feature sums stay in registers through the tap loops; a split would spill them.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void VerticalVector(float[] ring, int[] spatialOffsets, int[] featureOffsets, float[] output, int count)
    {
        const int Second = PlanesPerImage;
        int lanes = Vector<float>.Count;
        ref float r0 = ref MemoryMarshal.GetArrayDataReference(ring);
        ref float ws = ref MemoryMarshal.GetArrayDataReference(_spatialWeights);
        ref float wf = ref MemoryMarshal.GetArrayDataReference(_featureWeights);
        ref int so = ref MemoryMarshal.GetArrayDataReference(spatialOffsets);
        ref int fo = ref MemoryMarshal.GetArrayDataReference(featureOffsets);
        ref float dst = ref MemoryMarshal.GetArrayDataReference(output);
        int taps = spatialOffsets.Length;
        int featureTaps = featureOffsets.Length;
        int narrowFirst = _filters.SpatialRadius - _filters.NarrowRadius;
        int narrowTaps = (2 * _filters.NarrowRadius) + 1;
        for (int x = 0; x < count; x += lanes)
        {
            ref float column = ref Unsafe.Add(ref r0, x * Planes);
            var y1 = Vector<float>.Zero;
            var cx1 = Vector<float>.Zero;
            var czA1 = Vector<float>.Zero;
            var czB1 = Vector<float>.Zero;
            var y2 = Vector<float>.Zero;
            var cx2 = Vector<float>.Zero;
            var czA2 = Vector<float>.Zero;
            var czB2 = Vector<float>.Zero;
            for (int k = 0; k < taps; k++)
            {
                ref float p = ref Unsafe.Add(ref column, Unsafe.Add(ref so, k));
                ref float w = ref Unsafe.Add(ref ws, 4 * k);
                var wcz1 = new Vector<float>(Unsafe.Add(ref w, 2));
                var wcz2 = new Vector<float>(Unsafe.Add(ref w, 3));
                czA1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)(PlaneCz1 * lanes)), wcz1, czA1);
                czB1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)(PlaneCz2 * lanes)), wcz2, czB1);
                czA2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneCz1) * lanes)), wcz1, czA2);
                czB2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneCz2) * lanes)), wcz2, czB2);
                if ((uint)(k - narrowFirst) < (uint)narrowTaps)
                {
                    var wy = new Vector<float>(w);
                    var wcx = new Vector<float>(Unsafe.Add(ref w, 1));
                    y1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)(PlaneY * lanes)), wy, y1);
                    cx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)(PlaneCx * lanes)), wcx, cx1);
                    y2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneY) * lanes)), wy, y2);
                    cx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneCx) * lanes)), wcx, cx2);
                }
            }

            var color = FlipModel.ColorError(y1, cx1, czA1 + czB1, y2, cx2, czA2 + czB2);

            var dx1 = Vector<float>.Zero;
            var ddx1 = Vector<float>.Zero;
            var dy1 = Vector<float>.Zero;
            var ddy1 = Vector<float>.Zero;
            var dx2 = Vector<float>.Zero;
            var ddx2 = Vector<float>.Zero;
            var dy2 = Vector<float>.Zero;
            var ddy2 = Vector<float>.Zero;
            for (int k = 0; k < featureTaps; k++)
            {
                ref float p = ref Unsafe.Add(ref column, Unsafe.Add(ref fo, k));
                ref float w = ref Unsafe.Add(ref wf, 3 * k);
                var wg = new Vector<float>(w);
                var wd = new Vector<float>(Unsafe.Add(ref w, 1));
                var wdd = new Vector<float>(Unsafe.Add(ref w, 2));
                var g1 = Vector.LoadUnsafe(ref p, (nuint)(PlaneG * lanes));
                var g2 = Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneG) * lanes));
                dx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)(PlaneD * lanes)), wg, dx1);
                ddx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)(PlaneDD * lanes)), wg, ddx1);
                dy1 = Vector.MultiplyAddEstimate(g1, wd, dy1);
                ddy1 = Vector.MultiplyAddEstimate(g1, wdd, ddy1);
                dx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneD) * lanes)), wg, dx2);
                ddx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref p, (nuint)((Second + PlaneDD) * lanes)), wg, ddx2);
                dy2 = Vector.MultiplyAddEstimate(g2, wd, dy2);
                ddy2 = Vector.MultiplyAddEstimate(g2, wdd, ddy2);
            }

            var feature = FlipModel.FeatureError(
                Vector.SquareRoot((dx1 * dx1) + (dy1 * dy1)),
                Vector.SquareRoot((ddx1 * ddx1) + (ddy1 * ddy1)),
                Vector.SquareRoot((dx2 * dx2) + (dy2 * dy2)),
                Vector.SquareRoot((ddx2 * ddx2) + (ddy2 * ddy2)));
            FlipModel.Combine(color, feature).StoreUnsafe(ref dst, (nuint)x);
        }
    }
}
