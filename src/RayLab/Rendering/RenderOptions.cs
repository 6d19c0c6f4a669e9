namespace RayLab.Rendering;

/// <summary>
/// What every renderer room shares: how many threads, which kernel, who watches the progress, and the token
/// that cancels the render (checked before each row).
/// </summary>
/// <param name="MaxDegreeOfParallelism">The most threads, or −1 for as many as the runtime likes.</param>
/// <param name="Kernel">Which loop renders point samples (the adaptive and exact renderers run their own).</param>
/// <param name="Progress">Counts finished rows, or null.</param>
/// <param name="CancellationToken">Cancels the render: it then throws <see cref="OperationCanceledException"/>.</param>
/// <param name="Pool">Per-thread buffers kept across renders (a <see cref="Renderer"/>'s), or null to allocate them per render.</param>
internal readonly record struct RenderOptions(int MaxDegreeOfParallelism, RenderKernel Kernel, RenderProgress? Progress, CancellationToken CancellationToken,
    ScratchPool? Pool = null)
{
    /// <summary>The first row to render, 0 the top (<see cref="Renderer.RenderRows(Scene, Camera, RenderMethod, IPixelRows, int, int, float[])"/>).</summary>
    public int FirstRow { get; init; }

    /// <summary>One past the last row to render; <see cref="int.MaxValue"/> for every row to the bottom.</summary>
    public int EndRow { get; init; } = int.MaxValue;

    /// <summary>The rows [Start, End) of an image <paramref name="height"/> rows tall that this render fills.</summary>
    public (int Start, int End) Rows(int height) => (Math.Min(FirstRow, height), Math.Min(EndRow, height));

    /// <summary>Pieces per row for a renderer that cuts its rows (the adaptive renderer), for the scaling tool; 0 (the default) lets the renderer choose.</summary>
    public int RowPieces { get; init; }

    /// <summary>The device point-sampled renders go to first (<see cref="Renderer.Device"/>); null is the CPU.</summary>
    public RenderDevice? Device { get; init; }

    /// <summary>Records the row loop's phases and band times, for the scaling tool; null (the default) records nothing.</summary>
    public RowLoopTrace? Trace { get; init; }

    /// <summary>A kept <typeparamref name="T"/> from <see cref="Pool"/>, or a new one.</summary>
    public T Rent<T>()
        where T : class, new() => Pool is null ? new T() : Pool.Rent<T>();

    /// <summary>Gives <paramref name="item"/> back to <see cref="Pool"/>, if there is one.</summary>
    public void Return(object item) => Pool?.Return(item);

    /// <summary>The options for a <see cref="Parallel.For(int, int, ParallelOptions, Action{int})"/> outside the row loop: threads and cancellation.</summary>
    public ParallelOptions Parallel => new() { MaxDegreeOfParallelism = MaxDegreeOfParallelism, CancellationToken = CancellationToken };
}
