using RayLab.Cameras;
using RayLab.Rendering.Packets;
using RayLab.Simd;

namespace RayLab.Tests.Cameras;

/// <summary>
/// The camera's projection both ways: a pixel point to a ray and a world point to pixel coordinates, and the
/// packet (lane) form of the ray against the scalar form.
/// </summary>
public class ProjectionTests
{
    public static TheoryData<string> Cameras() => ["perspective", "orthographic", "perspective off-axis", "orthographic off-axis"];

    private static Camera Make(string name)
    {
        Window? window = name.EndsWith("off-axis", StringComparison.Ordinal) ? new Window(0.3, -0.2, 1.9, 0.7) : null;
        return name.StartsWith("perspective", StringComparison.Ordinal)
            ? new PerspectiveCamera { Position = new Double3(0.4, 1.1, 7), Target = new Double3(-0.2, 0, 0.3), Up = new Double3(0.1, 1, 0), Fov = 45, Distance = 1.5, Window = window }
            : new OrthoCamera { Position = new Double3(0.4, 1.1, 7), Target = new Double3(-0.2, 0, 0.3), Up = new Double3(0.1, 1, 0), ViewHeight = 5, Window = window };
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void TheRayThroughAPointsPixelCoordinatesPassesThroughThePoint(string name)
    {
        ImagePlane plane = Make(name).GetImagePlane(97, 61);
        var random = new Random(14);
        for (int i = 0; i < 200; i++)
        {
            var point = new Double3((random.NextDouble() * 8) - 4, (random.NextDouble() * 8) - 4, (random.NextDouble() * 6) - 4);
            (double x, double y) = plane.ToPixel(point);
            Ray ray = plane.GetRayAt(x, y);
            // The point's distance from the ray's line, relative to its distance from the origin.
            Double3 offset = point - ray.Origin;
            double miss = Double3.Cross(offset, ray.Direction).Length / ray.Direction.Length;
            Assert.True(miss <= 1e-12 * (1 + offset.Length), $"{name}: {point} → ({x}, {y}) misses by {miss}");
        }
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void APixelSampleIsThePointAtThePixelPlusItsOffset(string name)
    {
        ImagePlane plane = Make(name).GetImagePlane(97, 61);
        foreach ((int x, int row, double sx, double sy) in new[] { (0, 0, 0.0, 0.0), (96, 60, 0.999, 0.5), (40, 17, 0.25, 0.875) })
        {
            Assert.Equal(plane.GetRayAt(x + sx, row + sy), plane.GetPixelRay(x, row, sx, sy));
            Assert.Equal(plane.GetRay(plane.Alpha(x, sx), plane.Beta(row, sy)), plane.GetPixelRay(x, row, sx, sy));
        }

        Assert.Equal(0.0, plane.Alpha(0, 0));
        Assert.Equal(1.0, plane.Alpha(97, 0));
        Assert.Equal(1.0, plane.Beta(0, 0));
        Assert.Equal(0.0, plane.Beta(61, 0));
    }

    [Theory]
    [MemberData(nameof(Cameras))]
    public void ThePacketRaysAreTheScalarRaysInFloat(string name)
    {
        ImagePlane plane = Make(name).GetImagePlane(97, 61);
        if (plane.IsOrthographic)
        {
            CheckPackets<Lanes128, OrthographicProjection>(plane);
            CheckPackets<Lanes256, OrthographicProjection>(plane);
        }
        else
        {
            CheckPackets<Lanes128, PerspectiveProjection>(plane);
            CheckPackets<Lanes256, PerspectiveProjection>(plane);
        }
    }

    private static void CheckPackets<TL, TP>(ImagePlane plane)
        where TL : struct, ILanes<TL>
        where TP : struct, IProjection
    {
        Float3 a = plane.A, b = plane.B, c = plane.C, d = plane.IsOrthographic ? -plane.W : Double3.Zero;
        var window = new LaneWindow<TL>(new(a.X, a.Y, a.Z), new(b.X, b.Y, b.Z), new(c.X, c.Y, c.Z), new(d.X, d.Y, d.Z));
        TL inverseWidth = TL.Broadcast(1f / plane.Width), inverseHeight = TL.Broadcast(1f / plane.Height);
        int count = TL.Count;
        float[] sx = [.. Enumerable.Range(0, count).Select(i => ((i * 7) % 8) / 8f)], sy = [.. Enumerable.Range(0, count).Select(i => ((i * 3) % 8) / 8f)];
        const int x0 = 40, row = 17;
        TL alpha = WindowMapping.Alpha(TL.Load(sx), inverseWidth, WindowMapping.PacketLeft(x0, inverseWidth));
        TL beta = WindowMapping.Beta(TL.Load(sy), inverseHeight, WindowMapping.RowTop<TL>(row, plane.Height));
        TP.GetRays(window, alpha, beta, out Lanes3<TL> origin, out Lanes3<TL> direction);
        // The kernel's origin is relative to e (perspective) or e + c (orthographic): its sphere offsets hold the rest.
        Double3 fixedPart = plane.Eye + (plane.IsOrthographic ? plane.C : Double3.Zero);
        float[][] lanes = [.. new[] { origin.X, origin.Y, origin.Z, direction.X, direction.Y, direction.Z }.Select(l => Store(l, count))];
        for (int lane = 0; lane < count; lane++)
        {
            Ray expected = plane.GetPixelRay(x0 + lane, row, sx[lane], sy[lane]);
            var o = new Double3(lanes[0][lane], lanes[1][lane], lanes[2][lane]);
            var dir = new Double3(lanes[3][lane], lanes[4][lane], lanes[5][lane]);
            double scale = plane.A.Length + plane.B.Length + plane.C.Length;
            Assert.True((fixedPart + o - expected.Origin).Length <= 1e-6 * scale, $"lane {lane}: origin {fixedPart + o} ≠ {expected.Origin}");
            Assert.True((dir - expected.Direction).Length <= 1e-6 * scale, $"lane {lane}: direction {dir} ≠ {expected.Direction}");
        }
    }

    private static float[] Store<TL>(TL lanes, int count)
        where TL : struct, ILanes<TL>
    {
        float[] values = new float[count];
        lanes.Store(values);
        return values;
    }
}
