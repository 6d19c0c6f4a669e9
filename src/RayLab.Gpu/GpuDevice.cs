using System.Diagnostics;
using ILGPU;
using ILGPU.Runtime;
using ILGPU.Runtime.CPU;
using ILGPU.Runtime.Cuda;
using RayLab.Cameras;
using RayLab.Geometry;
using RayLab.Rendering;
using RayLab.Rendering.Adaptive;
using RayLab.Sampling;

namespace RayLab.Gpu;

/// <summary>
/// A GPU that renders RayLab's point-sampled images (<see cref="RenderDevice"/>): a CUDA device through ILGPU, or,
/// for tests and for checking the bytes where no GPU is, ILGPU's CPU accelerator, which runs the same kernel's code.
/// It renders every built-in point sampler and the lab's adaptive rule (plain and guarded, with the rays-per-pixel
/// map) with both cameras into 8-bit images, any scene (through its hierarchy where it has one), with the bytes of the
/// CPU renderer; every other render goes to the CPU renderers in the same call. Made once and kept: the kernel is compiled on the first render (for CUDA, PTX generation and load);
/// <see cref="Dispose"/> frees the device.
/// </summary>
public sealed class GpuDevice : RenderDevice, IDisposable
{
    /// <summary>ZSobol's 24 packed permutations, one a entry, as the kernel's table.</summary>
    private static readonly uint[] ZSobolPermutations = [.. ZSobolSampler.PermutationTable.ToArray().Select(packed => (uint)packed)];

    private readonly Context _context;
    private readonly Accelerator _accelerator;
    private readonly Lock _lock = new();
    private Action<Index1D, PointFrame, ArrayView<DeviceSphere>, ArrayView<uint>, ArrayView<byte>, ArrayView<HierarchyNode>, ArrayView<int>>? _kernel;
    private Action<Index1D, AdaptiveFrame, ArrayView<DeviceSphere>, ArrayView<HierarchyNode>, ArrayView<int>, ArrayView<GuardSphere>, ArrayView<byte>, ArrayView<float>, ArrayView<long>, ArrayView<int>>? _adaptiveKernel;
    private bool _disposed;
    private object? _tableSource;
    private MemoryBuffer1D<uint, Stride1D.Dense>? _table;
    private DeviceSceneBuffers? _scene;

    private GpuDevice(Context context, Accelerator accelerator, string name)
    {
        _context = context;
        _accelerator = accelerator;
        Name = name;
    }

    /// <inheritdoc />
    public override string Name { get; }

    /// <summary>True when the device is ILGPU's CPU accelerator (the kernel's code on the CPU), not a GPU.</summary>
    public bool IsCpuAccelerator => _accelerator.AcceleratorType == AcceleratorType.CPU;

