using System.Numerics;

namespace RayLab.Metrics;

/// <summary>
/// LDR-FLIP, the perceptual difference between two 8-bit sRGB pictures as seen when flipping between them
/// (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild, "FLIP: A Difference Evaluator for Alternating
/// Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2), HPG 2020). Both images are filtered by models of the
/// eye's contrast sensitivity in an opponent colour space, compared by the HyAB distance in CIELAB, and the colour
/// error is amplified where edges or points differ. Written from the paper and NVIDIA's public reference code
/// (github.com/NVlabs/flip, v1.6), which it matches to about 10⁻⁶ in the mean on the test pictures.
/// </summary>
public static class Flip
{
    /// <summary>
    /// Computes the FLIP error map of <paramref name="test"/> against <paramref name="reference"/>, and its mean.
    /// Vectorised (<see cref="Vector{T}"/>) when the hardware accelerates it, parallel over bands of rows; the result
    /// does not depend on the thread count.
    /// </summary>
    /// <param name="reference">The reference picture (e.g. the exact render).</param>
    /// <param name="test">The picture judged, of the reference's size.</param>
    /// <param name="options">Viewing conditions and threads; <see langword="null"/> for the paper's defaults
    /// (0.7 m from a 0.7 m wide display of 3 840 pixels, ≈ 67 pixels per degree) on all cores.</param>
    /// <returns>The per-pixel map (values in [0, 1]) and its mean.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="reference"/> or <paramref name="test"/> is null.</exception>
    /// <exception cref="ArgumentException">The two images differ in size (the exception names <c>test</c>).</exception>
    public static FlipResult Compute(Image reference, Image test, FlipOptions? options = null) =>
        Compute(reference, test, options, Vector.IsHardwareAccelerated);

    /// <summary><see cref="Compute(Image, Image, FlipOptions?)"/> with the code path chosen (tests compare the two).</summary>
    internal static FlipResult Compute(Image reference, Image test, FlipOptions? options, bool vectorized)
    {
        ArgumentNullException.ThrowIfNull(reference);
        ArgumentNullException.ThrowIfNull(test);
        if (test.Width != reference.Width || test.Height != reference.Height)
        {
            throw new ArgumentException(
                $"The test image is {test.Width}×{test.Height} but the reference is {reference.Width}×{reference.Height}: FLIP compares pictures of the same size.",
                nameof(test));
        }

        options ??= new FlipOptions();
        var kernel = new FlipKernel(reference, test, (float)options.PixelsPerDegree, vectorized);
        (float[] map, double mean) = kernel.Run(options.MaxDegreeOfParallelism);
        return new FlipResult(reference.Width, reference.Height, map, mean, options.PixelsPerDegree);
    }
}
