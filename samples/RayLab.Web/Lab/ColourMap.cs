namespace RayLab.Web.Lab;

/// <summary>
/// Magma, the perceptual colour map the compare report's heat maps use, as eight stops interpolated linearly:
/// dark for few rays or no error, bright for many.
/// </summary>
internal static class ColourMap
{
    private static readonly (byte R, byte G, byte B)[] Stops =
    [
        (0, 0, 4), (28, 16, 68), (79, 18, 123), (129, 37, 129), (181, 54, 122), (229, 80, 100), (251, 135, 97), (252, 253, 191),
    ];

    /// <summary>The RGB24 bytes of <paramref name="values"/> mapped from [0, <paramref name="max"/>] onto magma.</summary>
    public static byte[] Paint(ReadOnlySpan<float> values, double max)
    {
        var rgb = new byte[values.Length * 3];
        double scale = max > 0 ? (Stops.Length - 1) / max : 0;
        for (int i = 0; i < values.Length; i++)
        {
            double t = Math.Clamp(values[i] * scale, 0, Stops.Length - 1);
            int k = Math.Min((int)t, Stops.Length - 2);
            double f = t - k;
            (byte R, byte G, byte B) a = Stops[k], b = Stops[k + 1];
            rgb[3 * i] = (byte)(a.R + ((b.R - a.R) * f));
            rgb[(3 * i) + 1] = (byte)(a.G + ((b.G - a.G) * f));
            rgb[(3 * i) + 2] = (byte)(a.B + ((b.B - a.B) * f));
        }

        return rgb;
    }

    /// <summary>The CSS colour at <paramref name="t"/> in [0, 1], for the legend.</summary>
    public static string Css(double t)
    {
        byte[] rgb = Paint([(float)Math.Clamp(t, 0, 1)], 1);
        return $"rgb({rgb[0]},{rgb[1]},{rgb[2]})";
    }
}
