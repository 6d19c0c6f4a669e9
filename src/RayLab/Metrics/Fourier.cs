using System.Numerics;

namespace RayLab.Metrics;

/// <summary>
/// The discrete Fourier transform of any length: iterative radix-2 for powers of two, Bluestein's chirp-z
/// convolution (through a power-of-two transform) otherwise. X_k = Σⱼ x_j·exp(−2πi·jk/n).
/// </summary>
internal sealed class Fourier
{
    private readonly int _n;
    private readonly int _m;
    private readonly Complex[]? _chirp;
    private readonly Complex[]? _kernel;
    private readonly Complex[]? _work;
    private readonly Complex[] _twiddles;

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
