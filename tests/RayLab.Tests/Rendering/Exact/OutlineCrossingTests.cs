using RayLab.Rendering.Exact;

namespace RayLab.Tests.Rendering.Exact;

/// <summary>The crossings of the outlines, found in parallel and gathered by row, are each row's, sorted, and the same at every thread count.</summary>
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
        Assert.True(one.CrossingCount > 100);
        Assert.Equal(one.CrossingCount, many.CrossingCount);
        List<OutlineSet.Crossing> fromOne = [], fromMany = [];
        int seen = 0;
        for (int row = 0; row <= plane.Height; row++)
        {
            one.CrossingsInRow(row, fromOne);
            many.CrossingsInRow(row, fromMany);
            Assert.Equal(fromOne, fromMany);
            Assert.Equal(fromOne.Order(), fromOne);
            Assert.All(fromOne, c => Assert.InRange(c.Y, row, row + 1));
            Assert.All(fromOne, c => Assert.NotEqual(row + 1, c.Y));
            seen += fromOne.Count;
        }

        Assert.Equal(one.CrossingCount, seen);
    }
}
