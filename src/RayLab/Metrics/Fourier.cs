using System.Numerics;
using System.Runtime.InteropServices;

namespace RayLab.Metrics;

/// <summary>
/// The discrete Fourier transform of any length: iterative radix-2 for powers of two, mixed radix (Stockham's
/// self-sorting form, radices 4, 2, 3 and 5) for lengths with no other prime factor (1 080 and 1 920, the image
/// sides of a 1080p picture), Bluestein's chirp-z convolution (through a power-of-two transform) otherwise.
/// X_k = Σⱼ x_j·exp(−2πi·jk/n). An instance holds its work buffer: one per thread.
/// </summary>
/// <remarks>
/// <see cref="Transform(Span{double}, Span{double})"/> transforms <see cref="Vector{T}.Count"/> sequences at once, one
/// per lane: for lengths with no prime factor above 5 Stockham's stages run on whole vectors, every lane the same
/// operations on its own sequence. The scalar <see cref="Transform(Span{Complex})"/> of such a length (not a power of
/// two, which it does by radix 2) is that code with the sequence in lane 0, so one formula serves both; other lengths
/// go lane by lane through the scalar form. The error spectrum (3 000 transforms a plane at 1080p) is this class's
/// whole work; its CPU time per 1080p picture is in docs/compare.md.
/// </remarks>
internal sealed class Fourier
{
    private readonly int _n;
    private readonly int _m;
    private readonly Complex[]? _chirp;
    private readonly Complex[]? _kernel;
    private readonly Complex[]? _work;
    private readonly Complex[] _twiddles;
    private readonly int[]? _laneRadices;
    private double[]? _laneRootsRe;
    private double[]? _laneRootsIm;
    private double[]? _laneWork;
    private double[]? _laneScalarBuffer;
    private Complex[]? _laneScalar;

    /// <summary>sin(60°) = √3/2.</summary>
    private static readonly double Sin60 = Math.Sqrt(3) / 2;

    /// <summary>cos(72°), cos(144°), sin(72°) and sin(144°): the length-5 butterfly's constants.</summary>
    private static readonly double Cos72 = Math.Cos(2 * Math.PI / 5), Cos144 = Math.Cos(4 * Math.PI / 5), Sin72 = Math.Sin(2 * Math.PI / 5), Sin144 = Math.Sin(4 * Math.PI / 5);

    /// <summary>A transform of length <paramref name="n"/> ≥ 1, with its tables.</summary>
    public Fourier(int n)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(n, 1);
        _n = n;
        _laneRadices = SmallRadices(n);
        if (BitOperations.IsPow2(n))
        {
            _twiddles = Twiddles(n);
            return;
        }

        if (_laneRadices is not null)
        {
            _twiddles = [];
            return;
        }

        _m = (int)BitOperations.RoundUpToPowerOf2((uint)((2 * n) - 1));
        _chirp = new Complex[n];
        for (int k = 0; k < n; k++)
        {
            // exp(−iπk²/n), with k² reduced mod 2n so the angle stays exact for large k.
            long k2 = (long)k * k % (2L * n);
            _chirp[k] = Complex.FromPolarCoordinates(1, -Math.PI * k2 / n);
        }

        _kernel = new Complex[_m];
        _kernel[0] = Complex.Conjugate(_chirp[0]);
        for (int k = 1; k < n; k++)
        {
            _kernel[k] = _kernel[_m - k] = Complex.Conjugate(_chirp[k]);
        }

