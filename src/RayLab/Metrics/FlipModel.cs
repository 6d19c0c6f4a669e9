using System.Numerics;
using System.Runtime.CompilerServices;

namespace RayLab.Metrics;

/// <summary>
/// LDR-FLIP's constants and per-pixel colour transforms (Andersson et al., "FLIP: A Difference Evaluator for
/// Alternating Images", HPG 2020, sections 3–4), each in a scalar and a <see cref="Vector{T}"/> form that compute
/// the same expressions in the same order. Colours travel as sRGB → linear RGB → CIE XYZ (D65) → YCxCz
/// (the opponent space the contrast sensitivity filters act in) and, after filtering, back to linear RGB (clamped
/// to the gamut) → CIELAB with the Hunt adjustment, where the HyAB distance is taken.
/// </summary>
internal static class FlipModel
{
    /// <summary>q_c: the exponent that compresses the colour distance.</summary>
    public const float Qc = 0.7f;

    /// <summary>p_c: the fraction of the largest colour distance mapped to p_t.</summary>
    public const float Pc = 0.4f;

    /// <summary>p_t: the error the colour distance p_c·c_max is mapped to.</summary>
    public const float Pt = 0.95f;

    /// <summary>w: the feature detectors' width in degrees (σ = w/2 degrees).</summary>
    public const float FeatureWidth = 0.082f;

    /// <summary>q_f: the exponent of the feature difference (½: a square root).</summary>
    public const float Qf = 0.5f;

    // D65 reference white (X, Y = 1, Z) and its inverse, as the reference implementation states them.
    private const float WhiteX = 0.950428545f;
    private const float WhiteZ = 1.088900371f;
    private const float InvWhiteX = 1.052156925f;
    private const float InvWhiteZ = 0.918357670f;

    // Linear sRGB → XYZ (D65), exact fractions of the sRGB primaries.
    private const float M11 = 10135552.0f / 24577794.0f, M12 = 8788810.0f / 24577794.0f, M13 = 4435075.0f / 24577794.0f;
    private const float M21 = 2613072.0f / 12288897.0f, M22 = 8788810.0f / 12288897.0f, M23 = 887015.0f / 12288897.0f;
    private const float M31 = 1425312.0f / 73733382.0f, M32 = 8788810.0f / 73733382.0f, M33 = 70074185.0f / 73733382.0f;

    // XYZ (D65) → linear sRGB.
    private const float N11 = 3.241003275f, N12 = -1.537398934f, N13 = -0.498615861f;
    private const float N21 = -0.969224334f, N22 = 1.875930071f, N23 = 0.041554224f;
    private const float N31 = 0.055639423f, N32 = -0.204011202f, N33 = 1.057148933f;

    // CIELAB's f(t): the cube root above (6/29)³, a line below.
    private const float LabDelta = 6.0f / 29.0f;
    private const float LabDeltaCube = LabDelta * LabDelta * LabDelta;
    private const float LabFactor = 1.0f / (3.0f * LabDelta * LabDelta);
    private const float LabTerm = 4.0f / 29.0f;
    private const float OneThird = 1.0f / 3.0f;

    /// <summary>1/√2: the largest edge or point response difference is scaled by it before q_f.</summary>
    public static readonly float InvSqrt2 = 1.0f / MathF.Sqrt(2.0f);

    /// <summary>c_max: the HyAB distance (Hunt-adjusted) between pure green and pure blue, raised to q_c.</summary>
    public static readonly float MaxColorDistance = ComputeMaxColorDistance();

    /// <summary>p_c·c_max.</summary>
    public static readonly float PcMaxColorDistance = Pc * MaxColorDistance;

    /// <summary>8-bit sRGB level → linear RGB in [0, 1] (the sRGB transfer function, level/255 first).</summary>
    public static readonly float[] SrgbToLinear = BuildSrgbTable();

    private static float[] BuildSrgbTable()
    {
        var table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            float c = i / 255.0f;
            table[i] = c <= 0.04045f ? c / 12.92f : MathF.Pow((c + 0.055f) / 1.055f, 2.4f);
        }

