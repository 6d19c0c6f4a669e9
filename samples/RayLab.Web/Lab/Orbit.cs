using RayLab.Scenes;

namespace RayLab.Web.Lab;

/// <summary>Orbit and zoom about the camera's target: what a mouse drag, the wheel or a pinch does to the camera.</summary>
internal static class Orbit
{
    /// <summary>Radians of turn per CSS pixel of drag.</summary>
    public const double RadiansPerPixel = 0.008;

    /// <summary>
    /// Turns the eye about the target: <paramref name="yaw"/> about the camera's up vector, <paramref name="pitch"/>
    /// about its right vector, stopping short of looking straight along up (the view would flip).
    /// </summary>
    public static CameraSettings Rotate(CameraSettings camera, double yaw, double pitch)
    {
        Double3 up = Double3.Normalize(camera.Up);
        Double3 offset = RotateAbout(camera.Position - camera.Target, up, -yaw);
        Double3 right = Double3.Cross(up, offset);
        if (right.LengthSquared > 0)
        {
            Double3 pitched = RotateAbout(offset, Double3.Normalize(right), pitch);
            if (Math.Abs(Double3.Dot(Double3.Normalize(pitched), up)) < 0.995)
            {
                offset = pitched;
            }
        }

        return camera with { Position = camera.Target + offset };
    }

    /// <summary>Moves the eye towards (factor &lt; 1) or away from the target; the orthographic view height scales alike.</summary>
    public static CameraSettings Zoom(CameraSettings camera, double factor)
    {
        factor = Math.Clamp(factor, 0.2, 5);
        Double3 offset = (camera.Position - camera.Target) * factor;
        return offset.Length < 1e-6 || offset.Length > 1e6
            ? camera
            : camera with { Position = camera.Target + offset, Height = camera.Height * factor };
    }

    /// <summary>Rodrigues' rotation of <paramref name="v"/> by <paramref name="angle"/> about the unit axis <paramref name="k"/>.</summary>
    private static Double3 RotateAbout(Double3 v, Double3 k, double angle)
    {
        (double sin, double cos) = Math.SinCos(angle);
        return (v * cos) + (Double3.Cross(k, v) * sin) + (k * (Double3.Dot(k, v) * (1 - cos)));
    }
}
