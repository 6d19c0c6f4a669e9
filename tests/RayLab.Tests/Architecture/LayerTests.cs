using ArchUnitNET.Domain;
using ArchUnitNET.Domain.Dependencies;
using ArchUnitNET.Loader;

namespace RayLab.Tests.Architecture;

/// <summary>
/// The core's layers (docs/architecture.md), read from its IL: every type's dependencies on the core's other types,
/// checked against the allowed layer graph. A type's layer is its namespace (RayLab.Simd, RayLab.Cameras, …), except
/// for the everyday public types, which live in the root namespace <c>RayLab</c> (or, for three public sampler types,
/// in <c>RayLab.Sampling</c>) while their files sit in a concept folder: those are listed here by name with their
/// folder's layer, and a new type in one of those namespaces fails <see cref="EveryTypeHasALayer"/> until it is listed.
/// </summary>
public sealed class LayerTests
{
    /// <summary>
    /// The layers, bottom up, each with the layers it may use (itself always). Simd is lane arithmetic over the
    /// model alone; the samplers (Sampling, their lane forms and the lanes' helpers in Sampling.Lanes among them) sit
    /// over Simd, packet tracing
    /// (Rendering.Packets) over the cameras and Simd, and the renderers over both.
    /// </summary>
    private static readonly Dictionary<string, string[]> Allowed = new()
    {
        ["Model"] = [],
        ["Simd"] = ["Model"],
        ["Sampling"] = ["Model", "Simd"],
        ["Cameras"] = ["Model", "Simd"],
        ["Imaging"] = ["Model", "Simd"],
        ["Metrics"] = ["Model", "Imaging"],
        ["Rendering.Packets"] = ["Model", "Simd", "Cameras"],
        ["Rendering"] = ["Model", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets"],
        ["Rendering.Point"] = ["Model", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.Adaptive"] = ["Model", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.Exact"] = ["Model", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.PixelMethods"] = ["Model", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Facade"] = ["Model", "Sampling", "Simd", "Cameras", "Imaging", "Metrics", "Rendering.Packets", "Rendering", "Rendering.Point", "Rendering.Adaptive", "Rendering.Exact", "Rendering.PixelMethods"],
    };

    /// <summary>Namespace (and its sub-namespaces) → layer.</summary>
    private static readonly (string Namespace, string Layer)[] Namespaces =
    [
        ("RayLab.Geometry", "Model"),
        ("RayLab.Sampling", "Sampling"),
        ("RayLab.Simd", "Simd"),
        ("RayLab.Cameras", "Cameras"),
        ("RayLab.Imaging", "Imaging"),
        ("RayLab.Metrics", "Metrics"),
        ("RayLab.Rendering.Packets", "Rendering.Packets"),
        ("RayLab.Rendering.Point", "Rendering.Point"),
        ("RayLab.Rendering.Adaptive", "Rendering.Adaptive"),
        ("RayLab.Rendering.Exact", "Rendering.Exact"),
        ("RayLab.Rendering.PixelMethods", "Rendering.PixelMethods"),
        ("RayLab.Rendering", "Rendering"),
        ("RayLab.Scenes", "Facade"),
    ];

    /// <summary>The public types whose namespace is not their folder's: full name → the folder's layer.</summary>
    private static readonly Dictionary<string, string> Listed = new()
    {
        ["RayLab.Double3"] = "Model",
        ["RayLab.Ray"] = "Model",
        ["RayLab.Sphere"] = "Model",
        ["RayLab.Intensity"] = "Model",
        ["RayLab.Scene"] = "Model",
        ["RayLab.SceneAcceleration"] = "Model",
        ["RayLab.Camera"] = "Cameras",
        ["RayLab.OrthoCamera"] = "Cameras",
        ["RayLab.PerspectiveCamera"] = "Cameras",
        ["RayLab.Window"] = "Cameras",
        ["RayLab.EightBit"] = "Imaging",
        ["RayLab.Image"] = "Imaging",
        ["RayLab.IPixelRows"] = "Imaging",
        ["RayLab.ImageError"] = "Imaging",
        ["RayLab.ImageFormat"] = "Imaging",
        ["RayLab.ImageEncoder"] = "Imaging",
        ["RayLab.ImageFormats"] = "Imaging",
        ["RayLab.Rgb24"] = "Imaging",
        ["RayLab.RenderKernel"] = "Rendering",
        ["RayLab.RenderProgress"] = "Rendering",
        ["RayLab.RenderStatistics"] = "Rendering",
        ["RayLab.UnsupportedSceneException"] = "Rendering.Exact",
        ["RayLab.Sampling.AdaptiveSampler"] = "Rendering.Adaptive",
        ["RayLab.Sampling.IPixelMethod`1"] = "Rendering.PixelMethods",
        ["RayLab.Sampling.PixelTracer"] = "Rendering.PixelMethods",
        // A figure that sets the adaptive renderer's recursion beside the exact renderer's reference: it uses two
        // renderers, so it sits above them (its file stays beside the adaptive code it draws).
        ["RayLab.Rendering.Adaptive.AdaptiveDiagram"] = "Facade",
        ["RayLab.Renderer"] = "Facade",
        ["RayLab.RenderMethod"] = "Facade",
    };

    private static readonly Lazy<ArchUnitNET.Domain.Architecture> Core = new(() => new ArchLoader().LoadAssemblies(typeof(Scene).Assembly).Build());

    [Fact]
    public void EveryTypeHasALayer()
    {
        string[] unplaced = [.. CoreTypes().Where(type => LayerOf(type) is null).Select(type => type.FullName)];
        Assert.True(unplaced.Length == 0, $"No layer for: {string.Join(", ", unplaced)} (list it in {nameof(LayerTests)}).");
    }

    [Fact]
    public void NoLayerUsesALayerAboveItOrASiblingRenderer()
    {
        string[] violations =
        [
            .. LayerDependencies()
                .Where(d => d.From != d.To && !Allowed[d.From].Contains(d.To))
                .Select(d => $"{d.From} → {d.To}: {d.Source} uses {d.Target}")
                .Distinct()
                .Order(StringComparer.Ordinal),
        ];
        Assert.True(violations.Length == 0, $"{violations.Length} imports break the layers:\n{string.Join("\n", violations)}");
    }

    [Fact]
    public void TheLayerGraphHasNoCycle()
    {
        var edges = LayerDependencies().Where(d => d.From != d.To).Select(d => (d.From, d.To)).ToHashSet();
        List<string> cycle = FindCycle(edges);
        Assert.True(cycle.Count == 0, $"The layers form a cycle: {string.Join(" → ", cycle)}");
    }

    [Fact]
    public void TheAllowedGraphIsAcyclicAndTheCheckSeesRealDependencies()
    {
        // The rules themselves must be a DAG, and the check must see dependencies at all (a loader that found none would pass everything).
        Assert.Empty(FindCycle([.. Allowed.SelectMany(pair => pair.Value.Select(to => (pair.Key, to)))]));
        Assert.Contains(LayerDependencies(), d => d.From == "Rendering.Point" && d.To == "Simd");
        Assert.Contains(LayerDependencies(), d => d.From == "Cameras" && d.To == "Simd");
        Assert.Contains(LayerDependencies(), d => d.From == "Sampling" && d.To == "Simd");
        Assert.Contains(LayerDependencies(), d => d.From == "Rendering.Packets" && d.To == "Cameras");
    }

    private static IEnumerable<IType> CoreTypes() =>
        Core.Value.Types.Where(type => type.FullName.StartsWith("RayLab", StringComparison.Ordinal) && !type.Name.StartsWith('<'));

    private static IEnumerable<(string From, string To, string Source, string Target)> LayerDependencies()
    {
        foreach (IType type in CoreTypes())
        {
            string? from = LayerOf(type);
            foreach (ITypeDependency dependency in type.Dependencies)
            {
                IType target = dependency.Target;
                if (target is GenericParameter || !target.FullName.StartsWith("RayLab", StringComparison.Ordinal) || target.Assembly.FullName != type.Assembly.FullName)
                {
                    continue;
                }

                string? to = LayerOf(target);
                if (from is not null && to is not null)
                {
                    yield return (from, to, Outer(type.FullName), Outer(target.FullName));
                }
            }
        }
    }

    /// <summary>The layer of a type (a nested or generated type: its outermost type's).</summary>
    private static string? LayerOf(IType type)
    {
        string name = Outer(type.FullName);
        if (Listed.TryGetValue(name, out string? listed))
        {
            return listed;
        }

        foreach ((string ns, string layer) in Namespaces)
        {
            if (name.StartsWith(ns + ".", StringComparison.Ordinal))
            {
                return layer;
            }
        }

        return null;
    }

    private static string Outer(string fullName)
    {
        int cut = fullName.IndexOfAny(['+', '/']);
        return cut < 0 ? fullName : fullName[..cut];
    }

    /// <summary>A cycle of the directed graph, as its nodes with the first repeated at the end; empty when there is none.</summary>
    private static List<string> FindCycle(HashSet<(string From, string To)> edges)
    {
        var state = new Dictionary<string, int>(); // 1 on the path, 2 done
        var path = new List<string>();
        foreach (string start in edges.Select(e => e.From).Distinct().Order(StringComparer.Ordinal))
        {
            if (Visit(start))
            {
                return path;
            }
        }

        return [];

        bool Visit(string node)
        {
            if (state.TryGetValue(node, out int s))
            {
                if (s == 1)
                {
                    path = [.. path.SkipWhile(n => n != node), node];
                    return true;
                }

                return false;
            }

            state[node] = 1;
            path.Add(node);
            foreach ((_, string next) in edges.Where(e => e.From == node).OrderBy(e => e.To, StringComparer.Ordinal))
            {
                if (Visit(next))
                {
                    return true;
                }
            }

            path.RemoveAt(path.Count - 1);
            state[node] = 2;
            return false;
        }
    }
}