        return table;
    }

    private static float ComputeMaxColorDistance()
    {
        LinearToLabHunt(0, 1, 0, out float lg, out float ag, out float bg);
        LinearToLabHunt(0, 0, 1, out float lb, out float ab, out float bb);
        return MathF.Pow(HyAB(lg, ag, bg, lb, ab, bb), Qc);
    }

    /// <summary>
    /// Each 8-bit channel's share of YCxCz (which is linear in linear RGB): entry 4·(256·c + v) holds channel c's
    /// (R, G, B = 0, 1, 2) contribution at level v to Y + 16, Cx and Cz; a pixel's YCxCz is the sum of three entries
    /// (minus 16 for Y). The same numbers as <see cref="LinearToYCxCz"/> up to float rounding.
    /// </summary>
    public static readonly float[] ChannelTable = BuildChannelTable();

    private static float[] BuildChannelTable()
    {
        float[,] m = { { M11, M12, M13 }, { M21, M22, M23 }, { M31, M32, M33 } };
        var table = new float[4 * 3 * 256];
        for (int c = 0; c < 3; c++)
        {
            for (int v = 0; v < 256; v++)
            {
                float linear = SrgbToLinear[v];
                float x = m[0, c] * linear * InvWhiteX;
                float y = m[1, c] * linear;
                float z = m[2, c] * linear * InvWhiteZ;
                int i = 4 * ((256 * c) + v);
                table[i] = 116.0f * y;
                table[i + 1] = 500.0f * (x - y);
                table[i + 2] = 200.0f * (y - z);
            }
        }

        return table;
    }

    /// <summary>Linear RGB → YCxCz (via XYZ, normalised by the D65 white).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void LinearToYCxCz(float r, float g, float b, out float y, out float cx, out float cz)
    {
        float x = ((M11 * r) + (M12 * g) + (M13 * b)) * InvWhiteX;
        float yy = (M21 * r) + (M22 * g) + (M23 * b);
        float z = ((M31 * r) + (M32 * g) + (M33 * b)) * InvWhiteZ;
        y = (116.0f * yy) - 16.0f;
        cx = 500.0f * (x - yy);
        cz = 200.0f * (yy - z);
    }

    /// <summary>The achromatic channel Y of YCxCz mapped to [0, 1], the input of the edge and point detectors.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float NormalizedLuminance(float y) => (y * (1.0f / 116.0f)) + (16.0f / 116.0f);

    /// <summary>Filtered YCxCz → linear RGB clamped to [0, 1] → CIELAB with the Hunt adjustment (a, b scaled by 0.01·L).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void YCxCzToLabHunt(float y, float cx, float cz, out float l, out float a, out float b)
    {
        float yv = (y + 16.0f) / 116.0f;
        float x = (yv + (cx / 500.0f)) * WhiteX;
        float z = (yv - (cz / 200.0f)) * WhiteZ;
        float r = Math.Clamp((N11 * x) + (N12 * yv) + (N13 * z), 0.0f, 1.0f);
        float g = Math.Clamp((N21 * x) + (N22 * yv) + (N23 * z), 0.0f, 1.0f);
        float bl = Math.Clamp((N31 * x) + (N32 * yv) + (N33 * z), 0.0f, 1.0f);
        LinearToLabHunt(r, g, bl, out l, out a, out b);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void LinearToLabHunt(float r, float g, float bl, out float l, out float a, out float b)
    {
        float fx = LabF(((M11 * r) + (M12 * g) + (M13 * bl)) * InvWhiteX);
        float fy = LabF((M21 * r) + (M22 * g) + (M23 * bl));
        float fz = LabF(((M31 * r) + (M32 * g) + (M33 * bl)) * InvWhiteZ);
        l = (116.0f * fy) - 16.0f;
        a = 0.01f * l * (500.0f * (fx - fy));
        b = 0.01f * l * (200.0f * (fy - fz));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float LabF(float t) => t > LabDeltaCube ? MathF.Pow(t, OneThird) : (t * LabFactor) + LabTerm;

    /// <summary>HyAB: the city-block distance in L plus the Euclidean distance in (a, b).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float HyAB(float l1, float a1, float b1, float l2, float a2, float b2)
    {
        float da = a1 - a2;
        float db = b1 - b2;
        return MathF.Abs(l1 - l2) + MathF.Sqrt((da * da) + (db * db));
    }

    /// <summary>The colour error ΔE_c in [0, 1] from two filtered YCxCz colours.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float ColorError(float y1, float cx1, float cz1, float y2, float cx2, float cz2)
    {
        YCxCzToLabHunt(y1, cx1, cz1, out float l1, out float a1, out float b1);
        YCxCzToLabHunt(y2, cx2, cz2, out float l2, out float a2, out float b2);
        float d = MathF.Pow(HyAB(l1, a1, b1, l2, a2, b2), Qc);
        return d < PcMaxColorDistance
            ? d * (Pt / PcMaxColorDistance)
            : Pt + ((d - PcMaxColorDistance) / (MaxColorDistance - PcMaxColorDistance) * (1.0f - Pt));
    }

    /// <summary>The feature difference ΔE_f in [0, 1] from the edge (first-derivative) and point (second-derivative) responses.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float FeatureError(float edge1, float point1, float edge2, float point2) =>
        MathF.Sqrt(InvSqrt2 * MathF.Max(MathF.Abs(edge1 - edge2), MathF.Abs(point1 - point2)));

    /// <summary>FLIP: ΔE_c^(1 − ΔE_f).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float Combine(float colorError, float featureError) => MathF.Pow(colorError, 1.0f - featureError);

    // ---- The same transforms on Vector<float> lanes. ----

    /// <summary><see cref="ColorError(float, float, float, float, float, float)"/> on each lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector<float> ColorError(Vector<float> y1, Vector<float> cx1, Vector<float> cz1, Vector<float> y2, Vector<float> cx2, Vector<float> cz2)
    {
        YCxCzToLabHunt(y1, cx1, cz1, out var l1, out var a1, out var b1);
        YCxCzToLabHunt(y2, cx2, cz2, out var l2, out var a2, out var b2);
        var da = a1 - a2;
        var db = b1 - b2;
        var hyab = Vector.Abs(l1 - l2) + Vector.SquareRoot((da * da) + (db * db));
        var d = Pow(hyab, new Vector<float>(Qc));
        var pcmax = new Vector<float>(PcMaxColorDistance);
        var low = d * new Vector<float>(Pt / PcMaxColorDistance);
        var high = new Vector<float>(Pt) + ((d - pcmax) / new Vector<float>(MaxColorDistance - PcMaxColorDistance) * new Vector<float>(1.0f - Pt));
        return Vector.ConditionalSelect(Vector.LessThan(d, pcmax), low, high);
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static void YCxCzToLabHunt(Vector<float> y, Vector<float> cx, Vector<float> cz, out Vector<float> l, out Vector<float> a, out Vector<float> b)
    {
        var yv = (y + new Vector<float>(16.0f)) / new Vector<float>(116.0f);
        var x = (yv + (cx / new Vector<float>(500.0f))) * WhiteX;
        var z = (yv - (cz / new Vector<float>(200.0f))) * WhiteZ;
        var zero = Vector<float>.Zero;
        var one = Vector<float>.One;
        var r = Vector.Clamp((N11 * x) + (N12 * yv) + (N13 * z), zero, one);
        var g = Vector.Clamp((N21 * x) + (N22 * yv) + (N23 * z), zero, one);
        var bl = Vector.Clamp((N31 * x) + (N32 * yv) + (N33 * z), zero, one);
        var fx = LabF(((M11 * r) + (M12 * g) + (M13 * bl)) * InvWhiteX);
        var fy = LabF((M21 * r) + (M22 * g) + (M23 * bl));
        var fz = LabF(((M31 * r) + (M32 * g) + (M33 * bl)) * InvWhiteZ);
        l = (116.0f * fy) - new Vector<float>(16.0f);
        a = 0.01f * l * (500.0f * (fx - fy));
        b = 0.01f * l * (200.0f * (fy - fz));
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector<float> LabF(Vector<float> t) => Vector.ConditionalSelect(
        Vector.GreaterThan(t, new Vector<float>(LabDeltaCube)),
        Cbrt(t),
        (t * LabFactor) + new Vector<float>(LabTerm));

    /// <summary>
    /// ∛t for t &gt; 0 (LabF uses it above (6/29)³ only): a first guess from the float's bits (the exponent divided
    /// by 3), then three Newton steps y ← (2y + t/y²)/3, each squaring the relative error (5 % → 1e-7), so it is
    /// within a float rounding or two of powf(t, 1/3); four times cheaper than exp(ln t / 3).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector<float> Cbrt(Vector<float> t)
    {
        // The bits over 3 through float (SIMD has no integer division): off by at most 2^7 in the bits, harmless in a guess.
        var third = new Vector<float>(OneThird);
        var bits = Vector.ConvertToInt32(Vector.ConvertToSingle(Vector.AsVectorInt32(t)) * third);
        var y = Vector.AsVectorSingle(bits + new Vector<int>(0x2A514067));
        y = ((y + y) + (t / (y * y))) * third;
        y = ((y + y) + (t / (y * y))) * third;
        y = ((y + y) + (t / (y * y))) * third;
        return y;
    }

    /// <summary><see cref="FeatureError(float, float, float, float)"/> on each lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector<float> FeatureError(Vector<float> edge1, Vector<float> point1, Vector<float> edge2, Vector<float> point2) =>
        Vector.SquareRoot(InvSqrt2 * Vector.Max(Vector.Abs(edge1 - edge2), Vector.Abs(point1 - point2)));

    /// <summary><see cref="Combine(float, float)"/> on each lane.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector<float> Combine(Vector<float> colorError, Vector<float> featureError) =>
        Pow(colorError, Vector<float>.One - featureError);

    /// <summary>x^e for x ≥ 0 as exp(e·ln x), with 0^e = 0 for e &gt; 0 and 0^0 = 1 (as powf gives).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector<float> Pow(Vector<float> x, Vector<float> e)
    {
        var p = Vector.Exp(e * Vector.Log(x));
        var atZero = Vector.ConditionalSelect(Vector.Equals(e, Vector<float>.Zero), Vector<float>.One, Vector<float>.Zero);
        return Vector.ConditionalSelect(Vector.Equals(x, Vector<float>.Zero), atZero, p);
    }
}
