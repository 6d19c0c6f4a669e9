namespace RayLab.Imaging;

/// <summary>
/// PNG row filters (PNG specification, section 9): each predicts a byte from its neighbours so that DEFLATE
/// sees small numbers. <see cref="Adaptive"/> tries the five on every row and keeps the one whose bytes have
/// the smallest sum as signed numbers.
/// </summary>
internal enum PngFilter
{
    /// <summary>Bytes as they are.</summary>
    None = 0,

    /// <summary>Minus the byte to the left.</summary>
    Sub = 1,

    /// <summary>Minus the byte above; <see cref="PngEncoder"/>'s default.</summary>
    Up = 2,

    /// <summary>Minus the mean of left and above.</summary>
    Average = 3,

    /// <summary>Minus the Paeth predictor of left, above and upper left.</summary>
    Paeth = 4,

    /// <summary>The best of the five for each row (the minimum-sum heuristic).</summary>
    Adaptive = 5,
}
