using System.Numerics;

namespace RayLab.Rendering.Adaptive;

/// <summary>
/// The lab's combination rule for adaptive antialiasing (section 4.1.4): a quadrant that is not refined has the
/// value (corner + centre) / 2, a square the mean of its four quadrants' values, and a flat pixel the mean of its
/// four corners. Written once, generic over what is combined: the renderer (<see cref="AdaptivePixel"/>) combines
/// intensities, the lab's diagram (<see cref="Inspection.AdaptiveDiagram"/>) combines each traced point's weight.
/// </summary>
internal static class CombinationRule
{
    /// <summary>A quadrant that is not refined: (corner + centre) / 2.</summary>
    /// <typeparam name="T">What is combined.</typeparam>
    /// <param name="corner">The value at the quadrant's corner that is a corner of the square.</param>
    /// <param name="centre">The value at the square's centre.</param>
    public static T Quadrant<T>(T corner, T centre)
        where T : IAdditionOperators<T, T, T>, IMultiplyOperators<T, double, T> =>
        (corner + centre) * 0.5;

    /// <summary>The mean of four values: a square's value from its quadrants', or a flat pixel's from its corners.</summary>
    /// <typeparam name="T">What is combined.</typeparam>
    /// <param name="topLeft">The top-left quadrant (or corner).</param>
    /// <param name="topRight">The top-right one.</param>
    /// <param name="bottomLeft">The bottom-left one.</param>
    /// <param name="bottomRight">The bottom-right one.</param>
    public static T Mean<T>(T topLeft, T topRight, T bottomLeft, T bottomRight)
        where T : IAdditionOperators<T, T, T>, IMultiplyOperators<T, double, T> =>
        MeanOfSum(Sum(Sum(Sum(topLeft, topRight), bottomLeft), bottomRight));

    /// <summary>
    /// One step of <see cref="Mean"/>'s sum, which adds the four values in their order (top-left, top-right,
    /// bottom-left, bottom-right): the sum so far plus the next value. A caller that takes the values one at a time
    /// sums them so and gets <see cref="Mean"/>'s bits from <see cref="MeanOfSum"/>.
    /// </summary>
    /// <typeparam name="T">What is combined.</typeparam>
    /// <param name="sum">The values before this one, summed in order (the first value alone for the second).</param>
    /// <param name="value">The next value.</param>
    public static T Sum<T>(T sum, T value)
        where T : IAdditionOperators<T, T, T> =>
        sum + value;

    /// <summary><see cref="Mean"/> from the four values' sum, taken in their order by <see cref="Sum"/>.</summary>
    /// <typeparam name="T">What is combined.</typeparam>
    /// <param name="sum">The sum of the four values.</param>
    public static T MeanOfSum<T>(T sum)
        where T : IMultiplyOperators<T, double, T> =>
        sum * 0.25;
}