        _twiddles = Twiddles(_m);
        Radix2(_kernel, _twiddles, inverse: false);
        _work = new Complex[_m];
    }

    /// <summary>Transforms <paramref name="data"/> (length n) in place.</summary>
    public void Transform(Span<Complex> data)
    {
        // A mixed-radix length (a power of two has radices too, but its scalar form is radix 2)
        if (_laneRadices is not null && !BitOperations.IsPow2(_n))
        {
            InLaneZero(data);
            return;
        }

        if (_chirp is null)
        {
            Radix2(data, _twiddles, inverse: false);
            return;
        }

        Complex[] work = _work!;
        Array.Clear(work);
        for (int k = 0; k < _n; k++)
        {
            work[k] = data[k] * _chirp[k];
        }

        Radix2(work, _twiddles, inverse: false);
        for (int k = 0; k < _m; k++)
        {
            work[k] *= _kernel![k];
        }

        Radix2(work, _twiddles, inverse: true);
        for (int k = 0; k < _n; k++)
        {
            data[k] = work[k] * _chirp[k] / _m;
        }
    }

    /// <summary>
    /// Transforms <see cref="Vector{T}.Count"/> sequences at once, in place: element k of sequence l is
    /// (<paramref name="re"/>[k·L + l], <paramref name="im"/>[k·L + l]) with L = <see cref="Vector{T}.Count"/>.
    /// </summary>
    /// <param name="re">The real parts, n·L values.</param>
    /// <param name="im">The imaginary parts, n·L values.</param>
    public void Transform(Span<double> re, Span<double> im)
    {
        int lanes = Vector<double>.Count;
        if (re.Length != _n * lanes || im.Length != _n * lanes)
        {
            throw new ArgumentException($"A transform of {_n} in {lanes} lanes takes {_n * lanes} values, not {re.Length} and {im.Length}.", nameof(re));
        }

        if (_laneRadices is null)
        {
            LaneByLane(re, im, lanes);
            return;
        }

        StockhamLanes(MemoryMarshal.Cast<double, Vector<double>>(re), MemoryMarshal.Cast<double, Vector<double>>(im));
    }

    /// <summary>The lanes one at a time through the scalar form (lengths with a prime factor above 5).</summary>
    private void LaneByLane(Span<double> re, Span<double> im, int lanes)
    {
        Complex[] scalar = _laneScalar ??= new Complex[_n];
        for (int l = 0; l < lanes; l++)
        {
            for (int k = 0; k < _n; k++)
            {
                scalar[k] = new Complex(re[(k * lanes) + l], im[(k * lanes) + l]);
            }

            Transform(scalar);
            for (int k = 0; k < _n; k++)
            {
                re[(k * lanes) + l] = scalar[k].Real;
                im[(k * lanes) + l] = scalar[k].Imaginary;
            }
        }
    }

    /// <summary>A mixed-radix length's scalar transform: the sequence in lane 0 of the lane form, the other lanes zero.</summary>
    private void InLaneZero(Span<Complex> data)
    {
        int lanes = Vector<double>.Count;
        double[] single = _laneScalarBuffer ??= new double[2 * _n * lanes];
        Span<double> re = single.AsSpan(0, _n * lanes), im = single.AsSpan(_n * lanes);
        single.AsSpan().Clear();
        for (int k = 0; k < _n; k++)
        {
            re[k * lanes] = data[k].Real;
            im[k * lanes] = data[k].Imaginary;
        }

        StockhamLanes(MemoryMarshal.Cast<double, Vector<double>>(re), MemoryMarshal.Cast<double, Vector<double>>(im));
        for (int k = 0; k < _n; k++)
        {
            data[k] = new Complex(re[k * lanes], im[k * lanes]);
        }
    }

    /// <summary>
    /// The mixed-radix transform in Stockham's self-sorting form, on whole vectors (each lane its own sequence): stage by
    /// stage, with s the length of the transforms done so far, element j + r·n/p (r &lt; p) is multiplied by
    /// exp(−2πi·(j mod s)·r/(s·p)) (not at all where j mod s = 0), the p of them go through a length-p transform (the
    /// butterflies of 2, 3, 4 and 5, which share their sums and differences), and the results land at
    /// (j div s)·s·p + (j mod s) + q·s, in the other buffer.
    /// </summary>
    // Long: Stockham's stage loop with its four butterflies written out on vectors.
    private void StockhamLanes(Span<Vector<double>> dataRe, Span<Vector<double>> dataIm)
    {
        int n = _n;
        if (_laneRootsRe is null)
        {
            _laneRootsRe = new double[n];
            _laneRootsIm = new double[n];
            for (int t = 0; t < n; t++)
            {
                Complex root = Complex.FromPolarCoordinates(1, -2 * Math.PI * t / n);
                _laneRootsRe[t] = root.Real;
                _laneRootsIm[t] = root.Imaginary;
            }

            _laneWork = new double[2 * n * Vector<double>.Count];
        }

        double[] rootsRe = _laneRootsRe, rootsIm = _laneRootsIm!;
        Span<Vector<double>> work = MemoryMarshal.Cast<double, Vector<double>>(_laneWork.AsSpan());
        Span<Vector<double>> fromRe = dataRe, fromIm = dataIm, toRe = work[..n], toIm = work[n..];
        Span<Vector<double>> vRe = stackalloc Vector<double>[5];
        Span<Vector<double>> vIm = stackalloc Vector<double>[5];
        Span<Vector<double>> twRe = stackalloc Vector<double>[5];
        Span<Vector<double>> twIm = stackalloc Vector<double>[5];
        int s = 1;
        foreach (int p in _laneRadices!)
        {
            int stride = n / p, step = n / (s * p);
            for (int k = 0; k < s; k++)
            {
                for (int r = 1; r < p; r++)
                {
                    twRe[r] = new Vector<double>(rootsRe[k * r * step]);
                    twIm[r] = new Vector<double>(rootsIm[k * r * step]);
                }

                for (int b = 0; b * s < stride; b++)
                {
                    int j = (b * s) + k;
                    for (int r = 0; r < p; r++)
                    {
                        vRe[r] = fromRe[j + (r * stride)];
                        vIm[r] = fromIm[j + (r * stride)];
                    }

                    if (k != 0)
                    {
                        for (int r = 1; r < p; r++)
                        {
                            Vector<double> xr = vRe[r], xi = vIm[r];
                            vRe[r] = (xr * twRe[r]) - (xi * twIm[r]);
                            vIm[r] = (xi * twRe[r]) + (xr * twIm[r]);
                        }
                    }

                    int target = (b * s * p) + k;
                    switch (p)
                    {
                        case 2:
                            toRe[target] = vRe[0] + vRe[1];
                            toIm[target] = vIm[0] + vIm[1];
                            toRe[target + s] = vRe[0] - vRe[1];
                            toIm[target + s] = vIm[0] - vIm[1];
                            break;
                        case 3:
                            Butterfly3(vRe, vIm, toRe, toIm, target, s);
                            break;
                        case 4:
                            Butterfly4(vRe, vIm, toRe, toIm, target, s);
                            break;
                        default:
                            Butterfly5(vRe, vIm, toRe, toIm, target, s);
                            break;
                    }
                }
            }

            Span<Vector<double>> swapRe = fromRe, swapIm = fromIm;
            fromRe = toRe;
            fromIm = toIm;
            toRe = swapRe;
            toIm = swapIm;
            s *= p;
        }

        if (fromRe != dataRe)
        {
            fromRe.CopyTo(dataRe);
            fromIm.CopyTo(dataIm);
        }
    }

    /// <summary>X_q = Σ_r v_r·w^(qr), w = exp(−2πi/3): X₁,₂ = v₀ − (v₁ + v₂)/2 ∓ i·(√3/2)(v₁ − v₂).</summary>
    private static void Butterfly3(Span<Vector<double>> vRe, Span<Vector<double>> vIm, Span<Vector<double>> toRe, Span<Vector<double>> toIm, int target, int s)
    {
        var half = new Vector<double>(0.5);
        var sin = new Vector<double>(Sin60);
        Vector<double> tRe = vRe[1] + vRe[2], tIm = vIm[1] + vIm[2];
        Vector<double> mRe = vRe[0] - (half * tRe), mIm = vIm[0] - (half * tIm);
        Vector<double> dRe = sin * (vRe[1] - vRe[2]), dIm = sin * (vIm[1] - vIm[2]);
        toRe[target] = vRe[0] + tRe;
        toIm[target] = vIm[0] + tIm;
        toRe[target + s] = mRe + dIm;
        toIm[target + s] = mIm - dRe;
        toRe[target + (2 * s)] = mRe - dIm;
        toIm[target + (2 * s)] = mIm + dRe;
    }

    /// <summary>X_q = Σ_r v_r·(−i)^(qr): sums and differences only.</summary>
    private static void Butterfly4(Span<Vector<double>> vRe, Span<Vector<double>> vIm, Span<Vector<double>> toRe, Span<Vector<double>> toIm, int target, int s)
    {
        Vector<double> aRe = vRe[0] + vRe[2], aIm = vIm[0] + vIm[2];
        Vector<double> bRe = vRe[0] - vRe[2], bIm = vIm[0] - vIm[2];
        Vector<double> cRe = vRe[1] + vRe[3], cIm = vIm[1] + vIm[3];
        Vector<double> dRe = vRe[1] - vRe[3], dIm = vIm[1] - vIm[3];

        // d·(−i) = (d.Im, −d.Re)
        toRe[target] = aRe + cRe;
        toIm[target] = aIm + cIm;
        toRe[target + s] = bRe + dIm;
        toIm[target + s] = bIm - dRe;
        toRe[target + (2 * s)] = aRe - cRe;
        toIm[target + (2 * s)] = aIm - cIm;
        toRe[target + (3 * s)] = bRe - dIm;
        toIm[target + (3 * s)] = bIm + dRe;
    }

    /// <summary>
    /// X_q = Σ_r v_r·w^(qr), w = exp(−2πi/5), from t₁ = v₁ + v₄, t₂ = v₂ + v₃, t₃ = v₁ − v₄, t₄ = v₂ − v₃:
    /// X₁,₄ = v₀ + c₁t₁ + c₂t₂ ∓ i(s₁t₃ + s₂t₄) and X₂,₃ = v₀ + c₂t₁ + c₁t₂ ∓ i(s₂t₃ − s₁t₄), with cₖ = cos(2πk/5), sₖ = sin(2πk/5).
    /// </summary>
    private static void Butterfly5(Span<Vector<double>> vRe, Span<Vector<double>> vIm, Span<Vector<double>> toRe, Span<Vector<double>> toIm, int target, int s)
    {
        var c1 = new Vector<double>(Cos72);
        var c2 = new Vector<double>(Cos144);
        var s1 = new Vector<double>(Sin72);
        var s2 = new Vector<double>(Sin144);
        Vector<double> t1Re = vRe[1] + vRe[4], t1Im = vIm[1] + vIm[4];
        Vector<double> t2Re = vRe[2] + vRe[3], t2Im = vIm[2] + vIm[3];
        Vector<double> t3Re = vRe[1] - vRe[4], t3Im = vIm[1] - vIm[4];
        Vector<double> t4Re = vRe[2] - vRe[3], t4Im = vIm[2] - vIm[3];
        Vector<double> a1Re = vRe[0] + (c1 * t1Re) + (c2 * t2Re), a1Im = vIm[0] + (c1 * t1Im) + (c2 * t2Im);
        Vector<double> a2Re = vRe[0] + (c2 * t1Re) + (c1 * t2Re), a2Im = vIm[0] + (c2 * t1Im) + (c1 * t2Im);
        Vector<double> b1Re = (s1 * t3Re) + (s2 * t4Re), b1Im = (s1 * t3Im) + (s2 * t4Im);
        Vector<double> b2Re = (s2 * t3Re) - (s1 * t4Re), b2Im = (s2 * t3Im) - (s1 * t4Im);

        // a − i·b = (a.Re + b.Im, a.Im − b.Re); a + i·b = (a.Re − b.Im, a.Im + b.Re)
        toRe[target] = vRe[0] + t1Re + t2Re;
        toIm[target] = vIm[0] + t1Im + t2Im;
        toRe[target + s] = a1Re + b1Im;
        toIm[target + s] = a1Im - b1Re;
        toRe[target + (4 * s)] = a1Re - b1Im;
        toIm[target + (4 * s)] = a1Im + b1Re;
        toRe[target + (2 * s)] = a2Re + b2Im;
        toIm[target + (2 * s)] = a2Im - b2Re;
        toRe[target + (3 * s)] = a2Re - b2Im;
        toIm[target + (3 * s)] = a2Im + b2Re;
    }

    /// <summary>The radices of <paramref name="n"/>, fours first, then a two, threes and fives; null where another prime divides it.</summary>
    private static int[]? SmallRadices(int n)
    {
        var radices = new List<int>();
        while (n % 4 == 0)
        {
            radices.Add(4);
            n /= 4;
        }

        foreach (int p in (ReadOnlySpan<int>)[2, 3, 5])
        {
            while (n % p == 0)
            {
                radices.Add(p);
                n /= p;
            }
        }

        return n == 1 ? [.. radices] : null;
    }

    /// <summary>exp(−2πik/n) for k &lt; n/2.</summary>
    private static Complex[] Twiddles(int n)
    {
        var w = new Complex[Math.Max(1, n / 2)];
        for (int k = 0; k < w.Length; k++)
        {
            w[k] = Complex.FromPolarCoordinates(1, -2 * Math.PI * k / n);
        }

        return w;
    }

    /// <summary>The unscaled radix-2 transform (the inverse with +i), length a power of two; <paramref name="twiddles"/> are its length's.</summary>
    private static void Radix2(Span<Complex> a, Complex[] twiddles, bool inverse)
    {
        int n = a.Length;
        for (int i = 1, j = 0; i < n; i++)
        {
            int bit = n >> 1;
            for (; (j & bit) != 0; bit >>= 1)
            {
                j ^= bit;
            }

            j ^= bit;
            if (i < j)
            {
                (a[i], a[j]) = (a[j], a[i]);
            }
        }

        for (int length = 2; length <= n; length <<= 1)
        {
            int stride = n / length;
            for (int start = 0; start < n; start += length)
            {
                for (int k = 0; k < length / 2; k++)
                {
                    Complex w = inverse ? Complex.Conjugate(twiddles[k * stride]) : twiddles[k * stride];
                    Complex u = a[start + k], v = a[start + k + (length / 2)] * w;
                    a[start + k] = u + v;
                    a[start + k + (length / 2)] = u - v;
                }
            }
        }
    }
}
