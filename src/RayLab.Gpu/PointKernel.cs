using ILGPU;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Sampling;

namespace RayLab.Gpu;

/// <summary>Which built-in point sampler a <see cref="PointFrame"/> runs.</summary>
internal enum DeviceSampler
{
    /// <summary><see cref="RegularSampler"/>.</summary>
    Regular,

    /// <summary><see cref="JitteredSampler"/>.</summary>
    Jittered,

    /// <summary><see cref="RandomSampler"/>.</summary>
    Random,

    /// <summary><see cref="HammersleySampler"/>.</summary>
    Hammersley,
}

/// <summary>A sphere as the kernel reads it: centre, radius and its flat colour (<see cref="Scene.ColourOf"/>).</summary>
/// <param name="center">The centre.</param>
/// <param name="radius">The radius.</param>
/// <param name="colour">The colour the scene shades it with.</param>
internal readonly struct DeviceSphere(Double3 center, double radius, Intensity colour)
{
    /// <summary>The centre.</summary>
    public readonly Double3 Center = center;

    /// <summary>The radius.</summary>
    public readonly double Radius = radius;

    /// <summary>The colour.</summary>
    public readonly Intensity Colour = colour;
}

/// <summary>What one launch of <see cref="PointKernel"/> renders: the rays, the sampler and which CPU kernel's bytes to give.</summary>
internal struct PointFrame
{
    /// <summary>The camera's rays.</summary>
    public RayBasis Basis;

    /// <summary>The first row rendered (a band of rows starts below 0).</summary>
    public int FirstRow;

    /// <summary>Samples per pixel.</summary>
    public int Samples;

    /// <summary>The sampler.</summary>
    public DeviceSampler Sampler;

    /// <summary>The grid side of the regular and jittered samplers.</summary>
    public int GridSize;

    /// <summary>The salted seed of the hashed samplers.</summary>
    public uint Salt;

    /// <summary>The jitter's scale in float (<see cref="JitteredSampler"/>).</summary>
    public float JitterScale;

    /// <summary>
    /// 1: the packet kernels' bytes (points in float, the sum in float, the lanes' 8-bit rule); 0: the scalar double
    /// loop's (<see cref="RenderKernel.Scalar"/>). An int: a kernel parameter holds no bool (not blittable).
    /// </summary>
    public int Lanes;

    /// <summary>The scene's background.</summary>
    public Intensity Background;
}

/// <summary>
/// The device kernel: one thread a pixel, each pixel the mean of its samples, only its three bytes written. Every
/// formula in it is the CPU's own (the samplers' <c>Formula</c> structs over <see cref="IPointMath{TV}"/>,
/// <see cref="RayBasis.GetPixelRay"/>, <see cref="SphereHit.TryIntersect"/>, the 8-bit rules), so the bytes are the
/// CPU renderer's: with <see cref="PointFrame.Lanes"/> those of every packet width (the points in the lanes' float, the
/// hit decided in double, as the packet kernels decide every uncertain one), without it those of the scalar loop.
/// </summary>
internal static class PointKernel
{
    /// <summary>Renders pixel <paramref name="index"/> of the band (row by row) into <paramref name="rgb"/>, 3 bytes a pixel.</summary>
    /// <param name="index">The pixel's index in the band.</param>
    /// <param name="frame">The launch's settings.</param>
    /// <param name="spheres">The scene's spheres, in the scene's order.</param>
    /// <param name="rgb">The band's bytes, R G B per pixel, row by row.</param>
    public static void Render(Index1D index, PointFrame frame, ArrayView<DeviceSphere> spheres, ArrayView<byte> rgb)
    {
        int width = frame.Basis.Width;
        int x = index % width;
        int row = frame.FirstRow + (index / width);
        long at = 3L * index;
        if (frame.Lanes != 0)
        {
            LaneMean(frame, spheres, x, row, out float r, out float g, out float b);
            float scale = 256f / frame.Samples;
            rgb[at] = EightBit.LaneLevel(r, scale);
            rgb[at + 1] = EightBit.LaneLevel(g, scale);
            rgb[at + 2] = EightBit.LaneLevel(b, scale);
        }
        else
        {
            Intensity mean = ScalarMean(frame, spheres, x, row);
            rgb[at] = Intensity.ToLevel(mean.R);
            rgb[at + 1] = Intensity.ToLevel(mean.G);
            rgb[at + 2] = Intensity.ToLevel(mean.B);
        }
    }

