using System.Buffers;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using RayLab.Imaging;

namespace RayLab.Metrics;

/// <summary>
/// The LDR-FLIP pipeline on planar float rows. The picture is cut into horizontal bands, one task each; a band walks
/// its rows top to bottom, converting each input row (and the filters' margin above and below) to YCxCz, filtering it
/// horizontally into a ring of the last 2R + 1 rows (14 planes: for each image Y, Cx, Cz·h1, Cz·h2 and the feature
/// detectors' Gaussian, first and second derivative), then filtering that ring vertically and computing the error of
/// one output row. Every output value is computed by the same operations whatever the banding, so the map and its
/// mean (rows summed in double, then the row sums in order) are the same at any thread count.
/// </summary>
internal sealed class FlipKernel
{
    private const int PlanesPerImage = 7;
    private const int PlaneY = 0, PlaneCx = 1, PlaneCz1 = 2, PlaneCz2 = 3, PlaneG = 4, PlaneD = 5, PlaneDD = 6;

    private readonly Image _reference;
    private readonly Image _test;
    private readonly FlipFilters _filters;
    private readonly bool _vectorized;
    private readonly int _width;
    private readonly int _height;
    private readonly int _stride;      // Row length in the ring: the width rounded up to whole vectors.
    private readonly int _pad;         // Replicated edge pixels each side of a converted row.
    private readonly int _rowLength;   // _pad + _stride + _pad.
    private readonly int _ringRows;    // 2R + 1.
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
        _pad = _filters.MaxRadius;
        _rowLength = _pad + _stride + _pad;
        _ringRows = (2 * _filters.MaxRadius) + 1;
        _map = new float[(long)_width * _height];
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

    private void RunBand(int y0, int y1)
    {
        int r = _filters.MaxRadius;
        int rowFloats = 4 * _rowLength;
        int ringFloats = 2 * PlanesPerImage * _ringRows * _stride;
        float[] convertedReference = ArrayPool<float>.Shared.Rent(rowFloats);
        float[] convertedTest = ArrayPool<float>.Shared.Rent(rowFloats);
        float[] ring = ArrayPool<float>.Shared.Rent(ringFloats);
        float[] output = ArrayPool<float>.Shared.Rent(_stride);
        int[] spatialOffsets = new int[(2 * _filters.SpatialRadius) + 1];
        int[] featureOffsets = new int[(2 * _filters.FeatureRadius) + 1];
        try
        {
            int next = Math.Max(0, y0 - r);
            for (int y = y0; y < y1; y++)
            {
                int last = Math.Min(_height - 1, y + r);
                for (; next <= last; next++)
                {
                    int slot = next % _ringRows;
                    Convert(_reference.PixelBytes.Slice(next * 3 * _width, 3 * _width), convertedReference);
                    Convert(_test.PixelBytes.Slice(next * 3 * _width, 3 * _width), convertedTest);
                    if (_vectorized)
                    {
                        HorizontalVector(convertedReference, ring, slot, 0);
                        HorizontalVector(convertedTest, ring, slot, PlanesPerImage);
                    }
                    else
                    {
                        HorizontalScalar(convertedReference, ring, slot, 0);
                        HorizontalScalar(convertedTest, ring, slot, PlanesPerImage);
                    }
                }

                RowOffsets(y, _filters.SpatialRadius, spatialOffsets);
                RowOffsets(y, _filters.FeatureRadius, featureOffsets);
                if (_vectorized)
                {
                    VerticalVector(ring, spatialOffsets, featureOffsets, output);
                }
                else
                {
                    VerticalScalar(ring, spatialOffsets, featureOffsets, output);
                }

                Span<float> mapRow = _map.AsSpan(y * _width, _width);
                output.AsSpan(0, _width).CopyTo(mapRow);
                double rowSum = 0;
                foreach (float e in mapRow)
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
            offsets[k] = row % _ringRows * _stride;
        }
    }

    // One RGB24 row → four padded planar rows: Y, Cx, Cz and the normalised luminance, edges replicated.
    private void Convert(ReadOnlySpan<byte> rgb, float[] converted)
    {
        float[] lut = FlipModel.SrgbToLinear;
        Span<float> y = converted.AsSpan(0, _rowLength);
        Span<float> cx = converted.AsSpan(_rowLength, _rowLength);
        Span<float> cz = converted.AsSpan(2 * _rowLength, _rowLength);
        Span<float> yn = converted.AsSpan(3 * _rowLength, _rowLength);
        for (int x = 0; x < _width; x++)
        {
            FlipModel.LinearToYCxCz(lut[rgb[3 * x]], lut[rgb[(3 * x) + 1]], lut[rgb[(3 * x) + 2]], out float yy, out float cxx, out float czz);
            y[_pad + x] = yy;
            cx[_pad + x] = cxx;
            cz[_pad + x] = czz;
            yn[_pad + x] = FlipModel.NormalizedLuminance(yy);
        }

        Replicate(y);
        Replicate(cx);
        Replicate(cz);
        Replicate(yn);
    }

    private void Replicate(Span<float> row)
    {
        row[.._pad].Fill(row[_pad]);
        row[(_pad + _width)..].Fill(row[_pad + _width - 1]);
    }

    private int PlaneOffset(int plane) => plane * _ringRows * _stride;

    private void HorizontalScalar(float[] converted, float[] ring, int slot, int firstPlane)
    {
        FlipFilters f = _filters;
        int rs = f.SpatialRadius, rf = f.FeatureRadius;
        int row = slot * _stride;
        for (int x = 0; x < _width; x++)
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

            ring[PlaneOffset(firstPlane + PlaneY) + row + x] = y;
            ring[PlaneOffset(firstPlane + PlaneCx) + row + x] = cx;
            ring[PlaneOffset(firstPlane + PlaneCz1) + row + x] = cz1;
            ring[PlaneOffset(firstPlane + PlaneCz2) + row + x] = cz2;
            ring[PlaneOffset(firstPlane + PlaneG) + row + x] = g;
            ring[PlaneOffset(firstPlane + PlaneD) + row + x] = d;
            ring[PlaneOffset(firstPlane + PlaneDD) + row + x] = dd;
        }
    }

