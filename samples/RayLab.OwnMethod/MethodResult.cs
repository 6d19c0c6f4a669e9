
namespace RayLab.OwnMethod;

/// <summary>One method's render measured against the exact reference.</summary>
/// <param name="Name">The method, e.g. <c>mitchell</c> or <c>jittered 16</c>.</param>
/// <param name="RaysPerPixel">Primary rays traced, per pixel.</param>
/// <param name="Error">Its error against the exact image, in 8-bit levels.</param>
/// <param name="Image">The picture.</param>
public sealed record MethodResult(string Name, double RaysPerPixel, ImageError Error, Image Image)
{
    /// <summary>One line of the comparison table.</summary>
    /// <returns>Name, rays per pixel, RMSE, mean absolute and largest error.</returns>
    public override string ToString() =>
        $"{Name,-16} {RaysPerPixel,6:F2} rays/pixel   RMSE {Error.Rmse:F3}   mean |error| {Error.MeanAbsolute:F4}   max {Error.Max}";
}
