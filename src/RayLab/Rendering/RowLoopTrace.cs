using System.Diagnostics;

namespace RayLab.Rendering;

/// <summary>
/// What a <see cref="RowLoop"/> did, for the scaling tool (<c>tools/RayLab.Scaling</c>): when the clock started, when
/// the rows started (the renderer's set-up before them), each band's time (a row, or a piece of a row: see
/// <see cref="RowLoop.Run{TScratch}"/> for their numbering), when the rows ended and when the clock stopped (the work
/// after them), in ticks of <see cref="Clock"/>. One trace records one render.
/// </summary>
internal sealed class RowLoopTrace
{
    /// <summary>The clock, <see cref="Stopwatch.GetTimestamp"/> unless the tool gives another (a thread's CPU time, steadier on a shared machine).</summary>
    public Func<long> Clock { get; init; } = Stopwatch.GetTimestamp;

    /// <summary>Ticks of <see cref="Clock"/> per second.</summary>
    public long Frequency { get; init; } = Stopwatch.Frequency;

    /// <summary>For a one-thread render: the bands one by one, the even ones then the odd ones (<see cref="BandSchedule"/>), so that every band starts on a thread that did not render the band above it.</summary>
    public bool Scattered { get; init; }

    /// <summary>When the clock started.</summary>
    public long Started { get; private set; }

    /// <summary>When the rows started.</summary>
    public long RowsStarted { get; private set; }

    /// <summary>When the last row ended.</summary>
    public long RowsEnded { get; private set; }

    /// <summary>When the clock stopped.</summary>
    public long Finished { get; private set; }

    /// <summary>Each band's time in ticks.</summary>
    public long[] BandTicks { get; private set; } = [];

    /// <summary>When each band began.</summary>
    public long[] BandBegan { get; private set; } = [];

    /// <summary>The worker that rendered each band.</summary>
    public int[] BandWorker { get; private set; } = [];

    /// <summary>Steps of the set-up before the rows, each with when it ended (the exact outlines, their crossings).</summary>
    public List<(string Step, long Ended)> SetUpSteps { get; } = [];

    /// <summary>A step of the set-up has ended.</summary>
    public void SetUpStep(string step) => SetUpSteps.Add((step, Clock()));

    /// <summary>The clock starts.</summary>
    public void Start() => Started = Clock();

    /// <summary>The rows start: <paramref name="bands"/> bands.</summary>
    public void Begin(int bands)
    {
        RowsStarted = Clock();
        BandTicks = new long[bands];
        BandBegan = new long[bands];
        BandWorker = new int[bands];
    }

    /// <summary>Band <paramref name="band"/> ran on worker <paramref name="worker"/> from <paramref name="began"/> to <paramref name="ended"/>.</summary>
    public void Band(int band, int worker, long began, long ended)
    {
        BandTicks[band] = ended - began;
        BandBegan[band] = began;
        BandWorker[band] = worker;
    }

    /// <summary>The rows are done.</summary>
    public void End() => RowsEnded = Clock();

    /// <summary>The clock stopped.</summary>
    public void Finish() => Finished = Clock();
}