    /// <summary>The packet kernels' sum of a pixel's samples: points in float, each colour in float, summed in order.</summary>
    private static void LaneMean(in PointFrame frame, ArrayView<DeviceSphere> spheres, int x, int row, out float r, out float g, out float b)
    {
        FloatLane keys = PointHash.PixelKeys<FloatLane, FloatLaneMath>(x, row, frame.Salt);
        r = g = b = 0f;
        for (int i = 0; i < frame.Samples; i++)
        {
            float sx, sy;
            if (frame.Sampler == DeviceSampler.Regular)
            {
                SamplePoint p = RegularSampler.Formula.Point(i, frame.GridSize);
                (sx, sy) = ((float)p.X, (float)p.Y);
            }
            else if (frame.Sampler == DeviceSampler.Jittered)
            {
                JitteredSampler.Formula.Point<FloatLane, FloatLaneMath>(keys, i, JitteredSampler.Formula.CellOf(i, frame.GridSize), frame.GridSize, frame.JitterScale, out FloatLane px, out FloatLane py);
                (sx, sy) = (px.Value, py.Value);
            }
            else if (frame.Sampler == DeviceSampler.Random)
            {
                RandomSampler.Formula.Point<FloatLane, FloatLaneMath>(keys, i, out FloatLane px, out FloatLane py);
                (sx, sy) = (px.Value, py.Value);
            }
            else
            {
                HammersleySampler.Formula.Shift<FloatLane, FloatLaneMath>(keys, out FloatLane shiftX, out FloatLane shiftY);
                SamplePoint p = HammersleySampler.Formula.Unshifted(i, frame.Samples);
                (sx, sy) = (FloatLaneMath.Shifted(p.X, shiftX).Value, FloatLaneMath.Shifted(p.Y, shiftY).Value);
            }

            Intensity colour = Trace(frame, spheres, frame.Basis.GetPixelRay(x, row, sx, sy));
            r += (float)colour.R;
            g += (float)colour.G;
            b += (float)colour.B;
        }
    }

    /// <summary>The scalar loop's mean of a pixel's samples, in double.</summary>
    private static Intensity ScalarMean(in PointFrame frame, ArrayView<DeviceSphere> spheres, int x, int row)
    {
        ScalarLane keys = PointHash.PixelKeys<ScalarLane, ScalarMath>(x, row, frame.Salt);
        int n = frame.Samples;
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++)
        {
            double sx, sy;
            if (frame.Sampler == DeviceSampler.Regular)
            {
                SamplePoint p = RegularSampler.Formula.Point(i, frame.GridSize);
                (sx, sy) = (p.X, p.Y);
            }
            else if (frame.Sampler == DeviceSampler.Jittered)
            {
                JitteredSampler.Formula.Point<ScalarLane, ScalarMath>(keys, i, JitteredSampler.Formula.CellOf(i, frame.GridSize), frame.GridSize, frame.JitterScale, out ScalarLane px, out ScalarLane py);
                (sx, sy) = (px.Value, py.Value);
            }
            else if (frame.Sampler == DeviceSampler.Random)
            {
                RandomSampler.Formula.Point<ScalarLane, ScalarMath>(keys, i, out ScalarLane px, out ScalarLane py);
                (sx, sy) = (px.Value, py.Value);
            }
            else
            {
                HammersleySampler.Formula.Shift<ScalarLane, ScalarMath>(keys, out ScalarLane shiftX, out ScalarLane shiftY);
                SamplePoint p = HammersleySampler.Formula.Unshifted(i, n);
                (sx, sy) = (ScalarMath.Shifted(p.X, shiftX).Value, ScalarMath.Shifted(p.Y, shiftY).Value);
            }

            Intensity value = Trace(frame, spheres, frame.Basis.GetPixelRay(x, row, sx, sy));
            r += value.R;
            g += value.G;
            b += value.B;
        }

        return new Intensity(r / n, g / n, b / n);
    }

    /// <summary>The colour of the nearest sphere the ray meets in the visible range, or the background (the scene's loop over every sphere in order).</summary>
    private static Intensity Trace(in PointFrame frame, ArrayView<DeviceSphere> spheres, Ray ray)
    {
        int nearest = -1;
        double best = frame.Basis.TMax;
        for (int k = 0; k < (int)spheres.Length; k++)
        {
            DeviceSphere sphere = spheres[k];
            if (SphereHit.TryIntersect(sphere.Center, sphere.Radius, ray, frame.Basis.TMin, best, out double t))
            {
                best = t;
                nearest = k;
            }
        }

        return nearest < 0 ? frame.Background : spheres[nearest].Colour;
    }
}