    /// <summary>
    /// The first CUDA GPU (or the one numbered <paramref name="index"/>).
    /// </summary>
    /// <param name="index">Which CUDA device, 0 the first.</param>
    /// <returns>The device.</returns>
    /// <exception cref="GpuUnavailableException">No CUDA driver or no such device; its message is one line.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="index"/> is negative.</exception>
    public static GpuDevice Cuda(int index = 0)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        Context context = Context.Create(builder => builder.Cuda());
        try
        {
            Context.DeviceCollection<CudaDevice> devices = context.GetCudaDevices();
            if (devices.Count == 0)
            {
                throw new GpuUnavailableException("No CUDA GPU: no NVIDIA driver (libcuda) or no device was found; render on the CPU (--device cpu), or ask for a fallback (--device auto).");
            }

            if (index >= devices.Count)
            {
                throw new GpuUnavailableException($"No CUDA GPU {index}: {devices.Count} found.");
            }

            CudaDevice device = devices[index];
            return new GpuDevice(context, device.CreateAccelerator(context), $"cuda: {device.Name}");
        }
        catch
        {
            context.Dispose();
            throw;
        }
    }

    /// <summary>
    /// ILGPU's CPU accelerator: the device kernel's own code run on the CPU's threads. Slow; it is how the bytes of the
    /// device path are checked where no GPU is (the tests, <c>raylab render --device ilgpu-cpu</c>).
    /// </summary>
    /// <returns>The device.</returns>
    public static GpuDevice CpuAccelerator()
    {
        Context context = Context.Create(builder => builder.CPU());
        return new GpuDevice(context, context.GetCPUDevice(0).CreateAccelerator(context), "ilgpu-cpu");
    }

    /// <summary>True when a CUDA GPU can be opened here (a driver and at least one device).</summary>
    /// <returns>Whether <see cref="Cuda"/> would succeed.</returns>
    public static bool IsCudaAvailable()
    {
        using Context context = Context.Create(builder => builder.Cuda());
        return context.GetCudaDevices().Count > 0;
    }

    /// <summary>The last render's kernel alone, launch to finish, without the uploads and the copy back (the measuring test).</summary>
    internal TimeSpan LastKernelTime { get; private set; }

    /// <summary>The most pixels of an adaptive render whose guard test the device leaves to the host; beyond them the CPU renders the frame.</summary>
    internal const int MaxUncertainPixels = 1 << 16;

    /// <summary>The tests' check of the host's path: every guard test the device does not find crossing counts as uncertain.</summary>
    internal bool ForceUncertainGuard { get; set; }

    /// <summary>The pixels of the last adaptive render that the host evaluated again (the tests).</summary>
    internal int LastHostPixels { get; private set; }

    /// <summary>True when the scene last uploaded is traced through its hierarchy on the device (the tests).</summary>
    internal bool TracesThroughHierarchy => _scene?.UsesHierarchy ?? false;

    /// <summary>Compiles and loads the kernel now, so that the first render's time does not include it.</summary>
    public void Warm()
    {
        lock (_lock)
        {
            ObjectDisposedException.ThrowIf(_disposed, this);
            _ = Kernel;
            _ = AdaptiveKernelOf;
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        lock (_lock)
        {
            if (_disposed)
            {
                return;
            }

            _disposed = true;
            _table?.Dispose();
            _scene?.Dispose();
            _accelerator.Dispose();
            _context.Dispose();
        }
    }

    private Action<Index1D, PointFrame, ArrayView<DeviceSphere>, ArrayView<uint>, ArrayView<byte>, ArrayView<HierarchyNode>, ArrayView<int>> Kernel =>
        _kernel ??= _accelerator.LoadAutoGroupedStreamKernel<Index1D, PointFrame, ArrayView<DeviceSphere>, ArrayView<uint>, ArrayView<byte>, ArrayView<HierarchyNode>, ArrayView<int>>(PointKernel.Render);

    private Action<Index1D, AdaptiveFrame, ArrayView<DeviceSphere>, ArrayView<HierarchyNode>, ArrayView<int>, ArrayView<GuardSphere>, ArrayView<byte>, ArrayView<float>, ArrayView<long>, ArrayView<int>> AdaptiveKernelOf =>
        _adaptiveKernel ??= _accelerator.LoadAutoGroupedStreamKernel<Index1D, AdaptiveFrame, ArrayView<DeviceSphere>, ArrayView<HierarchyNode>, ArrayView<int>, ArrayView<GuardSphere>, ArrayView<byte>, ArrayView<float>, ArrayView<long>, ArrayView<int>>(AdaptiveKernel.Render);

    /// <summary>The kernel's sampler settings, or null when the device has no form of the sampler.</summary>
    internal static PointFrame? FrameOf(IPixelSampler sampler)
    {
        // Every hashed sampler salts its pixel keys with PointHash.Salt of its seed.
        var frame = new PointFrame { Samples = sampler.SamplesPerPixel, Salt = PointHash.Salt(sampler.Seed) };
        switch (sampler)
        {
            case RegularSampler regular:
                frame.Sampler = DeviceSampler.Regular;
                frame.GridSize = regular.GridSize;
                break;
            case JitteredSampler jittered:
                frame.Sampler = DeviceSampler.Jittered;
                frame.GridSize = jittered.GridSize;
                frame.JitterScale = jittered.Scale;
                break;
            case RandomSampler:
                frame.Sampler = DeviceSampler.Random;
                break;
            case HammersleySampler:
                frame.Sampler = DeviceSampler.Hammersley;
                break;
            case NRooksSampler:
                frame.Sampler = DeviceSampler.NRooks;
                break;
            case MultiJitteredSampler multiJittered:
                frame.Sampler = DeviceSampler.MultiJittered;
                frame.GridSize = multiJittered.GridSize;
                break;
            case CorrelatedMultiJitteredSampler cmj:
                frame.Sampler = DeviceSampler.CorrelatedMultiJittered;
                (frame.Columns, frame.Rows) = (cmj.Columns, cmj.Rows);
                break;
            case SobolSampler:
                frame.Sampler = DeviceSampler.Sobol;
                break;
            case Pmj02Sampler or Pmj02BNSampler:
                frame.Sampler = DeviceSampler.Pmj02;
                frame.SetLength = ((uint[][])TableOf(sampler)!)[0].Length;
                frame.Scramble = sampler is Pmj02Sampler ? 1 : 0;
                break;
            case ZSobolSampler zsobol:
                frame.Sampler = DeviceSampler.ZSobol;
                (frame.Log2Block, frame.DigitSalt, frame.XSeed, frame.YSeed) = (zsobol.Log2Block, zsobol.DigitSalt, zsobol.XSeed, zsobol.YSeed);
                break;
            default:
                return null;
        }

        return frame;
    }

    /// <summary>
    /// What the kernel's table holds for <paramref name="sampler"/> (pmj02's and pmj02bn's sets, zsobol's permutations), or
    /// null when it reads none; the same object while the sampler reads the same table.
    /// </summary>
    internal static object? TableOf(IPixelSampler sampler) => sampler switch
    {
        Pmj02Sampler pmj02 => pmj02.Sets,
        Pmj02BNSampler pmj02bn => pmj02bn.Sets,
        ZSobolSampler => ZSobolPermutations,
        _ => null,
    };

    /// <summary>
    /// The device's copy of <paramref name="source"/> (<see cref="TableOf"/>; pmj02's sets one after another), uploaded
    /// once and kept while renders read the same table (a one-entry buffer where they read none). Called under the lock.
    /// </summary>
    private ArrayView<uint> TableView(object? source)
    {
        if (_table is not null && ReferenceEquals(source, _tableSource))
        {
            return _table.View;
        }

        _table?.Dispose();
        _table = null;
        uint[] flat = source switch
        {
            uint[][] sets => [.. sets.SelectMany(set => set)],
            uint[] entries => entries,
            _ => new uint[1],
        };
        _table = _accelerator.Allocate1D(flat);
        _tableSource = source;
        return _table.View;
    }

    // Long: one launch's settings, uploads, kernel, copies back and the host's pixels, which share the band's buffers.
    internal override RenderStatistics? TryRenderAdaptive(Scene scene, ImagePlane plane, AdaptiveSampler sampler, PixelTarget image, RenderOptions options, float[]? raysPerPixel)
    {
        (int first, int end) = options.Rows(image.Height);
        if (image.EightBitRow(0).IsEmpty || end <= first)
        {
            return null;
        }

        options.CancellationToken.ThrowIfCancellationRequested();
        RenderKernel cpuKernel = KernelChoice.Choose(options.Kernel, scene, plane, out _, out string? reason);
        long size = 1L << (sampler.MaxDepth + 1);
        SilhouetteGuard? guard = sampler.Guard ? new SilhouetteGuard(scene, plane, size, tiles: false) : null;
        var frame = new AdaptiveFrame
        {
            Basis = plane.Basis,
            Rule = new AdaptiveRule(sampler),
            FirstRow = first,
            Size = size,
            StepWidth = guard?.StepWidth ?? 0,
            StepHeight = guard?.StepHeight ?? 0,
            Background = scene.Background,
            Map = raysPerPixel is null ? 0 : 1,
        };
        GuardSphere[] guardSpheres = guard is null ? new GuardSphere[1] : [.. guard.Spheres.ToArray().Select(s => new GuardSphere(s.Center, s.Radius, s.Clipped ? 1 : 0))];
        int width = image.Width, rows = end - first;
        frame.UncertainCapacity = (int)Math.Min((long)width * rows, MaxUncertainPixels);
        frame.ForceUncertain = ForceUncertainGuard ? 1 : 0;
        var bytes = new byte[3L * width * rows];
        float[] rays = raysPerPixel is null ? [] : new float[(long)width * rows];
        long[] counts = new long[2];
        int[] uncertain = new int[Math.Max(1, frame.UncertainCapacity)];
        var clock = Stopwatch.StartNew();
        lock (_lock)
        {
            ObjectDisposedException.ThrowIf(_disposed, this);
            DeviceSceneBuffers sceneBuffers = SceneBuffers(scene);
            (frame.Hierarchy, frame.HierarchyScale) = (sceneBuffers.UsesHierarchy ? 1 : 0, sceneBuffers.Scale);
            using MemoryBuffer1D<GuardSphere, Stride1D.Dense> guardBuffer = _accelerator.Allocate1D(guardSpheres);
            using MemoryBuffer1D<byte, Stride1D.Dense> output = _accelerator.Allocate1D<byte>(bytes.LongLength);
            using MemoryBuffer1D<float, Stride1D.Dense> rayBuffer = _accelerator.Allocate1D<float>(Math.Max(1, rays.LongLength));
            using MemoryBuffer1D<long, Stride1D.Dense> countBuffer = _accelerator.Allocate1D(counts);
            using MemoryBuffer1D<int, Stride1D.Dense> uncertainBuffer = _accelerator.Allocate1D<int>(uncertain.LongLength);
            ArrayView<GuardSphere> guardView = guard is null ? guardBuffer.View.SubView(0, 0) : guardBuffer.View;
            Action<Index1D, AdaptiveFrame, ArrayView<DeviceSphere>, ArrayView<HierarchyNode>, ArrayView<int>, ArrayView<GuardSphere>, ArrayView<byte>, ArrayView<float>, ArrayView<long>, ArrayView<int>> kernel = AdaptiveKernelOf;
            _accelerator.Synchronize();
            long launched = Stopwatch.GetTimestamp();
            kernel(width * rows, frame, sceneBuffers.Spheres, sceneBuffers.Nodes, sceneBuffers.Order, guardView, output.View, rayBuffer.View, countBuffer.View, uncertainBuffer.View);
            _accelerator.Synchronize();
            LastKernelTime = Stopwatch.GetElapsedTime(launched);
            countBuffer.CopyToCPU(counts);
            if (counts[1] > frame.UncertainCapacity)
            {
                return null; // more uncertain pixels than listed: the CPU renders the frame
            }

            output.CopyToCPU(bytes);
            rayBuffer.View.SubView(0, rays.LongLength).BaseView.CopyToCPU(rays.AsSpan());
            uncertainBuffer.View.SubView(0, counts[1]).BaseView.CopyToCPU(uncertain.AsSpan(0, (int)counts[1]));
        }

        long hostRays = EvaluateOnHost(scene, plane, sampler, guard, uncertain.AsSpan(0, (int)counts[1]), width, first, bytes, rays);
        LastHostPixels = (int)counts[1];
        clock.Stop();
        CopyRows(bytes, image, first, end);
        rays.CopyTo(raysPerPixel.AsSpan(first * width));
        return new RenderStatistics(counts[0] + hostRays, clock.Elapsed)
        {
            Kernel = cpuKernel,
            Device = Name,
            ScalarReason = reason,
        };
    }

    /// <summary>
    /// The pixels whose guard test the device could not decide (<paramref name="pixels"/>, indices in the band), each the
    /// CPU's rule on the CPU's lattice formulas and guard, written into the band's bytes and rays; returns the rays traced.
    /// </summary>
    private static long EvaluateOnHost(Scene scene, ImagePlane plane, AdaptiveSampler sampler, SilhouetteGuard? guard, ReadOnlySpan<int> pixels, int width, int first, byte[] bytes, float[] rays)
    {
        var host = new HostLattice(scene, plane, 1L << (sampler.MaxDepth + 1), guard);
        foreach (int index in pixels)
        {
            int x = index % width, row = first + (index / width);
            Intensity value = AdaptivePixel.Evaluate(sampler, ref host, x, row, out double samples);
            (bytes[3L * index], bytes[(3L * index) + 1], bytes[(3L * index) + 2]) = (EightBit.Level(value.R), EightBit.Level(value.G), EightBit.Level(value.B));
            if (rays.Length > 0)
            {
                rays[index] = (float)samples;
            }
        }

        return host.Traced;
    }

    /// <summary>Copies the band's bytes into rows <paramref name="first"/> to <paramref name="end"/> − 1 of <paramref name="image"/>.</summary>
    private static void CopyRows(byte[] bytes, PixelTarget image, int first, int end)
    {
        int width = image.Width;
        for (int y = first; y < end; y++)
        {
            bytes.AsSpan(3 * width * (y - first), 3 * width).CopyTo(System.Runtime.InteropServices.MemoryMarshal.AsBytes(image.EightBitRow(y)));
        }
    }

    /// <summary>
    /// The device's copy of <paramref name="scene"/>: its spheres, and its hierarchy's nodes and order when it traces
    /// through one (<see cref="Scene.Hierarchy"/>, no deeper than <see cref="DeviceScene.MaxDepth"/>), uploaded once
    /// and kept while renders draw the same scene. Called under the lock.
    /// </summary>
    private DeviceSceneBuffers SceneBuffers(Scene scene)
    {
        if (_scene is not null && ReferenceEquals(_scene.Source, scene))
        {
            return _scene;
        }

        _scene?.Dispose();
        _scene = null;
        _scene = new DeviceSceneBuffers(_accelerator, scene);
        return _scene;
    }

    internal override RenderStatistics? TryRender(Scene scene, ImagePlane plane, IPixelSampler sampler, PixelTarget image, RenderOptions options)
    {
        (int first, int end) = options.Rows(image.Height);
        if (image.EightBitRow(0).IsEmpty || end <= first)
        {
            return null;
        }

        RenderKernel cpuKernel = KernelChoice.Choose(options.Kernel, scene, plane, out _, out string? reason);
        if (FrameOf(sampler) is not PointFrame settings)
        {
            return null;
        }

        options.CancellationToken.ThrowIfCancellationRequested();
        settings.Basis = plane.Basis;
        settings.Background = scene.Background;
        settings.Lanes = cpuKernel != RenderKernel.Scalar ? 1 : 0;
        settings.FirstRow = first;
        int width = image.Width, rows = end - first;
        var bytes = new byte[3L * width * rows];
        var clock = Stopwatch.StartNew();
        lock (_lock)
        {
            ObjectDisposedException.ThrowIf(_disposed, this);
            DeviceSceneBuffers sceneBuffers = SceneBuffers(scene);
            (settings.Hierarchy, settings.HierarchyScale) = (sceneBuffers.UsesHierarchy ? 1 : 0, sceneBuffers.Scale);
            using MemoryBuffer1D<byte, Stride1D.Dense> output = _accelerator.Allocate1D<byte>(bytes.LongLength);
            ArrayView<uint> table = TableView(TableOf(sampler));
            Action<Index1D, PointFrame, ArrayView<DeviceSphere>, ArrayView<uint>, ArrayView<byte>, ArrayView<HierarchyNode>, ArrayView<int>> kernel = Kernel;
            _accelerator.Synchronize();
            long launched = Stopwatch.GetTimestamp();
            kernel(width * rows, settings, sceneBuffers.Spheres, table, output.View, sceneBuffers.Nodes, sceneBuffers.Order);
            _accelerator.Synchronize();
            LastKernelTime = Stopwatch.GetElapsedTime(launched);
            output.CopyToCPU(bytes);
        }

        clock.Stop();
        CopyRows(bytes, image, first, end);

        return new RenderStatistics((long)width * rows * sampler.SamplesPerPixel, clock.Elapsed)
        {
            Kernel = cpuKernel,
            Device = Name,
            ScalarReason = reason,
        };
    }
}

