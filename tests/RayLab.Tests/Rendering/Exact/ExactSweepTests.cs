namespace RayLab.Tests.Rendering.Exact;

/// <summary>
/// The exact renderer's row sweep (branches kept in order down a row, a piece's area added once per
/// lifetime, its colour carried) gives the pixels that cutting every strip of every row afresh gives, on scenes
/// where many outlines cross: a receding field of spheres and random, overlapping, intersecting spheres.
/// </summary>
public class ExactSweepTests
{
    private static readonly PerspectiveCamera FieldCamera = new() { Position = new Double3(0, 1.6, 4), Target = new Double3(0, 0, -6), Fov = 50, NearPlane = 0.1, FarPlane = 1000 };

    private static readonly PerspectiveCamera Perspective = new() { Position = new Double3(0, 1, 6), Target = new Double3(0, 0, -4), Fov = 55, NearPlane = 1, FarPlane = 60 };

    private static readonly OrthoCamera Orthographic = new() { Position = new Double3(0.3, 1, 6), Target = new Double3(0.1, 0, -4), ViewHeight = 9, NearPlane = 1, FarPlane = 60 };

    // The 960-sphere field of the performance figures (tools/sphere-scenes.py field 24 40), smaller: columns × rows
    // spheres of radius 0.35 on a plane.
    private static Scene Field(int columns, int rows)
    {
        var spheres = new List<Sphere>();
        for (int j = 0; j < rows; j++)
        {
            for (int i = 0; i < columns; i++)
            {
                Intensity colour = (i + j) % 2 == 0 ? new Intensity(0.95, 0.95, 0.9) : new Intensity(0.15, 0.3, 0.8);
                spheres.Add(new Sphere(new Double3(i - ((columns - 1) / 2.0), 0, -j), 0.35, colour));
            }
        }

        return new Scene(spheres, new Intensity(0.05, 0.05, 0.08), new Intensity(1, 1, 1));
    }

    // Random spheres that overlap on screen and in space (meeting circles), some cut by the near plane.
    private static Scene Random(int count, int seed)
    {
        var random = new Random(seed);
        var spheres = new List<Sphere>();
        for (int k = 0; k < count; k++)
        {
            var centre = new Double3((random.NextDouble() * 10) - 5, (random.NextDouble() * 6) - 3, 4.5 - (random.NextDouble() * 13));
            spheres.Add(new Sphere(centre, 0.3 + random.NextDouble(), new Intensity(random.NextDouble(), random.NextDouble(), random.NextDouble())));
        }

        return new Scene(spheres, new Intensity(0.1, 0.1, 0.15), new Intensity(1, 1, 1));
    }

    public static TheoryData<string, int, int> Cases => new()
    {
        { "field", 12, 20 },
        { "field", 24, 40 },
        { "random perspective", 60, 1 },
        { "random perspective", 300, 2 },
        { "random orthographic", 60, 3 },
        { "random orthographic", 300, 4 },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void TheSweepGivesThePixelsOfCuttingEveryStripAfresh(string kind, int size, int seed)
    {
        Scene scene = kind == "field" ? Field(size, seed) : Random(size, seed);
        Camera camera = kind switch
        {
            "field" => FieldCamera,
            "random perspective" => Perspective,
            _ => Orthographic,
        };
        // 300 random spheres cross every row of a 48×36 picture many times over; at 96×72 the strip-by-strip reference
        // costs four times as much (most of the unit tests' time on 2 cores) for more of the same crossings.
        (int width, int height) = size >= 300 ? (48, 36) : (96, 72);
        Intensity[] swept = ExactLinear.Of(scene, camera, width, height, threads: 2, sweep: true);
        Intensity[] strips = ExactLinear.Of(scene, camera, width, height, threads: 2, sweep: false);

        double worst = 0;
        int at = -1;
        for (int i = 0; i < swept.Length; i++)
        {
            double d = Math.Max(Math.Abs(swept[i].R - strips[i].R), Math.Max(Math.Abs(swept[i].G - strips[i].G), Math.Abs(swept[i].B - strips[i].B)));
            if (d > worst)
            {
                worst = d;
                at = i;
            }
        }

        Assert.True(worst <= 1e-9, $"{kind} {size}/{seed}: pixel ({at % width}, {at / width}) differs by {worst:G3} between the sweep and strip by strip");
    }
}
