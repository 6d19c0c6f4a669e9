using System.Collections.Concurrent;
using RayLab.Rendering;
using RayLab.Sampling;

namespace RayLab.Tests.Rendering;

/// <summary>
/// The row loop's crew: every worker once, worker 0 on the caller's thread, nobody inside the body once the call
/// returns, the first error rethrown as it was thrown, and a busy crew refusing a second loop (which then runs on the
/// thread pool with the same bytes).
/// </summary>
public class WorkerCrewTests
{
    [Fact]
    public void EveryWorkerRunsOnceAndWorkerZeroOnTheCallersThread()
    {
        var crew = new WorkerCrew();
        const int Workers = 8;
        using var others = new CountdownEvent(Workers - 1);
        var seen = new ConcurrentDictionary<int, int>();
        Assert.True(crew.TryRun(Workers, w =>
        {
            Assert.True(seen.TryAdd(w, Environment.CurrentManagedThreadId), $"worker {w} ran twice");
            if (w == 0)
            {
                others.Wait(); // a gate, so that no worker is skipped for waking late
            }
            else
            {
                others.Signal();
            }
        }));

        Assert.Equal(Enumerable.Range(0, Workers), seen.Keys.Order());
        Assert.Equal(Environment.CurrentManagedThreadId, seen[0]);
        Assert.Equal(Workers, seen.Values.Distinct().Count());
    }

    [Fact]
    public void NoWorkerIsInsideTheBodyOnceTheCallReturns()
    {
        var crew = new WorkerCrew();
        int inside = 0, late = 0;
        for (int run = 0; run < 2000; run++)
        {
            bool returned = false;
            crew.TryRun(4, w =>
            {
                Interlocked.Increment(ref inside);
                if (Volatile.Read(ref returned))
                {
                    Interlocked.Increment(ref late);
                }

                Thread.SpinWait(w * 50);
                Interlocked.Decrement(ref inside);
            });
            Volatile.Write(ref returned, true);
            Assert.Equal(0, Volatile.Read(ref inside));
        }

        Assert.Equal(0, late);
    }

    [Fact]
    public void AWorkersExceptionIsRethrownAsItWasThrown()
    {
        var crew = new WorkerCrew();
        using var thrown = new ManualResetEventSlim();
        var error = new InvalidOperationException("worker 3 failed");
        InvalidOperationException caught = Assert.Throws<InvalidOperationException>(() => crew.TryRun(4, w =>
        {
            if (w == 3)
            {
                thrown.Set();
                throw error;
            }

            if (w == 0)
            {
                thrown.Wait();
            }
        }));
        Assert.Same(error, caught);
        // The crew serves the next loop.
        Assert.True(crew.TryRun(2, _ => { }));
    }

    [Fact]
    public void ABusyCrewRefusesASecondLoop()
    {
        var crew = new WorkerCrew();
        bool? second = null;
        bool ran = false;
        crew.TryRun(2, w =>
        {
            if (w == 0)
            {
                second = crew.TryRun(2, _ => ran = true);
            }
        });
        Assert.False(second);
        Assert.False(ran);
    }

    [Fact]
    public void RendersSideBySideGiveTheBytesOfOneThread()
    {
        var scene = new Scene([new Sphere(new Double3(-0.6, 0, -3), 0.8, new Intensity(0.9, 0.2, 0.2)), new Sphere(new Double3(0.7, 0.1, -4), 1, new Intensity(0.2, 0.8, 0.3))], new Intensity(0.1, 0.1, 0.15), Intensity.White);
        var camera = new PerspectiveCamera { Position = Double3.Zero, Target = new Double3(0, 0, -1), Fov = 60 };
        byte[] Render(int threads)
        {
            var image = new Image(96, 64);
            new Renderer { MaxDegreeOfParallelism = threads }.Render(scene, camera, RenderMethod.Sampled(new JitteredSampler(9, 5)), image);
            return image.PixelBytes.ToArray();
        }

        byte[] one = Render(1);
        // Four renders at once: one holds the crew, the others run on the thread pool.
        byte[][] side = [.. Enumerable.Range(0, 4).AsParallel().WithDegreeOfParallelism(4).Select(_ => Render(5))];
        Assert.All(side, bytes => Assert.Equal(one, bytes));
    }
}