/// <summary>A scene uploaded to a device: its spheres (with their colours), its hierarchy's nodes and order.</summary>
internal sealed class DeviceSceneBuffers : IDisposable
{
    private readonly MemoryBuffer1D<DeviceSphere, Stride1D.Dense> _spheres;
    private readonly MemoryBuffer1D<HierarchyNode, Stride1D.Dense> _nodes;
    private readonly MemoryBuffer1D<int, Stride1D.Dense> _order;

    /// <summary>Uploads <paramref name="scene"/> to <paramref name="accelerator"/>.</summary>
    /// <param name="accelerator">The device.</param>
    /// <param name="scene">The scene.</param>
    public DeviceSceneBuffers(Accelerator accelerator, Scene scene)
    {
        Source = scene;
        var spheres = new DeviceSphere[Math.Max(1, scene.Spheres.Count)];
        for (int k = 0; k < scene.Spheres.Count; k++)
        {
            Sphere s = scene.Spheres[k];
            spheres[k] = new DeviceSphere(s.Center, s.Radius, scene.ColourOf(k));
        }

        SphereHierarchy? hierarchy = scene.Hierarchy;
        UsesHierarchy = hierarchy is not null && hierarchy.Depth <= DeviceScene.MaxDepth;
        HierarchyNode[] nodes = UsesHierarchy ? hierarchy!.Nodes.ToArray() : new HierarchyNode[1];
        int[] order = UsesHierarchy ? hierarchy!.Order.ToArray() : new int[1];
        Scale = UsesHierarchy ? hierarchy!.Scale : 0;
        _spheres = accelerator.Allocate1D(spheres);
        _nodes = accelerator.Allocate1D(nodes);
        _order = accelerator.Allocate1D(order);
        Spheres = _spheres.View.SubView(0, scene.Spheres.Count);
    }