    private void VerticalScalar(float[] ring, int[] spatialOffsets, int[] featureOffsets, float[] output)
    {
        FlipFilters f = _filters;
        int oY1 = PlaneOffset(PlaneY), oCx1 = PlaneOffset(PlaneCx), oCz11 = PlaneOffset(PlaneCz1), oCz21 = PlaneOffset(PlaneCz2);
        int oY2 = PlaneOffset(PlanesPerImage + PlaneY), oCx2 = PlaneOffset(PlanesPerImage + PlaneCx);
        int oCz12 = PlaneOffset(PlanesPerImage + PlaneCz1), oCz22 = PlaneOffset(PlanesPerImage + PlaneCz2);
        int oG1 = PlaneOffset(PlaneG), oD1 = PlaneOffset(PlaneD), oDD1 = PlaneOffset(PlaneDD);
        int oG2 = PlaneOffset(PlanesPerImage + PlaneG), oD2 = PlaneOffset(PlanesPerImage + PlaneD), oDD2 = PlaneOffset(PlanesPerImage + PlaneDD);
        for (int x = 0; x < _width; x++)
        {
            float y1 = 0, cx1 = 0, czA1 = 0, czB1 = 0, y2 = 0, cx2 = 0, czA2 = 0, czB2 = 0;
            for (int k = 0; k < spatialOffsets.Length; k++)
            {
                int o = spatialOffsets[k] + x;
                y1 += f.Y[k] * ring[oY1 + o];
                cx1 += f.Cx[k] * ring[oCx1 + o];
                czA1 += f.Cz1[k] * ring[oCz11 + o];
                czB1 += f.Cz2[k] * ring[oCz21 + o];
                y2 += f.Y[k] * ring[oY2 + o];
                cx2 += f.Cx[k] * ring[oCx2 + o];
                czA2 += f.Cz1[k] * ring[oCz12 + o];
                czB2 += f.Cz2[k] * ring[oCz22 + o];
            }

            float color = FlipModel.ColorError(y1, cx1, czA1 + czB1, y2, cx2, czA2 + czB2);

            float dx1 = 0, ddx1 = 0, dy1 = 0, ddy1 = 0, dx2 = 0, ddx2 = 0, dy2 = 0, ddy2 = 0;
            for (int k = 0; k < featureOffsets.Length; k++)
            {
                int o = featureOffsets[k] + x;
                float g1 = ring[oG1 + o], g2 = ring[oG2 + o];
                dx1 += f.G[k] * ring[oD1 + o];
                ddx1 += f.G[k] * ring[oDD1 + o];
                dy1 += f.D[k] * g1;
                ddy1 += f.DD[k] * g1;
                dx2 += f.G[k] * ring[oD2 + o];
                ddx2 += f.G[k] * ring[oDD2 + o];
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

    private void HorizontalVector(float[] converted, float[] ring, int slot, int firstPlane)
    {
        FlipFilters f = _filters;
        int rs = f.SpatialRadius, rf = f.FeatureRadius;
        int lanes = Vector<float>.Count;
        ref float src = ref MemoryMarshal.GetArrayDataReference(converted);
        ref float srcY = ref src;
        ref float srcCx = ref Unsafe.Add(ref src, _rowLength);
        ref float srcCz = ref Unsafe.Add(ref src, 2 * _rowLength);
        ref float srcYn = ref Unsafe.Add(ref src, 3 * _rowLength);
        ref float wY = ref MemoryMarshal.GetArrayDataReference(f.Y);
        ref float wCx = ref MemoryMarshal.GetArrayDataReference(f.Cx);
        ref float wCz1 = ref MemoryMarshal.GetArrayDataReference(f.Cz1);
        ref float wCz2 = ref MemoryMarshal.GetArrayDataReference(f.Cz2);
        ref float wG = ref MemoryMarshal.GetArrayDataReference(f.G);
        ref float wD = ref MemoryMarshal.GetArrayDataReference(f.D);
        ref float wDD = ref MemoryMarshal.GetArrayDataReference(f.DD);
        ref float dst = ref Unsafe.Add(ref MemoryMarshal.GetArrayDataReference(ring), slot * _stride);
        ref float dY = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneY));
        ref float dCx = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneCx));
        ref float dCz1 = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneCz1));
        ref float dCz2 = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneCz2));
        ref float dG = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneG));
        ref float dD = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneD));
        ref float dDD = ref Unsafe.Add(ref dst, PlaneOffset(firstPlane + PlaneDD));
        int taps = (2 * rs) + 1;
        int featureTaps = (2 * rf) + 1;
        for (int x = 0; x < _stride; x += lanes)
        {
            var y = Vector<float>.Zero;
            var cx = Vector<float>.Zero;
            var cz1 = Vector<float>.Zero;
            var cz2 = Vector<float>.Zero;
            nuint start = (nuint)(_pad + x - rs);
            for (int k = 0; k < taps; k++)
            {
                nuint i = start + (nuint)k;
                var vcz = Vector.LoadUnsafe(ref srcCz, i);
                y = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref srcY, i), new Vector<float>(Unsafe.Add(ref wY, k)), y);
                cx = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref srcCx, i), new Vector<float>(Unsafe.Add(ref wCx, k)), cx);
                cz1 = Vector.MultiplyAddEstimate(vcz, new Vector<float>(Unsafe.Add(ref wCz1, k)), cz1);
                cz2 = Vector.MultiplyAddEstimate(vcz, new Vector<float>(Unsafe.Add(ref wCz2, k)), cz2);
            }

            var g = Vector<float>.Zero;
            var d = Vector<float>.Zero;
            var dd = Vector<float>.Zero;
            start = (nuint)(_pad + x - rf);
            for (int k = 0; k < featureTaps; k++)
            {
                var v = Vector.LoadUnsafe(ref srcYn, start + (nuint)k);
                g = Vector.MultiplyAddEstimate(v, new Vector<float>(Unsafe.Add(ref wG, k)), g);
                d = Vector.MultiplyAddEstimate(v, new Vector<float>(Unsafe.Add(ref wD, k)), d);
                dd = Vector.MultiplyAddEstimate(v, new Vector<float>(Unsafe.Add(ref wDD, k)), dd);
            }

            nuint o = (nuint)x;
            y.StoreUnsafe(ref dY, o);
            cx.StoreUnsafe(ref dCx, o);
            cz1.StoreUnsafe(ref dCz1, o);
            cz2.StoreUnsafe(ref dCz2, o);
            g.StoreUnsafe(ref dG, o);
            d.StoreUnsafe(ref dD, o);
            dd.StoreUnsafe(ref dDD, o);
        }
    }

    private void VerticalVector(float[] ring, int[] spatialOffsets, int[] featureOffsets, float[] output)
    {
        FlipFilters f = _filters;
        int lanes = Vector<float>.Count;
        ref float r0 = ref MemoryMarshal.GetArrayDataReference(ring);
        ref float pY1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneY));
        ref float pCx1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneCx));
        ref float pCzA1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneCz1));
        ref float pCzB1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneCz2));
        ref float pG1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneG));
        ref float pD1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneD));
        ref float pDD1 = ref Unsafe.Add(ref r0, PlaneOffset(PlaneDD));
        ref float pY2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneY));
        ref float pCx2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneCx));
        ref float pCzA2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneCz1));
        ref float pCzB2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneCz2));
        ref float pG2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneG));
        ref float pD2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneD));
        ref float pDD2 = ref Unsafe.Add(ref r0, PlaneOffset(PlanesPerImage + PlaneDD));
        ref float wY = ref MemoryMarshal.GetArrayDataReference(f.Y);
        ref float wCx = ref MemoryMarshal.GetArrayDataReference(f.Cx);
        ref float wCz1 = ref MemoryMarshal.GetArrayDataReference(f.Cz1);
        ref float wCz2 = ref MemoryMarshal.GetArrayDataReference(f.Cz2);
        ref float wG = ref MemoryMarshal.GetArrayDataReference(f.G);
        ref float wD = ref MemoryMarshal.GetArrayDataReference(f.D);
        ref float wDD = ref MemoryMarshal.GetArrayDataReference(f.DD);
        ref int so = ref MemoryMarshal.GetArrayDataReference(spatialOffsets);
        ref int fo = ref MemoryMarshal.GetArrayDataReference(featureOffsets);
        ref float dst = ref MemoryMarshal.GetArrayDataReference(output);
        int taps = spatialOffsets.Length;
        int featureTaps = featureOffsets.Length;
        for (int x = 0; x < _stride; x += lanes)
        {
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
                nuint o = (nuint)(Unsafe.Add(ref so, k) + x);
                var wy = new Vector<float>(Unsafe.Add(ref wY, k));
                var wcx = new Vector<float>(Unsafe.Add(ref wCx, k));
                var wcz1 = new Vector<float>(Unsafe.Add(ref wCz1, k));
                var wcz2 = new Vector<float>(Unsafe.Add(ref wCz2, k));
                y1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pY1, o), wy, y1);
                cx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pCx1, o), wcx, cx1);
                czA1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pCzA1, o), wcz1, czA1);
                czB1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pCzB1, o), wcz2, czB1);
                y2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pY2, o), wy, y2);
                cx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pCx2, o), wcx, cx2);
                czA2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pCzA2, o), wcz1, czA2);
                czB2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pCzB2, o), wcz2, czB2);
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
                nuint o = (nuint)(Unsafe.Add(ref fo, k) + x);
                var wg = new Vector<float>(Unsafe.Add(ref wG, k));
                var wd = new Vector<float>(Unsafe.Add(ref wD, k));
                var wdd = new Vector<float>(Unsafe.Add(ref wDD, k));
                var g1 = Vector.LoadUnsafe(ref pG1, o);
                var g2 = Vector.LoadUnsafe(ref pG2, o);
                dx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pD1, o), wg, dx1);
                ddx1 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pDD1, o), wg, ddx1);
                dy1 = Vector.MultiplyAddEstimate(g1, wd, dy1);
                ddy1 = Vector.MultiplyAddEstimate(g1, wdd, ddy1);
                dx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pD2, o), wg, dx2);
                ddx2 = Vector.MultiplyAddEstimate(Vector.LoadUnsafe(ref pDD2, o), wg, ddx2);
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
