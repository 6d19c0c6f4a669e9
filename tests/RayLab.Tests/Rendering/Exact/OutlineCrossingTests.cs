using RayLab.Rendering.Exact;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>The crossings of the outlines, found in parallel and merged, are sorted and the same at every thread count.</summary>
public class OutlineCrossingTests
{
    [Fact]
    public void CrossingsAreSortedAndTheSameOnOneThreadAndOnMany()
    {
        var spheres = new List<Sphere>();
        for (int j = 0; j < 14; j++)
        {
            for (int i = 0; i < 10; i++)
            {
                spheres.Add(new Sphere(new Double3(i - 4.5, 0, -j), 0.35, Intensity.White));
            }
        }

        var scene = new Scene(spheres, Intensity.Black, Intensity.White);
        var camera = new PerspectiveCamera { Position = new Double3(0, 1.6, 4), Target = new Double3(0, 0, -7), Fov = 50, NearPlane = 0.1, FarPlane = 1000 };
        var plane = camera.GetImagePlane(320, 180);
        OutlineSet one = OutlineSet.Build(scene, plane, parallel: new ParallelOptions { MaxDegreeOfParallelism = 1 });
        OutlineSet many = OutlineSet.Build(scene, plane, parallel: new ParallelOptions { MaxDegreeOfParallelism = 8 });
        Assert.True(one.Crossings.Length > 100);
        Assert.Equal(one.Crossings, many.Crossings);
        Assert.Equal(one.Crossings.Order(), one.Crossings);
        Assert.Equal(one.Crossings.Select(c => c.Y), one.CrossingHeights);
    }
}
