using System.Collections.Concurrent;
using System.Globalization;
using RayLab;
#if (Sampler)
using RayLab.Sampling;
#endif

namespace MyLab.Tests;

/// <summary>
/// The time limit of every test that renders with your method: MyMethod runs watched (each pixel it is working on is
/// noted), and a render that outlasts <see cref="Limit"/> fails the test with the pixel MyMethod was on, instead of
/// hanging <c>dotnet test</c>.
/// </summary>
internal sealed class TimeLimit
{
    /// <summary>The environment variable that sets the limit in seconds (e.g. a smaller one for a quick try).</summary>
    public const string Variable = "LAB_TIME_LIMIT_S";

    private readonly ConcurrentDictionary<int, (int X, int Y)> _working = new();
    private long _last = -1;

    /// <summary>How long one render may take: 60 s, or <see cref="Variable"/> seconds where that is set.</summary>
    public static TimeSpan Limit { get; } =
        double.TryParse(Environment.GetEnvironmentVariable(Variable), NumberStyles.Float, CultureInfo.InvariantCulture, out double seconds) && seconds > 0
            ? TimeSpan.FromSeconds(seconds)
            : TimeSpan.FromSeconds(60);

    /// <summary>Your method (a new MyMethod), watched: the renderer's calls note the pixel they are for.</summary>
    /// <returns>The render method to give the renderer.</returns>
    public RenderMethod Method() =>
#if (Sampler)
        RenderMethod.Sampled(new WatchedSampler(new MyMethod(), this));
#else
        RenderMethod.Custom(Watched(new MyMethod()));
#endif

    /// <summary>
    /// Runs <paramref name="work"/> (a render with <see cref="Method"/>) with the limit; fails with the pixel
    /// MyMethod was on when the limit passed.
    /// </summary>
    /// <returns>What <paramref name="work"/> returned.</returns>
    public T Run<T>(Func<T> work)
    {
        var task = Task.Factory.StartNew(work, CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        bool finished;
        try
        {
            finished = task.Wait(Limit, TestContext.Current.CancellationToken);
        }
        catch (AggregateException)
        {
            finished = true; // its exception is thrown below, as it is
        }

        if (!finished)
        {
            Assert.Fail(string.Create(CultureInfo.InvariantCulture,
                $"Time limit of {Limit.TotalSeconds:0.#} s passed: MyMethod did not finish (an endless loop?). It was working on {Where()}."));
        }

        return task.GetAwaiter().GetResult();
    }

    /// <summary>The pixels MyMethod is inside now, or else the last one it was asked for.</summary>
    private string Where()
    {
        (int X, int Y)[] now = [.. _working.Values.Order().Take(4)];
        if (now.Length > 0)
        {
            return (now.Length == 1 ? "pixel " : "pixels ") + string.Join(", ", now.Select(p => $"({p.X}, {p.Y})"));
        }

        long last = Interlocked.Read(ref _last);
        return last < 0 ? "no pixel yet" : $"pixel ({last >> 32}, {last & 0xFFFFFFFF}) last";
    }

    private void Enter(int x, int y)
    {
        _working[Environment.CurrentManagedThreadId] = (x, y);
        Interlocked.Exchange(ref _last, ((long)x << 32) | (uint)y);
    }

    private void Leave() => _working.TryRemove(Environment.CurrentManagedThreadId, out _);

#if (Sampler)
    /// <summary>Your sampler, with each call noted.</summary>
    private sealed class WatchedSampler(IPixelSampler inner, TimeLimit limit) : IPixelSampler
    {
        public string Name => inner.Name;

        public int SamplesPerPixel => inner.SamplesPerPixel;

        public uint Seed => inner.Seed;

        public SamplePoint GetSample(int x, int y, int index)
        {
            limit.Enter(x, y);
            SamplePoint point = inner.GetSample(x, y, index);
            limit.Leave();
            return point;
        }

        public void GetSamples(int x, int y, Span<SamplePoint> points)
        {
            limit.Enter(x, y);
            inner.GetSamples(x, y, points);
            limit.Leave();
        }
    }
#else
    private WatchedMethod<TScratch> Watched<TScratch>(IPixelMethod<TScratch> inner) => new(inner, this);

    /// <summary>Your pixel method, with each pixel noted.</summary>
    private sealed class WatchedMethod<TScratch>(IPixelMethod<TScratch> inner, TimeLimit limit) : IPixelMethod<TScratch>
    {
        public string Name => inner.Name;

        public TScratch CreateScratch() => inner.CreateScratch();

        public Intensity RenderPixel(PixelTracer pixel, ref TScratch scratch)
        {
            limit.Enter(pixel.X, pixel.Row);
            Intensity value = inner.RenderPixel(pixel, ref scratch);
            limit.Leave();
            return value;
        }
    }
#endif
}
