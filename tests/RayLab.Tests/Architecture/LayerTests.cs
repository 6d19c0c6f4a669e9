using ArchUnitNET.Domain;
using ArchUnitNET.Loader;

namespace RayLab.Tests.Architecture;

/// <summary>
/// The core's layers (docs/architecture.md), read from its IL: every type's dependencies on the core's other types,
/// checked against the allowed layer graph. A layer is a namespace: <c>RayLab.X</c> is layer <c>X</c> (a deeper
/// namespace belongs to the longest layer its name starts with). The root namespace <c>RayLab</c> holds the everyday
/// public types of every level (<see cref="Double3"/> and <see cref="Renderer"/> alike), so a root type has no layer
/// of its own: it stands on the layers it uses, directly or through other root types, and a layer may use a root
/// type only where it may use every layer that root type stands on, directly or through the layers it may use (a
/// metric may use <see cref="Image"/>, which stands on Imaging and, through Imaging, on Simd).
/// </summary>
public sealed class LayerTests
{
    private const string Root = "RayLab";

    /// <summary>
    /// The layers, bottom up, each with the layers it may use (itself always). Simd is lane arithmetic over the
    /// geometry alone; the samplers (Sampling, with their lane forms) sit over Simd, packet tracing
    /// (Rendering.Packets) over the cameras and Simd, the renderers over both, the adaptive diagram
    /// (Rendering.Inspection) over two renderers, and scene files (Scenes) over everything.
    /// </summary>
    private static readonly Dictionary<string, string[]> Allowed = new()
    {
        ["Geometry"] = [],
        ["Simd"] = ["Geometry"],
        ["Sampling"] = ["Geometry", "Simd"],
        ["Cameras"] = ["Geometry", "Simd"],
        ["Imaging"] = ["Geometry", "Simd"],
        ["Metrics"] = ["Geometry", "Imaging"],
        ["Rendering.Packets"] = ["Geometry", "Simd", "Cameras"],
        ["Rendering"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets"],
        ["Rendering.Point"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.Adaptive"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.Exact"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.PixelMethods"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering"],
        ["Rendering.Inspection"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Rendering.Packets", "Rendering", "Rendering.Adaptive", "Rendering.Exact"],
        ["Scenes"] = ["Geometry", "Sampling", "Simd", "Cameras", "Imaging", "Metrics", "Rendering.Packets", "Rendering", "Rendering.Point", "Rendering.Adaptive", "Rendering.Exact", "Rendering.PixelMethods", "Rendering.Inspection"],
    };

    private static readonly Lazy<ArchUnitNET.Domain.Architecture> Core = new(() => new ArchLoader().LoadAssemblies(typeof(Scene).Assembly).Build());

    /// <summary>Each root type → the layers it stands on (those it uses, directly or through other root types).</summary>
    private static readonly Lazy<Dictionary<string, SortedSet<string>>> StandsOn = new(RootStandsOn);

    [Fact]
    public void EveryTypeHasALayer()
    {
        string[] unplaced = [.. CoreTypes().Where(type => !IsRoot(type) && LayerOf(type) is null).Select(type => type.FullName)];
        Assert.True(unplaced.Length == 0, $"No layer for: {string.Join(", ", unplaced)} (add its namespace to {nameof(LayerTests)}.{nameof(Allowed)}).");
    }

    [Fact]
    public void NoLayerUsesALayerAboveItOrASiblingRenderer()
    {
        string[] violations =
        [
            .. LayerDependencies()
                .Where(d => d.From != d.To && !(d.Via is null ? [.. Allowed[d.From]] : Reachable(d.From)).Contains(d.To))
                .Select(d => d.Via is null
                    ? $"{d.From} → {d.To}: {d.Source} uses {d.Target}"
                    : $"{d.From} → {d.To}: {d.Source} uses {d.Via}, which stands on {d.To} ({d.Target})")
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

        // The root types' levels are derived: the facade stands on the renderers, the model on nothing above the geometry.
        Assert.Contains("Rendering.Exact", StandsOn.Value[typeof(Renderer).FullName!]);
        Assert.Contains("Rendering.Adaptive", StandsOn.Value[typeof(RenderMethod).FullName!]);
        Assert.All(StandsOn.Value.GetValueOrDefault(typeof(Double3).FullName!) ?? [], layer => Assert.Equal("Geometry", layer));
        Assert.Contains(LayerDependencies(), d => d.Via is not null);
    }

    private static IEnumerable<IType> CoreTypes() =>
        Core.Value.Types.Where(type => type.FullName.StartsWith(Root, StringComparison.Ordinal) && !type.Name.StartsWith('<'));

    /// <summary>The core types each core type uses (generic parameters and other assemblies left out).</summary>
    private static IEnumerable<(IType Source, IType Target)> TypeDependencies() =>
        from type in CoreTypes()
        from dependency in type.Dependencies
        let target = dependency.Target
        where target is not GenericParameter
            && target.FullName.StartsWith(Root, StringComparison.Ordinal)
            && target.Assembly.FullName == type.Assembly.FullName
        select (type, target);

    /// <summary>
    /// Layer-to-layer uses: a direct one (<c>Via</c> null), or one through a root type, which is a use of every layer
    /// that root type stands on.
    /// </summary>
    private static IEnumerable<(string From, string To, string Source, string Target, string? Via)> LayerDependencies()
    {
        foreach ((IType source, IType target) in TypeDependencies())
        {
            if (IsRoot(source) || LayerOf(source) is not string from)
            {
                continue;
            }

            if (!IsRoot(target))
            {
                if (LayerOf(target) is string to)
                {
                    yield return (from, to, Outer(source.FullName), Outer(target.FullName), null);
                }

                continue;
            }

            string via = Outer(target.FullName);
            foreach (string to in StandsOn.Value.GetValueOrDefault(via) ?? [])
            {
                yield return (from, to, Outer(source.FullName), StandsOnExample(via, to), via);
            }
        }
    }

    /// <summary>The layers each root type stands on: a fixed point over the root types' uses of each other.</summary>
    private static Dictionary<string, SortedSet<string>> RootStandsOn()
    {
        var layers = new Dictionary<string, SortedSet<string>>(StringComparer.Ordinal);
        var uses = new Dictionary<string, HashSet<string>>(StringComparer.Ordinal);
        foreach ((IType source, IType target) in TypeDependencies().Where(d => IsRoot(d.Source)))
        {
            string from = Outer(source.FullName);
            SortedSet<string> own = layers.TryGetValue(from, out SortedSet<string>? set) ? set : layers[from] = new(StringComparer.Ordinal);
            HashSet<string> roots = uses.TryGetValue(from, out HashSet<string>? r) ? r : uses[from] = new(StringComparer.Ordinal);
            if (IsRoot(target))
            {
                roots.Add(Outer(target.FullName));
            }
            else if (LayerOf(target) is string layer)
            {
                own.Add(layer);
            }
        }

        for (bool changed = true; changed;)
        {
            changed = false;
            foreach ((string root, HashSet<string> used) in uses)
            {
                foreach (string other in used)
                {
                    if (layers.TryGetValue(other, out SortedSet<string>? more))
                    {
                        int before = layers[root].Count;
                        layers[root].UnionWith(more);
                        changed |= layers[root].Count != before;
                    }
                }
            }
        }

        return layers;
    }

    /// <summary>A type of <paramref name="layer"/> that <paramref name="root"/> uses, or names the root type it reaches it through.</summary>
    private static string StandsOnExample(string root, string layer)
    {
        (IType _, IType? target) = TypeDependencies().FirstOrDefault(d => Outer(d.Source.FullName) == root && !IsRoot(d.Target) && LayerOf(d.Target) == layer);
        return target is null ? "through other root types" : $"it uses {Outer(target.FullName)}";
    }

    /// <summary>The layers <paramref name="layer"/> may use, directly or through the layers it may use.</summary>
    private static HashSet<string> Reachable(string layer)
    {
        var reached = new HashSet<string>(StringComparer.Ordinal);
        var next = new Stack<string>(Allowed[layer]);
        while (next.TryPop(out string? current))
        {
            if (reached.Add(current))
            {
                foreach (string below in Allowed[current])
                {
                    next.Push(below);
                }
            }
        }

        return reached;
    }

    private static bool IsRoot(IType type) => type.Namespace.FullName == Root;

    /// <summary>The layer of a type: its namespace less <c>RayLab.</c>, or the longest layer that namespace starts with.</summary>
    private static string? LayerOf(IType type)
    {
        string ns = type.Namespace.FullName;
        if (!ns.StartsWith(Root + ".", StringComparison.Ordinal))
        {
            return null;
        }

        string name = ns[(Root.Length + 1)..];
        return Allowed.Keys
            .Where(layer => name == layer || name.StartsWith(layer + ".", StringComparison.Ordinal))
            .MaxBy(layer => layer.Length);
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
