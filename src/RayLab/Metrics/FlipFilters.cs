namespace RayLab.Metrics;

/// <summary>
/// LDR-FLIP's one-dimensional filter taps for a given pixels per degree. The 2-D filters are separable, or (the
/// blue–yellow channel's sum of two Gaussians) a sum of two separable ones, as in NVIDIA's note "separated
/// convolutions" that accompanies the reference implementation.
/// </summary>
internal sealed class FlipFilters
{
    // The contrast sensitivity functions of the paper (section 3.1), in the spatial domain: a·√(π/b)·exp(−π²x²/b)
    // per channel, x in degrees. Achromatic (Y) and red–green (Cx) are single Gaussians; blue–yellow (Cz) is a sum of two.
    private const float A1Y = 1.0f, B1Y = 0.0047f;
    private const float A1Cx = 1.0f, B1Cx = 0.0053f;
    private const float A1Cz = 34.1f, B1Cz = 0.04f;
    private const float A2Cz = 13.5f, B2Cz = 0.025f;

    // The largest scale parameter b over all channels and terms sets the spatial filters' radius (3 standard deviations).
    private const float MaxB = B1Cz;

    /// <summary>Builds the taps for <paramref name="pixelsPerDegree"/>.</summary>
    /// <param name="pixelsPerDegree">The observer's pixels per degree.</param>
    // Long: it assigns every get-only tap array and radius, which only the constructor may; spatial filters first, then feature detectors.
    public FlipFilters(float pixelsPerDegree)
    {
        float piSquared = MathF.PI * MathF.PI;
        SpatialRadius = (int)MathF.Ceiling(3.0f * MathF.Sqrt(MaxB / (2.0f * piSquared)) * pixelsPerDegree);
        int width = (2 * SpatialRadius) + 1;
        Y = new float[width];
        Cx = new float[width];
        Cz1 = new float[width];
        Cz2 = new float[width];
        float sumY = 0, sumCx = 0, sumCz1 = 0, sumCz2 = 0;
        for (int i = 0; i < width; i++)
        {
            float d = (i - SpatialRadius) / pixelsPerDegree;
            float d2 = d * d;
            Y[i] = Gaussian(d2, A1Y, B1Y);
            Cx[i] = Gaussian(d2, A1Cx, B1Cx);
            // Each separable term of the Cz sum carries the square root of its 2-D amplitude in each direction.
            Cz1[i] = MathF.Sqrt(A1Cz * MathF.Sqrt(MathF.PI / B1Cz)) * MathF.Exp(-piSquared * d2 / B1Cz);
            Cz2[i] = MathF.Sqrt(A2Cz * MathF.Sqrt(MathF.PI / B2Cz)) * MathF.Exp(-piSquared * d2 / B2Cz);
            sumY += Y[i];
            sumCx += Cx[i];
            sumCz1 += Cz1[i];
            sumCz2 += Cz2[i];
        }

        // Y and Cx filters sum to 1 in 1-D, so to 1 in 2-D; the Cz pair is scaled so that Σ(h1)² + Σ(h2)² = 1 in 2-D.
        float czScale = 1.0f / MathF.Sqrt((sumCz1 * sumCz1) + (sumCz2 * sumCz2));
        for (int i = 0; i < width; i++)
        {
            Y[i] /= sumY;
            Cx[i] /= sumCx;
            Cz1[i] *= czScale;
            Cz2[i] *= czScale;
        }

        // Y and Cx are narrow (σ ≈ 1 pixel at 67 ppd): beyond NarrowRadius their taps are below 1e-10 of the centre
        // tap, under a float's resolution of any sum they join, and the vectorised passes skip them.
        NarrowRadius = SpatialRadius;
        while (NarrowRadius > 0
            && Y[SpatialRadius + NarrowRadius] < 1e-10f * Y[SpatialRadius]
            && Cx[SpatialRadius + NarrowRadius] < 1e-10f * Cx[SpatialRadius])
        {
            NarrowRadius--;
        }

        // Feature detectors (section 3.2): a Gaussian of σ = w/2 degrees and its first and second derivatives, the
        // derivatives' positive and negative taps normalised to sum to +1 and −1.
        float sigma = 0.5f * FlipModel.FeatureWidth * pixelsPerDegree;
        FeatureRadius = (int)MathF.Ceiling(3.0f * sigma);
        int featureWidth = (2 * FeatureRadius) + 1;
        G = new float[featureWidth];
        D = new float[featureWidth];
        DD = new float[featureWidth];
        float gSum = 0, dPositive = 0, dNegative = 0, ddPositive = 0, ddNegative = 0;
        for (int i = 0; i < featureWidth; i++)
        {
            float x = i - FeatureRadius;
            float g = MathF.Exp(-(x * x) / (2.0f * sigma * sigma));
            float dg = -x * g;
            float ddg = ((x * x / (sigma * sigma)) - 1.0f) * g;
            G[i] = g;
            D[i] = dg;
            DD[i] = ddg;
            gSum += g;
            if (dg > 0)
            {
                dPositive += dg;
            }
            else
            {
                dNegative -= dg;
            }

            if (ddg > 0)
            {
                ddPositive += ddg;
            }
            else
            {
                ddNegative -= ddg;
            }
        }

        for (int i = 0; i < featureWidth; i++)
        {
            G[i] /= gSum;
            D[i] = Normalize(D[i], dPositive, dNegative);
            DD[i] = Normalize(DD[i], ddPositive, ddNegative);
        }
    }

    /// <summary>The spatial (contrast sensitivity) filters' radius r: 2r + 1 taps.</summary>
    public int SpatialRadius { get; }

    /// <summary>The radius beyond which the Y and Cx taps are negligible (&lt; 10⁻¹⁰ of the centre tap).</summary>
    public int NarrowRadius { get; }

    /// <summary>The feature detectors' radius: 2r + 1 taps.</summary>
    public int FeatureRadius { get; }

    /// <summary>The larger of the two radii.</summary>
    public int MaxRadius => Math.Max(SpatialRadius, FeatureRadius);

    /// <summary>The achromatic channel's taps.</summary>
    public float[] Y { get; }

    /// <summary>The red–green channel's taps.</summary>
    public float[] Cx { get; }

    /// <summary>The blue–yellow channel's first separable term.</summary>
    public float[] Cz1 { get; }

    /// <summary>The blue–yellow channel's second separable term.</summary>
    public float[] Cz2 { get; }

    /// <summary>The feature detectors' Gaussian.</summary>
    public float[] G { get; }

    /// <summary>Its first derivative (edges).</summary>
    public float[] D { get; }

    /// <summary>Its second derivative (points).</summary>
    public float[] DD { get; }

    private static float Gaussian(float d2, float a, float b) =>
        a * MathF.Sqrt(MathF.PI / b) * MathF.Exp(-(MathF.PI * MathF.PI) * d2 / b);

    // A tap over the sum of its sign's taps; a zero sum (a detector narrower than a pixel) leaves the tap at 0.
    private static float Normalize(float tap, float positiveSum, float negativeSum)
    {
        float sum = tap > 0 ? positiveSum : negativeSum;
        return sum > 0 ? tap / sum : 0.0f;
    }
}