    /// <summary>The scene uploaded.</summary>
    public Scene Source { get; }

    /// <summary>True when the device traces through the hierarchy.</summary>
    public bool UsesHierarchy { get; }

    /// <summary>The hierarchy's scale.</summary>
    public double Scale { get; }

    /// <summary>The spheres, in the scene's order.</summary>
    public ArrayView<DeviceSphere> Spheres { get; }

    /// <summary>The hierarchy's nodes.</summary>
    public ArrayView<HierarchyNode> Nodes => _nodes.View;

    /// <summary>The hierarchy's sphere order.</summary>
    public ArrayView<int> Order => _order.View;

    /// <inheritdoc />
    public void Dispose()
    {
        _spheres.Dispose();
        _nodes.Dispose();
        _order.Dispose();
    }
}

/// <summary>
/// The adaptive lattice on the host, for the pixels the device leaves to it: each point traced by the CPU's scalar
/// double path (<see cref="LatticeHits.TraceScalar"/>, the answer of the CPU's lattice), the CPU's own guard.
/// </summary>
internal struct HostLattice(Scene scene, ImagePlane plane, long size, SilhouetteGuard? guard) : ILatticeSource
{
    private readonly double _latticeWidth = plane.Width * (double)size, _latticeHeight = plane.Height * (double)size;

    /// <summary>The points traced.</summary>
    public long Traced { get; private set; }

    /// <inheritdoc />
    public Intensity At(long lx, long ly, out double weight)
    {
        weight = AdaptivePixel.Share(lx, ly, size);
        return Centre(lx, ly);
    }

    /// <inheritdoc />
    public Intensity Centre(long lx, long ly)
    {
        Traced++;
        return scene.ColourOf(LatticeHits.TraceScalar(scene, plane, _latticeWidth, _latticeHeight, lx, ly) - 1);
    }

    /// <inheritdoc />
    public readonly bool MayCross(long x0, long y0, long size) => guard?.MayCross(x0, y0, size) ?? false;
}
