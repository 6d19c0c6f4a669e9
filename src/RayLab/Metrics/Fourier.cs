using System.Numerics;

namespace RayLab.Metrics;

/// <summary>
/// The discrete Fourier transform of any length: iterative radix-2 for powers of two, mixed radix (Stockham's
/// self-sorting form, radices 4, 2, 3 and 5) for lengths with no other prime factor (1 080 and 1 920, the image
/// sides of a 1080p picture), Bluestein's chirp-z convolution (through a power-of-two transform) otherwise.
/// X_k = Σⱼ x_j·exp(−2πi·jk/n). An instance holds its work buffer: one per thread.
/// </summary>
internal sealed class Fourier
{
    private readonly int _n;
    private readonly int _m;
    private readonly Complex[]? _chirp;
    private readonly Complex[]? _kernel;
    private readonly Complex[]? _work;
    private readonly Complex[] _twiddles;
    private readonly int[]? _radices;
    private readonly Complex[]? _roots;

    /// <summary>A transform of length <paramref name="n"/> ≥ 1, with its tables.</summary>
    public Fourier(int n)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(n, 1);
        _n = n;
        if (BitOperations.IsPow2(n))
        {
            _twiddles = Twiddles(n);
            return;
        }

        if (SmallRadices(n) is { } radices)
        {
            _radices = radices;
            _roots = new Complex[n];
            for (int t = 0; t < n; t++)
            {
                _roots[t] = Complex.FromPolarCoordinates(1, -2 * Math.PI * t / n);
            }

            _twiddles = [];
            _work = new Complex[n];
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
        if (_radices is not null)
        {
            Stockham(data);
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

    /// <summary>
    /// The mixed-radix transform in Stockham's form: stage by stage, with s the length of the transforms done so far,
    /// element j + r·n/p (r &lt; p) is multiplied by exp(−2πi·(j mod s)·r/(s·p)), the p of them go through a
    /// length-p transform, and the results land at (j div s)·s·p + (j mod s) + q·s, in the other buffer.
    /// </summary>
    private void Stockham(Span<Complex> data)
    {
        int n = _n;
        Complex[] roots = _roots!;
        Span<Complex> from = data, to = _work!;
        Span<Complex> v = stackalloc Complex[5];
        int s = 1;
        foreach (int p in _radices!)
        {
            int stride = n / p, step = n / (s * p), rootStep = n / p;
            for (int j = 0; j < stride; j++)
            {
                int k = j % s;
                for (int r = 0; r < p; r++)
                {
                    v[r] = r == 0 ? from[j] : from[j + (r * stride)] * roots[k * r * step];
                }

                int target = ((j / s) * s * p) + k;
                switch (p)
                {
                    case 2:
                        to[target] = v[0] + v[1];
                        to[target + s] = v[0] - v[1];
                        break;
                    case 4:
                        Complex a = v[0] + v[2], b = v[0] - v[2], c = v[1] + v[3], d = v[1] - v[3];
                        var dTimesMinusI = new Complex(d.Imaginary, -d.Real);
                        to[target] = a + c;
                        to[target + s] = b + dTimesMinusI;
                        to[target + (2 * s)] = a - c;
                        to[target + (3 * s)] = b - dTimesMinusI;
                        break;
                    default:
                        for (int q = 0; q < p; q++)
                        {
                            Complex sum = v[0];
                            for (int r = 1; r < p; r++)
                            {
                                sum += v[r] * roots[q * r % p * rootStep];
                            }

                            to[target + (q * s)] = sum;
                        }

                        break;
                }
            }

            Span<Complex> swap = from;
            from = to;
            to = swap;
            s *= p;
        }

        if (from != data)
        {
            from.CopyTo(data);
        }
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
